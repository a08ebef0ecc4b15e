// SPDX-License-Identifier: MIT
#pragma once
/// @file odometry_information.h
/// @brief Open3D's CreateInformationMatrix for RGB-D odometry: J^T J of the point-to-point rows at the target
/// points of the final correspondences.
#include "o3d/odometry/odometry_level.h"

namespace o3d::odometry::detail {

/// @brief `full` is level 0 (full resolution), `motion` the final source-to-target motion.
Matrix6d information_matrix(const PackedLevel& full, const Eigen::Matrix4d& motion, double depth_diff_max);

}  // namespace o3d::odometry::detail
