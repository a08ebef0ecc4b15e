// SPDX-License-Identifier: MIT
#pragma once
/// @file frame_integration.h
/// @brief Fusing one checked depth frame into one voxel block (Open3D's projective update: each voxel
/// centre is projected to its nearest pixel; sdf = (depth - z) scaled from depth to distance along the ray).
#include <Eigen/Core>
#include <cstdint>
#include <vector>

#include "o3d/integration/depth_tiles.h"
#include "o3d/integration/voxel_block.h"

namespace o3d::integration::detail {

/// @brief What a voxel averages in besides the distance.
enum class FrameColor { None, RGB8, Gray32 };

/// @brief A pixel's depth and colour side by side in 8 bytes: the update reads both, one load serves both, and
/// the frame (2.4 MB at 640 x 480) stays mostly in cache.
struct FramePixel {
    float depth;     ///< metres; holes are 0, negative, NaN or infinite
    uint32_t color;  ///< RGB8: r | g << 8 | b << 16; Gray32: the intensity's float bits; None: 0
};

/// @brief Interleaves a frame's depth with its RGB8 colour or Gray32 intensity (at most one non-null), in parallel.
void interleave_pixels(const float* depth, const uint8_t* rgb, const float* intensity, size_t count,
                       std::vector<FramePixel>& out);

/// @brief Reorders blocks so that those whose centres project near each other on the image come together:
/// consecutive blocks then read the same pixels, which stay in cache (key order scatters them over the image).
void order_by_footprint(std::vector<VoxelBlock*>& blocks, const BlockMap& map, const struct FrameView& frame);

/// @brief A frame reduced to what the voxel update reads; pointers borrow the caller's buffers.
struct FrameView {
    int width = 0, height = 0;
    float fx = 0, fy = 0, cx = 0, cy = 0;
    const FramePixel* pixels = nullptr;          ///< width x height
    const DepthTiles* tiles = nullptr;           ///< the depth summarised, to skip boxes of voxels no pixel updates
    /// The squares of each column's and each row's normalised ray coordinate ((u - cx) / fx)^2, ((v - cy) / fy)^2:
    /// a pixel's depth-to-distance factor is sqrt(1 + both). Two short arrays stay in cache where a per-pixel
    /// factor image would cost a second cache miss per voxel.
    const float* ray_x2 = nullptr;
    const float* ray_y2 = nullptr;
    FrameColor color = FrameColor::None;         ///< what `pixels` carry besides depth
    Eigen::Matrix3f rotation;                    ///< world to camera
    Eigen::Vector3f translation;
    float sdf_trunc = 0;
};

/// @brief Voxels per side of the boxes that are tested against the frame as a whole and skipped when no voxel of
/// theirs can change (outside the image, over holes, or more than sdf_trunc behind the surface). Most voxels of
/// a block around the surface lie behind it: on the living-room sequence 4^3 boxes skip a third of them.
constexpr int kCullBox = 4;

/// @brief Updates every voxel of `block` (of `map`'s geometry) that projects onto a valid depth and lies in
/// front of the surface or less than sdf_trunc behind it: running average of tsdf and colour, weight + 1.
/// Only the slabs x in [x_begin, x_end) are touched, so one large block can be shared among threads; slabs that
/// start at multiples of kCullBox keep the boxes whole.
void integrate_block(VoxelBlock& block, const BlockMap& map, const FrameView& frame, int x_begin, int x_end);

}  // namespace o3d::integration::detail
