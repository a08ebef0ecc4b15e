// SPDX-License-Identifier: MIT
#pragma once
/// @file image_io.h
/// @brief Image files: PNG and JPEG (libpng, libjpeg), binary PPM (P6) and PGM (P5), 8 or 16 bit.
/// Format names: "png", "jpg", "jpeg", "ppm", "pgm"; "" or "auto" = from the extension. Failures throw
/// o3d::IoError (cannot open/write), o3d::ParseError (malformed), o3d::Unsupported (format).
#include <cstdint>
#include <string>
#include <vector>

#include "o3d/geometry/image.h"

namespace o3d::io {

geometry::Image read_image(const std::string& path, const std::string& format = "");
geometry::Image read_image_from_memory(const uint8_t* data, size_t size, const std::string& format);
/// @brief quality: JPEG 1..100, -1 = 90.
void write_image(const std::string& path, const geometry::Image& image, const std::string& format = "",
                 int quality = -1);
std::vector<uint8_t> write_image_to_memory(const geometry::Image& image, const std::string& format,
                                           int quality = -1);

}  // namespace o3d::io
