/* SPDX-License-Identifier: MIT */
/**
 * @file lineset.h
 * @brief Line sets (o3d.geometry.LineSet): points, lines between them and per-line colors.
 *
 * Points are (N x 3) float64, lines (M x 2) int32 point indices, colors (M x 3) float64 in [0,1], all
 * row-major. As for meshes, lines may hold any int32 values and every operation that follows them
 * checks them first (INVALID_ARGUMENT).
 *
 * **Ownership:** handles written through `o3d_lineset_t** out` belong to the caller
 * (o3d_lineset_destroy). Views are borrowed: valid until the next mutating call or destruction.
 */
#ifndef O3D_LINESET_H
#define O3D_LINESET_H

#include "o3d/common.h"
#include "o3d/types.h"
#include "o3d/boundingbox.h"

O3D_BEGIN_DECL



/** @brief New empty line set. */
O3D_API o3d_status o3d_lineset_create(o3d_lineset_t** out);
/** @brief Destroy. NULL is a no-op. */
O3D_API void o3d_lineset_destroy(o3d_lineset_t* lineset);
/** @brief Deep copy. */
O3D_API o3d_status o3d_lineset_clone(o3d_lineset_t** out, const o3d_lineset_t* src);
/** @brief Number of points. */
O3D_API o3d_status o3d_lineset_num_points(size_t* out_n, const o3d_lineset_t* lineset);
/** @brief Number of lines. */
O3D_API o3d_status o3d_lineset_num_lines(size_t* out_n, const o3d_lineset_t* lineset);
/* ---- Arrays: the same functions for every geometry (docs/conventions.md, "Arrays") ----
 * `which` names the array; rows are counted in items (a point, a line, a descriptor), never in
 * values. Copy-outs take the caller's capacity in rows and always report the rows needed;
 * views are borrowed, valid until the next mutating call on the handle or its destruction. */
#define O3D_LINESET_POINTS 0 /**< N x 3 float64 */
#define O3D_LINESET_COLORS 1 /**< M x 3 RGB in [0,1], one per line */
#define O3D_LINESET_LINES 100 /**< M x 2 int32 point indices */

/**
 * @brief Whether array `which` counts (Open3D's has_*: present and of the matching size).
 * @param out receives 1 or 0. @param lineset the lineset. @param which the array.
 * @return O3D_ERROR_INVALID_ARGUMENT on a NULL pointer or an unknown `which`. Thread-safe on a const handle.
 */
O3D_API o3d_status o3d_lineset_has_array(int32_t* out, const o3d_lineset_t* lineset, int32_t which);
/**
 * @brief Rows and columns (values per row) of array `which`: e.g. N x 3 for points, num x dimension for a
 * feature. @return O3D_ERROR_INVALID_ARGUMENT on a NULL pointer or an unknown `which`. Thread-safe on a const handle.
 */
O3D_API o3d_status o3d_lineset_array_shape(size_t* out_rows, size_t* out_cols, const o3d_lineset_t* lineset, int32_t which);
/**
 * @brief Replace array `which` with `rows` rows of `data`, copied once (`data` may be NULL when rows == 0).
 * @return O3D_ERROR_INVALID_ARGUMENT on a NULL handle, NULL data with rows > 0 or an unknown `which`.
 */
O3D_API o3d_status o3d_lineset_set_array(o3d_lineset_t* lineset, int32_t which, const double* data, size_t rows);
/** @brief As o3d_lineset_set_array from float32 values, converted in the one copy. */
O3D_API o3d_status o3d_lineset_set_array_f32(o3d_lineset_t* lineset, int32_t which, const float* data, size_t rows);
/**
 * @brief Copy array `which` into `out`, which holds `capacity` rows; `*out_rows` always gets the rows
 * needed. `out` NULL only reports them. @return O3D_ERROR_BUFFER_TOO_SMALL when capacity < rows,
 * O3D_ERROR_INVALID_ARGUMENT on a NULL handle or out_rows or an unknown `which`.
 */
O3D_API o3d_status o3d_lineset_get_array(double* out, size_t capacity, size_t* out_rows, const o3d_lineset_t* lineset,
                                         int32_t which);
/**
 * @brief Borrowed read-only view of array `which` (`*out_data` NULL when empty).
 * **Ownership:** the library's; valid until the next mutating call on `lineset` or its destruction.
 */
O3D_API o3d_status o3d_lineset_array_view(const double** out_data, size_t* out_rows, const o3d_lineset_t* lineset,
                                          int32_t which);
/** @brief Borrowed writable view of array `which`: as o3d_lineset_array_view; writing through it is a mutating call. */
O3D_API o3d_status o3d_lineset_array_mutable_view(double** out_data, size_t* out_rows, o3d_lineset_t* lineset,
                                                  int32_t which);
/** @brief Replace int32 array `which` with `rows` rows of `data` (copied once), as o3d_lineset_set_array. */
O3D_API o3d_status o3d_lineset_set_index_array(o3d_lineset_t* lineset, int32_t which, const int32_t* data, size_t rows);
/** @brief Copy int32 array `which` out, with the copy-out rules of o3d_lineset_get_array. */
O3D_API o3d_status o3d_lineset_get_index_array(int32_t* out, size_t capacity, size_t* out_rows,
                                               const o3d_lineset_t* lineset, int32_t which);
/** @brief Borrowed read-only view of int32 array `which` (ownership as o3d_lineset_array_view). */
O3D_API o3d_status o3d_lineset_index_array_view(const int32_t** out_data, size_t* out_rows,
                                                const o3d_lineset_t* lineset, int32_t which);
/** @brief Borrowed writable view of int32 array `which`; writing through it is a mutating call. */
O3D_API o3d_status o3d_lineset_index_array_mutable_view(int32_t** out_data, size_t* out_rows,
                                                        o3d_lineset_t* lineset, int32_t which);

/** @brief Set every line color to `rgb`. */
O3D_API o3d_status o3d_lineset_paint_uniform_color(o3d_lineset_t* lineset, const double rgb[3]);
/** @brief Apply a row-major 4x4 transform to the points. */
O3D_API o3d_status o3d_lineset_transform(o3d_lineset_t* lineset, const double transform[16]);

/**
 * @brief Points of both clouds (first `cloud0`'s, then `cloud1`'s) and one line per correspondence
 * (`pairs`: n_pairs x 2 int32, an index into cloud0 then into cloud1, range-checked).
 * @see LineSet.create_from_point_cloud_correspondences
 */
O3D_API o3d_status o3d_lineset_create_from_point_cloud_correspondences(o3d_lineset_t** out,
                                                                       const o3d_pointcloud_t* cloud0,
                                                                       const o3d_pointcloud_t* cloud1,
                                                                       const int32_t* pairs, size_t n_pairs);
/** @brief The 12 edges of an oriented box (points in get_box_points order). */
O3D_API o3d_status o3d_lineset_create_from_oriented_bounding_box(o3d_lineset_t** out, const o3d_obb_t* obb);
/** @brief The 12 edges of an axis-aligned box. */
O3D_API o3d_status o3d_lineset_create_from_axis_aligned_bounding_box(o3d_lineset_t** out,
                                                                     const double min_bound[3],
                                                                     const double max_bound[3]);
/** @brief The mesh's unique edges (each once), on its vertices. @see LineSet.create_from_triangle_mesh */
O3D_API o3d_status o3d_lineset_create_from_triangle_mesh(o3d_lineset_t** out, const o3d_trianglemesh_t* mesh);

O3D_END_DECL

#endif /* O3D_LINESET_H */
