// SPDX-License-Identifier: MIT
#pragma once
/// @file self_knn_distances.h
/// @brief For every point of a cloud, the mean distance to its k nearest points of the same cloud
/// (itself included), as statistical outlier removal needs it.
#include <Eigen/Core>
#include <vector>

namespace o3d::geometry {

/// @brief Mean of sqrt(d2) over the min(k, n) smallest squared distances of each point to the cloud,
/// summed in ascending order: bit-identical to averaging a KD-tree kNN result. Exact, through a uniform
/// grid (point queries of a cloud against itself are cache-friendly when visited cell by cell); falls
/// back to the KD-tree for points the grid cannot answer in a few rings and for clouds whose grid would
/// be degenerate. Results do not depend on the thread count.
/// @throws InvalidArgument when k < 1 or a point is not finite.
std::vector<double> mean_self_knn_distances(const std::vector<Eigen::Vector3d>& points, int k, int num_threads = 0);

}  // namespace o3d::geometry
