// SPDX-License-Identifier: MIT
// C API stubs: replaced by the implementation (each fails with O3D_ERROR_UNSUPPORTED until then).
#include "internal.h"
#include "o3d/o3d.h"

extern "C" {

o3d_status o3d_trianglemesh_create(o3d_trianglemesh_t** out) {
    return o3d::capi::fail(O3D_ERROR_UNSUPPORTED, "o3d_trianglemesh_create: not implemented yet");
}
void o3d_trianglemesh_destroy(o3d_trianglemesh_t* mesh) { delete mesh; }
o3d_status o3d_trianglemesh_clone(o3d_trianglemesh_t** out, const o3d_trianglemesh_t* src) {
    return o3d::capi::fail(O3D_ERROR_UNSUPPORTED, "o3d_trianglemesh_clone: not implemented yet");
}
o3d_status o3d_trianglemesh_clear(o3d_trianglemesh_t* mesh) {
    return o3d::capi::fail(O3D_ERROR_UNSUPPORTED, "o3d_trianglemesh_clear: not implemented yet");
}
o3d_status o3d_trianglemesh_num_vertices(const o3d_trianglemesh_t* mesh, size_t* out_n) {
    return o3d::capi::fail(O3D_ERROR_UNSUPPORTED, "o3d_trianglemesh_num_vertices: not implemented yet");
}
o3d_status o3d_trianglemesh_num_triangles(const o3d_trianglemesh_t* mesh, size_t* out_n) {
    return o3d::capi::fail(O3D_ERROR_UNSUPPORTED, "o3d_trianglemesh_num_triangles: not implemented yet");
}
o3d_status o3d_trianglemesh_has_array(const o3d_trianglemesh_t* mesh, int32_t which, int32_t* out) {
    return o3d::capi::fail(O3D_ERROR_UNSUPPORTED, "o3d_trianglemesh_has_array: not implemented yet");
}
o3d_status o3d_trianglemesh_set_array(o3d_trianglemesh_t* mesh, int32_t which, const double* data, size_t rows) {
    return o3d::capi::fail(O3D_ERROR_UNSUPPORTED, "o3d_trianglemesh_set_array: not implemented yet");
}
o3d_status o3d_trianglemesh_get_array(const o3d_trianglemesh_t* mesh, int32_t which, double* out, size_t capacity, size_t* out_rows) {
    return o3d::capi::fail(O3D_ERROR_UNSUPPORTED, "o3d_trianglemesh_get_array: not implemented yet");
}
o3d_status o3d_trianglemesh_array_view(const o3d_trianglemesh_t* mesh, int32_t which, const double** out_data, size_t* out_rows) {
    return o3d::capi::fail(O3D_ERROR_UNSUPPORTED, "o3d_trianglemesh_array_view: not implemented yet");
}
o3d_status o3d_trianglemesh_array_mutable_view(o3d_trianglemesh_t* mesh, int32_t which, double** out_data, size_t* out_rows) {
    return o3d::capi::fail(O3D_ERROR_UNSUPPORTED, "o3d_trianglemesh_array_mutable_view: not implemented yet");
}
o3d_status o3d_trianglemesh_set_index_array(o3d_trianglemesh_t* mesh, int32_t which, const int32_t* data, size_t rows) {
    return o3d::capi::fail(O3D_ERROR_UNSUPPORTED, "o3d_trianglemesh_set_index_array: not implemented yet");
}
o3d_status o3d_trianglemesh_get_index_array(const o3d_trianglemesh_t* mesh, int32_t which, int32_t* out, size_t capacity, size_t* out_rows) {
    return o3d::capi::fail(O3D_ERROR_UNSUPPORTED, "o3d_trianglemesh_get_index_array: not implemented yet");
}
o3d_status o3d_trianglemesh_index_array_view(const o3d_trianglemesh_t* mesh, int32_t which, const int32_t** out_data, size_t* out_rows) {
    return o3d::capi::fail(O3D_ERROR_UNSUPPORTED, "o3d_trianglemesh_index_array_view: not implemented yet");
}
o3d_status o3d_trianglemesh_index_array_mutable_view(o3d_trianglemesh_t* mesh, int32_t which, int32_t** out_data, size_t* out_rows) {
    return o3d::capi::fail(O3D_ERROR_UNSUPPORTED, "o3d_trianglemesh_index_array_mutable_view: not implemented yet");
}
o3d_status o3d_trianglemesh_texture_count(const o3d_trianglemesh_t* mesh, size_t* out_n) {
    return o3d::capi::fail(O3D_ERROR_UNSUPPORTED, "o3d_trianglemesh_texture_count: not implemented yet");
}
o3d_status o3d_trianglemesh_get_texture(o3d_image_t** out, const o3d_trianglemesh_t* mesh, size_t index) {
    return o3d::capi::fail(O3D_ERROR_UNSUPPORTED, "o3d_trianglemesh_get_texture: not implemented yet");
}
o3d_status o3d_trianglemesh_add_texture(o3d_trianglemesh_t* mesh, const o3d_image_t* image) {
    return o3d::capi::fail(O3D_ERROR_UNSUPPORTED, "o3d_trianglemesh_add_texture: not implemented yet");
}
o3d_status o3d_trianglemesh_clear_textures(o3d_trianglemesh_t* mesh) {
    return o3d::capi::fail(O3D_ERROR_UNSUPPORTED, "o3d_trianglemesh_clear_textures: not implemented yet");
}
o3d_status o3d_trianglemesh_append(o3d_trianglemesh_t* mesh, const o3d_trianglemesh_t* other) {
    return o3d::capi::fail(O3D_ERROR_UNSUPPORTED, "o3d_trianglemesh_append: not implemented yet");
}
o3d_status o3d_trianglemesh_compute_vertex_normals(o3d_trianglemesh_t* mesh, int32_t normalized) {
    return o3d::capi::fail(O3D_ERROR_UNSUPPORTED, "o3d_trianglemesh_compute_vertex_normals: not implemented yet");
}
o3d_status o3d_trianglemesh_compute_triangle_normals(o3d_trianglemesh_t* mesh, int32_t normalized) {
    return o3d::capi::fail(O3D_ERROR_UNSUPPORTED, "o3d_trianglemesh_compute_triangle_normals: not implemented yet");
}
o3d_status o3d_trianglemesh_normalize_normals(o3d_trianglemesh_t* mesh) {
    return o3d::capi::fail(O3D_ERROR_UNSUPPORTED, "o3d_trianglemesh_normalize_normals: not implemented yet");
}
o3d_status o3d_trianglemesh_paint_uniform_color(o3d_trianglemesh_t* mesh, const double rgb[3]) {
    return o3d::capi::fail(O3D_ERROR_UNSUPPORTED, "o3d_trianglemesh_paint_uniform_color: not implemented yet");
}
o3d_status o3d_trianglemesh_transform(o3d_trianglemesh_t* mesh, const double transform[16]) {
    return o3d::capi::fail(O3D_ERROR_UNSUPPORTED, "o3d_trianglemesh_transform: not implemented yet");
}
o3d_status o3d_trianglemesh_translate(o3d_trianglemesh_t* mesh, const double translation[3], int32_t relative) {
    return o3d::capi::fail(O3D_ERROR_UNSUPPORTED, "o3d_trianglemesh_translate: not implemented yet");
}
o3d_status o3d_trianglemesh_rotate(o3d_trianglemesh_t* mesh, const double rotation[9], const double center[3]) {
    return o3d::capi::fail(O3D_ERROR_UNSUPPORTED, "o3d_trianglemesh_rotate: not implemented yet");
}
o3d_status o3d_trianglemesh_scale(o3d_trianglemesh_t* mesh, double scale, const double center[3]) {
    return o3d::capi::fail(O3D_ERROR_UNSUPPORTED, "o3d_trianglemesh_scale: not implemented yet");
}
o3d_status o3d_trianglemesh_get_min_bound(const o3d_trianglemesh_t* mesh, double out[3]) {
    return o3d::capi::fail(O3D_ERROR_UNSUPPORTED, "o3d_trianglemesh_get_min_bound: not implemented yet");
}
o3d_status o3d_trianglemesh_get_max_bound(const o3d_trianglemesh_t* mesh, double out[3]) {
    return o3d::capi::fail(O3D_ERROR_UNSUPPORTED, "o3d_trianglemesh_get_max_bound: not implemented yet");
}
o3d_status o3d_trianglemesh_get_center(const o3d_trianglemesh_t* mesh, double out[3]) {
    return o3d::capi::fail(O3D_ERROR_UNSUPPORTED, "o3d_trianglemesh_get_center: not implemented yet");
}
o3d_status o3d_trianglemesh_get_axis_aligned_bounding_box(const o3d_trianglemesh_t* mesh, double out_min[3], double out_max[3]) {
    return o3d::capi::fail(O3D_ERROR_UNSUPPORTED, "o3d_trianglemesh_get_axis_aligned_bounding_box: not implemented yet");
}
o3d_status o3d_trianglemesh_remove_duplicated_vertices(o3d_trianglemesh_t* mesh) {
    return o3d::capi::fail(O3D_ERROR_UNSUPPORTED, "o3d_trianglemesh_remove_duplicated_vertices: not implemented yet");
}
o3d_status o3d_trianglemesh_remove_duplicated_triangles(o3d_trianglemesh_t* mesh) {
    return o3d::capi::fail(O3D_ERROR_UNSUPPORTED, "o3d_trianglemesh_remove_duplicated_triangles: not implemented yet");
}
o3d_status o3d_trianglemesh_remove_degenerate_triangles(o3d_trianglemesh_t* mesh) {
    return o3d::capi::fail(O3D_ERROR_UNSUPPORTED, "o3d_trianglemesh_remove_degenerate_triangles: not implemented yet");
}
o3d_status o3d_trianglemesh_remove_unreferenced_vertices(o3d_trianglemesh_t* mesh) {
    return o3d::capi::fail(O3D_ERROR_UNSUPPORTED, "o3d_trianglemesh_remove_unreferenced_vertices: not implemented yet");
}
o3d_status o3d_trianglemesh_remove_non_manifold_edges(o3d_trianglemesh_t* mesh) {
    return o3d::capi::fail(O3D_ERROR_UNSUPPORTED, "o3d_trianglemesh_remove_non_manifold_edges: not implemented yet");
}
o3d_status o3d_trianglemesh_merge_close_vertices(o3d_trianglemesh_t* mesh, double eps) {
    return o3d::capi::fail(O3D_ERROR_UNSUPPORTED, "o3d_trianglemesh_merge_close_vertices: not implemented yet");
}
o3d_status o3d_trianglemesh_get_surface_area(const o3d_trianglemesh_t* mesh, double* out) {
    return o3d::capi::fail(O3D_ERROR_UNSUPPORTED, "o3d_trianglemesh_get_surface_area: not implemented yet");
}
o3d_status o3d_trianglemesh_get_volume(const o3d_trianglemesh_t* mesh, double* out) {
    return o3d::capi::fail(O3D_ERROR_UNSUPPORTED, "o3d_trianglemesh_get_volume: not implemented yet");
}
o3d_status o3d_trianglemesh_is_watertight(const o3d_trianglemesh_t* mesh, int32_t* out) {
    return o3d::capi::fail(O3D_ERROR_UNSUPPORTED, "o3d_trianglemesh_is_watertight: not implemented yet");
}
o3d_status o3d_trianglemesh_is_edge_manifold(const o3d_trianglemesh_t* mesh, int32_t allow_boundary_edges, int32_t* out) {
    return o3d::capi::fail(O3D_ERROR_UNSUPPORTED, "o3d_trianglemesh_is_edge_manifold: not implemented yet");
}
o3d_status o3d_trianglemesh_is_vertex_manifold(const o3d_trianglemesh_t* mesh, int32_t* out) {
    return o3d::capi::fail(O3D_ERROR_UNSUPPORTED, "o3d_trianglemesh_is_vertex_manifold: not implemented yet");
}
o3d_status o3d_trianglemesh_is_self_intersecting(const o3d_trianglemesh_t* mesh, int32_t* out) {
    return o3d::capi::fail(O3D_ERROR_UNSUPPORTED, "o3d_trianglemesh_is_self_intersecting: not implemented yet");
}
o3d_status o3d_trianglemesh_is_orientable(const o3d_trianglemesh_t* mesh, int32_t* out) {
    return o3d::capi::fail(O3D_ERROR_UNSUPPORTED, "o3d_trianglemesh_is_orientable: not implemented yet");
}
o3d_status o3d_trianglemesh_euler_poincare_characteristic(const o3d_trianglemesh_t* mesh, int64_t* out) {
    return o3d::capi::fail(O3D_ERROR_UNSUPPORTED, "o3d_trianglemesh_euler_poincare_characteristic: not implemented yet");
}
o3d_status o3d_trianglemesh_cluster_connected_triangles(const o3d_trianglemesh_t* mesh, int32_t* out_triangle_clusters, int32_t* out_cluster_n_triangles, double* out_cluster_area, size_t capacity, size_t* out_num_triangles, size_t* out_num_clusters) {
    return o3d::capi::fail(O3D_ERROR_UNSUPPORTED, "o3d_trianglemesh_cluster_connected_triangles: not implemented yet");
}
o3d_status o3d_trianglemesh_create_box(o3d_trianglemesh_t** out, double width, double height, double depth) {
    return o3d::capi::fail(O3D_ERROR_UNSUPPORTED, "o3d_trianglemesh_create_box: not implemented yet");
}
o3d_status o3d_trianglemesh_create_sphere(o3d_trianglemesh_t** out, double radius, int32_t resolution) {
    return o3d::capi::fail(O3D_ERROR_UNSUPPORTED, "o3d_trianglemesh_create_sphere: not implemented yet");
}
o3d_status o3d_trianglemesh_create_cylinder(o3d_trianglemesh_t** out, double radius, double height, int32_t resolution, int32_t split) {
    return o3d::capi::fail(O3D_ERROR_UNSUPPORTED, "o3d_trianglemesh_create_cylinder: not implemented yet");
}
o3d_status o3d_trianglemesh_create_cone(o3d_trianglemesh_t** out, double radius, double height, int32_t resolution, int32_t split) {
    return o3d::capi::fail(O3D_ERROR_UNSUPPORTED, "o3d_trianglemesh_create_cone: not implemented yet");
}
o3d_status o3d_trianglemesh_create_torus(o3d_trianglemesh_t** out, double torus_radius, double tube_radius, int32_t radial_resolution, int32_t tubular_resolution) {
    return o3d::capi::fail(O3D_ERROR_UNSUPPORTED, "o3d_trianglemesh_create_torus: not implemented yet");
}
o3d_status o3d_trianglemesh_create_arrow(o3d_trianglemesh_t** out, double cylinder_radius, double cone_radius, double cylinder_height, double cone_height, int32_t resolution, int32_t cylinder_split, int32_t cone_split) {
    return o3d::capi::fail(O3D_ERROR_UNSUPPORTED, "o3d_trianglemesh_create_arrow: not implemented yet");
}
o3d_status o3d_trianglemesh_create_coordinate_frame(o3d_trianglemesh_t** out, double size, const double origin[3]) {
    return o3d::capi::fail(O3D_ERROR_UNSUPPORTED, "o3d_trianglemesh_create_coordinate_frame: not implemented yet");
}
o3d_status o3d_trianglemesh_create_tetrahedron(o3d_trianglemesh_t** out, double radius) {
    return o3d::capi::fail(O3D_ERROR_UNSUPPORTED, "o3d_trianglemesh_create_tetrahedron: not implemented yet");
}
o3d_status o3d_trianglemesh_create_octahedron(o3d_trianglemesh_t** out, double radius) {
    return o3d::capi::fail(O3D_ERROR_UNSUPPORTED, "o3d_trianglemesh_create_octahedron: not implemented yet");
}
o3d_status o3d_trianglemesh_create_icosahedron(o3d_trianglemesh_t** out, double radius) {
    return o3d::capi::fail(O3D_ERROR_UNSUPPORTED, "o3d_trianglemesh_create_icosahedron: not implemented yet");
}

}  // extern "C"
