// SPDX-License-Identifier: MIT
// Constants are those of the Open3D paper's dataset readers (Open3D 0.20): Redwood and SUN store millimetres,
// TUM 1/5000 m; SUN rotates the 16 depth bits, NYU stores big-endian Kinect disparity, which becomes
// depth = 351.3 / (1092.5 - disparity) metres, rounded to whole millimetres as Open3D does.
#include "o3d/geometry/rgbd_dataset_formats.h"

#include <cmath>
#include <cstring>
#include <string>

#include "o3d/geometry/image_ops.h"
#include "o3d/geometry/rgbd_image_ops.h"
#include "o3d/utility/error.h"

namespace o3d::geometry {
namespace {

void require_raw_depth(const Image& depth) {
    require_valid_image(depth, "depth");
    if (depth.num_channels != 1 || depth.bytes_per_channel != 2)
        throw InvalidArgument("depth: the dataset readers need a 1-channel uint16 depth image, not " +
                              std::to_string(depth.num_channels) + " channel(s) of " +
                              std::to_string(depth.bytes_per_channel) + " byte(s)");
}

uint16_t sun_to_millimetres(uint16_t raw) { return static_cast<uint16_t>((raw >> 3) | (raw << 13)); }

/// Disparities at or beyond 1092.5 have no depth in front of the camera: 0 marks them invalid, and so do
/// depths too far for 16-bit millimetres (they are beyond the 7 m truncation anyway).
uint16_t nyu_to_millimetres(uint16_t raw) {
    const unsigned disparity = ((raw & 0xffu) << 8) | (raw >> 8);
    const double metres = 351.3 / (1092.5 - double(disparity));
    if (!(metres > 0.0)) return 0;
    const double mm = std::floor(metres * 1000.0 + 0.5);
    return mm > 65535.0 ? 0 : static_cast<uint16_t>(mm);
}

/// A copy of `depth` with every sample mapped through `f`: the caller's image stays untouched.
template <typename F>
Image map_depth(const Image& depth, F f) {
    Image out = depth;
    const size_t n = size_t(depth.width) * size_t(depth.height);
    uint8_t* bytes = out.data.data();
    for (size_t i = 0; i < n; ++i) {
        uint16_t v;
        std::memcpy(&v, bytes + 2 * i, 2);
        v = f(v);
        std::memcpy(bytes + 2 * i, &v, 2);
    }
    return out;
}

}  // namespace

RGBDImage create_rgbd_from_dataset_format(RGBDDatasetFormat format, const Image& color, const Image& depth,
                                          bool convert_rgb_to_intensity) {
    require_raw_depth(depth);
    RGBDOptions options;
    options.convert_rgb_to_intensity = convert_rgb_to_intensity;
    switch (format) {
        case RGBDDatasetFormat::Redwood:
            options.depth_scale = 1000.0;
            options.depth_trunc = 4.0;
            return create_rgbd_from_color_and_depth(color, depth, options);
        case RGBDDatasetFormat::TUM:
            options.depth_scale = 5000.0;
            options.depth_trunc = 4.0;
            return create_rgbd_from_color_and_depth(color, depth, options);
        case RGBDDatasetFormat::SUN:
            options.depth_scale = 1000.0;
            options.depth_trunc = 7.0;
            require_rgbd_color(color, "color");  // fail before the copy
            return create_rgbd_from_color_and_depth(color, map_depth(depth, sun_to_millimetres), options);
        case RGBDDatasetFormat::NYU:
            options.depth_scale = 1000.0;
            options.depth_trunc = 7.0;
            require_rgbd_color(color, "color");
            return create_rgbd_from_color_and_depth(color, map_depth(depth, nyu_to_millimetres), options);
    }
    throw InvalidArgument("unknown RGB-D dataset format " + std::to_string(static_cast<int>(format)));
}

}  // namespace o3d::geometry
