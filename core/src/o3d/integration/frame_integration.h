// SPDX-License-Identifier: MIT
#pragma once
/// @file frame_integration.h
/// @brief Fusing one checked depth frame into one voxel block (Open3D's projective update: each voxel
/// centre is projected to its nearest pixel; sdf = (depth - z) scaled from depth to distance along the ray).
#include <Eigen/Core>
#include <cstdint>

#include "o3d/integration/voxel_block.h"

namespace o3d::integration::detail {

/// @brief A frame reduced to what the voxel update reads; pointers borrow the caller's images.
struct FrameView {
    int width = 0, height = 0;
    float fx = 0, fy = 0, cx = 0, cy = 0;
    const float* depth = nullptr;                ///< metres, width x height
    /// The squares of each column's and each row's normalised ray coordinate ((u - cx) / fx)^2, ((v - cy) / fy)^2:
    /// a pixel's depth-to-distance factor is sqrt(1 + both). Two short arrays stay in cache where a per-pixel
    /// factor image would cost a second cache miss per voxel.
    const float* ray_x2 = nullptr;
    const float* ray_y2 = nullptr;
    const uint8_t* rgb = nullptr;                ///< RGB8 colour, or null
    const float* intensity = nullptr;            ///< Gray32 intensity, or null
    Eigen::Matrix3f rotation;                    ///< world to camera
    Eigen::Vector3f translation;
    float sdf_trunc = 0;
};

/// @brief Updates every voxel of `block` (of `map`'s geometry) that projects onto a valid depth and lies in
/// front of the surface or less than sdf_trunc behind it: running average of tsdf and colour, weight + 1.
/// Only the slabs x in [x_begin, x_end) are touched, so one large block can be shared among threads.
void integrate_block(VoxelBlock& block, const BlockMap& map, const FrameView& frame, int x_begin, int x_end);

}  // namespace o3d::integration::detail
