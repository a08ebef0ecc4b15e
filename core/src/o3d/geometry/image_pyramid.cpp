// SPDX-License-Identifier: MIT
// One image-pyramid step (Open3D's Image::Downsample): each output pixel is the mean of a 2x2 block,
// summed in float in Open3D's order; odd sizes drop the last row/column (floor(size / 2)).
#include <string>

#include "o3d/geometry/image_ops.h"
#include "o3d/utility/error.h"

namespace o3d::geometry {

Image downsample_image(const Image& image) {
    require_float_gray(image, "downsample_image");
    if (image.width < 2 || image.height < 2)
        throw InvalidArgument("downsample_image: a " + std::to_string(image.width) + " x " +
                              std::to_string(image.height) + " image has no 2 x 2 block (both sides must be >= 2)");
    Image out = make_image(image.width / 2, image.height / 2, 1, 4);
    const float* in = reinterpret_cast<const float*>(image.data.data());
    float* o = reinterpret_cast<float*>(out.data.data());
    const size_t w = size_t(image.width);
    for (int y = 0; y < out.height; ++y) {
        const float* top = in + size_t(2 * y) * w;
        const float* bottom = top + w;
        float* row = o + size_t(y) * size_t(out.width);
        for (int x = 0; x < out.width; ++x) {
            const size_t u = size_t(2 * x);
            row[x] = (top[u] + top[u + 1] + bottom[u] + bottom[u + 1]) / 4.0f;
        }
    }
    return out;
}

}  // namespace o3d::geometry
