// SPDX-License-Identifier: MIT
#pragma once
/// @file image_io_internal.h
/// @brief The per-format image codecs the image_io dispatcher calls, and the limits they share.
#include <cstdint>
#include <vector>

#include "o3d/geometry/image.h"
#include "o3d/io/io_internal.h"

namespace o3d::io::detail {

/// Largest width or height a decoder accepts (JPEG's own limit is 65500); larger headers are corrupt.
constexpr uint32_t kMaxImageDimension = 65535;

geometry::Image read_png(const Input& in);
geometry::Image read_jpeg(const Input& in);
/// @brief Binary PGM (P5) or PPM (P6), 8-bit (maxval < 256) or 16-bit big-endian.
geometry::Image read_pnm(const Input& in);

std::vector<uint8_t> write_png(const geometry::Image& image);
/// @brief quality 1..100.
std::vector<uint8_t> write_jpeg(const geometry::Image& image, int quality);
/// @brief P5 for 1 channel, P6 for 3; maxval 255 (8-bit) or 65535 (16-bit, big-endian).
std::vector<uint8_t> write_pnm(const geometry::Image& image);

}  // namespace o3d::io::detail
