// SPDX-License-Identifier: MIT
#pragma once
/// @file iss_keypoints.h
/// @brief Intrinsic Shape Signature keypoints (Zhong 2009) with the defaults and semantics of Open3D 0.20
/// o3d.geometry.keypoint.compute_iss_keypoints.
#include <cstdint>
#include <vector>

#include "o3d/geometry/point_cloud.h"

namespace o3d::geometry {

/// @brief Parameters of ISS keypoint detection (Open3D's defaults).
struct IssOptions {
    /// Radius of the neighbourhood whose scatter matrix is analysed. 0: 6 x the cloud resolution.
    double salient_radius = 0.0;
    /// Radius of the non-maximum suppression. 0: 4 x the cloud resolution. When either radius is 0,
    /// both are derived from the resolution (mean distance of a point to its nearest other point).
    double non_max_radius = 0.0;
    double gamma_21 = 0.975;  ///< keep a point only if lambda2 / lambda1 < gamma_21
    double gamma_32 = 0.975;  ///< ... and lambda3 / lambda2 < gamma_32
    int min_neighbors = 5;    ///< fewer points in either ball (the point included) rule a point out
    int num_threads = 0;      ///< 0 = library default
};

/// @brief Indices (ascending) of the ISS keypoints of `cloud`: the points whose salient-radius scatter
/// matrix Sum (q - mean)(q - mean)^T has eigenvalues l1 >= l2 >= l3 with l2/l1 < gamma_21 and
/// l3/l2 < gamma_32, and whose l3 (> 0) is the largest within non_max_radius (ties keep both).
/// Balls are open (distance < radius), as Open3D's FLANN radius search. An empty cloud, or one whose
/// derived radius is 0 (a single point, all points equal), has no keypoints. Deterministic for any
/// thread count.
/// @throws InvalidArgument on a negative or non-finite radius, a gamma outside (0, 1], min_neighbors < 0,
/// or a non-finite point.
std::vector<int64_t> compute_iss_keypoint_indices(const PointCloud& cloud, const IssOptions& options = {});

/// @brief The keypoints as a cloud: select_by_index(cloud, indices), so normals, colors and covariances
/// follow when the cloud has them (Open3D 0.20 keeps normals and colors too).
PointCloud compute_iss_keypoints(const PointCloud& cloud, const IssOptions& options = {});

}  // namespace o3d::geometry
