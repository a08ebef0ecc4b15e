// SPDX-License-Identifier: MIT
#pragma once
/// @file information_matrix.h
/// @brief 6x6 information matrix of an alignment (Open3D's get_information_matrix_from_point_clouds).
#include <Eigen/Core>

#include "o3d/geometry/point_cloud.h"

namespace o3d::registration {

/// @brief Sum over the correspondences of G^T G, where G = [ -[q]x | I ] is the Jacobian of the
/// target point q = (x, y, z) under a small motion (rotation first, then translation; Choi et al.,
/// "Robust Reconstruction of Indoor Scenes", 2015). Correspondences are found as in
/// evaluate_registration. Zero when there are none.
/// @see o3d.pipelines.registration.get_information_matrix_from_point_clouds
/// @throws o3d::InvalidArgument as evaluate_registration.
Eigen::Matrix<double, 6, 6> get_information_matrix_from_point_clouds(
    const geometry::PointCloud& source, const geometry::PointCloud& target, double max_correspondence_distance,
    const Eigen::Matrix4d& transformation = Eigen::Matrix4d::Identity(), int num_threads = 0);

}  // namespace o3d::registration
