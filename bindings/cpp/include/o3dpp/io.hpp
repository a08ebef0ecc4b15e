// SPDX-License-Identifier: MIT
#pragma once
/// @file io.hpp
/// @brief Reading and writing point clouds (files and memory).
#include <cstdint>
#include <string>
#include <vector>

#include "o3d/io.h"
#include "o3dpp/common.hpp"
#include "o3dpp/error.hpp"
#include "o3dpp/pointcloud.hpp"

namespace o3dpp {

/// @brief o3d.io.read_point_cloud keyword arguments.
struct ReadOptions {
    bool remove_nan_points = false;
    bool remove_infinite_points = false;

    o3d_read_options_t to_c() const {
        o3d_read_options_t c;
        check(o3d_read_options_init(&c, sizeof c));
        c.remove_nan_points = remove_nan_points ? 1 : 0;
        c.remove_infinite_points = remove_infinite_points ? 1 : 0;
        return c;
    }
};

/// @brief o3d.io.write_point_cloud keyword arguments.
struct WriteOptions {
    bool write_ascii = false;
    bool compressed = false;

    o3d_write_options_t to_c() const {
        o3d_write_options_t c;
        check(o3d_write_options_init(&c, sizeof c));
        c.write_ascii = write_ascii ? 1 : 0;
        c.compressed = compressed ? 1 : 0;
        return c;
    }
};

/// @brief Read a cloud; an empty `format` means: from the extension.
inline PointCloud read_point_cloud(const std::string& path, const std::string& format = "",
                                   const ReadOptions& options = {}) {
    const o3d_read_options_t c = options.to_c();
    return PointCloud::adopt(
        [&](o3d_pointcloud_t** o) { return o3d_io_read_point_cloud(o, path.c_str(), format.c_str(), &c); });
}

inline void write_point_cloud(const std::string& path, const PointCloud& cloud, const std::string& format = "",
                              const WriteOptions& options = {}) {
    const o3d_write_options_t c = options.to_c();
    check(o3d_io_write_point_cloud(path.c_str(), cloud.get(), format.c_str(), &c));
}

/// @brief Read from `size` bytes at `data`; `format` is required.
inline PointCloud read_point_cloud_from_memory(const uint8_t* data, std::size_t size, const std::string& format,
                                               const ReadOptions& options = {}) {
    const o3d_read_options_t c = options.to_c();
    return PointCloud::adopt([&](o3d_pointcloud_t** o) {
        return o3d_io_read_point_cloud_from_memory(o, data, size, format.c_str(), &c);
    });
}
inline PointCloud read_point_cloud_from_memory(const std::vector<uint8_t>& bytes, const std::string& format,
                                               const ReadOptions& options = {}) {
    return read_point_cloud_from_memory(bytes.data(), bytes.size(), format, options);
}
inline PointCloud read_point_cloud_from_memory(const std::string& bytes, const std::string& format,
                                               const ReadOptions& options = {}) {
    return read_point_cloud_from_memory(reinterpret_cast<const uint8_t*>(bytes.data()), bytes.size(), format,
                                        options);
}

/// @brief Encode `cloud` in `format` into a new Buffer.
inline Buffer write_point_cloud_to_memory(const PointCloud& cloud, const std::string& format,
                                          const WriteOptions& options = {}) {
    const o3d_write_options_t c = options.to_c();
    o3d_buffer_t* b = nullptr;
    check(o3d_io_write_point_cloud_to_memory(&b, cloud.get(), format.c_str(), &c));
    return Buffer(b);
}

}  // namespace o3dpp
