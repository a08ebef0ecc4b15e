// SPDX-License-Identifier: MIT
// C API: io.h, a thin layer over o3d::io (core/src/o3d/io/point_cloud_io.h).
#include <memory>
#include <string>

#include "internal.h"
#include "o3d/io.h"
#include "o3d/io/point_cloud_io.h"

namespace {

const o3d_read_options_t kReadDefaults = {sizeof(o3d_read_options_t), 0, 0};
const o3d_write_options_t kWriteDefaults = {sizeof(o3d_write_options_t), 0, 0};

/// NULL means "auto", as the header promises.
std::string format_arg(const char* format) { return format ? format : "auto"; }

o3d::io::ReadOptions to_core(const o3d_read_options_t* user) {
    const o3d_read_options_t o = o3d::capi::read_options(user, kReadDefaults, "opts");
    o3d::io::ReadOptions r;
    r.remove_nan_points = o.remove_nan_points != 0;
    r.remove_infinite_points = o.remove_infinite_points != 0;
    return r;
}

o3d::io::WriteOptions to_core(const o3d_write_options_t* user) {
    const o3d_write_options_t o = o3d::capi::read_options(user, kWriteDefaults, "opts");
    o3d::io::WriteOptions w;
    w.write_ascii = o.write_ascii != 0;
    w.compressed = o.compressed != 0;
    return w;
}

}  // namespace

extern "C" {

O3D_API o3d_status o3d_read_options_init(o3d_read_options_t* opts, uint32_t struct_size) {
    return o3d::capi::guard(__func__, [&] { o3d::capi::init_options(opts, struct_size, kReadDefaults, "opts"); });
}

O3D_API o3d_status o3d_write_options_init(o3d_write_options_t* opts, uint32_t struct_size) {
    return o3d::capi::guard(__func__, [&] { o3d::capi::init_options(opts, struct_size, kWriteDefaults, "opts"); });
}

O3D_API o3d_status o3d_io_read_point_cloud(o3d_pointcloud_t** out, const char* path, const char* format,
                                           const o3d_read_options_t* opts) {
    return o3d::capi::guard(__func__, [&] {
        o3d::capi::require(out, "out");
        *out = nullptr;
        o3d::capi::require(path, "path");
        const o3d::io::ReadOptions options = to_core(opts);
        auto pc = std::make_unique<o3d_pointcloud>();
        pc->cloud = o3d::io::read_point_cloud(path, format_arg(format), options);
        *out = pc.release();
    });
}

O3D_API o3d_status o3d_io_write_point_cloud(const char* path, const o3d_pointcloud_t* pc, const char* format,
                                            const o3d_write_options_t* opts) {
    return o3d::capi::guard(__func__, [&] {
        o3d::capi::require(path, "path");
        o3d::capi::require(pc, "pc");
        o3d::io::write_point_cloud(path, pc->cloud, format_arg(format), to_core(opts));
    });
}

O3D_API o3d_status o3d_io_read_point_cloud_from_memory(o3d_pointcloud_t** out, const uint8_t* data, size_t size,
                                                       const char* format, const o3d_read_options_t* opts) {
    return o3d::capi::guard(__func__, [&] {
        o3d::capi::require(out, "out");
        *out = nullptr;
        if (!data && size) throw o3d::InvalidArgument("data is NULL but size is " + std::to_string(size));
        const o3d::io::ReadOptions options = to_core(opts);
        auto pc = std::make_unique<o3d_pointcloud>();
        pc->cloud = o3d::io::read_point_cloud_from_memory(data, size, format_arg(format), options);
        *out = pc.release();
    });
}

O3D_API o3d_status o3d_io_write_point_cloud_to_memory(o3d_buffer_t** out, const o3d_pointcloud_t* pc,
                                                      const char* format, const o3d_write_options_t* opts) {
    return o3d::capi::guard(__func__, [&] {
        o3d::capi::require(out, "out");
        *out = nullptr;
        o3d::capi::require(pc, "pc");
        auto buffer = std::make_unique<o3d_buffer>();
        buffer->bytes = o3d::io::write_point_cloud_to_memory(pc->cloud, format_arg(format), to_core(opts));
        *out = buffer.release();
    });
}

}  // extern "C"
