/* SPDX-License-Identifier: MIT */
/**
 * @file voxelgrid.h
 * @brief Sparse voxel grids (o3d.geometry.VoxelGrid): occupied cells of edge `voxel_size` on a grid
 * whose cell (0,0,0) starts at `origin`, each with a color.
 *
 * Voxels are always exported sorted by grid index (x, then y, then z), so the output is the same on
 * every run and platform (Open3D's order is its hash map's).
 *
 * **Out of memory:** any function here that allocates may also return O3D_ERROR_OUT_OF_MEMORY; the
 * per-function `@return` lists do not repeat it.
 */
#ifndef O3D_VOXELGRID_H
#define O3D_VOXELGRID_H

#include "o3d/common.h"
#include "o3d/types.h"
#include "o3d/camera.h"

O3D_BEGIN_DECL


/**
 * @brief Voxels holding at least one point; origin = the cloud's min bound - voxel_size / 2 (Open3D);
 * colors are the mean color of the points in each voxel (0 without colors).
 * @see VoxelGrid.create_from_point_cloud
 *
 * Threads: any thread; concurrent calls on the same handles are safe (all read-only).
 * Ownership: `*out` is the caller's, to free with o3d_voxelgrid_destroy(); left NULL on failure.
 * @param out receives the new handle (NULL on failure)
 * @param pc the point cloud
 * @param voxel_size voxel edge length (> 0)
 * @return O3D_OK, or O3D_ERROR_INVALID_ARGUMENT on a NULL pointer or a `voxel_size` that is not > 0.
 */
O3D_API o3d_status o3d_voxelgrid_create_from_point_cloud(o3d_voxelgrid_t** out, const o3d_pointcloud_t* pc,
                                                         double voxel_size);
/**
 * @brief As create_from_point_cloud, on the grid starting at min_bound; points outside the bounds ignored.
 *
 * Threads: any thread; concurrent calls on the same handles are safe (all read-only).
 * Ownership: `*out` is the caller's, to free with o3d_voxelgrid_destroy(); left NULL on failure.
 * @param out receives the new handle (NULL on failure)
 * @param pc the point cloud
 * @param voxel_size voxel edge length (> 0)
 * @param min_bound minimum corner (x, y, z)
 * @param max_bound maximum corner (x, y, z)
 * @return O3D_OK, or O3D_ERROR_INVALID_ARGUMENT on a NULL pointer or a `voxel_size` that is not > 0.
 */
O3D_API o3d_status o3d_voxelgrid_create_from_point_cloud_within_bounds(o3d_voxelgrid_t** out,
                                                                       const o3d_pointcloud_t* pc,
                                                                       double voxel_size,
                                                                       const double min_bound[3],
                                                                       const double max_bound[3]);
/**
 * @brief Voxels intersecting at least one triangle (box-triangle overlap test). @see create_from_triangle_mesh
 *
 * Threads: any thread; concurrent calls on the same handles are safe (all read-only).
 * Ownership: `*out` is the caller's, to free with o3d_voxelgrid_destroy(); left NULL on failure.
 * @param out receives the new handle (NULL on failure)
 * @param mesh the mesh
 * @param voxel_size voxel edge length (> 0)
 * @return O3D_OK, or O3D_ERROR_INVALID_ARGUMENT on a NULL pointer or a `voxel_size` that is not > 0.
 */
O3D_API o3d_status o3d_voxelgrid_create_from_triangle_mesh(o3d_voxelgrid_t** out, const o3d_trianglemesh_t* mesh,
                                                           double voxel_size);
/**
 * @brief Destroy. NULL is a no-op.
 *
 * Threads: needs exclusive access to `grid`: no other call may use it during or after.
 * @param grid the handle to destroy (NULL is a no-op)
 */
O3D_API void o3d_voxelgrid_destroy(o3d_voxelgrid_t* grid);
/**
 * @brief Edge length of a voxel.
 *
 * Threads: any thread; concurrent calls on the same handles are safe (all read-only).
 * @param out receives the result
 * @param grid the voxel grid
 * @return O3D_OK, or O3D_ERROR_INVALID_ARGUMENT on a NULL pointer.
 */
O3D_API o3d_status o3d_voxelgrid_get_voxel_size(double* out, const o3d_voxelgrid_t* grid);
/**
 * @brief Corner of voxel (0,0,0).
 *
 * Threads: any thread; concurrent calls on the same handles are safe (all read-only).
 * @param out receives the result
 * @param grid the voxel grid
 * @return O3D_OK, or O3D_ERROR_INVALID_ARGUMENT on a NULL pointer.
 */
O3D_API o3d_status o3d_voxelgrid_get_origin(double out[3], const o3d_voxelgrid_t* grid);
/**
 * @brief Number of occupied voxels.
 *
 * Threads: any thread; concurrent calls on the same handles are safe (all read-only).
 * @param out_n receives the count
 * @param grid the voxel grid
 * @return O3D_OK, or O3D_ERROR_INVALID_ARGUMENT on a NULL pointer.
 */
O3D_API o3d_status o3d_voxelgrid_num_voxels(size_t* out_n, const o3d_voxelgrid_t* grid);
/* ---- Arrays: as every geometry's (docs/conventions.md, "Arrays"); a voxel grid is read-only here,
 * so it has the copy-outs only. Rows are voxels, sorted by grid index (the same order in both). */
/** The arrays of a voxel grid (O3D_VOXELGRID_*). */
typedef int32_t o3d_voxelgrid_array;
#define O3D_VOXELGRID_COLORS 0       /**< N x 3 float64 RGB in [0,1] */
#define O3D_VOXELGRID_GRID_INDEX 100 /**< N x 3 int32 grid indices */
/**
 * @brief Whether array `which` counts (the grid has voxels).
 *
 * Threads: any thread; concurrent calls on the same handles are safe (all read-only).
 * @param out receives 1 (true) or 0 (false)
 * @param grid the voxel grid
 * @param which the array: one of this header's `which` constants
 * @return O3D_OK, or O3D_ERROR_INVALID_ARGUMENT on a NULL pointer or an unknown `which`.
 */
O3D_API o3d_status o3d_voxelgrid_has_array(int32_t* out, const o3d_voxelgrid_t* grid, o3d_voxelgrid_array which);
/**
 * @brief Rows (voxels) and columns (3) of array `which`.
 *
 * Threads: any thread; concurrent calls on the same handles are safe (all read-only).
 * @param out_rows receives the rows (items)
 * @param out_cols receives the values per row
 * @param grid the voxel grid
 * @param which the array: one of this header's `which` constants
 * @return O3D_OK, or O3D_ERROR_INVALID_ARGUMENT on a NULL pointer or an unknown `which`.
 */
O3D_API o3d_status o3d_voxelgrid_array_shape(size_t* out_rows, size_t* out_cols, const o3d_voxelgrid_t* grid,
                                             o3d_voxelgrid_array which);
/**
 * @brief Copy float64 array `which` into `out` (`capacity` rows); `*out_rows` always gets the rows needed,
 * `out` NULL only reports them. @see VoxelGrid.get_voxels
 *
 * Threads: any thread; concurrent calls on the same handles are safe (all read-only).
 * @param out caller buffer of `capacity` rows (NULL: only report the row count)
 * @param capacity rows `out` holds
 * @param out_rows receives the rows of the array (always, also when `out` is NULL or too small)
 * @param grid the voxel grid
 * @param which the array: one of this header's `which` constants
 * @return O3D_OK, or O3D_ERROR_INVALID_ARGUMENT on a NULL handle or `out_rows` or an unknown `which`;
 *   O3D_ERROR_BUFFER_TOO_SMALL when `capacity` is short (the count is still reported).
 */
O3D_API o3d_status o3d_voxelgrid_get_array(double* out, size_t capacity, size_t* out_rows, const o3d_voxelgrid_t* grid,
                                           o3d_voxelgrid_array which);
/**
 * @brief Copy int32 array `which` out, with the rules of o3d_voxelgrid_get_array.
 *
 * Threads: any thread; concurrent calls on the same handles are safe (all read-only).
 * @param out caller buffer of `capacity` rows (NULL: only report the row count)
 * @param capacity rows `out` holds
 * @param out_rows receives the rows of the array (always, also when `out` is NULL or too small)
 * @param grid the voxel grid
 * @param which the array: one of this header's `which` constants
 * @return O3D_OK, or O3D_ERROR_INVALID_ARGUMENT on a NULL handle or `out_rows` or an unknown `which`;
 *   O3D_ERROR_BUFFER_TOO_SMALL when `capacity` is short (the count is still reported).
 */
O3D_API o3d_status o3d_voxelgrid_get_index_array(int32_t* out, size_t capacity, size_t* out_rows,
                                                 const o3d_voxelgrid_t* grid, o3d_voxelgrid_array which);
/**
 * @brief Grid index of the cell containing `point` (occupied or not). @see VoxelGrid.get_voxel
 *
 * Threads: any thread; concurrent calls on the same handles are safe (all read-only).
 * @param out_index receives the grid index
 * @param grid the voxel grid
 * @param point the query point (x, y, z)
 * @return O3D_OK, or O3D_ERROR_INVALID_ARGUMENT on a NULL pointer or a non-finite `point`.
 */
O3D_API o3d_status o3d_voxelgrid_get_voxel(int32_t out_index[3], const o3d_voxelgrid_t* grid, const double point[3]);
/**
 * @brief For each of the `n` points of `xyz` (n x 3 float64), 1 in `out_included` when its cell is occupied,
 * else 0. `out_included` holds `capacity` flags; `*out_n` always gets n (`out_included` NULL only reports it).
 * @see VoxelGrid.check_if_included
 *
 * Threads: any thread; concurrent calls on the same handles are safe (all read-only).
 * @param out_included receives one 0/1 flag per point (`capacity` int32; NULL: only report the count)
 * @param capacity how many items the output buffer holds (ignored when it is NULL)
 * @param out_n receives the item count (always, also when the buffer is NULL or too small)
 * @param grid the voxel grid
 * @param xyz points, row-major n x 3 (may be NULL when n == 0)
 * @param n number of points (rows of 3 doubles) in `xyz`
 * @return O3D_OK, or O3D_ERROR_INVALID_ARGUMENT on a NULL `grid` or `out_n`, or NULL `xyz` with n > 0;
 *   O3D_ERROR_BUFFER_TOO_SMALL when `capacity` is short (the count is still reported).
 */
O3D_API o3d_status o3d_voxelgrid_check_if_included(int32_t* out_included, size_t capacity, size_t* out_n,
                                                   const o3d_voxelgrid_t* grid, const double* xyz, size_t n);

/* ---- Editing, dense grids, carving (Open3D's VoxelGrid) ---- */

/**
 * @brief A dense grid of round(width / voxel_size) x round(height / voxel_size) x round(depth / voxel_size) voxels of
 * one color, voxel (0, 0, 0) starting at `origin` (Open3D's VoxelGrid.create_dense).
 *
 * Threads: any thread.
 * Ownership: `*out` is the caller's, to free with o3d_voxelgrid_destroy(); left NULL on failure.
 * @param out receives the new handle (NULL on failure)
 * @param origin the grid's origin
 * @param color every voxel's color
 * @param voxel_size the voxel edge (finite, > 0)
 * @param width extent along x (finite, >= 0)
 * @param height extent along y (finite, >= 0)
 * @param depth extent along z (finite, >= 0)
 * @return O3D_OK, or O3D_ERROR_INVALID_ARGUMENT on a NULL pointer, a bad size or extent, or more than 2^31 voxels
 *   (checked before allocating).
 */
O3D_API o3d_status o3d_voxelgrid_create_dense(o3d_voxelgrid_t** out, const double origin[3], const double color[3],
                                              double voxel_size, double width, double height, double depth);
/**
 * @brief Voxels of the triangles that touch them (Open3D's VoxelGrid.create_from_triangle_mesh_within_bounds), on the
 * grid whose origin is `min_bound`, keeping only cells (i, j, k) with 0 <= index <= floor((max_bound - min_bound) /
 * voxel_size) on each axis (Open3D ignores `max_bound` and may also make cells at negative indices).
 *
 * Threads: any thread; concurrent calls on the same handles are safe (all read-only).
 * Ownership: `*out` is the caller's, to free with o3d_voxelgrid_destroy(); left NULL on failure.
 * @param out receives the new handle (NULL on failure)
 * @param mesh the mesh
 * @param voxel_size the voxel edge (finite, > 0)
 * @param min_bound the grid's origin
 * @param max_bound the far corner (>= min_bound)
 * @return O3D_OK, or O3D_ERROR_INVALID_ARGUMENT on a NULL pointer, a bad size or bounds, a triangle index out of
 *   range or a non-finite vertex.
 */
O3D_API o3d_status o3d_voxelgrid_create_from_triangle_mesh_within_bounds(o3d_voxelgrid_t** out,
                                                                         const o3d_trianglemesh_t* mesh,
                                                                         double voxel_size, const double min_bound[3],
                                                                         const double max_bound[3]);
/**
 * @brief Add the voxel at `grid_index` with `color`, replacing one already there (Open3D's add_voxel).
 *
 * Threads: needs exclusive access to `grid`.
 * @param grid the voxel grid
 * @param grid_index the voxel's (i, j, k)
 * @param color its color
 * @return O3D_OK, or O3D_ERROR_INVALID_ARGUMENT on a NULL pointer or a non-finite color.
 */
O3D_API o3d_status o3d_voxelgrid_add_voxel(o3d_voxelgrid_t* grid, const int32_t grid_index[3], const double color[3]);
/**
 * @brief Remove the voxel at `grid_index`; nothing happens when there is none (Open3D's remove_voxel).
 *
 * Threads: needs exclusive access to `grid`.
 * @param grid the voxel grid
 * @param grid_index the voxel's (i, j, k)
 * @return O3D_OK, or O3D_ERROR_INVALID_ARGUMENT on a NULL pointer.
 */
O3D_API o3d_status o3d_voxelgrid_remove_voxel(o3d_voxelgrid_t* grid, const int32_t grid_index[3]);
/**
 * @brief The centre of cell `grid_index`, occupied or not (Open3D's get_voxel_center_coordinate).
 *
 * Threads: any thread; concurrent calls on the same handles are safe (all read-only).
 * @param out receives the centre
 * @param grid the voxel grid
 * @param grid_index the cell's (i, j, k)
 * @return O3D_OK, or O3D_ERROR_INVALID_ARGUMENT on a NULL pointer.
 */
O3D_API o3d_status o3d_voxelgrid_get_voxel_center_coordinate(double out[3], const o3d_voxelgrid_t* grid,
                                                             const int32_t grid_index[3]);
/**
 * @brief The 8 corners of cell `grid_index` (row-major 8 x 3) in Open3D's get_voxel_bounding_points order.
 *
 * Threads: any thread; concurrent calls on the same handles are safe (all read-only).
 * @param out receives the 8 corners, row-major 8 x 3
 * @param grid the voxel grid
 * @param grid_index the cell's (i, j, k)
 * @return O3D_OK, or O3D_ERROR_INVALID_ARGUMENT on a NULL pointer.
 */
O3D_API o3d_status o3d_voxelgrid_get_voxel_bounding_points(double out[24], const o3d_voxelgrid_t* grid,
                                                           const int32_t grid_index[3]);
/**
 * @brief Space carving with a depth map (Open3D's carve_depth_map): each voxel's 8 corners are projected through
 * the camera; a voxel stays when a corner inside the image lies on or behind the observed depth (depth > 0), or,
 * with `keep_voxels_outside_image`, when a corner falls outside the image; the others are removed.
 *
 * Threads: needs exclusive access to `grid`; the other inputs are only read.
 * @param grid the voxel grid
 * @param depth a 1-channel float32 depth image in metres, of the intrinsic's size
 * @param intrinsic the camera intrinsic
 * @param extrinsic the world-to-camera transform, row-major 4x4 (rigid)
 * @param keep_voxels_outside_image whether voxels seen outside the image stay
 * @return O3D_OK, or O3D_ERROR_INVALID_ARGUMENT on a NULL pointer, an image of another format or size, a bad
 *   intrinsic or extrinsic.
 */
O3D_API o3d_status o3d_voxelgrid_carve_depth_map(o3d_voxelgrid_t* grid, const o3d_image_t* depth,
                                                 const o3d_pinhole_intrinsic_t* intrinsic, const double extrinsic[16],
                                                 o3d_bool keep_voxels_outside_image);
/**
 * @brief Space carving with a silhouette mask (Open3D's carve_silhouette): as o3d_voxelgrid_carve_depth_map, a
 * voxel staying when a corner inside the image falls on the mask (value > 0).
 *
 * Threads: needs exclusive access to `grid`; the other inputs are only read.
 * @param grid the voxel grid
 * @param mask a 1-channel float32 mask, of the intrinsic's size
 * @param intrinsic the camera intrinsic
 * @param extrinsic the world-to-camera transform, row-major 4x4 (rigid)
 * @param keep_voxels_outside_image whether voxels seen outside the image stay
 * @return O3D_OK, or O3D_ERROR_INVALID_ARGUMENT on a NULL pointer, an image of another format or size, a bad
 *   intrinsic or extrinsic.
 */
O3D_API o3d_status o3d_voxelgrid_carve_silhouette(o3d_voxelgrid_t* grid, const o3d_image_t* mask,
                                                  const o3d_pinhole_intrinsic_t* intrinsic, const double extrinsic[16],
                                                  o3d_bool keep_voxels_outside_image);
/**
 * @brief The voxel grid of an octree's leaves (Open3D's Octree.to_voxel_grid): voxel size = size / 2^max_depth,
 * origin at the octree's origin, one voxel per leaf with the leaf's color.
 *
 * Threads: any thread; concurrent calls on the same handles are safe (all read-only).
 * Ownership: `*out` is the caller's, to free with o3d_voxelgrid_destroy(); left NULL on failure.
 * @param out receives the new handle (NULL on failure)
 * @param octree the octree
 * @return O3D_OK, or O3D_ERROR_INVALID_ARGUMENT on a NULL pointer.
 */
O3D_API o3d_status o3d_voxelgrid_create_from_octree(o3d_voxelgrid_t** out, const o3d_octree_t* octree);

O3D_END_DECL

#endif /* O3D_VOXELGRID_H */
