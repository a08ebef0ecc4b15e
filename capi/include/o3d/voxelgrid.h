/* SPDX-License-Identifier: MIT */
/**
 * @file voxelgrid.h
 * @brief Sparse voxel grids (o3d.geometry.VoxelGrid): occupied cells of edge `voxel_size` on a grid
 * whose cell (0,0,0) starts at `origin`, each with a color.
 *
 * Voxels are always exported sorted by grid index (x, then y, then z), so the output is the same on
 * every run and platform (Open3D's order is its hash map's).
 */
#ifndef O3D_VOXELGRID_H
#define O3D_VOXELGRID_H

#include "o3d/common.h"
#include "o3d/types.h"

O3D_BEGIN_DECL


/**
 * @brief Voxels holding at least one point; origin = the cloud's min bound - voxel_size / 2 (Open3D);
 * colors are the mean color of the points in each voxel (0 without colors).
 * @see VoxelGrid.create_from_point_cloud
 */
O3D_API o3d_status o3d_voxelgrid_create_from_point_cloud(o3d_voxelgrid_t** out, const o3d_pointcloud_t* pc,
                                                         double voxel_size);
/** @brief As create_from_point_cloud, on the grid starting at min_bound; points outside the bounds ignored. */
O3D_API o3d_status o3d_voxelgrid_create_from_point_cloud_within_bounds(o3d_voxelgrid_t** out,
                                                                       const o3d_pointcloud_t* pc,
                                                                       double voxel_size,
                                                                       const double min_bound[3],
                                                                       const double max_bound[3]);
/** @brief Voxels intersecting at least one triangle (box-triangle overlap test). @see create_from_triangle_mesh */
O3D_API o3d_status o3d_voxelgrid_create_from_triangle_mesh(o3d_voxelgrid_t** out, const o3d_trianglemesh_t* mesh,
                                                           double voxel_size);
/** @brief Destroy. NULL is a no-op. */
O3D_API void o3d_voxelgrid_destroy(o3d_voxelgrid_t* grid);
/** @brief Edge length of a voxel. */
O3D_API o3d_status o3d_voxelgrid_get_voxel_size(double* out, const o3d_voxelgrid_t* grid);
/** @brief Corner of voxel (0,0,0). */
O3D_API o3d_status o3d_voxelgrid_get_origin(double out[3], const o3d_voxelgrid_t* grid);
/** @brief Number of occupied voxels. */
O3D_API o3d_status o3d_voxelgrid_num_voxels(size_t* out_n, const o3d_voxelgrid_t* grid);
/* ---- Arrays: as every geometry's (docs/conventions.md, "Arrays"); a voxel grid is read-only here,
 * so it has the copy-outs only. Rows are voxels, sorted by grid index (the same order in both). */
#define O3D_VOXELGRID_COLORS 0       /**< N x 3 float64 RGB in [0,1] */
#define O3D_VOXELGRID_GRID_INDEX 100 /**< N x 3 int32 grid indices */
/** @brief Whether array `which` counts (the grid has voxels). @return O3D_ERROR_INVALID_ARGUMENT on NULL or an unknown `which`. */
O3D_API o3d_status o3d_voxelgrid_has_array(int32_t* out, const o3d_voxelgrid_t* grid, int32_t which);
/** @brief Rows (voxels) and columns (3) of array `which`. @return O3D_ERROR_INVALID_ARGUMENT on NULL or an unknown `which`. */
O3D_API o3d_status o3d_voxelgrid_array_shape(size_t* out_rows, size_t* out_cols, const o3d_voxelgrid_t* grid,
                                             int32_t which);
/**
 * @brief Copy float64 array `which` into `out` (`capacity` rows); `*out_rows` always gets the rows needed,
 * `out` NULL only reports them. @return O3D_ERROR_BUFFER_TOO_SMALL when capacity is short,
 * O3D_ERROR_INVALID_ARGUMENT on a NULL grid or out_rows or an unknown `which`. @see VoxelGrid.get_voxels
 */
O3D_API o3d_status o3d_voxelgrid_get_array(double* out, size_t capacity, size_t* out_rows, const o3d_voxelgrid_t* grid,
                                           int32_t which);
/** @brief Copy int32 array `which` out, with the rules of o3d_voxelgrid_get_array. */
O3D_API o3d_status o3d_voxelgrid_get_index_array(int32_t* out, size_t capacity, size_t* out_rows,
                                                 const o3d_voxelgrid_t* grid, int32_t which);
/** @brief Grid index of the cell containing `point` (occupied or not). @see VoxelGrid.get_voxel */
O3D_API o3d_status o3d_voxelgrid_get_voxel(int32_t out_index[3], const o3d_voxelgrid_t* grid, const double point[3]);
/**
 * @brief For each of the `n` points of `xyz` (n x 3 float64), 1 in `out_included` when its cell is occupied,
 * else 0. `out_included` holds `capacity` flags; `*out_n` always gets n (`out_included` NULL only reports it).
 * @return O3D_ERROR_BUFFER_TOO_SMALL when capacity < n; O3D_ERROR_INVALID_ARGUMENT on a NULL grid, out_n, or
 * xyz with n > 0. Thread-safe on a const grid. @see VoxelGrid.check_if_included
 */
O3D_API o3d_status o3d_voxelgrid_check_if_included(int32_t* out_included, size_t capacity, size_t* out_n,
                                                   const o3d_voxelgrid_t* grid, const double* xyz, size_t n);

O3D_END_DECL

#endif /* O3D_VOXELGRID_H */
