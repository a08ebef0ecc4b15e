/* SPDX-License-Identifier: MIT */
/**
 * @file tetramesh.h
 * @brief Tetrahedral meshes (o3d.geometry.TetraMesh): vertices and tetrahedra, the 3-D Delaunay
 * tetrahedralization of a point cloud (through Qhull) and iso-surfaces of per-vertex values.
 *
 * Vertices are (N x 3) float64, tetras (M x 4) int32 vertex indices, row-major. Tetras may hold any int32
 * values: every operation that follows them checks them first (INVALID_ARGUMENT).
 *
 * **Ownership:** handles written through `o3d_tetramesh_t** out` belong to the caller
 * (o3d_tetramesh_destroy). Views are borrowed: valid until the next mutating call or destruction.
 *
 * **Out of memory:** any function here that allocates may also return O3D_ERROR_OUT_OF_MEMORY; the
 * per-function `@return` lists do not repeat it.
 */
#ifndef O3D_TETRAMESH_H
#define O3D_TETRAMESH_H

#include "o3d/common.h"
#include "o3d/types.h"

O3D_BEGIN_DECL

/**
 * @brief New empty tetra mesh.
 *
 * Threads: any thread.
 * Ownership: `*out` is the caller's, to free with o3d_tetramesh_destroy(); left NULL on failure.
 * @param out receives the new handle (NULL on failure)
 * @return O3D_OK, or O3D_ERROR_INVALID_ARGUMENT on a NULL pointer.
 */
O3D_API o3d_status o3d_tetramesh_create(o3d_tetramesh_t** out);
/**
 * @brief Destroy. NULL is a no-op.
 *
 * Threads: needs exclusive access to `tetramesh`: no other call may use it during or after.
 * @param tetramesh the handle to destroy (NULL is a no-op)
 */
O3D_API void o3d_tetramesh_destroy(o3d_tetramesh_t* tetramesh);
/**
 * @brief Deep copy.
 *
 * Threads: any thread; concurrent calls on the same handles are safe (all read-only).
 * Ownership: `*out` is the caller's, to free with o3d_tetramesh_destroy(); left NULL on failure.
 * @param out receives the new handle (NULL on failure)
 * @param src the handle to copy
 * @return O3D_OK, or O3D_ERROR_INVALID_ARGUMENT on a NULL pointer.
 */
O3D_API o3d_status o3d_tetramesh_clone(o3d_tetramesh_t** out, const o3d_tetramesh_t* src);
/**
 * @brief Number of vertices.
 *
 * Threads: any thread; concurrent calls on the same handles are safe (all read-only).
 * @param out_n receives the count
 * @param tetramesh the tetra mesh
 * @return O3D_OK, or O3D_ERROR_INVALID_ARGUMENT on a NULL pointer.
 */
O3D_API o3d_status o3d_tetramesh_num_vertices(size_t* out_n, const o3d_tetramesh_t* tetramesh);
/**
 * @brief Number of tetrahedra.
 *
 * Threads: any thread; concurrent calls on the same handles are safe (all read-only).
 * @param out_n receives the count
 * @param tetramesh the tetra mesh
 * @return O3D_OK, or O3D_ERROR_INVALID_ARGUMENT on a NULL pointer.
 */
O3D_API o3d_status o3d_tetramesh_num_tetras(size_t* out_n, const o3d_tetramesh_t* tetramesh);
/* ---- Arrays: the same functions for every geometry (docs/conventions.md, "Arrays") ----
 * `which` names the array; rows are counted in items (a vertex, a tetrahedron), never in
 * values. Copy-outs take the caller's capacity in rows and always report the rows needed;
 * views are borrowed, valid until the next mutating call on the handle or its destruction. */
/** The arrays of a tetra mesh (O3D_TETRAMESH_*). */
typedef int32_t o3d_tetramesh_array;
#define O3D_TETRAMESH_VERTICES 0 /**< N x 3 float64 */
#define O3D_TETRAMESH_TETRAS 100 /**< M x 4 int32 vertex indices */

/**
 * @brief Whether array `which` counts (Open3D's has_*: present and of the matching size).
 *
 * Threads: any thread; concurrent calls on the same handles are safe (all read-only).
 * @param out receives 1 (true) or 0 (false)
 * @param tetramesh the tetra mesh
 * @param which the array: one of this header's `which` constants
 * @return O3D_OK, or O3D_ERROR_INVALID_ARGUMENT on a NULL pointer or an unknown `which`.
 */
O3D_API o3d_status o3d_tetramesh_has_array(int32_t* out, const o3d_tetramesh_t* tetramesh, o3d_tetramesh_array which);
/**
 * @brief Rows and columns (values per row) of array `which`: e.g. N x 3 for points, num x dimension for a
 * feature.
 *
 * Threads: any thread; concurrent calls on the same handles are safe (all read-only).
 * @param out_rows receives the rows (items)
 * @param out_cols receives the values per row
 * @param tetramesh the tetra mesh
 * @param which the array: one of this header's `which` constants
 * @return O3D_OK, or O3D_ERROR_INVALID_ARGUMENT on a NULL pointer or an unknown `which`.
 */
O3D_API o3d_status o3d_tetramesh_array_shape(size_t* out_rows, size_t* out_cols, const o3d_tetramesh_t* tetramesh, o3d_tetramesh_array which);
/**
 * @brief Replace array `which` with `rows` rows of `data`, copied once (`data` may be NULL when rows == 0).
 *
 * Threads: needs exclusive access to `tetramesh`.
 * @param tetramesh the tetra mesh
 * @param which the array: one of this header's `which` constants
 * @param data `rows` rows of values, copied once (NULL allowed when rows == 0)
 * @param rows number of rows in `data`
 * @return O3D_OK, or O3D_ERROR_INVALID_ARGUMENT on a NULL handle, an unknown `which`, NULL `data` with rows > 0 or an
 *   unknown `which` (or one of the other type).
 */
O3D_API o3d_status o3d_tetramesh_set_array(o3d_tetramesh_t* tetramesh, o3d_tetramesh_array which, const double* data, size_t rows);
/**
 * @brief As o3d_tetramesh_set_array from float32 values, converted in the one copy.
 *
 * Threads: needs exclusive access to `tetramesh`.
 * @param tetramesh the tetra mesh
 * @param which the array: one of this header's `which` constants
 * @param data `rows` rows of values, copied once (NULL allowed when rows == 0)
 * @param rows number of rows in `data`
 * @return O3D_OK, or O3D_ERROR_INVALID_ARGUMENT on a NULL handle, an unknown `which`, NULL `data` with rows > 0, an
 *   unknown `which` (or one of the other type) or an array that takes no float32.
 */
O3D_API o3d_status o3d_tetramesh_set_array_f32(o3d_tetramesh_t* tetramesh, o3d_tetramesh_array which, const float* data, size_t rows);
/**
 * @brief Copy array `which` into `out`, which holds `capacity` rows; `*out_rows` always gets the rows
 * needed. `out` NULL only reports them.
 *
 * Threads: any thread; concurrent calls on the same handles are safe (all read-only).
 * @param out caller buffer of `capacity` rows (NULL: only report the row count)
 * @param capacity rows `out` holds
 * @param out_rows receives the rows of the array (always, also when `out` is NULL or too small)
 * @param tetramesh the tetra mesh
 * @param which the array: one of this header's `which` constants
 * @return O3D_OK, or O3D_ERROR_INVALID_ARGUMENT on a NULL handle or `out_rows` or an unknown `which`;
 *   O3D_ERROR_BUFFER_TOO_SMALL when `capacity` is short (the count is still reported).
 */
O3D_API o3d_status o3d_tetramesh_get_array(double* out, size_t capacity, size_t* out_rows, const o3d_tetramesh_t* tetramesh,
                                         o3d_tetramesh_array which);
/**
 * @brief Borrowed read-only view of array `which` (`*out_data` NULL when empty).
 *
 * Threads: any thread; concurrent calls on the same handles are safe (all read-only).
 * Ownership: `*out_data` points into `tetramesh` (the library's memory, never to be freed): valid until the next
 * mutating call on `tetramesh` or its destruction.
 * @param out_data receives the address of row 0 (NULL when the array is empty)
 * @param out_rows receives the row count
 * @param tetramesh the tetra mesh
 * @param which the array: one of this header's `which` constants
 * @return O3D_OK, or O3D_ERROR_INVALID_ARGUMENT on a NULL handle, `out_data` or `out_rows` or an unknown `which`.
 */
O3D_API o3d_status o3d_tetramesh_array_view(const double** out_data, size_t* out_rows, const o3d_tetramesh_t* tetramesh,
                                          o3d_tetramesh_array which);
/**
 * @brief Borrowed writable view of array `which`: as o3d_tetramesh_array_view; writing through it is a mutating call.
 *
 * Threads: needs exclusive access to `tetramesh`, also while the view is written through.
 * Ownership: `*out_data` points into `tetramesh` (the library's memory, never to be freed): valid until the next
 * mutating call on `tetramesh` or its destruction.
 * @param out_data receives the address of row 0 (NULL when the array is empty)
 * @param out_rows receives the row count
 * @param tetramesh the tetra mesh
 * @param which the array: one of this header's `which` constants
 * @return O3D_OK, or O3D_ERROR_INVALID_ARGUMENT on a NULL handle, `out_data` or `out_rows` or an unknown `which`.
 */
O3D_API o3d_status o3d_tetramesh_array_mutable_view(double** out_data, size_t* out_rows, o3d_tetramesh_t* tetramesh,
                                                  o3d_tetramesh_array which);
/**
 * @brief Replace int32 array `which` with `rows` rows of `data` (copied once), as o3d_tetramesh_set_array.
 *
 * Threads: needs exclusive access to `tetramesh`.
 * @param tetramesh the tetra mesh
 * @param which the array: one of this header's `which` constants
 * @param data `rows` rows of values, copied once (NULL allowed when rows == 0)
 * @param rows number of rows in `data`
 * @return O3D_OK, or O3D_ERROR_INVALID_ARGUMENT on a NULL handle, an unknown `which`, NULL `data` with rows > 0 or an
 *   unknown `which` (or one of the other type).
 */
O3D_API o3d_status o3d_tetramesh_set_index_array(o3d_tetramesh_t* tetramesh, o3d_tetramesh_array which, const int32_t* data, size_t rows);
/**
 * @brief Copy int32 array `which` out, with the copy-out rules of o3d_tetramesh_get_array.
 *
 * Threads: any thread; concurrent calls on the same handles are safe (all read-only).
 * @param out caller buffer of `capacity` rows (NULL: only report the row count)
 * @param capacity rows `out` holds
 * @param out_rows receives the rows of the array (always, also when `out` is NULL or too small)
 * @param tetramesh the tetra mesh
 * @param which the array: one of this header's `which` constants
 * @return O3D_OK, or O3D_ERROR_INVALID_ARGUMENT on a NULL handle or `out_rows` or an unknown `which`;
 *   O3D_ERROR_BUFFER_TOO_SMALL when `capacity` is short (the count is still reported).
 */
O3D_API o3d_status o3d_tetramesh_get_index_array(int32_t* out, size_t capacity, size_t* out_rows,
                                               const o3d_tetramesh_t* tetramesh, o3d_tetramesh_array which);
/**
 * @brief Borrowed read-only view of int32 array `which` (ownership as o3d_tetramesh_array_view).
 *
 * Threads: any thread; concurrent calls on the same handles are safe (all read-only).
 * Ownership: `*out_data` points into `tetramesh` (the library's memory, never to be freed): valid until the next
 * mutating call on `tetramesh` or its destruction.
 * @param out_data receives the address of row 0 (NULL when the array is empty)
 * @param out_rows receives the row count
 * @param tetramesh the tetra mesh
 * @param which the array: one of this header's `which` constants
 * @return O3D_OK, or O3D_ERROR_INVALID_ARGUMENT on a NULL handle, `out_data` or `out_rows` or an unknown `which`.
 */
O3D_API o3d_status o3d_tetramesh_index_array_view(const int32_t** out_data, size_t* out_rows,
                                                const o3d_tetramesh_t* tetramesh, o3d_tetramesh_array which);
/**
 * @brief Borrowed writable view of int32 array `which`; writing through it is a mutating call.
 *
 * Threads: needs exclusive access to `tetramesh`, also while the view is written through.
 * Ownership: `*out_data` points into `tetramesh` (the library's memory, never to be freed): valid until the next
 * mutating call on `tetramesh` or its destruction.
 * @param out_data receives the address of row 0 (NULL when the array is empty)
 * @param out_rows receives the row count
 * @param tetramesh the tetra mesh
 * @param which the array: one of this header's `which` constants
 * @return O3D_OK, or O3D_ERROR_INVALID_ARGUMENT on a NULL handle, `out_data` or `out_rows` or an unknown `which`.
 */
O3D_API o3d_status o3d_tetramesh_index_array_mutable_view(int32_t** out_data, size_t* out_rows,
                                                        o3d_tetramesh_t* tetramesh, o3d_tetramesh_array which);

/**
 * @brief The 3-D Delaunay tetrahedralization of the cloud's points (Qhull), and for each tetra-mesh vertex the
 * index of the input point it is. @see TetraMesh.create_from_point_cloud
 *
 * Threads: any thread; concurrent calls on the same handles are safe (all read-only).
 * Ownership: `*out` is the caller's, to free with o3d_tetramesh_destroy(); left NULL on failure.
 * @param out receives the new handle (NULL on failure)
 * @param out_point_map receives, per vertex, the index of its input point (`capacity` values, at most the point
 *   count; NULL skips them)
 * @param capacity how many items the output buffer holds (ignored when it is NULL)
 * @param out_n receives the item count (always, also when the buffer is NULL or too small)
 * @param pc the point cloud
 * @return O3D_OK, or O3D_ERROR_INVALID_ARGUMENT on a NULL pointer, fewer than 4 points, a non-finite point or a
 *   flat (coplanar or collinear) set; O3D_ERROR_BUFFER_TOO_SMALL when `capacity` is short (the count is still
 *   reported; `*out` is left NULL).
 */
O3D_API o3d_status o3d_tetramesh_create_from_point_cloud(o3d_tetramesh_t** out, int32_t* out_point_map,
                                                         size_t capacity, size_t* out_n, const o3d_pointcloud_t* pc);
/**
 * @brief The triangle mesh of the iso-surface `values == level` of one value per vertex, linear on each
 * tetrahedron (marching tetrahedra; vertices on a shared edge are shared). @see TetraMesh.extract_triangle_mesh
 *
 * Threads: any thread; concurrent calls on the same handles are safe (all read-only).
 * Ownership: `*out` is the caller's, to free with o3d_trianglemesh_destroy(); left NULL on failure.
 * @param out receives the new handle (NULL on failure)
 * @param tetramesh the tetra mesh
 * @param values one value per vertex
 * @param num_values number of values (the vertex count)
 * @param level the iso-level
 * @return O3D_OK, or O3D_ERROR_INVALID_ARGUMENT on a NULL pointer, a count other than the vertex count, a
 *   non-finite value or level, or a tetra index out of range.
 */
O3D_API o3d_status o3d_tetramesh_extract_triangle_mesh(o3d_trianglemesh_t** out, const o3d_tetramesh_t* tetramesh,
                                                       const double* values, size_t num_values, double level);

O3D_END_DECL

#endif /* O3D_TETRAMESH_H */
