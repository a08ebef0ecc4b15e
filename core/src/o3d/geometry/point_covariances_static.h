// SPDX-License-Identifier: MIT
#pragma once
/// @file point_covariances_static.h
/// @brief Per-point covariances returned instead of stored (Open3D's static
/// PointCloud.estimate_point_covariances(input, search_param)).
#include <Eigen/Core>
#include <vector>

#include "o3d/geometry/point_cloud.h"
#include "o3d/kdtree/kd_tree.h"

namespace o3d::geometry {

/// @brief The covariances estimate_covariances would store (point i's neighbourhood, itself included,
/// divided by the count; the identity below 3 neighbours), returned and the cloud left unchanged.
/// Identical for any num_threads (0 = default).
/// @throws InvalidArgument on a bad search parameter or a non-finite point.
std::vector<Eigen::Matrix3d> estimate_point_covariances(const PointCloud& cloud, const kdtree::SearchParam& param,
                                                        int num_threads = 0);

}  // namespace o3d::geometry
