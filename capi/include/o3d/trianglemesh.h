/* SPDX-License-Identifier: MIT */
/**
 * @file trianglemesh.h
 * @brief Triangle meshes: vertices, triangles and their attributes; normals, clean-up, topology
 * queries, processing (sampling, simplification, smoothing, subdivision) and primitives.
 *
 * Mirrors o3d.geometry.TriangleMesh. Arrays are row-major: vertices, vertex normals, vertex colors and
 * triangle normals are (N x 3) float64; triangle UVs are (3 * num_triangles x 2) float64, three rows per
 * triangle in corner order; triangles are (M x 3) int32 vertex indices; material ids are (M x 1) int32.
 * Counts are in rows. An attribute counts (has_array) only when its row count matches (Open3D semantics).
 *
 * Triangles may hold any int32 values; every operation that follows them checks them first and fails
 * with O3D_ERROR_INVALID_ARGUMENT on an index outside [0, num_vertices) instead of reading out of bounds.
 *
 * **Ownership:** handles written through `o3d_trianglemesh_t** out` belong to the caller
 * (o3d_trianglemesh_destroy). Views are borrowed: valid until the next mutating call on the mesh or
 * its destruction. On failure `*out` is left NULL. Clean-up functions edit the mesh in place;
 * processing functions write a new mesh.
 *
 * **Out of memory:** any function here that allocates may also return O3D_ERROR_OUT_OF_MEMORY; the
 * per-function `@return` lists do not repeat it.
 */
#ifndef O3D_TRIANGLEMESH_H
#define O3D_TRIANGLEMESH_H

#include "o3d/common.h"
#include "o3d/types.h"
#include "o3d/boundingbox.h"
#include "o3d/image.h"
#include "o3d/pointcloud.h"

O3D_BEGIN_DECL


/* ---- Container ---- */

/**
 * @brief New empty mesh. @see o3d.geometry.TriangleMesh()
 *
 * Threads: any thread.
 * Ownership: `*out` is the caller's, to free with o3d_trianglemesh_destroy(); left NULL on failure.
 * @param out receives the new handle (NULL on failure)
 * @return O3D_OK, or O3D_ERROR_INVALID_ARGUMENT on a NULL pointer.
 */
O3D_API o3d_status o3d_trianglemesh_create(o3d_trianglemesh_t** out);
/**
 * @brief Destroy. NULL is a no-op.
 *
 * Threads: needs exclusive access to `mesh`: no other call may use it during or after.
 * @param mesh the handle to destroy (NULL is a no-op)
 */
O3D_API void o3d_trianglemesh_destroy(o3d_trianglemesh_t* mesh);
/**
 * @brief Deep copy (textures included).
 *
 * Threads: any thread; concurrent calls on the same handles are safe (all read-only).
 * Ownership: `*out` is the caller's, to free with o3d_trianglemesh_destroy(); left NULL on failure.
 * @param out receives the new handle (NULL on failure)
 * @param src the handle to copy
 * @return O3D_OK, or O3D_ERROR_INVALID_ARGUMENT on a NULL pointer.
 */
O3D_API o3d_status o3d_trianglemesh_clone(o3d_trianglemesh_t** out, const o3d_trianglemesh_t* src);
/**
 * @brief Remove everything (arrays and textures).
 *
 * Threads: needs exclusive access to `mesh`.
 * @param mesh the mesh
 * @return O3D_OK, or O3D_ERROR_INVALID_ARGUMENT on a NULL pointer.
 */
O3D_API o3d_status o3d_trianglemesh_clear(o3d_trianglemesh_t* mesh);
/**
 * @brief Number of vertices.
 *
 * Threads: any thread; concurrent calls on the same handles are safe (all read-only).
 * @param out_n receives the count
 * @param mesh the mesh
 * @return O3D_OK, or O3D_ERROR_INVALID_ARGUMENT on a NULL pointer.
 */
O3D_API o3d_status o3d_trianglemesh_num_vertices(size_t* out_n, const o3d_trianglemesh_t* mesh);
/**
 * @brief Number of triangles.
 *
 * Threads: any thread; concurrent calls on the same handles are safe (all read-only).
 * @param out_n receives the count
 * @param mesh the mesh
 * @return O3D_OK, or O3D_ERROR_INVALID_ARGUMENT on a NULL pointer.
 */
O3D_API o3d_status o3d_trianglemesh_num_triangles(size_t* out_n, const o3d_trianglemesh_t* mesh);
/* ---- Arrays: the same functions for every geometry (docs/conventions.md, "Arrays") ----
 * `which` names the array; rows are counted in items (a point, a line, a descriptor), never in
 * values. Copy-outs take the caller's capacity in rows and always report the rows needed;
 * views are borrowed, valid until the next mutating call on the handle or its destruction. */
/** The arrays of a triangle mesh (O3D_MESH_*). */
typedef int32_t o3d_mesh_array;
#define O3D_MESH_VERTICES 0 /**< N x 3 float64 */
#define O3D_MESH_VERTEX_NORMALS 1 /**< N x 3 */
#define O3D_MESH_VERTEX_COLORS 2 /**< N x 3, RGB in [0,1] */
#define O3D_MESH_TRIANGLE_NORMALS 3 /**< M x 3 */
#define O3D_MESH_TRIANGLE_UVS 4 /**< 3M x 2, three rows per triangle in corner order */
#define O3D_MESH_TRIANGLES 100 /**< M x 3 int32 vertex indices */
#define O3D_MESH_TRIANGLE_MATERIAL_IDS 101 /**< M x 1 int32, index into the textures */

/**
 * @brief Whether array `which` counts (Open3D's has_*: present and of the matching size).
 *
 * Threads: any thread; concurrent calls on the same handles are safe (all read-only).
 * @param out receives 1 (true) or 0 (false)
 * @param mesh the mesh
 * @param which the array: one of this header's `which` constants
 * @return O3D_OK, or O3D_ERROR_INVALID_ARGUMENT on a NULL pointer or an unknown `which`.
 */
O3D_API o3d_status o3d_trianglemesh_has_array(int32_t* out, const o3d_trianglemesh_t* mesh, o3d_mesh_array which);
/**
 * @brief Rows and columns (values per row) of array `which`: e.g. N x 3 for points, num x dimension for a
 * feature.
 *
 * Threads: any thread; concurrent calls on the same handles are safe (all read-only).
 * @param out_rows receives the rows (items)
 * @param out_cols receives the values per row
 * @param mesh the mesh
 * @param which the array: one of this header's `which` constants
 * @return O3D_OK, or O3D_ERROR_INVALID_ARGUMENT on a NULL pointer or an unknown `which`.
 */
O3D_API o3d_status o3d_trianglemesh_array_shape(size_t* out_rows, size_t* out_cols, const o3d_trianglemesh_t* mesh, o3d_mesh_array which);
/**
 * @brief Replace array `which` with `rows` rows of `data`, copied once (`data` may be NULL when rows == 0).
 *
 * Threads: needs exclusive access to `mesh`.
 * @param mesh the mesh
 * @param which the array: one of this header's `which` constants
 * @param data `rows` rows of values, copied once (NULL allowed when rows == 0)
 * @param rows number of rows in `data`
 * @return O3D_OK, or O3D_ERROR_INVALID_ARGUMENT on a NULL handle, an unknown `which`, NULL `data` with rows > 0 or an
 *   unknown `which` (or one of the other type).
 */
O3D_API o3d_status o3d_trianglemesh_set_array(o3d_trianglemesh_t* mesh, o3d_mesh_array which, const double* data, size_t rows);
/**
 * @brief As o3d_trianglemesh_set_array from float32 values, converted in the one copy.
 *
 * Threads: needs exclusive access to `mesh`.
 * @param mesh the mesh
 * @param which the array: one of this header's `which` constants
 * @param data `rows` rows of values, copied once (NULL allowed when rows == 0)
 * @param rows number of rows in `data`
 * @return O3D_OK, or O3D_ERROR_INVALID_ARGUMENT on a NULL handle, an unknown `which`, NULL `data` with rows > 0, an
 *   unknown `which` (or one of the other type) or an array that takes no float32.
 */
O3D_API o3d_status o3d_trianglemesh_set_array_f32(o3d_trianglemesh_t* mesh, o3d_mesh_array which, const float* data, size_t rows);
/**
 * @brief Copy array `which` into `out`, which holds `capacity` rows; `*out_rows` always gets the rows
 * needed. `out` NULL only reports them.
 *
 * Threads: any thread; concurrent calls on the same handles are safe (all read-only).
 * @param out caller buffer of `capacity` rows (NULL: only report the row count)
 * @param capacity rows `out` holds
 * @param out_rows receives the rows of the array (always, also when `out` is NULL or too small)
 * @param mesh the mesh
 * @param which the array: one of this header's `which` constants
 * @return O3D_OK, or O3D_ERROR_INVALID_ARGUMENT on a NULL handle or `out_rows` or an unknown `which`;
 *   O3D_ERROR_BUFFER_TOO_SMALL when `capacity` is short (the count is still reported).
 */
O3D_API o3d_status o3d_trianglemesh_get_array(double* out, size_t capacity, size_t* out_rows, const o3d_trianglemesh_t* mesh,
                                              o3d_mesh_array which);
/**
 * @brief Borrowed read-only view of array `which` (`*out_data` NULL when empty).
 *
 * Threads: any thread; concurrent calls on the same handles are safe (all read-only).
 * Ownership: `*out_data` points into `mesh` (the library's memory, never to be freed): valid until the next mutating
 * call on `mesh` or its destruction.
 * @param out_data receives the address of row 0 (NULL when the array is empty)
 * @param out_rows receives the row count
 * @param mesh the mesh
 * @param which the array: one of this header's `which` constants
 * @return O3D_OK, or O3D_ERROR_INVALID_ARGUMENT on a NULL handle, `out_data` or `out_rows` or an unknown `which`.
 */
O3D_API o3d_status o3d_trianglemesh_array_view(const double** out_data, size_t* out_rows, const o3d_trianglemesh_t* mesh,
                                               o3d_mesh_array which);
/**
 * @brief Borrowed writable view of array `which`: as o3d_trianglemesh_array_view; writing through it is a mutating
 * call.
 *
 * Threads: needs exclusive access to `mesh`, also while the view is written through.
 * Ownership: `*out_data` points into `mesh` (the library's memory, never to be freed): valid until the next mutating
 * call on `mesh` or its destruction.
 * @param out_data receives the address of row 0 (NULL when the array is empty)
 * @param out_rows receives the row count
 * @param mesh the mesh
 * @param which the array: one of this header's `which` constants
 * @return O3D_OK, or O3D_ERROR_INVALID_ARGUMENT on a NULL handle, `out_data` or `out_rows` or an unknown `which`.
 */
O3D_API o3d_status o3d_trianglemesh_array_mutable_view(double** out_data, size_t* out_rows, o3d_trianglemesh_t* mesh,
                                                       o3d_mesh_array which);
/**
 * @brief Replace int32 array `which` with `rows` rows of `data` (copied once), as o3d_trianglemesh_set_array.
 *
 * Threads: needs exclusive access to `mesh`.
 * @param mesh the mesh
 * @param which the array: one of this header's `which` constants
 * @param data `rows` rows of values, copied once (NULL allowed when rows == 0)
 * @param rows number of rows in `data`
 * @return O3D_OK, or O3D_ERROR_INVALID_ARGUMENT on a NULL handle, an unknown `which`, NULL `data` with rows > 0 or an
 *   unknown `which` (or one of the other type).
 */
O3D_API o3d_status o3d_trianglemesh_set_index_array(o3d_trianglemesh_t* mesh, o3d_mesh_array which, const int32_t* data, size_t rows);
/**
 * @brief Copy int32 array `which` out, with the copy-out rules of o3d_trianglemesh_get_array.
 *
 * Threads: any thread; concurrent calls on the same handles are safe (all read-only).
 * @param out caller buffer of `capacity` rows (NULL: only report the row count)
 * @param capacity rows `out` holds
 * @param out_rows receives the rows of the array (always, also when `out` is NULL or too small)
 * @param mesh the mesh
 * @param which the array: one of this header's `which` constants
 * @return O3D_OK, or O3D_ERROR_INVALID_ARGUMENT on a NULL handle or `out_rows` or an unknown `which`;
 *   O3D_ERROR_BUFFER_TOO_SMALL when `capacity` is short (the count is still reported).
 */
O3D_API o3d_status o3d_trianglemesh_get_index_array(int32_t* out, size_t capacity, size_t* out_rows,
                                                    const o3d_trianglemesh_t* mesh, o3d_mesh_array which);
/**
 * @brief Borrowed read-only view of int32 array `which` (ownership as o3d_trianglemesh_array_view).
 *
 * Threads: any thread; concurrent calls on the same handles are safe (all read-only).
 * Ownership: `*out_data` points into `mesh` (the library's memory, never to be freed): valid until the next mutating
 * call on `mesh` or its destruction.
 * @param out_data receives the address of row 0 (NULL when the array is empty)
 * @param out_rows receives the row count
 * @param mesh the mesh
 * @param which the array: one of this header's `which` constants
 * @return O3D_OK, or O3D_ERROR_INVALID_ARGUMENT on a NULL handle, `out_data` or `out_rows` or an unknown `which`.
 */
O3D_API o3d_status o3d_trianglemesh_index_array_view(const int32_t** out_data, size_t* out_rows,
                                                     const o3d_trianglemesh_t* mesh, o3d_mesh_array which);
/**
 * @brief Borrowed writable view of int32 array `which`; writing through it is a mutating call.
 *
 * Threads: needs exclusive access to `mesh`, also while the view is written through.
 * Ownership: `*out_data` points into `mesh` (the library's memory, never to be freed): valid until the next mutating
 * call on `mesh` or its destruction.
 * @param out_data receives the address of row 0 (NULL when the array is empty)
 * @param out_rows receives the row count
 * @param mesh the mesh
 * @param which the array: one of this header's `which` constants
 * @return O3D_OK, or O3D_ERROR_INVALID_ARGUMENT on a NULL handle, `out_data` or `out_rows` or an unknown `which`.
 */
O3D_API o3d_status o3d_trianglemesh_index_array_mutable_view(int32_t** out_data, size_t* out_rows,
                                                             o3d_trianglemesh_t* mesh, o3d_mesh_array which);

/**
 * @brief Number of texture images.
 *
 * Threads: any thread; concurrent calls on the same handles are safe (all read-only).
 * @param out_n receives the count
 * @param mesh the mesh
 * @return O3D_OK, or O3D_ERROR_INVALID_ARGUMENT on a NULL pointer.
 */
O3D_API o3d_status o3d_trianglemesh_texture_count(size_t* out_n, const o3d_trianglemesh_t* mesh);
/**
 * @brief Copy of texture `index` as a new image (caller destroys it).
 *
 * Threads: any thread; concurrent calls on the same handles are safe (all read-only).
 * Ownership: `*out` is the caller's, to free with o3d_image_destroy(); left NULL on failure.
 * @param out receives the new handle (NULL on failure)
 * @param mesh the mesh
 * @param index zero-based index (must be below the count)
 * @return O3D_OK, or O3D_ERROR_INVALID_ARGUMENT on a NULL pointer or `index` out of range.
 */
O3D_API o3d_status o3d_trianglemesh_get_texture(o3d_image_t** out, const o3d_trianglemesh_t* mesh, size_t index);
/**
 * @brief Append a copy of `image` to the textures.
 *
 * Threads: needs exclusive access to `mesh`; `image` is only read.
 * @param mesh the mesh
 * @param image the image
 * @return O3D_OK, or O3D_ERROR_INVALID_ARGUMENT on a NULL pointer.
 */
O3D_API o3d_status o3d_trianglemesh_add_texture(o3d_trianglemesh_t* mesh, const o3d_image_t* image);
/**
 * @brief Remove all textures.
 *
 * Threads: needs exclusive access to `mesh`.
 * @param mesh the mesh
 * @return O3D_OK, or O3D_ERROR_INVALID_ARGUMENT on a NULL pointer.
 */
O3D_API o3d_status o3d_trianglemesh_clear_textures(o3d_trianglemesh_t* mesh);

/**
 * @brief Concatenate `other` onto `mesh` (Open3D `mesh += other`), re-indexing its triangles.
 *
 * Threads: needs exclusive access to `mesh`; `other` is only read.
 * @param mesh the mesh
 * @param other the geometry appended (only read)
 * @return O3D_OK, or O3D_ERROR_INVALID_ARGUMENT on a NULL pointer.
 */
O3D_API o3d_status o3d_trianglemesh_append(o3d_trianglemesh_t* mesh, const o3d_trianglemesh_t* other);

/* ---- Normals, colors, transforms, bounds (as for point clouds) ---- */

/**
 * @brief Area-weighted vertex normals from the triangle normals (unit length when `normalized`).
 *
 * Threads: needs exclusive access to `mesh`.
 * @param mesh the mesh
 * @param normalized non-zero scales the normals to unit length
 * @return O3D_OK, or O3D_ERROR_INVALID_ARGUMENT on a NULL pointer.
 */
O3D_API o3d_status o3d_trianglemesh_compute_vertex_normals(o3d_trianglemesh_t* mesh, o3d_bool normalized);
/**
 * @brief Triangle normals (b - a) x (c - a) (unit length when `normalized`).
 *
 * Threads: needs exclusive access to `mesh`.
 * @param mesh the mesh
 * @param normalized non-zero scales the normals to unit length
 * @return O3D_OK, or O3D_ERROR_INVALID_ARGUMENT on a NULL pointer.
 */
O3D_API o3d_status o3d_trianglemesh_compute_triangle_normals(o3d_trianglemesh_t* mesh, o3d_bool normalized);
/**
 * @brief Scale vertex and triangle normals to unit length.
 *
 * Threads: needs exclusive access to `mesh`.
 * @param mesh the mesh
 * @return O3D_OK, or O3D_ERROR_INVALID_ARGUMENT on a NULL pointer.
 */
O3D_API o3d_status o3d_trianglemesh_normalize_normals(o3d_trianglemesh_t* mesh);
/**
 * @brief Set every vertex color to `rgb`.
 *
 * Threads: needs exclusive access to `mesh`.
 * @param mesh the mesh
 * @param rgb the color, each channel in [0,1]
 * @return O3D_OK, or O3D_ERROR_INVALID_ARGUMENT on a NULL pointer.
 */
O3D_API o3d_status o3d_trianglemesh_paint_uniform_color(o3d_trianglemesh_t* mesh, const double rgb[3]);
/**
 * @brief Apply a row-major 4x4 transform to the vertices (normals rotated).
 *
 * Threads: needs exclusive access to `mesh`.
 * @param mesh the mesh
 * @param transform row-major 4x4 transform
 * @return O3D_OK, or O3D_ERROR_INVALID_ARGUMENT on a NULL pointer.
 */
O3D_API o3d_status o3d_trianglemesh_transform(o3d_trianglemesh_t* mesh, const double transform[16]);
/**
 * @brief Move the mesh: with `relative`, by `translation`; without, so that its center is at `translation`.
 *
 * Threads: needs exclusive access to `mesh`.
 * @param mesh the mesh
 * @param translation the translation, or the new center
 * @param relative non-zero: add `translation`; 0: move the center there
 * @return O3D_OK, or O3D_ERROR_INVALID_ARGUMENT on a NULL pointer.
 */
O3D_API o3d_status o3d_trianglemesh_translate(o3d_trianglemesh_t* mesh, const double translation[3],
                                              o3d_bool relative);
/**
 * @brief Rotate by row-major 3x3 `R` about `center` (NULL: the mesh's center).
 *
 * Threads: needs exclusive access to `mesh`.
 * @param mesh the mesh
 * @param rotation row-major 3x3 rotation matrix
 * @param center the pivot (NULL: the geometry's center)
 * @return O3D_OK, or O3D_ERROR_INVALID_ARGUMENT on a NULL pointer.
 */
O3D_API o3d_status o3d_trianglemesh_rotate(o3d_trianglemesh_t* mesh, const double rotation[9],
                                           const double center[3]);
/**
 * @brief Scale about `center` (NULL: the mesh's center).
 *
 * Threads: needs exclusive access to `mesh`.
 * @param mesh the mesh
 * @param scale the scale factor
 * @param center the pivot (NULL: the geometry's center)
 * @return O3D_OK, or O3D_ERROR_INVALID_ARGUMENT on a NULL pointer.
 */
O3D_API o3d_status o3d_trianglemesh_scale(o3d_trianglemesh_t* mesh, double scale, const double center[3]);
/**
 * @brief Component-wise minimum of the vertices ((0,0,0) when empty).
 *
 * Threads: any thread; concurrent calls on the same handles are safe (all read-only).
 * @param out receives the result
 * @param mesh the mesh
 * @return O3D_OK, or O3D_ERROR_INVALID_ARGUMENT on a NULL pointer.
 */
O3D_API o3d_status o3d_trianglemesh_get_min_bound(double out[3], const o3d_trianglemesh_t* mesh);
/**
 * @brief Component-wise maximum of the vertices ((0,0,0) when empty).
 *
 * Threads: any thread; concurrent calls on the same handles are safe (all read-only).
 * @param out receives the result
 * @param mesh the mesh
 * @return O3D_OK, or O3D_ERROR_INVALID_ARGUMENT on a NULL pointer.
 */
O3D_API o3d_status o3d_trianglemesh_get_max_bound(double out[3], const o3d_trianglemesh_t* mesh);
/**
 * @brief Mean of the vertices ((0,0,0) when empty).
 *
 * Threads: any thread; concurrent calls on the same handles are safe (all read-only).
 * @param out receives the result
 * @param mesh the mesh
 * @return O3D_OK, or O3D_ERROR_INVALID_ARGUMENT on a NULL pointer.
 */
O3D_API o3d_status o3d_trianglemesh_get_center(double out[3], const o3d_trianglemesh_t* mesh);
/**
 * @brief Axis-aligned bounding box as min and max corners.
 *
 * Threads: any thread; concurrent calls on the same handles are safe (all read-only).
 * @param out_min receives the minimum corner
 * @param out_max receives the maximum corner
 * @param mesh the mesh
 * @return O3D_OK, or O3D_ERROR_INVALID_ARGUMENT on a NULL pointer.
 */
O3D_API o3d_status o3d_trianglemesh_get_axis_aligned_bounding_box(double out_min[3], double out_max[3],
                                                                  const o3d_trianglemesh_t* mesh);

/* ---- Clean-up (in place; each keeps the attributes of what it keeps) ---- */

/**
 * @brief Merge vertices with exactly equal coordinates, re-indexing the triangles.
 *
 * Threads: needs exclusive access to `mesh`.
 * @param mesh the mesh
 * @return O3D_OK, or O3D_ERROR_INVALID_ARGUMENT on a NULL pointer.
 */
O3D_API o3d_status o3d_trianglemesh_remove_duplicated_vertices(o3d_trianglemesh_t* mesh);
/**
 * @brief Remove triangles with the same three vertices (in any order).
 *
 * Threads: needs exclusive access to `mesh`.
 * @param mesh the mesh
 * @return O3D_OK, or O3D_ERROR_INVALID_ARGUMENT on a NULL pointer.
 */
O3D_API o3d_status o3d_trianglemesh_remove_duplicated_triangles(o3d_trianglemesh_t* mesh);
/**
 * @brief Remove triangles that repeat a vertex index.
 *
 * Threads: needs exclusive access to `mesh`.
 * @param mesh the mesh
 * @return O3D_OK, or O3D_ERROR_INVALID_ARGUMENT on a NULL pointer.
 */
O3D_API o3d_status o3d_trianglemesh_remove_degenerate_triangles(o3d_trianglemesh_t* mesh);
/**
 * @brief Remove vertices no triangle uses.
 *
 * Threads: needs exclusive access to `mesh`.
 * @param mesh the mesh
 * @return O3D_OK, or O3D_ERROR_INVALID_ARGUMENT on a NULL pointer.
 */
O3D_API o3d_status o3d_trianglemesh_remove_unreferenced_vertices(o3d_trianglemesh_t* mesh);
/**
 * @brief Remove the smallest-area triangles on each edge shared by more than two, until all are manifold.
 *
 * Threads: needs exclusive access to `mesh`.
 * @param mesh the mesh
 * @return O3D_OK, or O3D_ERROR_INVALID_ARGUMENT on a NULL pointer.
 */
O3D_API o3d_status o3d_trianglemesh_remove_non_manifold_edges(o3d_trianglemesh_t* mesh);
/**
 * @brief Merge vertices closer than `eps` (>= 0) into their mean (normals and colors averaged).
 *
 * Threads: needs exclusive access to `mesh`.
 * @param mesh the mesh
 * @param eps the distance threshold (>= 0)
 * @return O3D_OK, or O3D_ERROR_INVALID_ARGUMENT on a NULL pointer.
 */
O3D_API o3d_status o3d_trianglemesh_merge_close_vertices(o3d_trianglemesh_t* mesh, double eps);
/**
 * @brief Remove the vertices at `indices` (repeats allowed) and every triangle that uses one of them; what stays
 * keeps its order and attributes. @see TriangleMesh.remove_vertices_by_index
 *
 * Threads: needs exclusive access to `mesh`.
 * @param mesh the mesh
 * @param indices vertex indices
 * @param num_indices number of indices
 * @return O3D_OK, or O3D_ERROR_INVALID_ARGUMENT on a NULL pointer, an index out of range or a triangle index out of
 *   range (the mesh is then unchanged).
 */
O3D_API o3d_status o3d_trianglemesh_remove_vertices_by_index(o3d_trianglemesh_t* mesh, const int32_t* indices,
                                                             size_t num_indices);
/**
 * @brief Remove the vertices whose mask entry is non-zero and every triangle that uses one of them (the trim of a
 * Poisson surface by its densities). @see TriangleMesh.remove_vertices_by_mask
 *
 * Threads: needs exclusive access to `mesh`.
 * @param mesh the mesh
 * @param mask one byte per vertex
 * @param num_mask number of bytes in `mask` (the vertex count)
 * @return O3D_OK, or O3D_ERROR_INVALID_ARGUMENT on a NULL pointer, a mask of another size or a triangle index out of
 *   range (the mesh is then unchanged).
 */
O3D_API o3d_status o3d_trianglemesh_remove_vertices_by_mask(o3d_trianglemesh_t* mesh, const uint8_t* mask,
                                                            size_t num_mask);
/**
 * @brief Remove the triangles at `indices` (repeats allowed); every vertex stays.
 * @see TriangleMesh.remove_triangles_by_index
 *
 * Threads: needs exclusive access to `mesh`.
 * @param mesh the mesh
 * @param indices triangle indices
 * @param num_indices number of indices
 * @return O3D_OK, or O3D_ERROR_INVALID_ARGUMENT on a NULL pointer or an index out of range (the mesh is then
 *   unchanged).
 */
O3D_API o3d_status o3d_trianglemesh_remove_triangles_by_index(o3d_trianglemesh_t* mesh, const int32_t* indices,
                                                              size_t num_indices);
/**
 * @brief Remove the triangles whose mask entry is non-zero; every vertex stays.
 * @see TriangleMesh.remove_triangles_by_mask
 *
 * Threads: needs exclusive access to `mesh`.
 * @param mesh the mesh
 * @param mask one byte per triangle
 * @param num_mask number of bytes in `mask` (the triangle count)
 * @return O3D_OK, or O3D_ERROR_INVALID_ARGUMENT on a NULL pointer or a mask of another size (the mesh is then
 *   unchanged).
 */
O3D_API o3d_status o3d_trianglemesh_remove_triangles_by_mask(o3d_trianglemesh_t* mesh, const uint8_t* mask,
                                                             size_t num_mask);

/* ---- Queries ---- */

/**
 * @brief Sum of the triangle areas.
 *
 * Threads: any thread; concurrent calls on the same handles are safe (all read-only).
 * @param out receives the result
 * @param mesh the mesh
 * @return O3D_OK, or O3D_ERROR_INVALID_ARGUMENT on a NULL pointer.
 */
O3D_API o3d_status o3d_trianglemesh_get_surface_area(double* out, const o3d_trianglemesh_t* mesh);
/**
 * @brief Enclosed volume; a mesh that is not watertight and orientable fails with INVALID_ARGUMENT.
 *
 * Threads: any thread; concurrent calls on the same handles are safe (all read-only).
 * @param out receives the result
 * @param mesh the mesh
 * @return O3D_OK, or O3D_ERROR_INVALID_ARGUMENT on a NULL pointer.
 */
O3D_API o3d_status o3d_trianglemesh_get_volume(double* out, const o3d_trianglemesh_t* mesh);
/**
 * @brief Edge- and vertex-manifold, no boundary edges, not self-intersecting.
 *
 * Threads: any thread; concurrent calls on the same handles are safe (all read-only).
 * @param out receives 1 (true) or 0 (false)
 * @param mesh the mesh
 * @return O3D_OK, or O3D_ERROR_INVALID_ARGUMENT on a NULL pointer.
 */
O3D_API o3d_status o3d_trianglemesh_is_watertight(int32_t* out, const o3d_trianglemesh_t* mesh);
/**
 * @brief Every edge in one or two triangles (only two when allow_boundary_edges == 0).
 *
 * Threads: any thread; concurrent calls on the same handles are safe (all read-only).
 * @param out receives 1 (true) or 0 (false)
 * @param mesh the mesh
 * @param allow_boundary_edges non-zero accepts edges in one triangle
 * @return O3D_OK, or O3D_ERROR_INVALID_ARGUMENT on a NULL pointer.
 */
O3D_API o3d_status o3d_trianglemesh_is_edge_manifold(int32_t* out, const o3d_trianglemesh_t* mesh,
                                                     int32_t allow_boundary_edges);
/**
 * @brief The triangles around every vertex form one fan.
 *
 * Threads: any thread; concurrent calls on the same handles are safe (all read-only).
 * @param out receives 1 (true) or 0 (false)
 * @param mesh the mesh
 * @return O3D_OK, or O3D_ERROR_INVALID_ARGUMENT on a NULL pointer.
 */
O3D_API o3d_status o3d_trianglemesh_is_vertex_manifold(int32_t* out, const o3d_trianglemesh_t* mesh);
/**
 * @brief Some two triangles that share no vertex intersect.
 *
 * Threads: any thread; concurrent calls on the same handles are safe (all read-only).
 * @param out receives 1 (true) or 0 (false)
 * @param mesh the mesh
 * @return O3D_OK, or O3D_ERROR_INVALID_ARGUMENT on a NULL pointer.
 */
O3D_API o3d_status o3d_trianglemesh_is_self_intersecting(int32_t* out, const o3d_trianglemesh_t* mesh);
/**
 * @brief The triangles can be oriented consistently.
 *
 * Threads: any thread; concurrent calls on the same handles are safe (all read-only).
 * @param out receives 1 (true) or 0 (false)
 * @param mesh the mesh
 * @return O3D_OK, or O3D_ERROR_INVALID_ARGUMENT on a NULL pointer.
 */
O3D_API o3d_status o3d_trianglemesh_is_orientable(int32_t* out, const o3d_trianglemesh_t* mesh);
/**
 * @brief V - E + F.
 *
 * Threads: any thread; concurrent calls on the same handles are safe (all read-only).
 * @param out receives the result
 * @param mesh the mesh
 * @return O3D_OK, or O3D_ERROR_INVALID_ARGUMENT on a NULL pointer.
 */
O3D_API o3d_status o3d_trianglemesh_euler_poincare_characteristic(int64_t* out, const o3d_trianglemesh_t* mesh);
/**
 * @brief Edge-connected components. `out_triangle_clusters` gets each triangle's cluster (numbered by
 * lowest triangle index), `out_cluster_n_triangles` and `out_cluster_area` each cluster's size and area.
 * All three buffers hold `capacity` values (num_triangles always fits); any may be NULL to skip it.
 * `*out_num_triangles` and `*out_num_clusters` always get the counts.
 *
 * Threads: any thread; concurrent calls on the same handles are safe (all read-only).
 * @param out_triangle_clusters receives each triangle's cluster (NULL skips it)
 * @param out_cluster_n_triangles receives each cluster's triangle count (NULL skips it)
 * @param out_cluster_area receives each cluster's area (NULL skips it)
 * @param capacity how many items the output buffer holds (ignored when it is NULL)
 * @param out_num_triangles receives the number of triangles
 * @param out_num_clusters receives the number of clusters
 * @param mesh the mesh
 * @return O3D_OK, or O3D_ERROR_INVALID_ARGUMENT on a NULL pointer; O3D_ERROR_BUFFER_TOO_SMALL when `capacity` is
 *   short (the count is still reported).
 */
O3D_API o3d_status o3d_trianglemesh_cluster_connected_triangles(int32_t* out_triangle_clusters,
                                                                int32_t* out_cluster_n_triangles,
                                                                double* out_cluster_area, size_t capacity,
                                                                size_t* out_num_triangles, size_t* out_num_clusters,
                                                                const o3d_trianglemesh_t* mesh);

/* ---- Processing (each writes a new mesh or cloud) ---- */

/**
 * @brief `number_of_points` points uniformly on the surface (area-weighted). Normals from the triangle
 * normals (use_triangle_normal != 0) or interpolated vertex normals; colors interpolated. Same seed →
 * same output. @see sample_points_uniformly
 *
 * Threads: any thread; concurrent calls on the same handles are safe (all read-only).
 * Ownership: `*out` is the caller's, to free with o3d_pointcloud_destroy(); left NULL on failure.
 * @param out receives the new handle (NULL on failure)
 * @param mesh the mesh
 * @param number_of_points how many points to sample
 * @param use_triangle_normal non-zero: each point gets its triangle's normal, 0: interpolated vertex normals
 * @param seed random seed: the same seed gives the same output
 * @return O3D_OK, or O3D_ERROR_INVALID_ARGUMENT on a NULL pointer.
 */
O3D_API o3d_status o3d_trianglemesh_sample_points_uniformly(o3d_pointcloud_t** out, const o3d_trianglemesh_t* mesh,
                                                            size_t number_of_points, int32_t use_triangle_normal,
                                                            uint64_t seed);
/**
 * @brief Poisson-disk samples by sample elimination (Yuksel 2015) from init_factor * number_of_points
 * uniform samples (init_factor >= 1; Open3D's default 5). @see sample_points_poisson_disk
 *
 * Threads: any thread; concurrent calls on the same handles are safe (all read-only).
 * Ownership: `*out` is the caller's, to free with o3d_pointcloud_destroy(); left NULL on failure.
 * @param out receives the new handle (NULL on failure)
 * @param mesh the mesh
 * @param number_of_points how many points to sample
 * @param init_factor initial samples per output point (>= 1)
 * @param use_triangle_normal non-zero: each point gets its triangle's normal, 0: interpolated vertex normals
 * @param seed random seed: the same seed gives the same output
 * @return O3D_OK, or O3D_ERROR_INVALID_ARGUMENT on a NULL pointer.
 */
O3D_API o3d_status o3d_trianglemesh_sample_points_poisson_disk(o3d_pointcloud_t** out,
                                                               const o3d_trianglemesh_t* mesh,
                                                               size_t number_of_points, double init_factor,
                                                               int32_t use_triangle_normal, uint64_t seed);

/** How vertex clustering places a cluster's vertex (O3D_SIMPLIFICATION_*). */
typedef int32_t o3d_simplification_contraction;
#define O3D_SIMPLIFICATION_AVERAGE 0 /**< vertex clustering: cluster vertex = mean */
#define O3D_SIMPLIFICATION_QUADRIC 1 /**< vertex clustering: cluster vertex minimises the quadric error */
/**
 * @brief Vertex clustering on a voxel grid of edge `voxel_size` > 0. @see simplify_vertex_clustering
 *
 * Threads: any thread; concurrent calls on the same handles are safe (all read-only).
 * Ownership: `*out` is the caller's, to free with o3d_trianglemesh_destroy(); left NULL on failure.
 * @param out receives the new handle (NULL on failure)
 * @param mesh the mesh
 * @param voxel_size voxel edge length (> 0)
 * @param contraction O3D_SIMPLIFICATION_*
 * @return O3D_OK, or O3D_ERROR_INVALID_ARGUMENT on a NULL pointer.
 */
O3D_API o3d_status o3d_trianglemesh_simplify_vertex_clustering(o3d_trianglemesh_t** out,
                                                               const o3d_trianglemesh_t* mesh, double voxel_size,
                                                               o3d_simplification_contraction contraction);
/**
 * @brief Quadric edge-collapse decimation (Garland & Heckbert 1997) down to `target_number_of_triangles`,
 * stopping early when the cheapest collapse costs more than `maximum_error` (INFINITY: no limit);
 * `boundary_weight` weights the boundary-preserving quadrics (Open3D default 1).
 *
 * Threads: any thread; concurrent calls on the same handles are safe (all read-only).
 * Ownership: `*out` is the caller's, to free with o3d_trianglemesh_destroy(); left NULL on failure.
 * @param out receives the new handle (NULL on failure)
 * @param mesh the mesh
 * @param target_number_of_triangles triangles to keep
 * @param maximum_error stop when the cheapest collapse costs more (INFINITY: no limit)
 * @param boundary_weight weight of the boundary-preserving quadrics
 * @return O3D_OK, or O3D_ERROR_INVALID_ARGUMENT on a NULL pointer.
 */
O3D_API o3d_status o3d_trianglemesh_simplify_quadric_decimation(o3d_trianglemesh_t** out,
                                                                const o3d_trianglemesh_t* mesh,
                                                                size_t target_number_of_triangles,
                                                                double maximum_error, double boundary_weight);

/** Which vertex attributes the smoothing filters change (O3D_FILTER_SCOPE_*). */
typedef int32_t o3d_filter_scope;
#define O3D_FILTER_SCOPE_ALL 0    /**< positions, normals and colors */
#define O3D_FILTER_SCOPE_COLOR 1 /**< colors only */
#define O3D_FILTER_SCOPE_NORMAL 2 /**< normals only */
#define O3D_FILTER_SCOPE_VERTEX 3 /**< positions only */
/**
 * @brief Average of each vertex and its neighbours, `number_of_iterations` times.
 *
 * Threads: any thread; concurrent calls on the same handles are safe (all read-only).
 * Ownership: `*out` is the caller's, to free with o3d_trianglemesh_destroy(); left NULL on failure.
 * @param out receives the new handle (NULL on failure)
 * @param mesh the mesh
 * @param number_of_iterations how many times to apply the step (>= 1)
 * @param filter_scope what to filter: O3D_FILTER_SCOPE_*
 * @return O3D_OK, or O3D_ERROR_INVALID_ARGUMENT on a NULL pointer.
 */
O3D_API o3d_status o3d_trianglemesh_filter_smooth_simple(o3d_trianglemesh_t** out, const o3d_trianglemesh_t* mesh,
                                                         int32_t number_of_iterations, o3d_filter_scope filter_scope);
/**
 * @brief Laplacian smoothing v += lambda * (weighted mean of neighbours - v), neighbours weighted by inverse
 * distance as in Open3D (default lambda 0.5).
 *
 * Threads: any thread; concurrent calls on the same handles are safe (all read-only).
 * Ownership: `*out` is the caller's, to free with o3d_trianglemesh_destroy(); left NULL on failure.
 * @param out receives the new handle (NULL on failure)
 * @param mesh the mesh
 * @param number_of_iterations how many times to apply the step (>= 1)
 * @param lambda_filter the Laplacian step (lambda)
 * @param filter_scope what to filter: O3D_FILTER_SCOPE_*
 * @return O3D_OK, or O3D_ERROR_INVALID_ARGUMENT on a NULL pointer.
 */
O3D_API o3d_status o3d_trianglemesh_filter_smooth_laplacian(o3d_trianglemesh_t** out,
                                                            const o3d_trianglemesh_t* mesh,
                                                            int32_t number_of_iterations, double lambda_filter,
                                                            o3d_filter_scope filter_scope);
/**
 * @brief Taubin smoothing: alternating Laplacian steps with lambda and mu (defaults 0.5, -0.53).
 *
 * Threads: any thread; concurrent calls on the same handles are safe (all read-only).
 * Ownership: `*out` is the caller's, to free with o3d_trianglemesh_destroy(); left NULL on failure.
 * @param out receives the new handle (NULL on failure)
 * @param mesh the mesh
 * @param number_of_iterations how many times to apply the step (>= 1)
 * @param lambda_filter the Laplacian step (lambda)
 * @param mu the second (negative) step
 * @param filter_scope what to filter: O3D_FILTER_SCOPE_*
 * @return O3D_OK, or O3D_ERROR_INVALID_ARGUMENT on a NULL pointer.
 */
O3D_API o3d_status o3d_trianglemesh_filter_smooth_taubin(o3d_trianglemesh_t** out, const o3d_trianglemesh_t* mesh,
                                                         int32_t number_of_iterations, double lambda_filter,
                                                         double mu, o3d_filter_scope filter_scope);
/**
 * @brief Split every triangle into four at its edge midpoints, `number_of_iterations` times.
 *
 * Threads: any thread; concurrent calls on the same handles are safe (all read-only).
 * Ownership: `*out` is the caller's, to free with o3d_trianglemesh_destroy(); left NULL on failure.
 * @param out receives the new handle (NULL on failure)
 * @param mesh the mesh
 * @param number_of_iterations how many times to apply the step (>= 1)
 * @return O3D_OK, or O3D_ERROR_INVALID_ARGUMENT on a NULL pointer.
 */
O3D_API o3d_status o3d_trianglemesh_subdivide_midpoint(o3d_trianglemesh_t** out, const o3d_trianglemesh_t* mesh,
                                                       int32_t number_of_iterations);
/**
 * @brief Loop subdivision (Loop 1987), `number_of_iterations` times.
 *
 * Threads: any thread; concurrent calls on the same handles are safe (all read-only).
 * Ownership: `*out` is the caller's, to free with o3d_trianglemesh_destroy(); left NULL on failure.
 * @param out receives the new handle (NULL on failure)
 * @param mesh the mesh
 * @param number_of_iterations how many times to apply the step (>= 1)
 * @return O3D_OK, or O3D_ERROR_INVALID_ARGUMENT on a NULL pointer.
 */
O3D_API o3d_status o3d_trianglemesh_subdivide_loop(o3d_trianglemesh_t** out, const o3d_trianglemesh_t* mesh,
                                                   int32_t number_of_iterations);
/**
 * @brief Triangles whose three vertices lie in [min_bound, max_bound] (unused vertices dropped).
 *
 * Threads: any thread; concurrent calls on the same handles are safe (all read-only).
 * Ownership: `*out` is the caller's, to free with o3d_trianglemesh_destroy(); left NULL on failure.
 * @param out receives the new handle (NULL on failure)
 * @param mesh the mesh
 * @param min_bound minimum corner (x, y, z)
 * @param max_bound maximum corner (x, y, z)
 * @return O3D_OK, or O3D_ERROR_INVALID_ARGUMENT on a NULL pointer.
 */
O3D_API o3d_status o3d_trianglemesh_crop_aabb(o3d_trianglemesh_t** out, const o3d_trianglemesh_t* mesh,
                                              const double min_bound[3], const double max_bound[3]);

/* ---- Primitives (Open3D's create_* with its defaults noted) ---- */

/**
 * @brief Box [0,w] x [0,h] x [0,d] (defaults 1, 1, 1).
 *
 * Threads: any thread.
 * Ownership: `*out` is the caller's, to free with o3d_trianglemesh_destroy(); left NULL on failure.
 * @param out receives the new handle (NULL on failure)
 * @param width the width
 * @param height the height
 * @param depth the depth image
 * @return O3D_OK, or O3D_ERROR_INVALID_ARGUMENT on a NULL pointer.
 */
O3D_API o3d_status o3d_trianglemesh_create_box(o3d_trianglemesh_t** out, double width, double height,
                                               double depth);
/**
 * @brief UV sphere about the origin (defaults radius 1, resolution 20).
 *
 * Threads: any thread.
 * Ownership: `*out` is the caller's, to free with o3d_trianglemesh_destroy(); left NULL on failure.
 * @param out receives the new handle (NULL on failure)
 * @param radius the radius (> 0)
 * @param resolution segments around the axis
 * @return O3D_OK, or O3D_ERROR_INVALID_ARGUMENT on a NULL pointer.
 */
O3D_API o3d_status o3d_trianglemesh_create_sphere(o3d_trianglemesh_t** out, double radius, int32_t resolution);
/**
 * @brief Cylinder along z centred at the origin (defaults 1, 2, resolution 20, split 4).
 *
 * Threads: any thread.
 * Ownership: `*out` is the caller's, to free with o3d_trianglemesh_destroy(); left NULL on failure.
 * @param out receives the new handle (NULL on failure)
 * @param radius the radius (> 0)
 * @param height the height
 * @param resolution segments around the axis
 * @param split segments along the axis
 * @return O3D_OK, or O3D_ERROR_INVALID_ARGUMENT on a NULL pointer.
 */
O3D_API o3d_status o3d_trianglemesh_create_cylinder(o3d_trianglemesh_t** out, double radius, double height,
                                                    int32_t resolution, int32_t split);
/**
 * @brief Cone along z with its base at z = 0 (defaults 1, 2, resolution 20, split 1).
 *
 * Threads: any thread.
 * Ownership: `*out` is the caller's, to free with o3d_trianglemesh_destroy(); left NULL on failure.
 * @param out receives the new handle (NULL on failure)
 * @param radius the radius (> 0)
 * @param height the height
 * @param resolution segments around the axis
 * @param split segments along the axis
 * @return O3D_OK, or O3D_ERROR_INVALID_ARGUMENT on a NULL pointer.
 */
O3D_API o3d_status o3d_trianglemesh_create_cone(o3d_trianglemesh_t** out, double radius, double height,
                                                int32_t resolution, int32_t split);
/**
 * @brief Torus about z (defaults 1, 0.5, radial 30, tubular 20).
 *
 * Threads: any thread.
 * Ownership: `*out` is the caller's, to free with o3d_trianglemesh_destroy(); left NULL on failure.
 * @param out receives the new handle (NULL on failure)
 * @param torus_radius radius of the centre circle
 * @param tube_radius radius of the tube
 * @param radial_resolution segments around the z axis
 * @param tubular_resolution segments around the tube
 * @return O3D_OK, or O3D_ERROR_INVALID_ARGUMENT on a NULL pointer.
 */
O3D_API o3d_status o3d_trianglemesh_create_torus(o3d_trianglemesh_t** out, double torus_radius, double tube_radius,
                                                 int32_t radial_resolution, int32_t tubular_resolution);
/**
 * @brief Arrow along z: a cylinder then a cone (defaults 1, 1.5, 5, 4, 20, 4, 1).
 *
 * Threads: any thread.
 * Ownership: `*out` is the caller's, to free with o3d_trianglemesh_destroy(); left NULL on failure.
 * @param out receives the new handle (NULL on failure)
 * @param cylinder_radius cylinder radius
 * @param cone_radius cone radius
 * @param cylinder_height cylinder height
 * @param cone_height cone height
 * @param resolution segments around the axis
 * @param cylinder_split segments along the cylinder
 * @param cone_split segments along the cone
 * @return O3D_OK, or O3D_ERROR_INVALID_ARGUMENT on a NULL pointer.
 */
O3D_API o3d_status o3d_trianglemesh_create_arrow(o3d_trianglemesh_t** out, double cylinder_radius,
                                                 double cone_radius, double cylinder_height, double cone_height,
                                                 int32_t resolution, int32_t cylinder_split, int32_t cone_split);
/**
 * @brief Coloured axes (x red, y green, z blue) of length `size` at `origin` (NULL: 0,0,0).
 *
 * Threads: any thread.
 * Ownership: `*out` is the caller's, to free with o3d_trianglemesh_destroy(); left NULL on failure.
 * @param out receives the new handle (NULL on failure)
 * @param size number of bytes at `data`
 * @param origin the frame origin (NULL: 0,0,0)
 * @return O3D_OK, or O3D_ERROR_INVALID_ARGUMENT on a NULL pointer.
 */
O3D_API o3d_status o3d_trianglemesh_create_coordinate_frame(o3d_trianglemesh_t** out, double size,
                                                            const double origin[3]);
/** TriangleMesh.create_mobius keyword arguments. */
typedef struct o3d_mobius_options {
    uint32_t struct_size; /**< sizeof(o3d_mobius_options_t) */
    o3d_count length_split; /**< columns along the band, >= 3; default 70 */
    o3d_count width_split; /**< vertices across the band, >= 2; default 15 */
    o3d_count twists;     /**< half turns along the band, >= 0 (odd: a Moebius strip); default 1 */
    double radius;        /**< radius of the band's centre circle, > 0; default 1 */
    double flatness;      /**< factor on z (0 flattens the band into the plane); default 1 */
    double width;         /**< width of the band, > 0; default 1 */
    double scale;         /**< factor on every coordinate, > 0; default 1 */
} o3d_mobius_options_t;

/**
 * @brief Fill `opts` with the defaults (Open3D's).
 *
 * Threads: any thread.
 * @param opts the struct to fill
 * @param struct_size sizeof the struct as the caller knows it (an older, smaller size is accepted)
 * @return O3D_OK, or O3D_ERROR_INVALID_ARGUMENT on a NULL pointer or a `struct_size` this library does not know.
 */
O3D_API o3d_status o3d_mobius_options_init(o3d_mobius_options_t* opts, uint32_t struct_size);
/**
 * @brief A twisted band about the z axis: length_split columns of width_split vertices, two triangles per
 * cell; an odd `twists` closes it into a one-sided Moebius strip. @see TriangleMesh.create_mobius
 *
 * Threads: any thread.
 * Ownership: `*out` is the caller's, to free with o3d_trianglemesh_destroy(); left NULL on failure.
 * @param out receives the new handle (NULL on failure)
 * @param opts options (NULL: the defaults of the matching `*_init`)
 * @return O3D_OK, or O3D_ERROR_INVALID_ARGUMENT on a NULL pointer or a bad `opts->struct_size`.
 */
O3D_API o3d_status o3d_trianglemesh_create_mobius(o3d_trianglemesh_t** out, const o3d_mobius_options_t* opts);
/**
 * @brief Regular solids inscribed in a sphere of `radius` about the origin (default 1), as Open3D documents
 * them (Open3D 0.20's icosahedron actually puts its vertices at 1.902 * radius; ours are at radius).
 *
 * Threads: any thread.
 * Ownership: `*out` is the caller's, to free with o3d_trianglemesh_destroy(); left NULL on failure.
 * @param out receives the new handle (NULL on failure)
 * @param radius the radius (> 0)
 * @return O3D_OK, or O3D_ERROR_INVALID_ARGUMENT on a NULL pointer.
 */
O3D_API o3d_status o3d_trianglemesh_create_tetrahedron(o3d_trianglemesh_t** out, double radius);
/**
 * @brief Regular octahedron inscribed in a sphere of `radius` (default 1).
 *
 * Threads: any thread.
 * Ownership: `*out` is the caller's, to free with o3d_trianglemesh_destroy(); left NULL on failure.
 * @param out receives the new handle (NULL on failure)
 * @param radius the radius (> 0)
 * @return O3D_OK, or O3D_ERROR_INVALID_ARGUMENT on a NULL pointer.
 */
O3D_API o3d_status o3d_trianglemesh_create_octahedron(o3d_trianglemesh_t** out, double radius);
/**
 * @brief Regular icosahedron inscribed in a sphere of `radius` (default 1).
 *
 * Threads: any thread.
 * Ownership: `*out` is the caller's, to free with o3d_trianglemesh_destroy(); left NULL on failure.
 * @param out receives the new handle (NULL on failure)
 * @param radius the radius (> 0)
 * @return O3D_OK, or O3D_ERROR_INVALID_ARGUMENT on a NULL pointer.
 */
O3D_API o3d_status o3d_trianglemesh_create_icosahedron(o3d_trianglemesh_t** out, double radius);

/* ---- Convex hull (Qhull) ---- */

/**
 * @brief Convex hull of a mesh's vertices. @see TriangleMesh.compute_convex_hull
 *
 * Threads: any thread; concurrent calls on the same handles are safe (all read-only).
 * Ownership: `*out_mesh` is the caller's, to free with o3d_trianglemesh_destroy(); left NULL on failure.
 * @param out_mesh receives the new handle (NULL on failure)
 * @param out_point_indices receives the indices of the hull vertices in the input (`capacity` values; NULL skips
 *   them)
 * @param capacity how many items the output buffer holds (ignored when it is NULL)
 * @param out_n receives the item count (always, also when the buffer is NULL or too small)
 * @param mesh the mesh
 * @param joggle_inputs non-zero lets Qhull perturb the input ("QJ") so degenerate sets still give a hull
 * @return O3D_OK, or O3D_ERROR_INVALID_ARGUMENT on a NULL pointer; O3D_ERROR_BUFFER_TOO_SMALL when `capacity` is
 *   short (the count is still reported).
 */
O3D_API o3d_status o3d_trianglemesh_compute_convex_hull(o3d_trianglemesh_t** out_mesh, int32_t* out_point_indices,
                                                        size_t capacity, size_t* out_n,
                                                        const o3d_trianglemesh_t* mesh, int32_t joggle_inputs);

/* ---- Oriented bounding boxes ---- */

/**
 * @brief Oriented box of a mesh's vertices. @see TriangleMesh.get_oriented_bounding_box(robust)
 *
 * Threads: any thread; concurrent calls on the same handles are safe (all read-only).
 * @param out receives the result
 * @param mesh the mesh
 * @param robust non-zero joggles the input so degenerate (e.g. planar) point sets still give a box
 * @return O3D_OK, or O3D_ERROR_INVALID_ARGUMENT on a NULL pointer.
 */
O3D_API o3d_status o3d_trianglemesh_get_oriented_bounding_box(o3d_obb_t* out, const o3d_trianglemesh_t* mesh,
                                                              int32_t robust);
/**
 * @brief Triangles whose three vertices lie inside `obb` (unused vertices dropped). @see TriangleMesh.crop
 *
 * Threads: any thread; concurrent calls on the same handles are safe (all read-only).
 * Ownership: `*out` is the caller's, to free with o3d_trianglemesh_destroy(); left NULL on failure.
 * @param out receives the new handle (NULL on failure)
 * @param mesh the mesh
 * @param obb the oriented box
 * @return O3D_OK, or O3D_ERROR_INVALID_ARGUMENT on a NULL pointer.
 */
O3D_API o3d_status o3d_trianglemesh_crop_obb(o3d_trianglemesh_t** out, const o3d_trianglemesh_t* mesh,
                                             const o3d_obb_t* obb);


/* ---- Surface reconstruction from point clouds ---- */

/** TriangleMesh.create_from_point_cloud_poisson keyword arguments, plus progress. */
typedef struct o3d_poisson_options {
    uint32_t struct_size;           /**< sizeof(o3d_poisson_options_t) */
    o3d_count depth;                /**< maximum octree depth, in [1, 16]; default 8 */
    double width;                   /**< > 0: the finest cells' width, which then sets the depth; default 0 (use depth) */
    double scale;                   /**< ratio of the reconstruction cube to the samples' bounding cube, > 0; default 1.1 */
    o3d_bool linear_fit;            /**< 1: iso-vertices by linear interpolation; default 0 */
    o3d_count num_threads;          /**< 0 = library default (Open3D's n_threads=-1); the result does not depend on it */
    o3d_progress_callback progress; /**< fraction of the work done; may be NULL */
    void* user_data;                /**< passed to `progress` */
} o3d_poisson_options_t;

/**
 * @brief Fill defaults (Open3D's).
 *
 * Threads: any thread.
 * @param opts the struct to fill
 * @param struct_size sizeof the struct as the caller knows it (an older, smaller size is accepted)
 * @return O3D_OK, or O3D_ERROR_INVALID_ARGUMENT on a NULL pointer or a `struct_size` this library does not know;
 *   O3D_ERROR_CANCELLED when the progress callback returns non-zero.
 */
O3D_API o3d_status o3d_poisson_options_init(o3d_poisson_options_t* opts, uint32_t struct_size);
/**
 * @brief Screened Poisson surface reconstruction (Kazhdan & Hoppe 2013) of an oriented cloud, on an adaptive
 * octree: a watertight mesh, and per vertex the sampling density there as an octree depth (Open3D's densities:
 * trim with `densities < quantile`). Colors are carried when the cloud has them.
 * @see TriangleMesh.create_from_point_cloud_poisson
 *
 * Threads: any thread; `pc` is only read; the progress callback runs on the calling thread.
 * Ownership: `*out_mesh` and `*out_densities` are the caller's, to free with o3d_trianglemesh_destroy() and
 * o3d_feature_destroy(); both left NULL on failure.
 * @param out_mesh receives the new handle (NULL on failure)
 * @param out_densities receives the densities as a feature of dimension 1, one value per mesh vertex
 * @param pc the point cloud, with normals
 * @param opts options (NULL: the defaults of the matching `*_init`)
 * @return O3D_OK, or O3D_ERROR_INVALID_ARGUMENT on a NULL pointer, a bad `opts->struct_size`, an empty cloud, a
 *   cloud without normals, a non-finite point or normal, or an option out of range; O3D_ERROR_CANCELLED when the
 *   progress callback returns non-zero.
 */
O3D_API o3d_status o3d_trianglemesh_create_from_point_cloud_poisson(o3d_trianglemesh_t** out_mesh,
                                                                   o3d_feature_t** out_densities,
                                                                   const o3d_pointcloud_t* pc,
                                                                   const o3d_poisson_options_t* opts);
/**
 * @brief Ball pivoting (Bernardini et al. 1999): a ball of each radius in turn, in increasing order, pivots about
 * the front's edges; the mesh's vertices are the cloud's points (with their normals and colors), its triangles
 * wound to agree with the normals. @see TriangleMesh.create_from_point_cloud_ball_pivoting
 *
 * Threads: any thread; `pc` is only read; the progress callback runs on the calling thread.
 * Ownership: `*out` is the caller's, to free with o3d_trianglemesh_destroy(); left NULL on failure.
 * @param out receives the new handle (NULL on failure)
 * @param pc the point cloud, with normals
 * @param radii the ball radii, each finite and > 0
 * @param num_radii number of radii (>= 1)
 * @param opts options (NULL: the defaults of the matching `*_init`)
 * @return O3D_OK, or O3D_ERROR_INVALID_ARGUMENT on a NULL pointer, a bad `opts->struct_size`, an empty cloud, a
 *   cloud without normals, a non-finite point, no radius or a bad one; O3D_ERROR_CANCELLED when the progress
 *   callback returns non-zero.
 */
O3D_API o3d_status o3d_trianglemesh_create_from_point_cloud_ball_pivoting(o3d_trianglemesh_t** out,
                                                                         const o3d_pointcloud_t* pc,
                                                                         const double* radii, size_t num_radii,
                                                                         const o3d_progress_options_t* opts);
/**
 * @brief The alpha shape (Edelsbrunner & Muecke 1994): the boundary of the Delaunay tetrahedra whose circumradius
 * is below `alpha`, wound outwards. @see TriangleMesh.create_from_point_cloud_alpha_shape
 *
 * Threads: any thread; the inputs are only read; the progress callback runs on the calling thread.
 * Ownership: `*out` is the caller's, to free with o3d_trianglemesh_destroy(); left NULL on failure.
 * @param out receives the new handle (NULL on failure)
 * @param pc the point cloud
 * @param alpha the alpha radius (finite, > 0)
 * @param tetramesh the Delaunay tetrahedralization of `pc` from o3d_tetramesh_create_from_point_cloud, reused
 *   (NULL: computed here)
 * @param point_map that call's point map (ignored when `tetramesh` is NULL)
 * @param num_point_map number of values in `point_map` (the tetra mesh's vertex count)
 * @param opts options (NULL: the defaults of the matching `*_init`)
 * @return O3D_OK, or O3D_ERROR_INVALID_ARGUMENT on a NULL pointer, a bad `opts->struct_size`, fewer than 4
 *   points, a non-finite point, a flat (coplanar) cloud, a bad `alpha`, or a point map that does not fit;
 *   O3D_ERROR_CANCELLED when the progress callback returns non-zero.
 */
O3D_API o3d_status o3d_trianglemesh_create_from_point_cloud_alpha_shape(o3d_trianglemesh_t** out,
                                                                       const o3d_pointcloud_t* pc, double alpha,
                                                                       const o3d_tetramesh_t* tetramesh,
                                                                       const int32_t* point_map,
                                                                       size_t num_point_map,
                                                                       const o3d_progress_options_t* opts);

/**
 * @brief The vertex adjacency list (Open3D's compute_adjacency_list / adjacency_list): list v holds the vertices
 * joined to v by a triangle side, ascending, never v itself; one list per vertex (empty for an unused vertex).
 * @see TriangleMesh.compute_adjacency_list
 *
 * Threads: any thread; concurrent calls on the same handles are safe (all read-only).
 * Ownership: `*out` is the caller's, to free with o3d_index_lists_destroy(); left NULL on failure.
 * @param out receives the new lists (NULL on failure)
 * @param mesh the mesh
 * @return O3D_OK, or O3D_ERROR_INVALID_ARGUMENT on a NULL pointer or a triangle index out of range.
 */
O3D_API o3d_status o3d_trianglemesh_compute_adjacency_list(o3d_index_lists_t** out, const o3d_trianglemesh_t* mesh);

/**
 * @brief The non-manifold edges (Open3D's get_non_manifold_edges): edges with more than two triangles, and, when
 * `allow_boundary_edges` is 0, also those with one. Each edge as (min, max) vertex index, row after row, ascending.
 * Capacity and count are in edges (rows of 2 int32).
 *
 * Threads: any thread; concurrent calls on the same handles are safe (all read-only).
 * @param out caller buffer of `capacity` rows of 2 (NULL: only report the count)
 * @param capacity how many items the output buffer holds (ignored when it is NULL)
 * @param out_n receives the item count (always, also when the buffer is NULL or too small)
 * @param mesh the mesh
 * @param allow_boundary_edges whether edges of one triangle are allowed (not listed)
 * @return O3D_OK, or O3D_ERROR_INVALID_ARGUMENT on a NULL `mesh` or `out_n`, or a triangle index out of range;
 *   O3D_ERROR_BUFFER_TOO_SMALL when `capacity` is short (the count is still reported).
 */
O3D_API o3d_status o3d_trianglemesh_get_non_manifold_edges(int32_t* out, size_t capacity, size_t* out_n,
                                                           const o3d_trianglemesh_t* mesh,
                                                           o3d_bool allow_boundary_edges);
/**
 * @brief The non-manifold vertices (Open3D's get_non_manifold_vertices): vertices whose triangles do not form one
 * fan (their link is not connected), ascending.
 *
 * Threads: any thread; concurrent calls on the same handles are safe (all read-only).
 * @param out caller buffer of `capacity` items (NULL: only report the count)
 * @param capacity how many items the output buffer holds (ignored when it is NULL)
 * @param out_n receives the item count (always, also when the buffer is NULL or too small)
 * @param mesh the mesh
 * @return O3D_OK, or O3D_ERROR_INVALID_ARGUMENT on a NULL `mesh` or `out_n`, or a triangle index out of range;
 *   O3D_ERROR_BUFFER_TOO_SMALL when `capacity` is short (the count is still reported).
 */
O3D_API o3d_status o3d_trianglemesh_get_non_manifold_vertices(int32_t* out, size_t capacity, size_t* out_n,
                                                              const o3d_trianglemesh_t* mesh);
/**
 * @brief The pairs (i < j) of triangles that share no vertex index and intersect (Open3D's
 * get_self_intersecting_triangles), ascending. Zero-area and non-finite triangles are ignored. Capacity and count
 * are in pairs (rows of 2 int32).
 *
 * Threads: any thread; concurrent calls on the same handles are safe (all read-only).
 * @param out caller buffer of `capacity` rows of 2 (NULL: only report the count)
 * @param capacity how many items the output buffer holds (ignored when it is NULL)
 * @param out_n receives the item count (always, also when the buffer is NULL or too small)
 * @param mesh the mesh
 * @return O3D_OK, or O3D_ERROR_INVALID_ARGUMENT on a NULL `mesh` or `out_n`, or a triangle index out of range;
 *   O3D_ERROR_BUFFER_TOO_SMALL when `capacity` is short (the count is still reported).
 */
O3D_API o3d_status o3d_trianglemesh_get_self_intersecting_triangles(int32_t* out, size_t capacity, size_t* out_n,
                                                                    const o3d_trianglemesh_t* mesh);
/**
 * @brief Whether any triangle of `mesh` intersects any triangle of `other` (touching counts).
 * @see TriangleMesh.is_intersecting
 *
 * Threads: any thread; concurrent calls on the same handles are safe (all read-only).
 * @param out receives 1 (true) or 0 (false)
 * @param mesh the mesh
 * @param other the other mesh
 * @return O3D_OK, or O3D_ERROR_INVALID_ARGUMENT on a NULL pointer or a triangle index out of range.
 */
O3D_API o3d_status o3d_trianglemesh_is_intersecting(int32_t* out, const o3d_trianglemesh_t* mesh,
                                                    const o3d_trianglemesh_t* other);
/**
 * @brief Turn triangles over so that every edge shared by two triangles is walked once each way (Open3D's
 * orient_triangles); in each connected part the lowest-index triangle keeps its winding, and the normals of the
 * turned triangles are negated. A mesh that cannot be oriented (a Moebius strip, an edge of three triangles) is
 * left unchanged and gives 0.
 *
 * Threads: needs exclusive access to `mesh`.
 * @param out_success receives 1 (true) or 0 (false): whether the mesh is now consistently oriented
 * @param mesh the mesh
 * @return O3D_OK, or O3D_ERROR_INVALID_ARGUMENT on a NULL pointer or a triangle index out of range.
 */
O3D_API o3d_status o3d_trianglemesh_orient_triangles(int32_t* out_success, o3d_trianglemesh_t* mesh);
/**
 * @brief Sharpening: `number_of_iterations` times, v += strength * sum over its neighbours (v - neighbour), for
 * the attributes `filter_scope` selects (Open3D's filter_sharpen; colors are not clamped, as there). Otherwise as
 * o3d_trianglemesh_filter_smooth_simple. @see TriangleMesh.filter_sharpen
 *
 * Threads: any thread; concurrent calls on the same handles are safe (all read-only).
 * Ownership: `*out` is the caller's, to free with o3d_trianglemesh_destroy(); left NULL on failure.
 * @param out receives the new handle (NULL on failure)
 * @param mesh the mesh
 * @param number_of_iterations number of iterations (>= 0)
 * @param strength the sharpening strength (finite)
 * @param filter_scope which attributes change (O3D_FILTER_SCOPE_*)
 * @return O3D_OK, or O3D_ERROR_INVALID_ARGUMENT on a NULL pointer, no vertices, a triangle index out of range, a
 *   negative iteration count, a non-finite strength or an unknown scope.
 */
O3D_API o3d_status o3d_trianglemesh_filter_sharpen(o3d_trianglemesh_t** out, const o3d_trianglemesh_t* mesh,
                                                   int32_t number_of_iterations, double strength,
                                                   o3d_filter_scope filter_scope);
/**
 * @brief An ellipsoid centred at the origin with semi-axes `radius_x`, `radius_y`, `radius_z` along x, y, z: the
 * vertices and triangles of Open3D's create_ellipsoid (2 poles and resolution - 1 rings of 2 * resolution
 * vertices), wound outwards. @see TriangleMesh.create_ellipsoid
 *
 * Threads: any thread.
 * Ownership: `*out` is the caller's, to free with o3d_trianglemesh_destroy(); left NULL on failure.
 * @param out receives the new handle (NULL on failure)
 * @param radius_x semi-axis along x (finite, > 0)
 * @param radius_y semi-axis along y (finite, > 0)
 * @param radius_z semi-axis along z (finite, > 0)
 * @param resolution rings from pole to pole (>= 2)
 * @param create_uv_map whether to add Open3D's per-corner UV coordinates
 * @return O3D_OK, or O3D_ERROR_INVALID_ARGUMENT on a NULL pointer, a bad radius or resolution.
 */
O3D_API o3d_status o3d_trianglemesh_create_ellipsoid(o3d_trianglemesh_t** out, double radius_x, double radius_y,
                                                     double radius_z, int32_t resolution, o3d_bool create_uv_map);
/**
 * @brief The minimum-volume oriented box of the vertices (o3d_obb_create_from_points_minimal).
 * @see TriangleMesh.get_minimal_oriented_bounding_box
 *
 * Threads: any thread; concurrent calls on the same handles are safe (all read-only).
 * @param out receives the box
 * @param mesh the mesh
 * @param robust joggles the input so degenerate (e.g. planar) vertex sets still give a box
 * @return O3D_OK, or O3D_ERROR_INVALID_ARGUMENT on a NULL pointer, fewer than 4 vertices, a non-finite vertex or a
 *   flat mesh without `robust`.
 */
O3D_API o3d_status o3d_trianglemesh_get_minimal_oriented_bounding_box(o3d_obb_t* out, const o3d_trianglemesh_t* mesh,
                                                                      o3d_bool robust);
/**
 * @brief The minimum-volume enclosing ellipsoid of the vertices (o3d_obe_create_from_points).
 * @see TriangleMesh.get_oriented_bounding_ellipsoid
 *
 * Threads: any thread; concurrent calls on the same handles are safe (all read-only).
 * @param out receives the ellipsoid
 * @param mesh the mesh
 * @param robust joggles the hull's input
 * @return O3D_OK, or O3D_ERROR_INVALID_ARGUMENT on a NULL pointer, fewer than 4 vertices, a non-finite vertex or a
 *   flat mesh.
 */
O3D_API o3d_status o3d_trianglemesh_get_oriented_bounding_ellipsoid(o3d_obe_t* out, const o3d_trianglemesh_t* mesh,
                                                                    o3d_bool robust);
/**
 * @brief The box as a closed mesh of 8 vertices (Open3D's corner order, get_box_points) and 12 triangles wound
 * outwards, its extents multiplied by `scale` about the centre. @see TriangleMesh.create_from_oriented_bounding_box
 *
 * Threads: any thread.
 * Ownership: `*out` is the caller's, to free with o3d_trianglemesh_destroy(); left NULL on failure.
 * @param out receives the new handle (NULL on failure)
 * @param obb the box (finite, extents >= 0, R orthonormal)
 * @param scale factors for the three extents (NULL: 1, 1, 1; finite, > 0)
 * @param create_uv_map whether to add Open3D's per-corner UV coordinates
 * @return O3D_OK, or O3D_ERROR_INVALID_ARGUMENT on a NULL pointer, an invalid box or scale.
 */
O3D_API o3d_status o3d_trianglemesh_create_from_oriented_bounding_box(o3d_trianglemesh_t** out, const o3d_obb_t* obb,
                                                                      const double scale[3], o3d_bool create_uv_map);
/**
 * @brief The ellipsoid as a mesh: o3d_trianglemesh_create_ellipsoid of its radii times `scale`, rotated by R and
 * moved to its centre, painted white as Open3D paints it. @see TriangleMesh.create_from_oriented_bounding_ellipsoid
 *
 * Threads: any thread.
 * Ownership: `*out` is the caller's, to free with o3d_trianglemesh_destroy(); left NULL on failure.
 * @param out receives the new handle (NULL on failure)
 * @param obe the ellipsoid (finite, radii > 0, R orthonormal)
 * @param scale factors for the three radii (NULL: 1, 1, 1; finite, > 0)
 * @param resolution rings from pole to pole (>= 2)
 * @param create_uv_map whether to add Open3D's per-corner UV coordinates
 * @return O3D_OK, or O3D_ERROR_INVALID_ARGUMENT on a NULL pointer, an invalid ellipsoid, scale or resolution.
 */
O3D_API o3d_status o3d_trianglemesh_create_from_oriented_bounding_ellipsoid(o3d_trianglemesh_t** out,
                                                                            const o3d_obe_t* obe, const double scale[3],
                                                                            int32_t resolution, o3d_bool create_uv_map);


/** The energy deform_as_rigid_as_possible minimises (O3D_ARAP_ENERGY_*; Open3D's DeformAsRigidAsPossibleEnergy). */
typedef int32_t o3d_arap_energy;
#define O3D_ARAP_ENERGY_SPOKES 0   /**< Sorkine & Alexa 2007: the spokes of each vertex's one-ring */
#define O3D_ARAP_ENERGY_SMOOTHED 1 /**< Spokes plus the rotation smoothness of Levi & Gotsman 2015 */

/**
 * @brief As-rigid-as-possible deformation (Sorkine & Alexa 2007; Open3D's deform_as_rigid_as_possible): moves the
 * constrained vertices to their positions and the others so that every one-ring turns as rigidly as it can, with
 * cotangent weights, alternating `max_iter` times between fitting rotations and one sparse solve (factorised once).
 * The new mesh holds the vertices and triangles only, as Open3D's. A connected part without a constraint keeps its
 * place. @see TriangleMesh.deform_as_rigid_as_possible
 *
 * Threads: any thread; concurrent calls on the same handles are safe (all read-only).
 * Ownership: `*out` is the caller's, to free with o3d_trianglemesh_destroy(); left NULL on failure.
 * @param out receives the new handle (NULL on failure)
 * @param mesh the mesh
 * @param constraint_vertex_indices the constrained vertices (distinct, in range)
 * @param num_indices number of values in `constraint_vertex_indices` (>= 1)
 * @param constraint_vertex_positions their target positions, row-major num_positions x 3 (finite)
 * @param num_positions number of positions (rows of 3 doubles; must equal `num_indices`)
 * @param max_iter number of iterations (>= 0; 0 returns the input positions)
 * @param energy O3D_ARAP_ENERGY_SPOKES or O3D_ARAP_ENERGY_SMOOTHED
 * @param smoothed_alpha the weight of the smoothness term of O3D_ARAP_ENERGY_SMOOTHED (finite; Open3D: 0.01)
 * @return O3D_OK, or O3D_ERROR_INVALID_ARGUMENT on a NULL pointer, no constraints, counts that differ, a repeated or
 *   out-of-range index, a non-finite position or vertex, a triangle index out of range, a negative `max_iter`, an unknown
 *   energy or a non-finite `smoothed_alpha`.
 */
O3D_API o3d_status o3d_trianglemesh_deform_as_rigid_as_possible(o3d_trianglemesh_t** out,
                                                                const o3d_trianglemesh_t* mesh,
                                                                const int32_t* constraint_vertex_indices,
                                                                size_t num_indices,
                                                                const double* constraint_vertex_positions,
                                                                size_t num_positions, int32_t max_iter,
                                                                o3d_arap_energy energy, double smoothed_alpha);

O3D_END_DECL

#endif /* O3D_TRIANGLEMESH_H */
