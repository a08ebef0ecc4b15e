// SPDX-License-Identifier: MIT
#pragma once
/// @file statistics.h
/// @brief Point statistics: mean/covariance and Mahalanobis distances (Open3D's
/// ComputeMeanAndCovariance / ComputeMahalanobisDistance).
#include <Eigen/Core>
#include <utility>
#include <vector>

#include "o3d/geometry/point_cloud.h"

namespace o3d::geometry {

/// @brief Mean and covariance (divided by N, as Open3D) of the points. Computed in two passes
/// (centred sums), which equals Open3D's one-pass cumulants up to rounding but does not lose precision
/// on clouds far from the origin. @throws InvalidArgument on an empty cloud.
std::pair<Eigen::Vector3d, Eigen::Matrix3d> compute_mean_and_covariance(const PointCloud& cloud);

/// @brief sqrt((p - mean)^T C^+ (p - mean)) per point, C the covariance above.
/// Open3D uses C.inverse(), which yields NaN/inf for a singular covariance (planar, collinear or
/// single-point clouds). Here C^+ is the Moore-Penrose pseudo-inverse (eigenvalues below
/// 1e-12 * the largest count as zero): equal to the inverse whenever C is invertible, and for a
/// degenerate cloud the distance measured inside the subspace the points span (0 for all-equal points).
/// @throws InvalidArgument on an empty cloud.
std::vector<double> compute_mahalanobis_distance(const PointCloud& cloud, int num_threads = 0);

}  // namespace o3d::geometry
