// SPDX-License-Identifier: MIT
#pragma once
/// @file segment_plane.h
/// @brief RANSAC plane segmentation (Open3D's PointCloud::SegmentPlane), deterministic for a seed.
#include <Eigen/Core>
#include <cstdint>
#include <vector>

#include "o3d/geometry/point_cloud.h"

namespace o3d::geometry {

struct PlaneSegmentation {
    Eigen::Vector4d plane = Eigen::Vector4d::Zero();  ///< (a, b, c, d), a x + b y + c z + d = 0, |(a, b, c)| = 1
    std::vector<int64_t> inliers;                     ///< ascending
};

/// @brief Least-squares plane through `points[indices]` (Open3D's GetPlaneFromPoints: centroid plus the
/// largest 2x2 cofactor of the scatter matrix); (0, 0, 0, 0) when the points do not span a plane.
Eigen::Vector4d fit_plane(const std::vector<Eigen::Vector3d>& points, const std::vector<int64_t>& indices);

/// @brief Open3D's RANSAC: each iteration samples `ransac_n` distinct points, fits a plane (cross product
/// for 3, least squares for more; degenerate samples are skipped and not counted), and scores it by
/// fitness = inliers / N (inlier: |plane . (p, 1)| <= distance_threshold), ties broken by the lower
/// "rmse" (Open3D's sum of distances / sqrt(inliers)). After an improvement the iteration budget shrinks
/// to log(1 - probability) / log(1 - fitness^ransac_n) evaluated models (0 once fitness is 1). The inliers of
/// the best model are then refitted by least squares, as Open3D does (the refit is dropped in favour
/// of the RANSAC model if it is degenerate).
///
/// Determinism: iteration i draws its sample from a generator seeded by (seed, i) alone, and models are
/// compared in iteration order, so the result is identical for any `num_threads` (the threads only
/// evaluate blocks of iterations ahead). Open3D's sampler is global and unseeded, so its numbers differ
/// draw by draw, not in kind.
/// @throws InvalidArgument on a non-finite or negative distance_threshold, ransac_n < 3, num_iterations < 1,
/// probability outside (0, 1], or fewer than ransac_n points. @throws NotConverged when every sample was
/// degenerate (e.g. all points collinear).
PlaneSegmentation segment_plane(const PointCloud& cloud, double distance_threshold, int ransac_n, int num_iterations,
                                double probability, uint64_t seed, int num_threads = 0);

}  // namespace o3d::geometry
