/* SPDX-License-Identifier: MIT */
/*
 * o3d.i — the ONE SWIG interface shared by the C# and Java bindings.
 *
 * It wraps only the public C headers (capi/include/o3d/*.h) as flat functions in a raw,
 * non-public module class `O3dNative` (internal in C#, package-private in Java). The idiomatic
 * classes (bindings/csharp/src/*.cs, bindings/java/src/main/java/org/o3d/*.java) are written by
 * hand on top of it and are the only public surface.
 *
 * Conventions of the raw layer (the same in both languages):
 *   - opaque handles (o3d_pointcloud_t*, ...) and borrowed pointers are raw addresses
 *     (C# IntPtr, Java long); `T** out` handle/view outputs are `out IntPtr` / `long[1]`;
 *   - arrays are one managed array per call (double[]/float[]/int[]/long[]/byte[]), pinned or
 *     copied once; fixed-size arrays (`double out[16]`) likewise;
 *   - scalar outputs are `out T` in C# and `T[1]` in Java;
 *   - plain structs (options, o3d_correspondence_checker_t, o3d_pose_graph_edge_t, summaries) are
 *     non-public proxy classes; C arrays of them and their fixed-size array members go through the
 *     o3dx_ helpers below (the same in both languages), never through language-specific code;
 *   - ERRORS: every function returning o3d_status goes through the single `ret` typemap below,
 *     which turns a non-OK status plus o3d_last_error_message() into the language's
 *     O3dException (carrying the status). It runs after argout/freearg, so pinned arrays are
 *     always released first. It is on by default; there is no way to turn it off.
 *
 * Language-specific typemaps live in bindings/csharp/o3d_csharp.i and bindings/java/o3d_java.i;
 * each defines the abstract typemap names used here (O3D_IN, O3D_OUT, O3D_SOUT, O3D_PTR,
 * O3D_PTROUT) and the macro O3D_SWIG_RAISE(status, message).
 */
%module O3dNative

%{
#include <stdint.h>
#include <stdlib.h>
#include "o3d/o3d.h"
%}

%include <stdint.i>

#if defined(SWIGCSHARP)
%include "../csharp/o3d_csharp.i"
#elif defined(SWIGJAVA)
%include "../java/o3d_java.i"
#else
#error "o3d.i: only C# and Java are supported"
#endif

/* ---- the single error mechanism ------------------------------------------------------------ */
%typemap(out, canthrow=1) o3d_status %{ $result = $1; %}
%typemap(ret) o3d_status %{
  if ($1 != O3D_OK) {
    O3D_SWIG_RAISE($1, o3d_last_error_message());
  }
%}
/* o3d_last_error_code() returns a status as data, it must not raise. */
%typemap(ret) o3d_status o3d_last_error_code ""

/* ---- sizes of the option structs (their *_init functions need the caller's sizeof) --------- */
%inline %{
static uint32_t o3dx_sizeof_search_param(void) { return (uint32_t)sizeof(o3d_search_param_t); }
static uint32_t o3dx_sizeof_read_options(void) { return (uint32_t)sizeof(o3d_read_options_t); }
static uint32_t o3dx_sizeof_write_options(void) { return (uint32_t)sizeof(o3d_write_options_t); }
static uint32_t o3dx_sizeof_icp_options(void) { return (uint32_t)sizeof(o3d_icp_options_t); }
static uint32_t o3dx_sizeof_mesh_read_options(void) { return (uint32_t)sizeof(o3d_mesh_read_options_t); }
static uint32_t o3dx_sizeof_mesh_write_options(void) { return (uint32_t)sizeof(o3d_mesh_write_options_t); }
static uint32_t o3dx_sizeof_rgbd_options(void) { return (uint32_t)sizeof(o3d_rgbd_options_t); }
static uint32_t o3dx_sizeof_depth_to_cloud_options(void) { return (uint32_t)sizeof(o3d_depth_to_cloud_options_t); }
static uint32_t o3dx_sizeof_correspondence_checker(void) { return (uint32_t)sizeof(o3d_correspondence_checker_t); }
static uint32_t o3dx_sizeof_ransac_options(void) { return (uint32_t)sizeof(o3d_ransac_options_t); }
static uint32_t o3dx_sizeof_fgr_options(void) { return (uint32_t)sizeof(o3d_fgr_options_t); }
static uint32_t o3dx_sizeof_pose_graph_edge(void) { return (uint32_t)sizeof(o3d_pose_graph_edge_t); }
static uint32_t o3dx_sizeof_global_optimization_options(void) { return (uint32_t)sizeof(o3d_global_optimization_options_t); }
static uint32_t o3dx_sizeof_global_optimization_summary(void) { return (uint32_t)sizeof(o3d_global_optimization_summary_t); }
%}

/* ---- opaque handles and raw pointers ------------------------------------------------------- */
%apply SWIGTYPE *O3D_PTR {
  o3d_pointcloud_t *, const o3d_pointcloud_t *,
  o3d_kdtree_t *, const o3d_kdtree_t *,
  o3d_search_result_t *, const o3d_search_result_t *,
  o3d_registration_result_t *, const o3d_registration_result_t *,
  o3d_buffer_t *, const o3d_buffer_t *,
  o3d_trianglemesh_t *, const o3d_trianglemesh_t *,
  o3d_image_t *, const o3d_image_t *,
  o3d_rgbd_image_t *, const o3d_rgbd_image_t *,
  o3d_camera_trajectory_t *, const o3d_camera_trajectory_t *,
  o3d_lineset_t *, const o3d_lineset_t *,
  o3d_voxelgrid_t *, const o3d_voxelgrid_t *,
  o3d_octree_t *, const o3d_octree_t *,
  o3d_feature_t *, const o3d_feature_t *,
  o3d_pose_graph_t *, const o3d_pose_graph_t *,
  void *, o3d_log_callback, o3d_progress_callback
}
%apply SWIGTYPE **O3D_PTROUT {
  o3d_pointcloud_t **, o3d_kdtree_t **, o3d_search_result_t **, o3d_registration_result_t **,
  o3d_buffer_t **, o3d_trianglemesh_t **, o3d_image_t **, o3d_rgbd_image_t **, o3d_camera_trajectory_t **,
  o3d_lineset_t **, o3d_voxelgrid_t **, o3d_octree_t **, o3d_feature_t **, o3d_pose_graph_t **,
  const uint8_t **out_data, uint8_t **out_data, const double **out_data, double **out_data,
  const int32_t **out_data, int32_t **out_data,
  const int64_t **out_offsets, const int32_t **out_indices, const double **out_distances2
}

/* ---- common.h ------------------------------------------------------------------------------ */
%apply uint8_t *O3D_OUT { uint8_t *out }
%apply size_t *O3D_SOUT { size_t *out_size }
%include "o3d/common.h"
%clear uint8_t *out;

/* ---- pointcloud.h -------------------------------------------------------------------------- */
%apply const double *O3D_IN {
  const double *xyz, const double *rgb,
  const double transform[ANY], const double translation[ANY], const double rotation[ANY],
  const double center[ANY], const double direction[ANY], const double camera_location[ANY]
}
%apply const double *O3D_IN { const double rgb[ANY] }
%apply const float *O3D_IN { const float *xyz, const float *rgb }
%apply const int32_t *O3D_IN { const int32_t *indices }
%apply const double *O3D_IN { const double *data } /* set_covariances: n x 9 */
%apply double *O3D_OUT { double *out, double out[ANY], double out_min[ANY], double out_max[ANY] }
%apply int32_t *O3D_SOUT { int32_t *out }
%apply size_t *O3D_SOUT { size_t *out_n }
/* point-cloud tools: boxes in, plane / mean / covariance out, index and label buffers out */
%apply const double *O3D_IN { const double min_bound[ANY], const double max_bound[ANY] }
%apply double *O3D_OUT { double out_plane[ANY], double out_mean[ANY], double out_covariance[ANY] }
%apply int32_t *O3D_OUT { int32_t *out_indices, int32_t *out_labels }
%include "o3d/pointcloud.h"
%clear double *out;
%clear int32_t *out;
%clear int32_t *out_indices;
%clear int32_t *out_labels;

/* ---- kdtree.h ------------------------------------------------------------------------------ */
%apply const double *O3D_IN { const double *queries }
%apply const float *O3D_IN { const float *queries }
%apply int64_t *O3D_OUT { int64_t *out }
%apply int32_t *O3D_OUT { int32_t *out }
%apply double *O3D_OUT { double *out }
%apply size_t *O3D_SOUT { size_t *out_num_queries, size_t *out_total }
%include "o3d/kdtree.h"
%clear int64_t *out;
%clear int32_t *out;
%clear double *out;

/* ---- image.h ------------------------------------------------------------------------------- */
/* Scalars (width, height, ...) are `out T`; the pixel bytes go through one byte[] per call. */
%apply const uint8_t *O3D_IN { const uint8_t *data }
%apply uint8_t *O3D_OUT { uint8_t *out }
%apply int32_t *O3D_SOUT { int32_t *out }
%apply size_t *O3D_SOUT { size_t *out_size }
%include "o3d/image.h"
%clear uint8_t *out;
%clear int32_t *out;

/* ---- camera.h ------------------------------------------------------------------------------ */
/* o3d_pinhole_intrinsic_t is a plain struct: a (non-public) proxy class the hand-written
 * PinholeCameraIntrinsic value converts to and from. Extrinsics are double[16]. */
%apply const double *O3D_IN { const double extrinsic[ANY] }
%apply double *O3D_OUT { double out_extrinsic[ANY] }
%include "o3d/camera.h"

/* ---- trianglemesh.h ------------------------------------------------------------------------ */
/* `out` is both an array (get_array, get_index_array) and a scalar (get_volume, is_watertight, ...)
 * in this header; SWIG matches typemaps by type and name only, so both are arrays here and the
 * idiomatic layers pass a 1-element array for the scalars. */
%apply const double *O3D_IN { const double *data, const double origin[ANY] }
%apply const int32_t *O3D_IN { const int32_t *data }
%apply double *O3D_OUT { double *out, double *out_cluster_area }
%apply int32_t *O3D_OUT { int32_t *out, int32_t *out_triangle_clusters, int32_t *out_cluster_n_triangles }
%apply int64_t *O3D_OUT { int64_t *out }
%apply size_t *O3D_SOUT { size_t *out_rows, size_t *out_num_triangles, size_t *out_num_clusters }
%include "o3d/trianglemesh.h"
%clear double *out;
%clear int32_t *out;
%clear int64_t *out;

/* ---- rgbd.h -------------------------------------------------------------------------------- */
%include "o3d/rgbd.h"

/* ---- io.h ---------------------------------------------------------------------------------- */
%apply const uint8_t *O3D_IN { const uint8_t *data }
%include "o3d/io.h"

/* ---- feature.h ----------------------------------------------------------------------------- */
/* `double *out` (get_data) and `int32_t *out` (correspondence pairs) are arrays; `size_t *out`
 * (dimension, num) is a scalar. Descriptors and xd points come in through `const double *data`. */
%apply const int64_t *O3D_IN { const int64_t *indices }
%apply double *O3D_OUT { double *out }
%apply int32_t *O3D_OUT { int32_t *out }
%apply size_t *O3D_SOUT { size_t *out }
%include "o3d/feature.h"
%clear double *out;
%clear int32_t *out;
%clear size_t *out;

/* ---- registration.h ------------------------------------------------------------------------ */
%apply const double *O3D_IN { const double init[ANY], const double transformation[ANY] }
%apply const int32_t *O3D_IN { const int32_t *corres }
%apply double *O3D_SOUT { double *out }
%apply int32_t *O3D_OUT { int32_t *out }
%apply int32_t *O3D_SOUT { int32_t *out_passed }
%include "o3d/registration.h"
%clear double *out;
%clear int32_t *out;

/* The `checkers, num_checkers` pairs take a C array of o3d_correspondence_checker_t: the idiomatic
 * layers fill each entry through a (non-public) proxy filled by o3d_correspondence_checker_init,
 * copy it in with o3dx_checkers_set, pass the array and free it (in finally). */
%inline %{
/* `n` zeroed checkers (at least one slot, so that n = 0 still gives a valid address); NULL when out of memory. */
static o3d_correspondence_checker_t *o3dx_checkers_new(size_t n) {
  return (o3d_correspondence_checker_t *)calloc(n ? n : 1, sizeof(o3d_correspondence_checker_t));
}
/* Copy `checker` into slot `i` of an array of `n` from o3dx_checkers_new; out-of-range or NULL: no-op. */
static void o3dx_checkers_set(o3d_correspondence_checker_t *checkers, size_t n, size_t i,
                              const o3d_correspondence_checker_t *checker) {
  if (checkers && checker && i < n) checkers[i] = *checker;
}
static void o3dx_checkers_delete(o3d_correspondence_checker_t *checkers) { free(checkers); }
%}

/* ---- posegraph.h --------------------------------------------------------------------------- */
/* o3d_pose_graph_edge_t and o3d_global_optimization_summary_t are plain structs: (non-public) proxy
 * classes; the edge's two matrices are read and written as one flat double[] (below). */
%ignore o3d_pose_graph_edge::transformation;
%ignore o3d_pose_graph_edge::information;
%apply const double *O3D_IN { const double pose[ANY] }
%apply double *O3D_OUT { double out_pose[ANY] }
%apply size_t *O3D_SOUT { size_t *out }
%include "o3d/posegraph.h"
%clear size_t *out;
%apply const double *O3D_IN { const double *values }
%apply double *O3D_OUT { double *out_values }
%inline %{
/* The edge's matrices as 52 doubles: row-major transformation (16), then row-major information (36). */
static void o3dx_pose_graph_edge_set_matrices(o3d_pose_graph_edge_t *edge, const double *values) {
  int i;
  if (!edge || !values) return;
  for (i = 0; i < 16; ++i) edge->transformation[i] = values[i];
  for (i = 0; i < 36; ++i) edge->information[i] = values[16 + i];
}
static void o3dx_pose_graph_edge_get_matrices(const o3d_pose_graph_edge_t *edge, double *out_values) {
  int i;
  if (!edge || !out_values) return;
  for (i = 0; i < 16; ++i) out_values[i] = edge->transformation[i];
  for (i = 0; i < 36; ++i) out_values[16 + i] = edge->information[i];
}
%}

/* ---- boundingbox.h, hull.h, lineset.h, voxelgrid.h, octree.h ---------------------------------- */
/* o3d_obb_t and o3d_octree_node_info_t are frozen-layout value structs: (non-public) proxy classes
 * whose fixed-size array members are read and written as one flat double[] through the o3dx_ helpers
 * below (SWIG would otherwise expose them as opaque double pointers). */
%ignore o3d_obb::center;
%ignore o3d_obb::R;
%ignore o3d_obb::extent;
%ignore o3d_octree_node_info::origin;
%apply const double *O3D_IN { const double *values, const double point[ANY] }
%apply double *O3D_OUT { double *out_values, double out_origin[ANY], double out_color[ANY] }
%inline %{
/* The box as 15 doubles: center (3), row-major R (9), extent (3). */
static void o3dx_obb_set(o3d_obb_t *obb, const double *values) {
  int i;
  if (!obb || !values) return;
  for (i = 0; i < 3; ++i) obb->center[i] = values[i];
  for (i = 0; i < 9; ++i) obb->R[i] = values[3 + i];
  for (i = 0; i < 3; ++i) obb->extent[i] = values[12 + i];
}
static void o3dx_obb_get(const o3d_obb_t *obb, double *out_values) {
  int i;
  if (!obb || !out_values) return;
  for (i = 0; i < 3; ++i) out_values[i] = obb->center[i];
  for (i = 0; i < 9; ++i) out_values[3 + i] = obb->R[i];
  for (i = 0; i < 3; ++i) out_values[12 + i] = obb->extent[i];
}
/* The node cube's min corner (3 doubles). */
static void o3dx_octree_node_info_origin(const o3d_octree_node_info_t *info, double *out_values) {
  int i;
  if (!info || !out_values) return;
  for (i = 0; i < 3; ++i) out_values[i] = info->origin[i];
}
%}

%apply double *O3D_OUT { double *out, double out[ANY], double *out_colors }
%apply int32_t *O3D_OUT { int32_t *out, int32_t *out_indices, int32_t *out_point_indices,
                          int32_t *out_grid_index, int32_t out_index[ANY], int32_t *out_included }
%apply const int32_t *O3D_IN { const int32_t *pairs }
%include "o3d/boundingbox.h"

%include "o3d/lineset.h"
%clear double *out;
/* voxelgrid.h / octree.h: `double *out` and the root's size / depth / found flag are scalars */
%apply double *O3D_SOUT { double *out, double *out_size }
%apply int32_t *O3D_SOUT { int32_t *out_max_depth, int32_t *out_found }
%include "o3d/voxelgrid.h"
%include "o3d/octree.h"
%clear double *out;
%clear int32_t *out;
%clear int32_t *out_indices;
