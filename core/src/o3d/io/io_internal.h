// SPDX-License-Identifier: MIT
#pragma once
/// @file io_internal.h
/// @brief What the format readers and writers share: the input they parse, the error they raise,
/// the per-format entry points the dispatcher calls, and colour quantisation.
#include <cmath>
#include <cstdint>
#include <string>
#include <vector>

#include "o3d/geometry/point_cloud.h"
#include "o3d/io/point_cloud_io.h"

namespace o3d::io::detail {

/// @brief One whole input file in memory and the name errors cite (its path, or "<memory>").
struct Input {
    const uint8_t* data;
    size_t size;
    const std::string& name;

    const char* chars() const { return reinterpret_cast<const char*>(data); }
    const char* chars_end() const { return reinterpret_cast<const char*>(data) + size; }
};

/// @brief Throw o3d::ParseError("<name>: <reason>").
[[noreturn]] void parse_error(const Input& in, const std::string& reason);

geometry::PointCloud read_ply(const Input& in);
geometry::PointCloud read_pcd(const Input& in);
geometry::PointCloud read_xyz(const Input& in);
geometry::PointCloud read_xyzn(const Input& in);
geometry::PointCloud read_xyzrgb(const Input& in);
geometry::PointCloud read_pts(const Input& in);

std::vector<uint8_t> write_ply(const geometry::PointCloud& cloud, const WriteOptions& options);
std::vector<uint8_t> write_pcd(const geometry::PointCloud& cloud, const WriteOptions& options);
std::vector<uint8_t> write_xyz(const geometry::PointCloud& cloud);
std::vector<uint8_t> write_xyzn(const geometry::PointCloud& cloud);
std::vector<uint8_t> write_xyzrgb(const geometry::PointCloud& cloud);
std::vector<uint8_t> write_pts(const geometry::PointCloud& cloud);

/// @brief Size the cloud's arrays for n points (left uninitialised, to be overwritten) and map
/// their memory up front.
void allocate_cloud(geometry::PointCloud& cloud, size_t n, bool normals, bool colors);

/// @brief A zero-filled byte vector of size n whose pages are mapped up front (see prefault()).
std::vector<uint8_t> output_buffer(size_t n);

/// @brief A [0,1] colour channel as 0..255, the way Open3D quantises (clamp, round); NaN gives 0.
inline uint8_t color_to_u8(double c) {
    if (!(c > 0.0)) return 0;
    if (c >= 1.0) return 255;
    return static_cast<uint8_t>(std::lround(c * 255.0));
}

}  // namespace o3d::io::detail
