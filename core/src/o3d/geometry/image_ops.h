// SPDX-License-Identifier: MIT
#pragma once
/// @file image_ops.h
/// @brief Image construction, format checks and the Open3D image operations (filter, pyramid step, flips,
/// float and depth conversion). Every function leaves its input unchanged and throws
/// o3d::InvalidArgument on an unsupported format.
#include <cstdint>

#include "o3d/geometry/image.h"

namespace o3d::geometry {

enum class ImageFilterType { Gaussian3, Gaussian5, Gaussian7, Sobel3Dx, Sobel3Dy };
enum class ImageConvertType { Equal, Weighted };

/// @brief Largest pixel buffer an image may have (4 GiB): far above any camera image, and small enough that a
/// corrupt or mistaken size fails with a clear error instead of exhausting memory.
inline constexpr uint64_t kMaxImageBytes = uint64_t(1) << 32;

/// @brief Zero-filled image; validates the size (>= 1, at most kMaxImageBytes), channels (1/3/4) and bytes (1/2/4).
Image make_image(int width, int height, int num_channels, int bytes_per_channel);
/// @brief Throw InvalidArgument unless the image is a 1-channel float32 image (`what` names it).
void require_float_gray(const Image& image, const char* what);
/// @brief Throw InvalidArgument unless the image is non-empty with a supported format and data of byte_size().
void require_valid_image(const Image& image, const char* what);

Image filter_image(const Image& image, ImageFilterType type);
Image downsample_image(const Image& image);
Image flip_vertical(const Image& image);
Image flip_horizontal(const Image& image);
Image create_float_image(const Image& image, ImageConvertType type);
Image convert_depth_to_float(const Image& image, double depth_scale, double depth_trunc);

}  // namespace o3d::geometry
