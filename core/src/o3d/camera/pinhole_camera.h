// SPDX-License-Identifier: MIT
#pragma once
/// @file pinhole_camera.h
/// @brief Pinhole intrinsics, camera parameters (intrinsic + world-to-camera extrinsic) and trajectories.
#include <Eigen/Core>
#include <vector>

namespace o3d::camera {

struct PinholeCameraIntrinsic {
    int width = -1;
    int height = -1;
    double fx = 0, fy = 0, cx = 0, cy = 0;
};

struct PinholeCameraParameters {
    PinholeCameraIntrinsic intrinsic;
    Eigen::Matrix4d extrinsic = Eigen::Matrix4d::Identity();
};

struct PinholeCameraTrajectory {
    std::vector<PinholeCameraParameters> parameters;
};

}  // namespace o3d::camera
