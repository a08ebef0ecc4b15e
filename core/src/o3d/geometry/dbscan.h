// SPDX-License-Identifier: MIT
#pragma once
/// @file dbscan.h
/// @brief DBSCAN clustering (Open3D's PointCloud::ClusterDBSCAN).
#include <cstdint>
#include <vector>

#include "o3d/geometry/point_cloud.h"

namespace o3d::geometry {

/// @brief One label per point: clusters 0, 1, ... numbered in order of their lowest point index, -1 for noise.
/// Open3D's algorithm: the neighbours of a point are those strictly closer than `eps` (itself included);
/// a point is core with >= `min_points` neighbours. Points are visited in index order; an unlabelled core
/// point starts a cluster that grows through core points; a border point joins the first cluster (in
/// that visiting order) that reaches it. The partition equals Open3D's; Open3D numbers clusters by their
/// first core point instead, which differs only when a border point precedes every core point of its
/// cluster. Deterministic for any thread count.
/// @throws InvalidArgument on eps not finite or <= 0, min_points < 0, an empty cloud or a non-finite point.
std::vector<int32_t> cluster_dbscan(const PointCloud& cloud, double eps, int min_points, int num_threads = 0);

}  // namespace o3d::geometry
