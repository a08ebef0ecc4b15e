// SPDX-License-Identifier: MIT
#include "o3d/geometry/rgbd_image_ops.h"

#include <string>

#include "o3d/geometry/image_ops.h"
#include "o3d/utility/error.h"

namespace o3d::geometry {

void require_rgbd_color(const Image& color, const char* what) {
    require_valid_image(color, what);
    const bool u8 = color.bytes_per_channel == 1 && (color.num_channels == 1 || color.num_channels == 3);
    const bool intensity = color.bytes_per_channel == 4 && color.num_channels == 1;
    if (!u8 && !intensity)
        throw InvalidArgument(std::string(what) + ": expected an 8-bit 1- or 3-channel image or a 1-channel float32 "
                              "intensity, not " + std::to_string(color.num_channels) + " channel(s) of " +
                              std::to_string(color.bytes_per_channel) + " byte(s)");
}

RGBDImage create_rgbd_from_color_and_depth(const Image& color, const Image& depth, const RGBDOptions& options) {
    require_rgbd_color(color, "color");
    require_valid_image(depth, "depth");
    if (color.width != depth.width || color.height != depth.height)
        throw InvalidArgument("color is " + std::to_string(color.width) + "x" + std::to_string(color.height) +
                              " but depth is " + std::to_string(depth.width) + "x" + std::to_string(depth.height));
    RGBDImage out;
    out.depth = convert_depth_to_float(depth, options.depth_scale, options.depth_trunc);
    out.color = options.convert_rgb_to_intensity ? create_float_image(color, ImageConvertType::Weighted) : color;
    return out;
}

}  // namespace o3d::geometry
