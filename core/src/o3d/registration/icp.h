// SPDX-License-Identifier: MIT
#pragma once
/// @file icp.h
/// @brief Iterative closest point (Open3D's registration_icp).
#include <Eigen/Core>
#include <functional>

#include "o3d/geometry/point_cloud.h"
#include "o3d/registration/registration_result.h"
#include "o3d/registration/robust_kernel.h"

namespace o3d::registration {

/// @brief TransformationEstimation kinds: PointToPoint, PointToPlane, ForColoredICP (Park et al. 2017),
/// ForGeneralizedICP (Segal et al. 2009), Symmetric (Rusinkiewicz 2019).
enum class Estimation { PointToPoint, PointToPlane, Colored, Generalized, Symmetric };

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
    /// Weighs the residuals of point-to-plane, colored, generalized and symmetric (not point-to-point).
    RobustKernel kernel;
    /// Colored: weight of the geometric term, in [0, 1] (the photometric term gets 1 - lambda).
    double lambda_geometric = 0.968;
    /// Generalized: variance across the surface of covariances built from normals, > 0.
    double epsilon = 1e-3;
};

/// @brief Align `source` to `target` starting from `init`.
/// Each iteration pairs every moved source point with its nearest target point within
/// `max_correspondence_distance`, fits an update to those pairs and composes it on the left. Fitness
/// and inlier RMSE are those of the nearest-point pairs (Euclidean), for every estimation.
/// What an estimation needs is prepared once per call: colored ICP's target intensity gradients (hybrid
/// search, radius 2 * max_correspondence_distance, 30 neighbours, as Open3D), generalized ICP's
/// covariances (see generalized_icp_covariances). Results are bitwise identical for any thread count.
/// @see o3d.pipelines.registration.registration_icp, registration_colored_icp,
/// registration_generalized_icp, registration_symmetric_icp
/// @throws o3d::InvalidArgument on an empty cloud, max_correspondence_distance <= 0 or NaN, a non-finite
/// `init`, max_iteration < 0, a negative or NaN relative criterion, num_threads < 0, an unknown
/// estimation, an invalid kernel, lambda_geometric outside [0, 1], epsilon not > 0, point-to-plane or
/// colored without target normals, colored without colors on both clouds, or symmetric without normals
/// on both clouds. @throws o3d::Cancelled when `progress` returns false.
RegistrationResult registration_icp(const geometry::PointCloud& source, const geometry::PointCloud& target,
                                    double max_correspondence_distance,
                                    const Eigen::Matrix4d& init = Eigen::Matrix4d::Identity(),
                                    const IcpOptions& options = {});

}  // namespace o3d::registration
