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
#include "o3d/pointcloud.h"
#include "o3d/trianglemesh.h"

O3D_BEGIN_DECL

typedef struct o3d_voxelgrid o3d_voxelgrid_t;

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
O3D_API o3d_status o3d_voxelgrid_get_voxel_size(const o3d_voxelgrid_t* grid, double* out);
/** @brief Corner of voxel (0,0,0). */
O3D_API o3d_status o3d_voxelgrid_get_origin(const o3d_voxelgrid_t* grid, double out[3]);
/** @brief Number of occupied voxels. */
O3D_API o3d_status o3d_voxelgrid_num_voxels(const o3d_voxelgrid_t* grid, size_t* out_n);
/**
 * @brief Copy the voxels out sorted by grid index: `out_grid_index` (capacity x 3 int32) and
 * `out_colors` (capacity x 3 float64); either may be NULL. `*out_n` always gets the count.
 * @see VoxelGrid.get_voxels
 */
O3D_API o3d_status o3d_voxelgrid_get_voxels(const o3d_voxelgrid_t* grid, int32_t* out_grid_index,
                                            double* out_colors, size_t capacity, size_t* out_n);
/** @brief Grid index of the cell containing `point` (occupied or not). @see VoxelGrid.get_voxel */
O3D_API o3d_status o3d_voxelgrid_get_voxel(const o3d_voxelgrid_t* grid, const double point[3], int32_t out_index[3]);
/** @brief For each of `n` points, 1 when its cell is occupied, else 0. @see VoxelGrid.check_if_included */
O3D_API o3d_status o3d_voxelgrid_check_if_included(const o3d_voxelgrid_t* grid, const double* xyz, size_t n,
                                                   int32_t* out_included);

O3D_END_DECL

#endif /* O3D_VOXELGRID_H */
