/* SPDX-License-Identifier: MIT */
/**
 * @file octree.h
 * @brief Octrees over point clouds (o3d.geometry.Octree with OctreePointColorLeafNode leaves):
 * a cube of edge `size` at `origin`, split to `max_depth`; each leaf keeps the indices of its points
 * and their mean color.
 *
 * **Out of memory:** any function here that allocates may also return O3D_ERROR_OUT_OF_MEMORY; the
 * per-function `@return` lists do not repeat it.
 */
#ifndef O3D_OCTREE_H
#define O3D_OCTREE_H

#include "o3d/common.h"
#include "o3d/types.h"

O3D_BEGIN_DECL


/** o3d.geometry.OctreeNodeInfo: where a node sits (frozen layout). */
typedef struct o3d_octree_node_info {
    double origin[3];    /**< the node cube's min corner */
    double size;         /**< the node cube's edge */
    int32_t depth;       /**< 0 for the root */
    int32_t child_index; /**< 0..7 within its parent (0 for the root) */
} o3d_octree_node_info_t;

/**
 * @brief New empty octree of `max_depth` >= 1 (Open3D: Octree(max_depth)).
 *
 * Threads: any thread.
 * Ownership: `*out` is the caller's, to free with o3d_octree_destroy(); left NULL on failure.
 * @param out receives the new handle (NULL on failure)
 * @param max_depth the depth (>= 1)
 * @return O3D_OK, or O3D_ERROR_INVALID_ARGUMENT on a NULL pointer or `max_depth` < 1.
 */
O3D_API o3d_status o3d_octree_create(o3d_octree_t** out, int32_t max_depth);
/**
 * @brief Destroy. NULL is a no-op.
 *
 * Threads: needs exclusive access to `octree`: no other call may use it during or after.
 * @param octree the handle to destroy (NULL is a no-op)
 */
O3D_API void o3d_octree_destroy(o3d_octree_t* octree);
/**
 * @brief Rebuild from a cloud: the root cube is the cloud's bounding cube enlarged by `size_expand`
 * (a fraction >= 0, Open3D default 0.01), every point inserted. @see Octree.convert_from_point_cloud
 *
 * Threads: needs exclusive access to `octree`; `pc` is only read.
 * @param octree the octree
 * @param pc the point cloud
 * @param size_expand enlargement of the root cube, a fraction >= 0
 * @return O3D_OK, or O3D_ERROR_INVALID_ARGUMENT on a NULL pointer or a negative or non-finite `size_expand`.
 */
O3D_API o3d_status o3d_octree_convert_from_point_cloud(o3d_octree_t* octree, const o3d_pointcloud_t* pc,
                                                       double size_expand);
/**
 * @brief Root origin, root edge and max depth (any output may be NULL).
 *
 * Threads: any thread; concurrent calls on the same handles are safe (all read-only).
 * @param out_origin receives the root cube's min corner (may be NULL)
 * @param out_size receives the size in bytes
 * @param out_max_depth receives the max depth (may be NULL)
 * @param octree the octree
 * @return O3D_OK, or O3D_ERROR_INVALID_ARGUMENT on a NULL `octree`.
 */
O3D_API o3d_status o3d_octree_get_root(double out_origin[3], double* out_size, int32_t* out_max_depth,
                                       const o3d_octree_t* octree);
/**
 * @brief Number of non-empty leaves.
 *
 * Threads: any thread; concurrent calls on the same handles are safe (all read-only).
 * @param out_n receives the count
 * @param octree the octree
 * @return O3D_OK, or O3D_ERROR_INVALID_ARGUMENT on a NULL pointer.
 */
O3D_API o3d_status o3d_octree_num_leaf_nodes(size_t* out_n, const o3d_octree_t* octree);
/**
 * @brief The leaf containing `point`: `*out_found` = 0 when the point is outside the root or in an empty
 * cell (Open3D returns None); else the leaf's node info, mean color (either may be NULL) and its point
 * indices (int32, ascending, copy-out convention; NULL skips them).
 * @see Octree.locate_leaf_node
 *
 * Threads: any thread; concurrent calls on the same handles are safe (all read-only).
 * @param out_found receives 1 when a leaf was found, else 0
 * @param out_info receives the leaf's node info (may be NULL)
 * @param out_color receives the leaf's mean color (may be NULL)
 * @param out_indices receives the indices (`capacity` int32; NULL skips them)
 * @param capacity how many items the output buffer holds (ignored when it is NULL)
 * @param out_n receives the index count (may be NULL)
 * @param octree the octree
 * @param point the query point (x, y, z)
 * @return O3D_OK, or O3D_ERROR_INVALID_ARGUMENT on a NULL `octree`, `out_found` or `point`, or a non-finite
 *   `point`; O3D_ERROR_BUFFER_TOO_SMALL when `capacity` is short (the count is still reported).
 */
O3D_API o3d_status o3d_octree_locate_leaf_node(int32_t* out_found, o3d_octree_node_info_t* out_info,
                                               double out_color[3], int32_t* out_indices, size_t capacity,
                                               size_t* out_n, const o3d_octree_t* octree, const double point[3]);

/**
 * @brief New empty octree of `max_depth` over the cube of edge `size` at `origin` (Open3D's
 * Octree(max_depth, origin, size)).
 *
 * Threads: any thread.
 * Ownership: `*out` is the caller's, to free with o3d_octree_destroy(); left NULL on failure.
 * @param out receives the new handle (NULL on failure)
 * @param max_depth the depth (1 to 21)
 * @param origin the root cube's min corner
 * @param size the root cube's edge (finite, > 0)
 * @return O3D_OK, or O3D_ERROR_INVALID_ARGUMENT on a NULL pointer, a bad depth, origin or size.
 */
O3D_API o3d_status o3d_octree_create_with_bounds(o3d_octree_t** out, int32_t max_depth, const double origin[3],
                                                 double size);
/**
 * @brief Whether `point` lies in the half-open cube [origin, origin + size)^3 (Open3D's static
 * Octree.is_point_in_bound).
 *
 * Threads: any thread.
 * @param out receives 1 (true) or 0 (false)
 * @param point the point
 * @param origin the cube's min corner
 * @param size the cube's edge
 * @return O3D_OK, or O3D_ERROR_INVALID_ARGUMENT on a NULL pointer.
 */
O3D_API o3d_status o3d_octree_is_point_in_bound(int32_t* out, const double point[3], const double origin[3],
                                                double size);
/**
 * @brief Insert point number `index` with `color` into the leaf at max depth that holds `point`, creating the
 * nodes on the way (Open3D's insert_point with OctreePointColorLeafNode leaves): the leaf keeps its indices
 * ascending and unique and the mean color of its points. A point outside the root cube changes nothing.
 *
 * Threads: needs exclusive access to `octree`.
 * @param out_inserted receives 1 (true) or 0 (false): whether the point was inside the root cube
 * @param octree the octree
 * @param point the point (finite)
 * @param index the point's index (>= 0)
 * @param color the point's color (finite)
 * @return O3D_OK, or O3D_ERROR_INVALID_ARGUMENT on a NULL pointer, a non-finite point or color, a negative index.
 */
O3D_API o3d_status o3d_octree_insert_point(int32_t* out_inserted, o3d_octree_t* octree, const double point[3],
                                           int32_t index, const double color[3]);
/**
 * @brief Rebuild the octree from a voxel grid (Open3D's create_from_voxel_grid): the root at the grid's origin
 * (lowered to the lowest index when some are negative) with the edge of the grid's largest extent, one leaf per
 * voxel centre at the octree's max depth holding the voxel's color and its position in the grid's voxel order.
 *
 * Threads: needs exclusive access to `octree`; `grid` is only read.
 * @param octree the octree (its max depth is kept)
 * @param grid the voxel grid
 * @return O3D_OK, or O3D_ERROR_INVALID_ARGUMENT on a NULL pointer.
 */
O3D_API o3d_status o3d_octree_create_from_voxel_grid(o3d_octree_t* octree, const o3d_voxelgrid_t* grid);

O3D_END_DECL

#endif /* O3D_OCTREE_H */
