// SPDX-License-Identifier: MIT
#pragma once
/// @file camera_json_io.h
/// @brief Open3D's JSON layouts for PinholeCameraIntrinsic, PinholeCameraParameters and
/// PinholeCameraTrajectory, as text. Matrices are stored column-major ("intrinsic_matrix": 9 values,
/// "extrinsic": 16). Malformed text throws o3d::ParseError("<name>: <reason>"); writing a
/// non-finite value throws o3d::InvalidArgument (JSON cannot hold it).
#include <string>
#include <string_view>

#include "o3d/camera/pinhole_camera.h"

namespace o3d::camera {

PinholeCameraIntrinsic parse_intrinsic_json(std::string_view text, const std::string& name);
PinholeCameraParameters parse_parameters_json(std::string_view text, const std::string& name);
PinholeCameraTrajectory parse_trajectory_json(std::string_view text, const std::string& name);

std::string format_intrinsic_json(const PinholeCameraIntrinsic& intrinsic);
std::string format_parameters_json(const PinholeCameraParameters& parameters);
std::string format_trajectory_json(const PinholeCameraTrajectory& trajectory);

}  // namespace o3d::camera
