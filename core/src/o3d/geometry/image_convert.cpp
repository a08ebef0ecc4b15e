// SPDX-License-Identifier: MIT
// Intensity and depth conversion to 1-channel float32 (Open3D's CreateFloatImage and
// ConvertDepthToFloatImage). The arithmetic is done in float in Open3D's order so that results match it.
#include <cmath>
#include <string>

#include "o3d/geometry/image_ops.h"
#include "o3d/utility/error.h"

namespace o3d::geometry {

namespace {

template <typename T>
float to_float(const uint8_t* p) {
    T v;
    std::memcpy(&v, p, sizeof(T));
    return static_cast<float>(v);
}

/// 8-bit values are scaled to [0, 1]; 16-bit and float values are kept.
template <typename T>
constexpr float channel_scale() {
    return sizeof(T) == 1 ? 255.0f : 1.0f;
}

template <typename T>
void convert_pixels(const Image& in, Image& out, ImageConvertType type) {
    const size_t n = size_t(in.width) * size_t(in.height);
    const size_t stride = size_t(in.num_channels) * sizeof(T);
    const uint8_t* src = in.data.data();
    float* dst = reinterpret_cast<float*>(out.data.data());
    constexpr bool scaled = sizeof(T) == 1;
    if (in.num_channels == 1) {
        for (size_t i = 0; i < n; ++i, src += stride) {
            const float v = to_float<T>(src);
            dst[i] = scaled ? v / channel_scale<T>() : v;
        }
        return;
    }
    // 3 or 4 channels: the gray value comes from R, G, B (alpha is ignored).
    for (size_t i = 0; i < n; ++i, src += stride) {
        const float r = to_float<T>(src), g = to_float<T>(src + sizeof(T)), b = to_float<T>(src + 2 * sizeof(T));
        float v = type == ImageConvertType::Equal ? (r + g + b) / 3.0f : 0.2990f * r + 0.5870f * g + 0.1140f * b;
        dst[i] = scaled ? v / channel_scale<T>() : v;
    }
}

}  // namespace

Image create_float_image(const Image& image, ImageConvertType type) {
    require_valid_image(image, "create_float_image");
    if (type != ImageConvertType::Equal && type != ImageConvertType::Weighted)
        throw InvalidArgument("create_float_image: unknown conversion type");
    Image out = make_image(image.width, image.height, 1, 4);
    switch (image.bytes_per_channel) {
        case 1: convert_pixels<uint8_t>(image, out, type); break;
        case 2: convert_pixels<uint16_t>(image, out, type); break;
        default: convert_pixels<float>(image, out, type); break;
    }
    return out;
}

Image convert_depth_to_float(const Image& image, double depth_scale, double depth_trunc) {
    require_valid_image(image, "convert_depth_to_float");
    if (image.num_channels != 1 || (image.bytes_per_channel != 2 && image.bytes_per_channel != 4))
        throw InvalidArgument("convert_depth_to_float needs a 1-channel uint16 or float32 depth image, not " +
                              std::to_string(image.num_channels) + " channel(s) of " +
                              std::to_string(image.bytes_per_channel) + " byte(s)");
    if (!(depth_scale > 0.0) || !std::isfinite(depth_scale))
        throw InvalidArgument("depth_scale " + std::to_string(depth_scale) + " is not a finite number > 0");
    if (std::isnan(depth_trunc)) throw InvalidArgument("depth_trunc is NaN");
    Image out = create_float_image(image, ImageConvertType::Weighted);
    const float scale = static_cast<float>(depth_scale);
    float* d = reinterpret_cast<float*>(out.data.data());
    const size_t n = size_t(out.width) * size_t(out.height);
    for (size_t i = 0; i < n; ++i) {
        const float z = d[i] / scale;
        // Open3D zeroes depths at or beyond the truncation; non-finite depths are invalid too.
        d[i] = (std::isfinite(z) && double(z) < depth_trunc) ? z : 0.0f;
    }
    return out;
}

}  // namespace o3d::geometry
