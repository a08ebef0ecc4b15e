// SPDX-License-Identifier: MIT
#pragma once
/// @file warping_field.h
/// @brief The non-rigid optimizer's per-image deformation: a regular grid of anchor points, each with a 2-D
/// offset in pixels; a point of the image moves by the bilinear blend of the four anchors around it
/// (Zhou & Koltun 2014, section 4). Small, smooth and cheap: each residual touches only four anchors.
#include <Eigen/Core>
#include <array>
#include <vector>

namespace o3d::color_map::detail {

class WarpingField {
public:
    /// @brief The four anchors around a point and their bilinear weights.
    struct Cell {
        std::array<int, 4> anchor{};
        std::array<double, 4> weight{};
    };

    /// @brief No anchors: the identity warp of the rigid optimizer.
    WarpingField() = default;
    /// @brief `vertical_anchors` (>= 2) rows spanning the image height; as many columns at the same spacing as
    /// reach the last pixel column. All offsets start at zero.
    WarpingField(int width, int height, int vertical_anchors);

    bool empty() const { return offsets_.empty(); }
    int size() const { return int(offsets_.size()); }
    const Eigen::Vector2d& offset(int anchor) const { return offsets_[size_t(anchor)]; }
    Eigen::Vector2d& offset(int anchor) { return offsets_[size_t(anchor)]; }

    /// @brief The cell holding pixel (u, v); points outside the grid use the nearest border cell, clamped.
    Cell cell(double u, double v) const;
    /// @brief How far the blend of `cell`'s anchors moves a point.
    Eigen::Vector2d displacement(const Cell& cell) const;

private:
    int columns_ = 0, rows_ = 0;
    double spacing_ = 1.0;
    std::vector<Eigen::Vector2d> offsets_;  ///< anchor (column i, row j) at j * columns_ + i
};

}  // namespace o3d::color_map::detail
