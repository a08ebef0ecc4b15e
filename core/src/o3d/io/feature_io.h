// SPDX-License-Identifier: MIT
#pragma once
/// @file feature_io.h
/// @brief Open3D's binary feature files (o3d.io.read_feature / write_feature): int32 dimension,
/// int32 count, then count x dimension float64, descriptor by descriptor, all little-endian.
/// Errors: o3d::IoError (cannot open/read/write), o3d::ParseError (truncated, oversized or
/// inconsistent data, a negative size or a non-finite value; the message names the file or "<memory>").
#include <cstdint>
#include <string>
#include <vector>

#include "o3d/registration/feature.h"

namespace o3d::io {

registration::Feature read_feature(const std::string& path);
registration::Feature read_feature_from_memory(const uint8_t* data, size_t size);
/// @throws o3d::InvalidArgument when a size does not fit an int32 (the file's header fields) or a value
/// is not finite (which the reader would reject).
void write_feature(const std::string& path, const registration::Feature& feature);
std::vector<uint8_t> write_feature_to_memory(const registration::Feature& feature);

}  // namespace o3d::io
