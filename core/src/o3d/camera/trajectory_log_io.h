// SPDX-License-Identifier: MIT
#pragma once
/// @file trajectory_log_io.h
/// @brief The .log trajectory format (Redwood / Choi et al.): per frame a line "id id next" and a
/// 4x4 camera-to-world pose in four rows. As in Open3D, each pose becomes extrinsic = inverse(pose)
/// with the PrimeSense default intrinsic; writing stores inverse(extrinsic) and drops the intrinsic.
#include <string>
#include <string_view>

#include "o3d/camera/pinhole_camera.h"

namespace o3d::camera {

/// @brief Throws o3d::ParseError("<name>: line N: <reason>") on malformed or singular poses.
PinholeCameraTrajectory parse_trajectory_log(std::string_view text, const std::string& name);
/// @brief Numbers are written in their shortest exact form, so a read gives back the same poses.
/// A non-invertible extrinsic throws o3d::InvalidArgument.
std::string format_trajectory_log(const PinholeCameraTrajectory& trajectory);

}  // namespace o3d::camera
