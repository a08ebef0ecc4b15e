// SPDX-License-Identifier: MIT
// C API stubs: replaced by the implementation (each fails with O3D_ERROR_UNSUPPORTED until then).
#include "internal.h"
#include "o3d/o3d.h"

extern "C" {

o3d_status o3d_trianglemesh_sample_points_uniformly(o3d_pointcloud_t** out, const o3d_trianglemesh_t* mesh, size_t number_of_points, int32_t use_triangle_normal, uint64_t seed) {
    return o3d::capi::fail(O3D_ERROR_UNSUPPORTED, "o3d_trianglemesh_sample_points_uniformly: not implemented yet");
}
o3d_status o3d_trianglemesh_sample_points_poisson_disk(o3d_pointcloud_t** out, const o3d_trianglemesh_t* mesh, size_t number_of_points, double init_factor, int32_t use_triangle_normal, uint64_t seed) {
    return o3d::capi::fail(O3D_ERROR_UNSUPPORTED, "o3d_trianglemesh_sample_points_poisson_disk: not implemented yet");
}
o3d_status o3d_trianglemesh_simplify_vertex_clustering(o3d_trianglemesh_t** out, const o3d_trianglemesh_t* mesh, double voxel_size, int32_t contraction) {
    return o3d::capi::fail(O3D_ERROR_UNSUPPORTED, "o3d_trianglemesh_simplify_vertex_clustering: not implemented yet");
}
o3d_status o3d_trianglemesh_simplify_quadric_decimation(o3d_trianglemesh_t** out, const o3d_trianglemesh_t* mesh, size_t target_number_of_triangles, double maximum_error, double boundary_weight) {
    return o3d::capi::fail(O3D_ERROR_UNSUPPORTED, "o3d_trianglemesh_simplify_quadric_decimation: not implemented yet");
}
o3d_status o3d_trianglemesh_filter_smooth_simple(o3d_trianglemesh_t** out, const o3d_trianglemesh_t* mesh, int32_t number_of_iterations, int32_t filter_scope) {
    return o3d::capi::fail(O3D_ERROR_UNSUPPORTED, "o3d_trianglemesh_filter_smooth_simple: not implemented yet");
}
o3d_status o3d_trianglemesh_filter_smooth_laplacian(o3d_trianglemesh_t** out, const o3d_trianglemesh_t* mesh, int32_t number_of_iterations, double lambda_filter, int32_t filter_scope) {
    return o3d::capi::fail(O3D_ERROR_UNSUPPORTED, "o3d_trianglemesh_filter_smooth_laplacian: not implemented yet");
}
o3d_status o3d_trianglemesh_filter_smooth_taubin(o3d_trianglemesh_t** out, const o3d_trianglemesh_t* mesh, int32_t number_of_iterations, double lambda_filter, double mu, int32_t filter_scope) {
    return o3d::capi::fail(O3D_ERROR_UNSUPPORTED, "o3d_trianglemesh_filter_smooth_taubin: not implemented yet");
}
o3d_status o3d_trianglemesh_subdivide_midpoint(o3d_trianglemesh_t** out, const o3d_trianglemesh_t* mesh, int32_t number_of_iterations) {
    return o3d::capi::fail(O3D_ERROR_UNSUPPORTED, "o3d_trianglemesh_subdivide_midpoint: not implemented yet");
}
o3d_status o3d_trianglemesh_subdivide_loop(o3d_trianglemesh_t** out, const o3d_trianglemesh_t* mesh, int32_t number_of_iterations) {
    return o3d::capi::fail(O3D_ERROR_UNSUPPORTED, "o3d_trianglemesh_subdivide_loop: not implemented yet");
}
o3d_status o3d_trianglemesh_crop_aabb(o3d_trianglemesh_t** out, const o3d_trianglemesh_t* mesh, const double min_bound[3], const double max_bound[3]) {
    return o3d::capi::fail(O3D_ERROR_UNSUPPORTED, "o3d_trianglemesh_crop_aabb: not implemented yet");
}

}  // extern "C"
