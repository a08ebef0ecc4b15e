// SPDX-License-Identifier: MIT
// C API: kdtree.h (stubs, to be replaced by the implementation).
#include "internal.h"
#include "o3d/kdtree.h"

// Unused-parameter warnings are expected in stubs.
#pragma GCC diagnostic ignored "-Wunused-parameter"

extern "C" {

O3D_API o3d_status o3d_kdtree_create_from_pointcloud(o3d_kdtree_t** out, const o3d_pointcloud_t* pc) {
    return o3d::capi::guard(__func__, [&]() -> o3d_status { throw o3d::Unsupported("not implemented yet"); });
}

O3D_API o3d_status o3d_kdtree_create_from_points(o3d_kdtree_t** out, const double* xyz, size_t n) {
    return o3d::capi::guard(__func__, [&]() -> o3d_status { throw o3d::Unsupported("not implemented yet"); });
}

O3D_API void o3d_kdtree_destroy(o3d_kdtree_t* tree) {}

O3D_API o3d_status o3d_kdtree_size(const o3d_kdtree_t* tree, size_t* out_n) {
    return o3d::capi::guard(__func__, [&]() -> o3d_status { throw o3d::Unsupported("not implemented yet"); });
}

O3D_API o3d_status o3d_kdtree_search(const o3d_kdtree_t* tree, const double* queries, size_t num_queries, const o3d_search_param_t* param, int32_t num_threads, o3d_search_result_t** out) {
    return o3d::capi::guard(__func__, [&]() -> o3d_status { throw o3d::Unsupported("not implemented yet"); });
}

O3D_API o3d_status o3d_kdtree_search_f32(const o3d_kdtree_t* tree, const float* queries, size_t num_queries, const o3d_search_param_t* param, int32_t num_threads, o3d_search_result_t** out) {
    return o3d::capi::guard(__func__, [&]() -> o3d_status { throw o3d::Unsupported("not implemented yet"); });
}

O3D_API void o3d_search_result_destroy(o3d_search_result_t* result) {}

O3D_API o3d_status o3d_search_result_counts(const o3d_search_result_t* result, size_t* out_num_queries, size_t* out_total) {
    return o3d::capi::guard(__func__, [&]() -> o3d_status { throw o3d::Unsupported("not implemented yet"); });
}

O3D_API o3d_status o3d_search_result_view(const o3d_search_result_t* result, const int64_t** out_offsets, const int32_t** out_indices, const double** out_distances2) {
    return o3d::capi::guard(__func__, [&]() -> o3d_status { throw o3d::Unsupported("not implemented yet"); });
}

O3D_API o3d_status o3d_search_result_get_offsets(const o3d_search_result_t* result, int64_t* out, size_t capacity) {
    return o3d::capi::guard(__func__, [&]() -> o3d_status { throw o3d::Unsupported("not implemented yet"); });
}

O3D_API o3d_status o3d_search_result_get_indices(const o3d_search_result_t* result, int32_t* out, size_t capacity) {
    return o3d::capi::guard(__func__, [&]() -> o3d_status { throw o3d::Unsupported("not implemented yet"); });
}

O3D_API o3d_status o3d_search_result_get_distances2(const o3d_search_result_t* result, double* out, size_t capacity) {
    return o3d::capi::guard(__func__, [&]() -> o3d_status { throw o3d::Unsupported("not implemented yet"); });
}

}  // extern "C"
