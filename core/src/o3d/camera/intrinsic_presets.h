// SPDX-License-Identifier: MIT
#pragma once
/// @file intrinsic_presets.h
/// @brief Open3D's PinholeCameraIntrinsicParameters presets.
#include "o3d/camera/pinhole_camera.h"

namespace o3d::camera {

/// Values match the O3D_INTRINSIC_* constants of the C API.
enum class IntrinsicPreset { PrimeSenseDefault = 0, Kinect2DepthCameraDefault = 1, Kinect2ColorCameraDefault = 2 };

/// @brief The preset's intrinsic; an unknown value throws o3d::InvalidArgument.
PinholeCameraIntrinsic intrinsic_preset(IntrinsicPreset preset);

}  // namespace o3d::camera
