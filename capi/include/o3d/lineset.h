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

#include "o3d/boundingbox.h"
#include "o3d/common.h"
#include "o3d/pointcloud.h"
#include "o3d/trianglemesh.h"

O3D_BEGIN_DECL

typedef struct o3d_lineset o3d_lineset_t;

/* Float64 arrays of a line set (the `which` of the *_array functions). */
#define O3D_LINESET_POINTS 0 /**< N x 3 */
#define O3D_LINESET_COLORS 1 /**< M x 3, one per line */

/** @brief New empty line set. */
O3D_API o3d_status o3d_lineset_create(o3d_lineset_t** out);
/** @brief Destroy. NULL is a no-op. */
O3D_API void o3d_lineset_destroy(o3d_lineset_t* lineset);
/** @brief Deep copy. */
O3D_API o3d_status o3d_lineset_clone(o3d_lineset_t** out, const o3d_lineset_t* src);
/** @brief Number of points. */
O3D_API o3d_status o3d_lineset_num_points(const o3d_lineset_t* lineset, size_t* out_n);
/** @brief Number of lines. */
O3D_API o3d_status o3d_lineset_num_lines(const o3d_lineset_t* lineset, size_t* out_n);
/** @brief Replace the float64 array `which` with `rows` rows of `data` (copied; NULL when rows == 0). */
O3D_API o3d_status o3d_lineset_set_array(o3d_lineset_t* lineset, int32_t which, const double* data, size_t rows);
/** @brief Copy the float64 array `which` out (copy-out convention: `*out_rows` always set). */
O3D_API o3d_status o3d_lineset_get_array(const o3d_lineset_t* lineset, int32_t which, double* out,
                                         size_t capacity, size_t* out_rows);
/** @brief Borrowed read-only view of the float64 array `which`. */
O3D_API o3d_status o3d_lineset_array_view(const o3d_lineset_t* lineset, int32_t which, const double** out_data,
                                          size_t* out_rows);
/** @brief Replace the lines (M x 2 int32). */
O3D_API o3d_status o3d_lineset_set_lines(o3d_lineset_t* lineset, const int32_t* data, size_t rows);
/** @brief Copy the lines out (copy-out convention). */
O3D_API o3d_status o3d_lineset_get_lines(const o3d_lineset_t* lineset, int32_t* out, size_t capacity,
                                         size_t* out_rows);
/** @brief Borrowed read-only view of the lines. */
O3D_API o3d_status o3d_lineset_lines_view(const o3d_lineset_t* lineset, const int32_t** out_data, size_t* out_rows);
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
