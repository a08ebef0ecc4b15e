// SPDX-License-Identifier: MIT
// C API: pointcloud.h (stubs, to be replaced by the implementation).
#include "internal.h"
#include "o3d/pointcloud.h"

// Unused-parameter warnings are expected in stubs.
#pragma GCC diagnostic ignored "-Wunused-parameter"

extern "C" {

O3D_API o3d_status o3d_pointcloud_create(o3d_pointcloud_t** out) {
    return o3d::capi::guard(__func__, [&]() -> o3d_status { throw o3d::Unsupported("not implemented yet"); });
}

O3D_API void o3d_pointcloud_destroy(o3d_pointcloud_t* pc) {}

O3D_API o3d_status o3d_pointcloud_clone(o3d_pointcloud_t** out, const o3d_pointcloud_t* src) {
    return o3d::capi::guard(__func__, [&]() -> o3d_status { throw o3d::Unsupported("not implemented yet"); });
}

O3D_API o3d_status o3d_pointcloud_size(const o3d_pointcloud_t* pc, size_t* out_n) {
    return o3d::capi::guard(__func__, [&]() -> o3d_status { throw o3d::Unsupported("not implemented yet"); });
}

O3D_API o3d_status o3d_pointcloud_has_points(const o3d_pointcloud_t* pc, int32_t* out) {
    return o3d::capi::guard(__func__, [&]() -> o3d_status { throw o3d::Unsupported("not implemented yet"); });
}

O3D_API o3d_status o3d_pointcloud_has_normals(const o3d_pointcloud_t* pc, int32_t* out) {
    return o3d::capi::guard(__func__, [&]() -> o3d_status { throw o3d::Unsupported("not implemented yet"); });
}

O3D_API o3d_status o3d_pointcloud_has_colors(const o3d_pointcloud_t* pc, int32_t* out) {
    return o3d::capi::guard(__func__, [&]() -> o3d_status { throw o3d::Unsupported("not implemented yet"); });
}

O3D_API o3d_status o3d_pointcloud_clear(o3d_pointcloud_t* pc) {
    return o3d::capi::guard(__func__, [&]() -> o3d_status { throw o3d::Unsupported("not implemented yet"); });
}

O3D_API o3d_status o3d_pointcloud_set_points(o3d_pointcloud_t* pc, const double* xyz, size_t n) {
    return o3d::capi::guard(__func__, [&]() -> o3d_status { throw o3d::Unsupported("not implemented yet"); });
}

O3D_API o3d_status o3d_pointcloud_set_points_f32(o3d_pointcloud_t* pc, const float* xyz, size_t n) {
    return o3d::capi::guard(__func__, [&]() -> o3d_status { throw o3d::Unsupported("not implemented yet"); });
}

O3D_API o3d_status o3d_pointcloud_set_normals(o3d_pointcloud_t* pc, const double* xyz, size_t n) {
    return o3d::capi::guard(__func__, [&]() -> o3d_status { throw o3d::Unsupported("not implemented yet"); });
}

O3D_API o3d_status o3d_pointcloud_set_normals_f32(o3d_pointcloud_t* pc, const float* xyz, size_t n) {
    return o3d::capi::guard(__func__, [&]() -> o3d_status { throw o3d::Unsupported("not implemented yet"); });
}

O3D_API o3d_status o3d_pointcloud_set_colors(o3d_pointcloud_t* pc, const double* rgb, size_t n) {
    return o3d::capi::guard(__func__, [&]() -> o3d_status { throw o3d::Unsupported("not implemented yet"); });
}

O3D_API o3d_status o3d_pointcloud_set_colors_f32(o3d_pointcloud_t* pc, const float* rgb, size_t n) {
    return o3d::capi::guard(__func__, [&]() -> o3d_status { throw o3d::Unsupported("not implemented yet"); });
}

O3D_API o3d_status o3d_pointcloud_get_points(const o3d_pointcloud_t* pc, double* out, size_t capacity, size_t* out_n) {
    return o3d::capi::guard(__func__, [&]() -> o3d_status { throw o3d::Unsupported("not implemented yet"); });
}

O3D_API o3d_status o3d_pointcloud_get_normals(const o3d_pointcloud_t* pc, double* out, size_t capacity, size_t* out_n) {
    return o3d::capi::guard(__func__, [&]() -> o3d_status { throw o3d::Unsupported("not implemented yet"); });
}

O3D_API o3d_status o3d_pointcloud_get_colors(const o3d_pointcloud_t* pc, double* out, size_t capacity, size_t* out_n) {
    return o3d::capi::guard(__func__, [&]() -> o3d_status { throw o3d::Unsupported("not implemented yet"); });
}

O3D_API o3d_status o3d_pointcloud_points_view(const o3d_pointcloud_t* pc, const double** out_data, size_t* out_n) {
    return o3d::capi::guard(__func__, [&]() -> o3d_status { throw o3d::Unsupported("not implemented yet"); });
}

O3D_API o3d_status o3d_pointcloud_normals_view(const o3d_pointcloud_t* pc, const double** out_data, size_t* out_n) {
    return o3d::capi::guard(__func__, [&]() -> o3d_status { throw o3d::Unsupported("not implemented yet"); });
}

O3D_API o3d_status o3d_pointcloud_colors_view(const o3d_pointcloud_t* pc, const double** out_data, size_t* out_n) {
    return o3d::capi::guard(__func__, [&]() -> o3d_status { throw o3d::Unsupported("not implemented yet"); });
}

O3D_API o3d_status o3d_pointcloud_points_mutable_view(o3d_pointcloud_t* pc, double** out_data, size_t* out_n) {
    return o3d::capi::guard(__func__, [&]() -> o3d_status { throw o3d::Unsupported("not implemented yet"); });
}

O3D_API o3d_status o3d_pointcloud_normals_mutable_view(o3d_pointcloud_t* pc, double** out_data, size_t* out_n) {
    return o3d::capi::guard(__func__, [&]() -> o3d_status { throw o3d::Unsupported("not implemented yet"); });
}

O3D_API o3d_status o3d_pointcloud_colors_mutable_view(o3d_pointcloud_t* pc, double** out_data, size_t* out_n) {
    return o3d::capi::guard(__func__, [&]() -> o3d_status { throw o3d::Unsupported("not implemented yet"); });
}

O3D_API o3d_status o3d_pointcloud_append(o3d_pointcloud_t* pc, const o3d_pointcloud_t* other) {
    return o3d::capi::guard(__func__, [&]() -> o3d_status { throw o3d::Unsupported("not implemented yet"); });
}

O3D_API o3d_status o3d_pointcloud_transform(o3d_pointcloud_t* pc, const double transform[16]) {
    return o3d::capi::guard(__func__, [&]() -> o3d_status { throw o3d::Unsupported("not implemented yet"); });
}

O3D_API o3d_status o3d_pointcloud_translate(o3d_pointcloud_t* pc, const double translation[3], int32_t relative) {
    return o3d::capi::guard(__func__, [&]() -> o3d_status { throw o3d::Unsupported("not implemented yet"); });
}

O3D_API o3d_status o3d_pointcloud_rotate(o3d_pointcloud_t* pc, const double rotation[9], const double center[3]) {
    return o3d::capi::guard(__func__, [&]() -> o3d_status { throw o3d::Unsupported("not implemented yet"); });
}

O3D_API o3d_status o3d_pointcloud_scale(o3d_pointcloud_t* pc, double scale, const double center[3]) {
    return o3d::capi::guard(__func__, [&]() -> o3d_status { throw o3d::Unsupported("not implemented yet"); });
}

O3D_API o3d_status o3d_pointcloud_get_min_bound(const o3d_pointcloud_t* pc, double out[3]) {
    return o3d::capi::guard(__func__, [&]() -> o3d_status { throw o3d::Unsupported("not implemented yet"); });
}

O3D_API o3d_status o3d_pointcloud_get_max_bound(const o3d_pointcloud_t* pc, double out[3]) {
    return o3d::capi::guard(__func__, [&]() -> o3d_status { throw o3d::Unsupported("not implemented yet"); });
}

O3D_API o3d_status o3d_pointcloud_get_center(const o3d_pointcloud_t* pc, double out[3]) {
    return o3d::capi::guard(__func__, [&]() -> o3d_status { throw o3d::Unsupported("not implemented yet"); });
}

O3D_API o3d_status o3d_pointcloud_get_axis_aligned_bounding_box(const o3d_pointcloud_t* pc, double out_min[3], double out_max[3]) {
    return o3d::capi::guard(__func__, [&]() -> o3d_status { throw o3d::Unsupported("not implemented yet"); });
}

O3D_API o3d_status o3d_pointcloud_paint_uniform_color(o3d_pointcloud_t* pc, const double rgb[3]) {
    return o3d::capi::guard(__func__, [&]() -> o3d_status { throw o3d::Unsupported("not implemented yet"); });
}

O3D_API o3d_status o3d_pointcloud_select_by_index(o3d_pointcloud_t** out, const o3d_pointcloud_t* pc, const int32_t* indices, size_t n, int32_t invert) {
    return o3d::capi::guard(__func__, [&]() -> o3d_status { throw o3d::Unsupported("not implemented yet"); });
}

O3D_API o3d_status o3d_pointcloud_remove_non_finite_points(o3d_pointcloud_t* pc, int32_t remove_nan, int32_t remove_infinite) {
    return o3d::capi::guard(__func__, [&]() -> o3d_status { throw o3d::Unsupported("not implemented yet"); });
}

O3D_API o3d_status o3d_pointcloud_normalize_normals(o3d_pointcloud_t* pc) {
    return o3d::capi::guard(__func__, [&]() -> o3d_status { throw o3d::Unsupported("not implemented yet"); });
}

O3D_API o3d_status o3d_pointcloud_voxel_down_sample(o3d_pointcloud_t** out, const o3d_pointcloud_t* pc, double voxel_size) {
    return o3d::capi::guard(__func__, [&]() -> o3d_status { throw o3d::Unsupported("not implemented yet"); });
}

O3D_API o3d_status o3d_pointcloud_uniform_down_sample(o3d_pointcloud_t** out, const o3d_pointcloud_t* pc, size_t every_k_points) {
    return o3d::capi::guard(__func__, [&]() -> o3d_status { throw o3d::Unsupported("not implemented yet"); });
}

O3D_API o3d_status o3d_pointcloud_random_down_sample(o3d_pointcloud_t** out, const o3d_pointcloud_t* pc, double sampling_ratio, uint64_t seed) {
    return o3d::capi::guard(__func__, [&]() -> o3d_status { throw o3d::Unsupported("not implemented yet"); });
}

O3D_API o3d_status o3d_pointcloud_farthest_point_down_sample(o3d_pointcloud_t** out, const o3d_pointcloud_t* pc, size_t num_samples, size_t start_index) {
    return o3d::capi::guard(__func__, [&]() -> o3d_status { throw o3d::Unsupported("not implemented yet"); });
}

O3D_API o3d_status o3d_search_param_init(o3d_search_param_t* param, uint32_t struct_size) {
    return o3d::capi::guard(__func__, [&]() -> o3d_status { throw o3d::Unsupported("not implemented yet"); });
}

O3D_API o3d_status o3d_pointcloud_estimate_normals(o3d_pointcloud_t* pc, const o3d_search_param_t* param, int32_t num_threads) {
    return o3d::capi::guard(__func__, [&]() -> o3d_status { throw o3d::Unsupported("not implemented yet"); });
}

O3D_API o3d_status o3d_pointcloud_orient_normals_to_align_with_direction(o3d_pointcloud_t* pc, const double direction[3]) {
    return o3d::capi::guard(__func__, [&]() -> o3d_status { throw o3d::Unsupported("not implemented yet"); });
}

O3D_API o3d_status o3d_pointcloud_orient_normals_towards_camera_location(o3d_pointcloud_t* pc, const double camera_location[3]) {
    return o3d::capi::guard(__func__, [&]() -> o3d_status { throw o3d::Unsupported("not implemented yet"); });
}

O3D_API o3d_status o3d_pointcloud_compute_nearest_neighbor_distance(const o3d_pointcloud_t* pc, double* out, size_t capacity, size_t* out_n, int32_t num_threads) {
    return o3d::capi::guard(__func__, [&]() -> o3d_status { throw o3d::Unsupported("not implemented yet"); });
}

O3D_API o3d_status o3d_pointcloud_compute_point_cloud_distance(const o3d_pointcloud_t* source, const o3d_pointcloud_t* target, double* out, size_t capacity, size_t* out_n, int32_t num_threads) {
    return o3d::capi::guard(__func__, [&]() -> o3d_status { throw o3d::Unsupported("not implemented yet"); });
}

}  // extern "C"
