// SPDX-License-Identifier: MIT
// C API stubs: replaced by the implementation (each fails with O3D_ERROR_UNSUPPORTED until then).
#include "internal.h"
#include "o3d/o3d.h"

extern "C" {

o3d_status o3d_image_create(o3d_image_t** out, int32_t width, int32_t height, int32_t num_channels, int32_t bytes_per_channel) {
    return o3d::capi::fail(O3D_ERROR_UNSUPPORTED, "o3d_image_create: not implemented yet");
}
o3d_status o3d_image_create_from_data(o3d_image_t** out, int32_t width, int32_t height, int32_t num_channels, int32_t bytes_per_channel, const uint8_t* data, size_t size) {
    return o3d::capi::fail(O3D_ERROR_UNSUPPORTED, "o3d_image_create_from_data: not implemented yet");
}
void o3d_image_destroy(o3d_image_t* image) { delete image; }
o3d_status o3d_image_clone(o3d_image_t** out, const o3d_image_t* src) {
    return o3d::capi::fail(O3D_ERROR_UNSUPPORTED, "o3d_image_clone: not implemented yet");
}
o3d_status o3d_image_width(const o3d_image_t* image, int32_t* out) {
    return o3d::capi::fail(O3D_ERROR_UNSUPPORTED, "o3d_image_width: not implemented yet");
}
o3d_status o3d_image_height(const o3d_image_t* image, int32_t* out) {
    return o3d::capi::fail(O3D_ERROR_UNSUPPORTED, "o3d_image_height: not implemented yet");
}
o3d_status o3d_image_num_channels(const o3d_image_t* image, int32_t* out) {
    return o3d::capi::fail(O3D_ERROR_UNSUPPORTED, "o3d_image_num_channels: not implemented yet");
}
o3d_status o3d_image_bytes_per_channel(const o3d_image_t* image, int32_t* out) {
    return o3d::capi::fail(O3D_ERROR_UNSUPPORTED, "o3d_image_bytes_per_channel: not implemented yet");
}
o3d_status o3d_image_data_view(const o3d_image_t* image, const uint8_t** out_data, size_t* out_size) {
    return o3d::capi::fail(O3D_ERROR_UNSUPPORTED, "o3d_image_data_view: not implemented yet");
}
o3d_status o3d_image_data_mutable_view(o3d_image_t* image, uint8_t** out_data, size_t* out_size) {
    return o3d::capi::fail(O3D_ERROR_UNSUPPORTED, "o3d_image_data_mutable_view: not implemented yet");
}
o3d_status o3d_image_get_data(const o3d_image_t* image, uint8_t* out, size_t capacity, size_t* out_size) {
    return o3d::capi::fail(O3D_ERROR_UNSUPPORTED, "o3d_image_get_data: not implemented yet");
}
o3d_status o3d_image_filter(o3d_image_t** out, const o3d_image_t* image, int32_t filter_type) {
    return o3d::capi::fail(O3D_ERROR_UNSUPPORTED, "o3d_image_filter: not implemented yet");
}
o3d_status o3d_image_downsample(o3d_image_t** out, const o3d_image_t* image) {
    return o3d::capi::fail(O3D_ERROR_UNSUPPORTED, "o3d_image_downsample: not implemented yet");
}
o3d_status o3d_image_flip_vertical(o3d_image_t** out, const o3d_image_t* image) {
    return o3d::capi::fail(O3D_ERROR_UNSUPPORTED, "o3d_image_flip_vertical: not implemented yet");
}
o3d_status o3d_image_flip_horizontal(o3d_image_t** out, const o3d_image_t* image) {
    return o3d::capi::fail(O3D_ERROR_UNSUPPORTED, "o3d_image_flip_horizontal: not implemented yet");
}
o3d_status o3d_image_create_float_image(o3d_image_t** out, const o3d_image_t* image, int32_t convert_type) {
    return o3d::capi::fail(O3D_ERROR_UNSUPPORTED, "o3d_image_create_float_image: not implemented yet");
}
o3d_status o3d_image_convert_depth_to_float(o3d_image_t** out, const o3d_image_t* image, double depth_scale, double depth_trunc) {
    return o3d::capi::fail(O3D_ERROR_UNSUPPORTED, "o3d_image_convert_depth_to_float: not implemented yet");
}
o3d_status o3d_io_read_image(o3d_image_t** out, const char* path, const char* format) {
    return o3d::capi::fail(O3D_ERROR_UNSUPPORTED, "o3d_io_read_image: not implemented yet");
}
o3d_status o3d_io_write_image(const char* path, const o3d_image_t* image, const char* format, int32_t quality) {
    return o3d::capi::fail(O3D_ERROR_UNSUPPORTED, "o3d_io_write_image: not implemented yet");
}
o3d_status o3d_io_read_image_from_memory(o3d_image_t** out, const uint8_t* data, size_t size, const char* format) {
    return o3d::capi::fail(O3D_ERROR_UNSUPPORTED, "o3d_io_read_image_from_memory: not implemented yet");
}
o3d_status o3d_io_write_image_to_memory(o3d_buffer_t** out, const o3d_image_t* image, const char* format, int32_t quality) {
    return o3d::capi::fail(O3D_ERROR_UNSUPPORTED, "o3d_io_write_image_to_memory: not implemented yet");
}

}  // extern "C"
