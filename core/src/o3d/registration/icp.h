// SPDX-License-Identifier: MIT
#pragma once
/// @file icp.h
/// @brief Iterative closest point (Open3D's registration_icp).
#include <Eigen/Core>
#include <functional>

#include "o3d/geometry/point_cloud.h"
#include "o3d/registration/registration_result.h"

namespace o3d::registration {

/// @brief TransformationEstimation kinds.
enum class Estimation { PointToPoint, PointToPlane };

/// @brief ICPConvergenceCriteria: stop when both changes fall below their threshold.
struct ICPConvergenceCriteria {
    double relative_fitness = 1e-6;
    double relative_rmse = 1e-6;
    int max_iteration = 30;
};

/// @brief Mirrors o3d_icp_options_t.
struct IcpOptions {
    Estimation estimation = Estimation::PointToPoint;
    bool with_scaling = false;  ///< point-to-point only; ignored for point-to-plane
    ICPConvergenceCriteria criteria;
    int num_threads = 0;  ///< 0 = library default
    /// Called on the calling thread after each iteration with (iteration + 1) / max_iteration.
    /// Returning false cancels the call (o3d::Cancelled).
    std::function<bool(double)> progress;
};

/// @brief Align `source` to `target` starting from `init`.
/// Each iteration pairs every moved source point with its nearest target point within
/// `max_correspondence_distance`, fits an update to those pairs and composes it on the left.
/// Results are bitwise identical for any thread count.
/// @see o3d.pipelines.registration.registration_icp
/// @throws o3d::InvalidArgument on an empty cloud, max_correspondence_distance <= 0 or NaN, a non-finite
/// `init`, max_iteration < 0, a negative or NaN relative criterion, num_threads < 0, or point-to-plane
/// without target normals. @throws o3d::Cancelled when `progress` returns false.
RegistrationResult registration_icp(const geometry::PointCloud& source, const geometry::PointCloud& target,
                                    double max_correspondence_distance,
                                    const Eigen::Matrix4d& init = Eigen::Matrix4d::Identity(),
                                    const IcpOptions& options = {});

}  // namespace o3d::registration
