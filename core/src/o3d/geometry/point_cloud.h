// SPDX-License-Identifier: MIT
#pragma once
/// @file point_cloud.h
/// @brief The point-cloud container: contiguous N x 3 float64 arrays (zero-copy views are legal).
#include <Eigen/Core>
#include <vector>

namespace o3d::geometry {

/// @brief Points, optional per-point normals, colors (RGB in [0,1]) and 3x3 covariances.
/// Attributes count only when their size equals the number of points (Open3D semantics).
struct PointCloud {
    std::vector<Eigen::Vector3d> points;
    std::vector<Eigen::Vector3d> normals;
    std::vector<Eigen::Vector3d> colors;
    std::vector<Eigen::Matrix3d> covariances;

    size_t size() const { return points.size(); }
    bool has_points() const { return !points.empty(); }
    bool has_normals() const { return !points.empty() && normals.size() == points.size(); }
    bool has_colors() const { return !points.empty() && colors.size() == points.size(); }
    bool has_covariances() const { return !points.empty() && covariances.size() == points.size(); }
    void clear() {
        points.clear();
        normals.clear();
        colors.clear();
        covariances.clear();
    }
};

}  // namespace o3d::geometry
