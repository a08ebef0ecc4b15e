// SPDX-License-Identifier: MIT
#pragma once
/// @file outlier_removal.h
/// @brief Statistical and radius outlier removal (Open3D's RemoveStatisticalOutliers /
/// RemoveRadiusOutliers). Both return the kept indices in ascending order.
#include <cstdint>
#include <vector>

#include "o3d/geometry/point_cloud.h"

namespace o3d::geometry {

/// @brief Open3D's rule: for each point, the mean of the sqrt distances to its `nb_neighbors` nearest
/// points (the point itself included, as the KD-tree returns it). Over the points whose mean is > 0,
/// m = sum / N and s = sqrt(sum (avg - m)^2 / (N - 1)) (N counts every point, as Open3D); a point is
/// kept when 0 < avg < m + std_ratio * s. Like Open3D, a point whose neighbours all coincide with it
/// (avg == 0) is dropped.
/// @throws InvalidArgument when nb_neighbors < 1, std_ratio is not finite or <= 0, the cloud is empty
/// or holds a non-finite point.
std::vector<int64_t> statistical_outlier_indices(const PointCloud& cloud, int nb_neighbors, double std_ratio,
                                                 int num_threads = 0);

/// @brief Open3D's rule: keep a point when more than `nb_points` points (itself included, i.e. at least
/// `nb_points` others) lie strictly closer than `radius`.
/// @throws InvalidArgument when nb_points < 1, radius is not finite or <= 0, the cloud is empty or
/// holds a non-finite point.
std::vector<int64_t> radius_outlier_indices(const PointCloud& cloud, int nb_points, double radius,
                                            int num_threads = 0);

}  // namespace o3d::geometry
