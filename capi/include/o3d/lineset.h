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
 *
 * **Out of memory:** any function here that allocates may also return O3D_ERROR_OUT_OF_MEMORY; the
 * per-function `@return` lists do not repeat it.
 */
#ifndef O3D_LINESET_H
#define O3D_LINESET_H

#include "o3d/common.h"
#include "o3d/types.h"
#include "o3d/boundingbox.h"

O3D_BEGIN_DECL



/**
 * @brief New empty line set.
 *
 * Threads: any thread.
 * Ownership: `*out` is the caller's, to free with o3d_lineset_destroy(); left NULL on failure.
 * @param out receives the new handle (NULL on failure)
 * @return O3D_OK, or O3D_ERROR_INVALID_ARGUMENT on a NULL pointer.
 */
O3D_API o3d_status o3d_lineset_create(o3d_lineset_t** out);
/**
 * @brief Destroy. NULL is a no-op.
 *
 * Threads: needs exclusive access to `lineset`: no other call may use it during or after.
 * @param lineset the handle to destroy (NULL is a no-op)
 */
O3D_API void o3d_lineset_destroy(o3d_lineset_t* lineset);
/**
 * @brief Deep copy.
 *
 * Threads: any thread; concurrent calls on the same handles are safe (all read-only).
 * Ownership: `*out` is the caller's, to free with o3d_lineset_destroy(); left NULL on failure.
 * @param out receives the new handle (NULL on failure)
 * @param src the handle to copy
 * @return O3D_OK, or O3D_ERROR_INVALID_ARGUMENT on a NULL pointer.
 */
O3D_API o3d_status o3d_lineset_clone(o3d_lineset_t** out, const o3d_lineset_t* src);
/**
 * @brief Number of points.
 *
 * Threads: any thread; concurrent calls on the same handles are safe (all read-only).
 * @param out_n receives the count
 * @param lineset the line set
 * @return O3D_OK, or O3D_ERROR_INVALID_ARGUMENT on a NULL pointer.
 */
O3D_API o3d_status o3d_lineset_num_points(size_t* out_n, const o3d_lineset_t* lineset);
/**
 * @brief Number of lines.
 *
 * Threads: any thread; concurrent calls on the same handles are safe (all read-only).
 * @param out_n receives the count
 * @param lineset the line set
 * @return O3D_OK, or O3D_ERROR_INVALID_ARGUMENT on a NULL pointer.
 */
O3D_API o3d_status o3d_lineset_num_lines(size_t* out_n, const o3d_lineset_t* lineset);
/* ---- Arrays: the same functions for every geometry (docs/conventions.md, "Arrays") ----
 * `which` names the array; rows are counted in items (a point, a line, a descriptor), never in
 * values. Copy-outs take the caller's capacity in rows and always report the rows needed;
 * views are borrowed, valid until the next mutating call on the handle or its destruction. */
/** The arrays of a line set (O3D_LINESET_*). */
typedef int32_t o3d_lineset_array;
#define O3D_LINESET_POINTS 0 /**< N x 3 float64 */
#define O3D_LINESET_COLORS 1 /**< M x 3 RGB in [0,1], one per line */
#define O3D_LINESET_LINES 100 /**< M x 2 int32 point indices */

/**
 * @brief Whether array `which` counts (Open3D's has_*: present and of the matching size).
 *
 * Threads: any thread; concurrent calls on the same handles are safe (all read-only).
 * @param out receives 1 (true) or 0 (false)
 * @param lineset the line set
 * @param which the array: one of this header's `which` constants
 * @return O3D_OK, or O3D_ERROR_INVALID_ARGUMENT on a NULL pointer or an unknown `which`.
 */
O3D_API o3d_status o3d_lineset_has_array(int32_t* out, const o3d_lineset_t* lineset, o3d_lineset_array which);
/**
 * @brief Rows and columns (values per row) of array `which`: e.g. N x 3 for points, num x dimension for a
 * feature.
 *
 * Threads: any thread; concurrent calls on the same handles are safe (all read-only).
 * @param out_rows receives the rows (items)
 * @param out_cols receives the values per row
 * @param lineset the line set
 * @param which the array: one of this header's `which` constants
 * @return O3D_OK, or O3D_ERROR_INVALID_ARGUMENT on a NULL pointer or an unknown `which`.
 */
O3D_API o3d_status o3d_lineset_array_shape(size_t* out_rows, size_t* out_cols, const o3d_lineset_t* lineset, o3d_lineset_array which);
/**
 * @brief Replace array `which` with `rows` rows of `data`, copied once (`data` may be NULL when rows == 0).
 *
 * Threads: needs exclusive access to `lineset`.
 * @param lineset the line set
 * @param which the array: one of this header's `which` constants
 * @param data `rows` rows of values, copied once (NULL allowed when rows == 0)
 * @param rows number of rows in `data`
 * @return O3D_OK, or O3D_ERROR_INVALID_ARGUMENT on a NULL handle, an unknown `which`, NULL `data` with rows > 0 or an
 *   unknown `which` (or one of the other type).
 */
O3D_API o3d_status o3d_lineset_set_array(o3d_lineset_t* lineset, o3d_lineset_array which, const double* data, size_t rows);
/**
 * @brief As o3d_lineset_set_array from float32 values, converted in the one copy.
 *
 * Threads: needs exclusive access to `lineset`.
 * @param lineset the line set
 * @param which the array: one of this header's `which` constants
 * @param data `rows` rows of values, copied once (NULL allowed when rows == 0)
 * @param rows number of rows in `data`
 * @return O3D_OK, or O3D_ERROR_INVALID_ARGUMENT on a NULL handle, an unknown `which`, NULL `data` with rows > 0, an
 *   unknown `which` (or one of the other type) or an array that takes no float32.
 */
O3D_API o3d_status o3d_lineset_set_array_f32(o3d_lineset_t* lineset, o3d_lineset_array which, const float* data, size_t rows);
/**
 * @brief Copy array `which` into `out`, which holds `capacity` rows; `*out_rows` always gets the rows
 * needed. `out` NULL only reports them.
 *
 * Threads: any thread; concurrent calls on the same handles are safe (all read-only).
 * @param out caller buffer of `capacity` rows (NULL: only report the row count)
 * @param capacity rows `out` holds
 * @param out_rows receives the rows of the array (always, also when `out` is NULL or too small)
 * @param lineset the line set
 * @param which the array: one of this header's `which` constants
 * @return O3D_OK, or O3D_ERROR_INVALID_ARGUMENT on a NULL handle or `out_rows` or an unknown `which`;
 *   O3D_ERROR_BUFFER_TOO_SMALL when `capacity` is short (the count is still reported).
 */
O3D_API o3d_status o3d_lineset_get_array(double* out, size_t capacity, size_t* out_rows, const o3d_lineset_t* lineset,
                                         o3d_lineset_array which);
/**
 * @brief Borrowed read-only view of array `which` (`*out_data` NULL when empty).
 *
 * Threads: any thread; concurrent calls on the same handles are safe (all read-only).
 * Ownership: `*out_data` points into `lineset` (the library's memory, never to be freed): valid until the next
 * mutating call on `lineset` or its destruction.
 * @param out_data receives the address of row 0 (NULL when the array is empty)
 * @param out_rows receives the row count
 * @param lineset the line set
 * @param which the array: one of this header's `which` constants
 * @return O3D_OK, or O3D_ERROR_INVALID_ARGUMENT on a NULL handle, `out_data` or `out_rows` or an unknown `which`.
 */
O3D_API o3d_status o3d_lineset_array_view(const double** out_data, size_t* out_rows, const o3d_lineset_t* lineset,
                                          o3d_lineset_array which);
/**
 * @brief Borrowed writable view of array `which`: as o3d_lineset_array_view; writing through it is a mutating call.
 *
 * Threads: needs exclusive access to `lineset`, also while the view is written through.
 * Ownership: `*out_data` points into `lineset` (the library's memory, never to be freed): valid until the next
 * mutating call on `lineset` or its destruction.
 * @param out_data receives the address of row 0 (NULL when the array is empty)
 * @param out_rows receives the row count
 * @param lineset the line set
 * @param which the array: one of this header's `which` constants
 * @return O3D_OK, or O3D_ERROR_INVALID_ARGUMENT on a NULL handle, `out_data` or `out_rows` or an unknown `which`.
 */
O3D_API o3d_status o3d_lineset_array_mutable_view(double** out_data, size_t* out_rows, o3d_lineset_t* lineset,
                                                  o3d_lineset_array which);
/**
 * @brief Replace int32 array `which` with `rows` rows of `data` (copied once), as o3d_lineset_set_array.
 *
 * Threads: needs exclusive access to `lineset`.
 * @param lineset the line set
 * @param which the array: one of this header's `which` constants
 * @param data `rows` rows of values, copied once (NULL allowed when rows == 0)
 * @param rows number of rows in `data`
 * @return O3D_OK, or O3D_ERROR_INVALID_ARGUMENT on a NULL handle, an unknown `which`, NULL `data` with rows > 0 or an
 *   unknown `which` (or one of the other type).
 */
O3D_API o3d_status o3d_lineset_set_index_array(o3d_lineset_t* lineset, o3d_lineset_array which, const int32_t* data, size_t rows);
/**
 * @brief Copy int32 array `which` out, with the copy-out rules of o3d_lineset_get_array.
 *
 * Threads: any thread; concurrent calls on the same handles are safe (all read-only).
 * @param out caller buffer of `capacity` rows (NULL: only report the row count)
 * @param capacity rows `out` holds
 * @param out_rows receives the rows of the array (always, also when `out` is NULL or too small)
 * @param lineset the line set
 * @param which the array: one of this header's `which` constants
 * @return O3D_OK, or O3D_ERROR_INVALID_ARGUMENT on a NULL handle or `out_rows` or an unknown `which`;
 *   O3D_ERROR_BUFFER_TOO_SMALL when `capacity` is short (the count is still reported).
 */
O3D_API o3d_status o3d_lineset_get_index_array(int32_t* out, size_t capacity, size_t* out_rows,
                                               const o3d_lineset_t* lineset, o3d_lineset_array which);
/**
 * @brief Borrowed read-only view of int32 array `which` (ownership as o3d_lineset_array_view).
 *
 * Threads: any thread; concurrent calls on the same handles are safe (all read-only).
 * Ownership: `*out_data` points into `lineset` (the library's memory, never to be freed): valid until the next
 * mutating call on `lineset` or its destruction.
 * @param out_data receives the address of row 0 (NULL when the array is empty)
 * @param out_rows receives the row count
 * @param lineset the line set
 * @param which the array: one of this header's `which` constants
 * @return O3D_OK, or O3D_ERROR_INVALID_ARGUMENT on a NULL handle, `out_data` or `out_rows` or an unknown `which`.
 */
O3D_API o3d_status o3d_lineset_index_array_view(const int32_t** out_data, size_t* out_rows,
                                                const o3d_lineset_t* lineset, o3d_lineset_array which);
/**
 * @brief Borrowed writable view of int32 array `which`; writing through it is a mutating call.
 *
 * Threads: needs exclusive access to `lineset`, also while the view is written through.
 * Ownership: `*out_data` points into `lineset` (the library's memory, never to be freed): valid until the next
 * mutating call on `lineset` or its destruction.
 * @param out_data receives the address of row 0 (NULL when the array is empty)
 * @param out_rows receives the row count
 * @param lineset the line set
 * @param which the array: one of this header's `which` constants
 * @return O3D_OK, or O3D_ERROR_INVALID_ARGUMENT on a NULL handle, `out_data` or `out_rows` or an unknown `which`.
 */
O3D_API o3d_status o3d_lineset_index_array_mutable_view(int32_t** out_data, size_t* out_rows,
                                                        o3d_lineset_t* lineset, o3d_lineset_array which);

/**
 * @brief Set every line color to `rgb`.
 *
 * Threads: needs exclusive access to `lineset`.
 * @param lineset the line set
 * @param rgb the color, each channel in [0,1]
 * @return O3D_OK, or O3D_ERROR_INVALID_ARGUMENT on a NULL pointer.
 */
O3D_API o3d_status o3d_lineset_paint_uniform_color(o3d_lineset_t* lineset, const double rgb[3]);
/**
 * @brief Apply a row-major 4x4 transform to the points.
 *
 * Threads: needs exclusive access to `lineset`.
 * @param lineset the line set
 * @param transform row-major 4x4 transform
 * @return O3D_OK, or O3D_ERROR_INVALID_ARGUMENT on a NULL pointer.
 */
O3D_API o3d_status o3d_lineset_transform(o3d_lineset_t* lineset, const double transform[16]);

/**
 * @brief Points of both clouds (first `cloud0`'s, then `cloud1`'s) and one line per correspondence
 * (`pairs`: n_pairs x 2 int32, an index into cloud0 then into cloud1, range-checked).
 * @see LineSet.create_from_point_cloud_correspondences
 *
 * Threads: any thread; concurrent calls on the same handles are safe (all read-only).
 * Ownership: `*out` is the caller's, to free with o3d_lineset_destroy(); left NULL on failure.
 * @param out receives the new handle (NULL on failure)
 * @param cloud0 the first cloud
 * @param cloud1 the second cloud
 * @param pairs n_pairs x 2 int32 (index into cloud0, index into cloud1)
 * @param n_pairs number of pairs
 * @return O3D_OK, or O3D_ERROR_INVALID_ARGUMENT on a NULL pointer.
 */
O3D_API o3d_status o3d_lineset_create_from_point_cloud_correspondences(o3d_lineset_t** out,
                                                                       const o3d_pointcloud_t* cloud0,
                                                                       const o3d_pointcloud_t* cloud1,
                                                                       const int32_t* pairs, size_t n_pairs);
/**
 * @brief The 12 edges of an oriented box (points in get_box_points order).
 *
 * Threads: any thread.
 * Ownership: `*out` is the caller's, to free with o3d_lineset_destroy(); left NULL on failure.
 * @param out receives the new handle (NULL on failure)
 * @param obb the oriented box
 * @return O3D_OK, or O3D_ERROR_INVALID_ARGUMENT on a NULL pointer.
 */
O3D_API o3d_status o3d_lineset_create_from_oriented_bounding_box(o3d_lineset_t** out, const o3d_obb_t* obb);
/**
 * @brief The 12 edges of an axis-aligned box.
 *
 * Threads: any thread.
 * Ownership: `*out` is the caller's, to free with o3d_lineset_destroy(); left NULL on failure.
 * @param out receives the new handle (NULL on failure)
 * @param min_bound minimum corner (x, y, z)
 * @param max_bound maximum corner (x, y, z)
 * @return O3D_OK, or O3D_ERROR_INVALID_ARGUMENT on a NULL pointer.
 */
O3D_API o3d_status o3d_lineset_create_from_axis_aligned_bounding_box(o3d_lineset_t** out,
                                                                     const double min_bound[3],
                                                                     const double max_bound[3]);
/**
 * @brief The mesh's unique edges (each once), on its vertices. @see LineSet.create_from_triangle_mesh
 *
 * Threads: any thread; concurrent calls on the same handles are safe (all read-only).
 * Ownership: `*out` is the caller's, to free with o3d_lineset_destroy(); left NULL on failure.
 * @param out receives the new handle (NULL on failure)
 * @param mesh the mesh
 * @return O3D_OK, or O3D_ERROR_INVALID_ARGUMENT on a NULL pointer.
 */
O3D_API o3d_status o3d_lineset_create_from_triangle_mesh(o3d_lineset_t** out, const o3d_trianglemesh_t* mesh);

O3D_END_DECL

#endif /* O3D_LINESET_H */
