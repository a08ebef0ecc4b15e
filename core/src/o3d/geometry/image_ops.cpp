// SPDX-License-Identifier: MIT
// Image construction, format checks and the flips (the format-agnostic operations).
#include "o3d/geometry/image_ops.h"

#include <string>

#include "o3d/utility/error.h"

namespace o3d::geometry {

Image make_image(int width, int height, int num_channels, int bytes_per_channel) {
    if (width < 1 || height < 1)
        throw InvalidArgument("image size " + std::to_string(width) + " x " + std::to_string(height) +
                              " is not at least 1 x 1");
    if (num_channels != 1 && num_channels != 3 && num_channels != 4)
        throw InvalidArgument("num_channels " + std::to_string(num_channels) + " is not 1, 3 or 4");
    if (bytes_per_channel != 1 && bytes_per_channel != 2 && bytes_per_channel != 4)
        throw InvalidArgument("bytes_per_channel " + std::to_string(bytes_per_channel) +
                              " is not 1 (uint8), 2 (uint16) or 4 (float32)");
    // Both factors are < 2^31 and the pixel size <= 16, so the product cannot overflow 64 bits.
    const uint64_t bytes = uint64_t(width) * uint64_t(height) * uint64_t(num_channels * bytes_per_channel);
    if (bytes > kMaxImageBytes)
        throw InvalidArgument("image of " + std::to_string(width) + " x " + std::to_string(height) + " x " +
                              std::to_string(num_channels) + " x " + std::to_string(bytes_per_channel) +
                              " bytes exceeds the 4 GiB limit");
    Image image;
    image.width = width;
    image.height = height;
    image.num_channels = num_channels;
    image.bytes_per_channel = bytes_per_channel;
    image.data.assign(size_t(bytes), 0);
    return image;
}

void require_valid_image(const Image& image, const char* what) {
    if (image.empty()) throw InvalidArgument(std::string(what) + ": the image is empty");
    if ((image.num_channels != 1 && image.num_channels != 3 && image.num_channels != 4) ||
        (image.bytes_per_channel != 1 && image.bytes_per_channel != 2 && image.bytes_per_channel != 4))
        throw InvalidArgument(std::string(what) + ": unsupported image format (" +
                              std::to_string(image.num_channels) + " channel(s) of " +
                              std::to_string(image.bytes_per_channel) + " byte(s))");
    if (image.data.size() != image.byte_size())
        throw InvalidArgument(std::string(what) + ": the image holds " + std::to_string(image.data.size()) +
                              " bytes but its size needs " + std::to_string(image.byte_size()));
}

void require_float_gray(const Image& image, const char* what) {
    require_valid_image(image, what);
    if (image.num_channels != 1 || image.bytes_per_channel != 4)
        throw InvalidArgument(std::string(what) + " needs a 1-channel float32 image, not " +
                              std::to_string(image.num_channels) + " channel(s) of " +
                              std::to_string(image.bytes_per_channel) +
                              " byte(s); convert with create_float_image first");
}

Image flip_vertical(const Image& image) {
    require_valid_image(image, "flip_vertical");
    Image out = make_image(image.width, image.height, image.num_channels, image.bytes_per_channel);
    const size_t line = image.bytes_per_line();
    for (int v = 0; v < image.height; ++v)
        std::memcpy(out.data.data() + size_t(image.height - 1 - v) * line, image.data.data() + size_t(v) * line,
                    line);
    return out;
}

Image flip_horizontal(const Image& image) {
    require_valid_image(image, "flip_horizontal");
    Image out = make_image(image.width, image.height, image.num_channels, image.bytes_per_channel);
    const size_t pixel = size_t(image.num_channels) * size_t(image.bytes_per_channel);
    const size_t line = image.bytes_per_line();
    for (int v = 0; v < image.height; ++v) {
        const uint8_t* src = image.data.data() + size_t(v) * line;
        uint8_t* dst = out.data.data() + size_t(v) * line + line - pixel;
        for (int u = 0; u < image.width; ++u, src += pixel, dst -= pixel) std::memcpy(dst, src, pixel);
    }
    return out;
}

}  // namespace o3d::geometry
