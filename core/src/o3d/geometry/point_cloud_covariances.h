// SPDX-License-Identifier: MIT
#pragma once
/// @file point_cloud_covariances.h
/// @brief Per-point neighbourhood covariances (PointCloud.estimate_covariances).
#include <vector>

#include "o3d/geometry/point_cloud.h"
#include "o3d/kdtree/kd_tree.h"

namespace o3d::geometry {

/// @brief Covariance (divided by the count) of the listed points, two-pass (mean first): unlike
/// Open3D's raw moments it keeps its precision on clouds far from the origin. Shared by the normal and
/// covariance estimators. `indices` must be non-empty and in range.
Eigen::Matrix3d neighbourhood_covariance(const std::vector<Eigen::Vector3d>& points, const std::vector<int>& indices);

/// @brief cloud.covariances[i] = covariance (divided by the count) of point i's neighbourhood, the point
/// itself included; fewer than 3 neighbours give the identity, as Open3D. Identical for any num_threads
/// (0 = default). @throws InvalidArgument on a bad search parameter or a non-finite point.
void estimate_covariances(PointCloud& cloud, const kdtree::SearchParam& param, int num_threads = 0);
/// @brief As above with a tree already built over cloud.points.
void estimate_covariances(PointCloud& cloud, const kdtree::KDTree& tree, const kdtree::SearchParam& param,
                          int num_threads = 0);

}  // namespace o3d::geometry
