// SPDX-License-Identifier: MIT
#include "o3d/integration/tsdf_volume.h"

#include <algorithm>
#include <cmath>
#include <string>

#include "o3d/integration/frame_integration.h"
#include "o3d/utility/error.h"
#include "o3d/utility/parallel.h"

namespace o3d::integration {
namespace {

bool same_intrinsic(const camera::PinholeCameraIntrinsic& a, const camera::PinholeCameraIntrinsic& b) {
    return a.width == b.width && a.height == b.height && a.fx == b.fx && a.fy == b.fy && a.cx == b.cx &&
           a.cy == b.cy;
}

std::string format_of(const geometry::Image& image) {
    return std::to_string(image.num_channels) + " channel(s) of " + std::to_string(image.bytes_per_channel) +
           " byte(s), " + std::to_string(image.width) + " x " + std::to_string(image.height);
}

}  // namespace

TSDFVolume::TSDFVolume(double voxel_length, double sdf_trunc, ColorType color_type, int block_side,
                       const Eigen::Vector3d& origin)
    : voxel_length_(voxel_length),
      sdf_trunc_(sdf_trunc),
      color_type_(color_type),
      blocks_(block_side, voxel_length, origin, color_type != ColorType::None) {
    if (!(voxel_length > 0) || !std::isfinite(voxel_length))
        throw InvalidArgument("TSDF volume: voxel_length must be a finite number > 0");
    if (!(sdf_trunc > 0) || !std::isfinite(sdf_trunc))
        throw InvalidArgument("TSDF volume: sdf_trunc must be a finite number > 0");
    if (color_type != ColorType::None && color_type != ColorType::RGB8 && color_type != ColorType::Gray32)
        throw InvalidArgument("TSDF volume: unknown color_type");
    if (!origin.allFinite()) throw InvalidArgument("TSDF volume: origin must be finite");
}

void TSDFVolume::check_frame(const geometry::RGBDImage& image, const camera::PinholeCameraIntrinsic& intrinsic,
                             const Eigen::Matrix4d& extrinsic) const {
    if (intrinsic.width <= 0 || intrinsic.height <= 0 || !(intrinsic.fx > 0) || !(intrinsic.fy > 0) ||
        !std::isfinite(intrinsic.fx) || !std::isfinite(intrinsic.fy) || !std::isfinite(intrinsic.cx) ||
        !std::isfinite(intrinsic.cy))
        throw InvalidArgument("integrate: the intrinsic needs a size and finite fx, fy > 0");
    if (!extrinsic.allFinite()) throw InvalidArgument("integrate: the extrinsic has a NaN or infinite entry");
    const geometry::Image& depth = image.depth;
    if (depth.empty() || depth.num_channels != 1 || depth.bytes_per_channel != 4)
        throw InvalidArgument("integrate: depth must be a 1-channel float image in metres, got " + format_of(depth) +
                              " (make the RGBDImage with create_from_color_and_depth)");
    if (depth.width != intrinsic.width || depth.height != intrinsic.height)
        throw InvalidArgument("integrate: depth is " + format_of(depth) + " but the intrinsic is " +
                              std::to_string(intrinsic.width) + " x " + std::to_string(intrinsic.height));
    if (color_type_ == ColorType::None) return;
    const geometry::Image& color = image.color;
    const bool rgb8 = color_type_ == ColorType::RGB8;
    if (color.empty() || color.num_channels != (rgb8 ? 3 : 1) || color.bytes_per_channel != (rgb8 ? 1 : 4))
        throw InvalidArgument(std::string("integrate: a ") + (rgb8 ? "RGB8" : "Gray32") + " volume needs " +
                              (rgb8 ? "3-channel uint8 color (convert_rgb_to_intensity=False)"
                                    : "1-channel float intensity (convert_rgb_to_intensity=True)") +
                              ", got " + format_of(color));
    if (color.width != depth.width || color.height != depth.height)
        throw InvalidArgument("integrate: color is " + format_of(color) + " but depth is " + format_of(depth));
}

void TSDFVolume::integrate_into(const geometry::RGBDImage& image, const camera::PinholeCameraIntrinsic& intrinsic,
                                const Eigen::Matrix4d& extrinsic, const std::vector<Eigen::Vector3i>& keys) {
    if (!same_intrinsic(intrinsic, ray_intrinsic_) || ray_x2_.empty()) {
        ray_x2_.resize(size_t(intrinsic.width));
        ray_y2_.resize(size_t(intrinsic.height));
        for (int u = 0; u < intrinsic.width; ++u) ray_x2_[size_t(u)] = float(std::pow((u - intrinsic.cx) / intrinsic.fx, 2));
        for (int v = 0; v < intrinsic.height; ++v) ray_y2_[size_t(v)] = float(std::pow((v - intrinsic.cy) / intrinsic.fy, 2));
        ray_intrinsic_ = intrinsic;
    }
    detail::FrameView frame;
    frame.width = intrinsic.width;
    frame.height = intrinsic.height;
    frame.fx = float(intrinsic.fx);
    frame.fy = float(intrinsic.fy);
    frame.cx = float(intrinsic.cx);
    frame.cy = float(intrinsic.cy);
    const float* depth = reinterpret_cast<const float*>(image.depth.data.data());
    const uint8_t* rgb = color_type_ == ColorType::RGB8 ? image.color.data.data() : nullptr;
    std::vector<detail::FramePixel> pixels;
    const float* intensity = color_type_ == ColorType::Gray32
                                 ? reinterpret_cast<const float*>(image.color.data.data())
                                 : nullptr;
    detail::interleave_pixels(depth, rgb, intensity, size_t(intrinsic.width) * size_t(intrinsic.height), pixels);
    frame.pixels = pixels.data();
    frame.color = rgb ? detail::FrameColor::RGB8 : intensity ? detail::FrameColor::Gray32 : detail::FrameColor::None;
    depth_tiles_.build(depth, intrinsic.width, intrinsic.height);
    frame.tiles = &depth_tiles_;
    frame.ray_x2 = ray_x2_.data();
    frame.ray_y2 = ray_y2_.data();
    frame.rotation = extrinsic.topLeftCorner<3, 3>().cast<float>();
    frame.translation = extrinsic.topRightCorner<3, 1>().cast<float>();
    frame.sdf_trunc = float(sdf_trunc_);

    std::vector<detail::VoxelBlock*> targets;
    targets.reserve(keys.size());
    for (const Eigen::Vector3i& key : keys) targets.push_back(&blocks_.find_or_create(key));
    const int threads = utility::resolve_num_threads();
    const int side = blocks_.side();
    if (targets.size() == 1) {  // the uniform volume: share its one block out by x slabs a culling box thick
        const int slabs = (side + detail::kCullBox - 1) / detail::kCullBox;
#pragma omp parallel for schedule(dynamic, 1) num_threads(threads)
        for (int slab = 0; slab < slabs; ++slab)
            detail::integrate_block(*targets[0], blocks_, frame, slab * detail::kCullBox,
                                    std::min(side, (slab + 1) * detail::kCullBox));
        return;
    }
    detail::order_by_footprint(targets, blocks_, frame);
    // Blocks are independent; dynamic scheduling because blocks outside the view cost little.
#pragma omp parallel for schedule(dynamic, 8) num_threads(threads)
    for (long i = 0; i < long(targets.size()); ++i)
        detail::integrate_block(*targets[size_t(i)], blocks_, frame, 0, side);
}

}  // namespace o3d::integration
