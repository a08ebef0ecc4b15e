// SPDX-License-Identifier: MIT
#pragma once
/// @file ball_pivoting_grid.h
/// @brief Ball-pivoting internals: a hashed uniform grid for the many fixed-radius neighbour queries.
#include <Eigen/Core>
#include <cstdint>
#include <vector>

namespace o3d::geometry::ball_pivoting {

/// @brief Points bucketed in cubic cells of one size. Every query of the algorithm has a radius of about
/// the ball's diameter, so with cells that large a query visits at most 3 x 3 x 3 cells and, unlike a
/// KD-tree's radius search, needs no sorting of its answer.
class PointGrid {
public:
    PointGrid(const std::vector<Eigen::Vector3d>& points, double cell_size);

    /// @brief The points within `radius` of `query` (indices and squared distances), cell by cell and by
    /// index within a cell: a fixed order, not sorted by distance.
    void search(const Eigen::Vector3d& query, double radius, std::vector<int>& indices,
                std::vector<double>& distances2) const;

private:
    int64_t cell_coordinate(double x, int axis) const;
    /// Index of the cell with this key in cell_start_, or -1.
    int64_t find_cell(uint64_t key) const;

    Eigen::Vector3d origin_;
    double inv_cell_ = 1.0;
    int64_t max_coordinate_ = 0;
    std::vector<Eigen::Vector3d> sorted_points_;  ///< points in cell order, for locality
    std::vector<int32_t> sorted_index_;           ///< their input indices
    std::vector<uint64_t> cell_key_;              ///< key of each non-empty cell
    std::vector<int64_t> cell_start_;             ///< its first point in sorted order (+ one sentinel)
    std::vector<int64_t> table_;                  ///< open-addressing hash: key -> cell, -1 empty
    int table_shift_ = 64;
};

}  // namespace o3d::geometry::ball_pivoting
