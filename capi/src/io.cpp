// SPDX-License-Identifier: MIT
// C API: io.h (stubs, to be replaced by the implementation).
#include "internal.h"
#include "o3d/io.h"

// Unused-parameter warnings are expected in stubs.
#pragma GCC diagnostic ignored "-Wunused-parameter"

extern "C" {

O3D_API o3d_status o3d_read_options_init(o3d_read_options_t* opts, uint32_t struct_size) {
    return o3d::capi::guard(__func__, [&]() -> o3d_status { throw o3d::Unsupported("not implemented yet"); });
}

O3D_API o3d_status o3d_write_options_init(o3d_write_options_t* opts, uint32_t struct_size) {
    return o3d::capi::guard(__func__, [&]() -> o3d_status { throw o3d::Unsupported("not implemented yet"); });
}

O3D_API o3d_status o3d_io_read_point_cloud(o3d_pointcloud_t** out, const char* path, const char* format, const o3d_read_options_t* opts) {
    return o3d::capi::guard(__func__, [&]() -> o3d_status { throw o3d::Unsupported("not implemented yet"); });
}

O3D_API o3d_status o3d_io_write_point_cloud(const char* path, const o3d_pointcloud_t* pc, const char* format, const o3d_write_options_t* opts) {
    return o3d::capi::guard(__func__, [&]() -> o3d_status { throw o3d::Unsupported("not implemented yet"); });
}

O3D_API o3d_status o3d_io_read_point_cloud_from_memory(o3d_pointcloud_t** out, const uint8_t* data, size_t size, const char* format, const o3d_read_options_t* opts) {
    return o3d::capi::guard(__func__, [&]() -> o3d_status { throw o3d::Unsupported("not implemented yet"); });
}

O3D_API o3d_status o3d_io_write_point_cloud_to_memory(o3d_buffer_t** out, const o3d_pointcloud_t* pc, const char* format, const o3d_write_options_t* opts) {
    return o3d::capi::guard(__func__, [&]() -> o3d_status { throw o3d::Unsupported("not implemented yet"); });
}

}  // extern "C"
