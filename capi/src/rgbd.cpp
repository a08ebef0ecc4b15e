// SPDX-License-Identifier: MIT
// C API stubs: replaced by the implementation (each fails with O3D_ERROR_UNSUPPORTED until then).
#include "internal.h"
#include "o3d/o3d.h"

extern "C" {

o3d_status o3d_rgbd_options_init(o3d_rgbd_options_t* opts, uint32_t struct_size) {
    return o3d::capi::fail(O3D_ERROR_UNSUPPORTED, "o3d_rgbd_options_init: not implemented yet");
}
o3d_status o3d_rgbd_image_create_from_color_and_depth(o3d_rgbd_image_t** out, const o3d_image_t* color, const o3d_image_t* depth, const o3d_rgbd_options_t* opts) {
    return o3d::capi::fail(O3D_ERROR_UNSUPPORTED, "o3d_rgbd_image_create_from_color_and_depth: not implemented yet");
}
o3d_status o3d_rgbd_image_create_from_dataset_format(o3d_rgbd_image_t** out, int32_t format, const o3d_image_t* color, const o3d_image_t* depth, int32_t convert_rgb_to_intensity) {
    return o3d::capi::fail(O3D_ERROR_UNSUPPORTED, "o3d_rgbd_image_create_from_dataset_format: not implemented yet");
}
void o3d_rgbd_image_destroy(o3d_rgbd_image_t* rgbd) { delete rgbd; }
o3d_status o3d_rgbd_image_get_color(o3d_image_t** out, const o3d_rgbd_image_t* rgbd) {
    return o3d::capi::fail(O3D_ERROR_UNSUPPORTED, "o3d_rgbd_image_get_color: not implemented yet");
}
o3d_status o3d_rgbd_image_get_depth(o3d_image_t** out, const o3d_rgbd_image_t* rgbd) {
    return o3d::capi::fail(O3D_ERROR_UNSUPPORTED, "o3d_rgbd_image_get_depth: not implemented yet");
}
o3d_status o3d_depth_to_cloud_options_init(o3d_depth_to_cloud_options_t* opts, uint32_t struct_size) {
    return o3d::capi::fail(O3D_ERROR_UNSUPPORTED, "o3d_depth_to_cloud_options_init: not implemented yet");
}
o3d_status o3d_pointcloud_create_from_depth_image(o3d_pointcloud_t** out, const o3d_image_t* depth, const o3d_pinhole_intrinsic_t* intrinsic, const double extrinsic[16], const o3d_depth_to_cloud_options_t* opts) {
    return o3d::capi::fail(O3D_ERROR_UNSUPPORTED, "o3d_pointcloud_create_from_depth_image: not implemented yet");
}
o3d_status o3d_pointcloud_create_from_rgbd_image(o3d_pointcloud_t** out, const o3d_rgbd_image_t* rgbd, const o3d_pinhole_intrinsic_t* intrinsic, const double extrinsic[16], int32_t project_valid_depth_only) {
    return o3d::capi::fail(O3D_ERROR_UNSUPPORTED, "o3d_pointcloud_create_from_rgbd_image: not implemented yet");
}

}  // extern "C"
