// SPDX-License-Identifier: MIT
#pragma once
/// @file camera_checks.h
/// @brief Validation shared by the camera readers, the trajectory API and back-projection.
#include <Eigen/Core>

#include "o3d/camera/pinhole_camera.h"

namespace o3d::camera {

/// @brief Throw o3d::InvalidArgument unless fx, fy, cx, cy are finite (`what` names the argument).
void require_finite_intrinsic(const PinholeCameraIntrinsic& intrinsic, const char* what);
/// @brief As require_finite_intrinsic, and the focal lengths are non-zero: needed to divide by them.
void require_projectable_intrinsic(const PinholeCameraIntrinsic& intrinsic, const char* what);
/// @brief Throw o3d::InvalidArgument unless every entry is finite and the last row is (0, 0, 0, 1).
void require_rigid_layout(const Eigen::Matrix4d& extrinsic, const char* what);
/// @brief As require_rigid_layout, and the upper-left 3x3 block is a rotation (orthonormal to 1e-6, det > 0).
void require_rigid(const Eigen::Matrix4d& extrinsic, const char* what);
/// @brief The inverse of a finite, invertible 4x4 matrix; anything else throws o3d::InvalidArgument.
Eigen::Matrix4d checked_inverse(const Eigen::Matrix4d& m, const char* what);

}  // namespace o3d::camera
