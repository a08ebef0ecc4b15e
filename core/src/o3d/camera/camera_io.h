// SPDX-License-Identifier: MIT
#pragma once
/// @file camera_io.h
/// @brief Camera files: o3d.io.read/write_pinhole_camera_{intrinsic,parameters,trajectory}.
/// Trajectory formats: "json", "log"; "auto" or "" picks by the extension. Errors: o3d::IoError
/// (cannot open/write), o3d::ParseError (malformed), o3d::Unsupported (format).
#include <string>

#include "o3d/camera/pinhole_camera.h"

namespace o3d::camera {

PinholeCameraIntrinsic read_pinhole_camera_intrinsic(const std::string& path);
void write_pinhole_camera_intrinsic(const std::string& path, const PinholeCameraIntrinsic& intrinsic);
PinholeCameraParameters read_pinhole_camera_parameters(const std::string& path);
void write_pinhole_camera_parameters(const std::string& path, const PinholeCameraParameters& parameters);
PinholeCameraTrajectory read_pinhole_camera_trajectory(const std::string& path, const std::string& format = "auto");
void write_pinhole_camera_trajectory(const std::string& path, const PinholeCameraTrajectory& trajectory,
                                     const std::string& format = "auto");

}  // namespace o3d::camera
