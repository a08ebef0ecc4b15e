// SPDX-License-Identifier: MIT
// C API stubs: replaced by the implementation (each fails with O3D_ERROR_UNSUPPORTED until then).
#include "internal.h"
#include "o3d/o3d.h"

extern "C" {

o3d_status o3d_mesh_read_options_init(o3d_mesh_read_options_t* opts, uint32_t struct_size) {
    return o3d::capi::fail(O3D_ERROR_UNSUPPORTED, "o3d_mesh_read_options_init: not implemented yet");
}
o3d_status o3d_mesh_write_options_init(o3d_mesh_write_options_t* opts, uint32_t struct_size) {
    return o3d::capi::fail(O3D_ERROR_UNSUPPORTED, "o3d_mesh_write_options_init: not implemented yet");
}
o3d_status o3d_io_read_triangle_mesh(o3d_trianglemesh_t** out, const char* path, const char* format, const o3d_mesh_read_options_t* opts) {
    return o3d::capi::fail(O3D_ERROR_UNSUPPORTED, "o3d_io_read_triangle_mesh: not implemented yet");
}
o3d_status o3d_io_write_triangle_mesh(const char* path, const o3d_trianglemesh_t* mesh, const char* format, const o3d_mesh_write_options_t* opts) {
    return o3d::capi::fail(O3D_ERROR_UNSUPPORTED, "o3d_io_write_triangle_mesh: not implemented yet");
}
o3d_status o3d_io_read_triangle_mesh_from_memory(o3d_trianglemesh_t** out, const uint8_t* data, size_t size, const char* format, const o3d_mesh_read_options_t* opts) {
    return o3d::capi::fail(O3D_ERROR_UNSUPPORTED, "o3d_io_read_triangle_mesh_from_memory: not implemented yet");
}
o3d_status o3d_io_write_triangle_mesh_to_memory(o3d_buffer_t** out, const o3d_trianglemesh_t* mesh, const char* format, const o3d_mesh_write_options_t* opts) {
    return o3d::capi::fail(O3D_ERROR_UNSUPPORTED, "o3d_io_write_triangle_mesh_to_memory: not implemented yet");
}

}  // extern "C"
