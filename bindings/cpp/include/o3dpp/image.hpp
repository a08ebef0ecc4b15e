// SPDX-License-Identifier: MIT
#pragma once
/// @file image.hpp
/// @brief o3dpp::Image (move-only owner of an o3d_image_t): 1, 3 or 4 channels of uint8, uint16 or
/// float32, rows top to bottom, channels interleaved.
#include <cstdint>
#include <cstring>
#include <vector>

#include "o3d/image.h"
#include "o3dpp/arrays.hpp"
#include "o3dpp/common.hpp"
#include "o3dpp/error.hpp"
#include "o3dpp/generated/enums.hpp"
#include "o3dpp/generated/image.hpp"
#include "o3dpp/handle.hpp"
#include "o3dpp/span.hpp"

namespace o3dpp {

namespace detail {
using ImageArrayFns = ArrayFns<&o3d_image_has_array, &o3d_image_array_shape, &o3d_image_get_array,
                               &o3d_image_array_view, &o3d_image_array_mutable_view, &o3d_image_set_array, nullptr>;
}  // namespace detail

/// @brief An image (o3d.geometry.Image). The methods that pass their arguments to one C function are generated
/// (detail::ImageCalls).
class Image : public Owner<Image, o3d_image_t, &o3d_image_destroy>,
              public Arrays<Image, ImageArray, detail::ImageArrayFns>,
              public detail::ImageCalls<Image> {
public:
    /// @brief Zero-filled image; bytes_per_channel 1 (uint8), 2 (uint16) or 4 (float32).
    Image(int width, int height, int num_channels, int bytes_per_channel)
        : Owner(make([&](o3d_image_t** o) {
              return o3d_image_create(o, width, height, num_channels, bytes_per_channel);
          })) {}
    /// @brief Take ownership of `owned` (must not be NULL).
    explicit Image(o3d_image_t* owned) : Owner(owned) {}
    /// @brief Copy of `size` bytes of pixel data (exactly width * height * channels * bytes_per_channel).
    static Image from_data(int width, int height, int num_channels, int bytes_per_channel, const void* data,
                           std::size_t size) {
        return create(&o3d_image_create_from_data, width, height, num_channels, bytes_per_channel,
                      static_cast<const uint8_t*>(data), size);
    }
    /// @brief 1-channel image from width * height values of uint8_t, uint16_t or float.
    template <typename T>
    static Image from_values(int width, int height, const std::vector<T>& values, int num_channels = 1) {
        static_assert(sizeof(T) == 1 || sizeof(T) == 2 || sizeof(T) == 4, "uint8_t, uint16_t or float");
        return from_data(width, height, num_channels, static_cast<int>(sizeof(T)), values.data(),
                         values.size() * sizeof(T));
    }

    /// @brief Deep copy.
    Image clone() const { return derive(&o3d_image_clone); }

    /// @brief Borrowed pixel bytes: valid until the next mutating call or destruction.
    Span<const uint8_t> data() const { return array<uint8_t>(ImageArray::Data).flat(); }
    Span<uint8_t> data_mutable() { return array_mutable<uint8_t>(ImageArray::Data).flat(); }
    /// @brief Copy of the pixel bytes.
    std::vector<uint8_t> to_bytes() const { return get_array<uint8_t>(ImageArray::Data); }
    /// @brief Copy of the values as T (sizeof(T) must equal bytes_per_channel).
    template <typename T>
    std::vector<T> to_values() const {
        if (static_cast<int>(sizeof(T)) != bytes_per_channel())
            throw Error(O3D_ERROR_INVALID_ARGUMENT, "o3dpp::Image::to_values: element size differs from the image's");
        auto bytes = data();
        std::vector<T> out(bytes.size() / sizeof(T));
        if (!out.empty()) std::memcpy(out.data(), bytes.data(), out.size() * sizeof(T));
        return out;
    }

    /// @brief Open3D's create_pyramid: level 0 is a copy, each next level the previous one (Gaussian3
    /// filtered when asked) downsampled by 2. 1-channel float32 input.
    std::vector<Image> create_pyramid(int num_of_levels, bool with_gaussian_filter = true) const {
        if (num_of_levels < 0 || num_channels() != 1 || bytes_per_channel() != 4)
            throw Error(O3D_ERROR_INVALID_ARGUMENT,
                        "o3dpp::Image::create_pyramid: needs num_of_levels >= 0 and a 1-channel float32 image");
        std::vector<Image> levels;
        if (num_of_levels > 0) levels.push_back(clone());
        for (int i = 1; i < num_of_levels; ++i) {
            const Image& prev = levels.back();
            levels.push_back(with_gaussian_filter ? prev.filter(ImageFilter::Gaussian3).downsample() : prev.downsample());
        }
        return levels;
    }
};

}  // namespace o3dpp
