// SPDX-License-Identifier: MIT
#pragma once
/// @file evaluation.h
/// @brief Scoring a given alignment (Open3D's evaluate_registration).
#include <Eigen/Core>

#include "o3d/geometry/point_cloud.h"
#include "o3d/registration/registration_result.h"

namespace o3d::registration {

/// @brief Fitness, inlier RMSE and correspondences of `source` moved by `transformation` against
/// `target` (pairs farther than `max_correspondence_distance` are ignored). The result carries
/// `transformation`. @see o3d.pipelines.registration.evaluate_registration
/// @throws o3d::InvalidArgument on an empty cloud, a distance <= 0 or NaN, a non-finite
/// transformation or num_threads < 0.
RegistrationResult evaluate_registration(const geometry::PointCloud& source, const geometry::PointCloud& target,
                                         double max_correspondence_distance,
                                         const Eigen::Matrix4d& transformation = Eigen::Matrix4d::Identity(),
                                         int num_threads = 0);

}  // namespace o3d::registration
