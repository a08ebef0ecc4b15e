// SPDX-License-Identifier: MIT
// C API: the triangle-mesh part of io.h, a thin layer over o3d::io (core/src/o3d/io/triangle_mesh_io.h).
#include <memory>
#include <string>

#include "internal.h"
#include "o3d/io.h"
#include "o3d/io/triangle_mesh_io.h"

namespace {

const o3d_mesh_read_options_t kMeshReadDefaults = {sizeof(o3d_mesh_read_options_t), 0};
const o3d_mesh_write_options_t kMeshWriteDefaults = {sizeof(o3d_mesh_write_options_t), 0, 0, 1, 1, 1};

/// NULL means "auto", as the header promises.
std::string format_arg(const char* format) { return format ? format : "auto"; }

o3d::io::MeshReadOptions to_core(const o3d_mesh_read_options_t* user) {
    const o3d_mesh_read_options_t o = o3d::capi::read_options(user, kMeshReadDefaults, "opts");
    o3d::io::MeshReadOptions r;
    r.enable_post_processing = o.enable_post_processing != 0;
    return r;
}

o3d::io::MeshWriteOptions to_core(const o3d_mesh_write_options_t* user) {
    const o3d_mesh_write_options_t o = o3d::capi::read_options(user, kMeshWriteDefaults, "opts");
    o3d::io::MeshWriteOptions w;
    w.write_ascii = o.write_ascii != 0;
    w.compressed = o.compressed != 0;
    w.write_vertex_normals = o.write_vertex_normals != 0;
    w.write_vertex_colors = o.write_vertex_colors != 0;
    w.write_triangle_uvs = o.write_triangle_uvs != 0;
    return w;
}

}  // namespace

extern "C" {

O3D_API o3d_status o3d_mesh_read_options_init(o3d_mesh_read_options_t* opts, uint32_t struct_size) {
    return o3d::capi::guard(__func__, [&] { o3d::capi::init_options(opts, struct_size, kMeshReadDefaults, "opts"); });
}

O3D_API o3d_status o3d_mesh_write_options_init(o3d_mesh_write_options_t* opts, uint32_t struct_size) {
    return o3d::capi::guard(__func__, [&] { o3d::capi::init_options(opts, struct_size, kMeshWriteDefaults, "opts"); });
}

O3D_API o3d_status o3d_io_read_triangle_mesh(o3d_trianglemesh_t** out, const char* path, const char* format,
                                             const o3d_mesh_read_options_t* opts) {
    return o3d::capi::guard(__func__, [&] {
        o3d::capi::require(out, "out");
        *out = nullptr;
        o3d::capi::require(path, "path");
        const o3d::io::MeshReadOptions options = to_core(opts);
        auto mesh = std::make_unique<o3d_trianglemesh>();
        mesh->mesh = o3d::io::read_triangle_mesh(path, format_arg(format), options);
        *out = mesh.release();
    });
}

O3D_API o3d_status o3d_io_write_triangle_mesh(const char* path, const o3d_trianglemesh_t* mesh, const char* format,
                                              const o3d_mesh_write_options_t* opts) {
    return o3d::capi::guard(__func__, [&] {
        o3d::capi::require(path, "path");
        o3d::capi::require(mesh, "mesh");
        o3d::io::write_triangle_mesh(path, mesh->mesh, format_arg(format), to_core(opts));
    });
}

O3D_API o3d_status o3d_io_read_triangle_mesh_from_memory(o3d_trianglemesh_t** out, const uint8_t* data, size_t size,
                                                         const char* format, const o3d_mesh_read_options_t* opts) {
    return o3d::capi::guard(__func__, [&] {
        o3d::capi::require(out, "out");
        *out = nullptr;
        if (!data && size) throw o3d::InvalidArgument("data is NULL but size is " + std::to_string(size));
        const o3d::io::MeshReadOptions options = to_core(opts);
        auto mesh = std::make_unique<o3d_trianglemesh>();
        mesh->mesh = o3d::io::read_triangle_mesh_from_memory(data, size, format_arg(format), options);
        *out = mesh.release();
    });
}

O3D_API o3d_status o3d_io_write_triangle_mesh_to_memory(o3d_buffer_t** out, const o3d_trianglemesh_t* mesh,
                                                        const char* format, const o3d_mesh_write_options_t* opts) {
    return o3d::capi::guard(__func__, [&] {
        o3d::capi::require(out, "out");
        *out = nullptr;
        o3d::capi::require(mesh, "mesh");
        auto buffer = std::make_unique<o3d_buffer>();
        buffer->bytes = o3d::io::write_triangle_mesh_to_memory(mesh->mesh, format_arg(format), to_core(opts));
        *out = buffer.release();
    });
}

}  // extern "C"
