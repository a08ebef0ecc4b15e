// SPDX-License-Identifier: MIT
#pragma once
/// @file distances.h
/// @brief Point-to-point distances within and between clouds (Open3D's compute_*_distance).
#include <vector>

#include "o3d/geometry/point_cloud.h"

namespace o3d::geometry {

/// @brief For each point, the distance to its nearest other point (0 for a single point or a
/// duplicate). @throws InvalidArgument on a non-finite point.
std::vector<double> compute_nearest_neighbor_distance(const PointCloud& cloud, int num_threads = 0);

/// @brief For each point of `source`, the distance to the closest point of `target`.
/// @throws InvalidArgument when `target` is empty (and source is not) or a point is non-finite.
std::vector<double> compute_point_cloud_distance(const PointCloud& source, const PointCloud& target,
                                                 int num_threads = 0);

}  // namespace o3d::geometry
