// SPDX-License-Identifier: MIT
#pragma once
/// @file point_cloud_io.h
/// @brief Point-cloud reading and writing: PLY, PCD, XYZ, XYZN, XYZRGB, PTS, to files or memory.
/// Formats use Open3D's names; "auto" (or "") picks the format from the path's extension.
/// Errors: o3d::IoError (cannot open/read/write), o3d::ParseError (malformed input; the message
/// names the file or "<memory>" and the reason), o3d::Unsupported (unknown format).
#include <cstdint>
#include <string>
#include <vector>

#include "o3d/geometry/point_cloud.h"

namespace o3d::io {

struct ReadOptions {
    bool remove_nan_points = false;
    bool remove_infinite_points = false;
};

struct WriteOptions {
    bool write_ascii = false;
    bool compressed = false;
};

geometry::PointCloud read_point_cloud(const std::string& path, const std::string& format = "auto",
                                      const ReadOptions& options = {});
geometry::PointCloud read_point_cloud_from_memory(const uint8_t* data, size_t size, const std::string& format,
                                                  const ReadOptions& options = {});
void write_point_cloud(const std::string& path, const geometry::PointCloud& cloud, const std::string& format = "auto",
                       const WriteOptions& options = {});
std::vector<uint8_t> write_point_cloud_to_memory(const geometry::PointCloud& cloud, const std::string& format,
                                                 const WriteOptions& options = {});

}  // namespace o3d::io
