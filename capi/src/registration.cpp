// SPDX-License-Identifier: MIT
// C API: registration.h (stubs, to be replaced by the implementation).
#include "internal.h"
#include "o3d/registration.h"

// Unused-parameter warnings are expected in stubs.
#pragma GCC diagnostic ignored "-Wunused-parameter"

extern "C" {

O3D_API o3d_status o3d_icp_options_init(o3d_icp_options_t* opts, uint32_t struct_size) {
    return o3d::capi::guard(__func__, [&]() -> o3d_status { throw o3d::Unsupported("not implemented yet"); });
}

O3D_API o3d_status o3d_register_icp(o3d_registration_result_t** out, const o3d_pointcloud_t* source, const o3d_pointcloud_t* target, double max_correspondence_distance, const double init[16], const o3d_icp_options_t* opts) {
    return o3d::capi::guard(__func__, [&]() -> o3d_status { throw o3d::Unsupported("not implemented yet"); });
}

O3D_API o3d_status o3d_evaluate_registration(o3d_registration_result_t** out, const o3d_pointcloud_t* source, const o3d_pointcloud_t* target, double max_correspondence_distance, const double transformation[16]) {
    return o3d::capi::guard(__func__, [&]() -> o3d_status { throw o3d::Unsupported("not implemented yet"); });
}

O3D_API o3d_status o3d_get_information_matrix_from_point_clouds(const o3d_pointcloud_t* source, const o3d_pointcloud_t* target, double max_correspondence_distance, const double transformation[16], double out[36]) {
    return o3d::capi::guard(__func__, [&]() -> o3d_status { throw o3d::Unsupported("not implemented yet"); });
}

O3D_API void o3d_registration_result_destroy(o3d_registration_result_t* result) {}

O3D_API o3d_status o3d_registration_result_get_transformation(const o3d_registration_result_t* result, double out[16]) {
    return o3d::capi::guard(__func__, [&]() -> o3d_status { throw o3d::Unsupported("not implemented yet"); });
}

O3D_API o3d_status o3d_registration_result_get_fitness(const o3d_registration_result_t* result, double* out) {
    return o3d::capi::guard(__func__, [&]() -> o3d_status { throw o3d::Unsupported("not implemented yet"); });
}

O3D_API o3d_status o3d_registration_result_get_inlier_rmse(const o3d_registration_result_t* result, double* out) {
    return o3d::capi::guard(__func__, [&]() -> o3d_status { throw o3d::Unsupported("not implemented yet"); });
}

O3D_API o3d_status o3d_registration_result_get_correspondence_set(const o3d_registration_result_t* result, int32_t* out, size_t capacity, size_t* out_n) {
    return o3d::capi::guard(__func__, [&]() -> o3d_status { throw o3d::Unsupported("not implemented yet"); });
}

}  // extern "C"
