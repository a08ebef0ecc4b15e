// SPDX-License-Identifier: MIT
// C API stubs: replaced by the implementation (each fails with O3D_ERROR_UNSUPPORTED until then).
#include "internal.h"
#include "o3d/o3d.h"

extern "C" {

o3d_status o3d_pinhole_intrinsic_set_preset(o3d_pinhole_intrinsic_t* out, int32_t preset) {
    return o3d::capi::fail(O3D_ERROR_UNSUPPORTED, "o3d_pinhole_intrinsic_set_preset: not implemented yet");
}
o3d_status o3d_camera_trajectory_create(o3d_camera_trajectory_t** out) {
    return o3d::capi::fail(O3D_ERROR_UNSUPPORTED, "o3d_camera_trajectory_create: not implemented yet");
}
void o3d_camera_trajectory_destroy(o3d_camera_trajectory_t* trajectory) { delete trajectory; }
o3d_status o3d_camera_trajectory_size(const o3d_camera_trajectory_t* trajectory, size_t* out_n) {
    return o3d::capi::fail(O3D_ERROR_UNSUPPORTED, "o3d_camera_trajectory_size: not implemented yet");
}
o3d_status o3d_camera_trajectory_get(const o3d_camera_trajectory_t* trajectory, size_t index, o3d_pinhole_intrinsic_t* out_intrinsic, double out_extrinsic[16]) {
    return o3d::capi::fail(O3D_ERROR_UNSUPPORTED, "o3d_camera_trajectory_get: not implemented yet");
}
o3d_status o3d_camera_trajectory_append(o3d_camera_trajectory_t* trajectory, const o3d_pinhole_intrinsic_t* intrinsic, const double extrinsic[16]) {
    return o3d::capi::fail(O3D_ERROR_UNSUPPORTED, "o3d_camera_trajectory_append: not implemented yet");
}
o3d_status o3d_camera_trajectory_clear(o3d_camera_trajectory_t* trajectory) {
    return o3d::capi::fail(O3D_ERROR_UNSUPPORTED, "o3d_camera_trajectory_clear: not implemented yet");
}
o3d_status o3d_io_read_pinhole_camera_intrinsic(const char* path, o3d_pinhole_intrinsic_t* out) {
    return o3d::capi::fail(O3D_ERROR_UNSUPPORTED, "o3d_io_read_pinhole_camera_intrinsic: not implemented yet");
}
o3d_status o3d_io_write_pinhole_camera_intrinsic(const char* path, const o3d_pinhole_intrinsic_t* intrinsic) {
    return o3d::capi::fail(O3D_ERROR_UNSUPPORTED, "o3d_io_write_pinhole_camera_intrinsic: not implemented yet");
}
o3d_status o3d_io_read_pinhole_camera_parameters(const char* path, o3d_pinhole_intrinsic_t* out_intrinsic, double out_extrinsic[16]) {
    return o3d::capi::fail(O3D_ERROR_UNSUPPORTED, "o3d_io_read_pinhole_camera_parameters: not implemented yet");
}
o3d_status o3d_io_write_pinhole_camera_parameters(const char* path, const o3d_pinhole_intrinsic_t* intrinsic, const double extrinsic[16]) {
    return o3d::capi::fail(O3D_ERROR_UNSUPPORTED, "o3d_io_write_pinhole_camera_parameters: not implemented yet");
}
o3d_status o3d_io_read_pinhole_camera_trajectory(o3d_camera_trajectory_t** out, const char* path, const char* format) {
    return o3d::capi::fail(O3D_ERROR_UNSUPPORTED, "o3d_io_read_pinhole_camera_trajectory: not implemented yet");
}
o3d_status o3d_io_write_pinhole_camera_trajectory(const char* path, const o3d_camera_trajectory_t* trajectory, const char* format) {
    return o3d::capi::fail(O3D_ERROR_UNSUPPORTED, "o3d_io_write_pinhole_camera_trajectory: not implemented yet");
}

}  // extern "C"
