/* SPDX-License-Identifier: MIT */
/**
 * @file octree.h
 * @brief Octrees over point clouds (o3d.geometry.Octree with OctreePointColorLeafNode leaves):
 * a cube of edge `size` at `origin`, split to `max_depth`; each leaf keeps the indices of its points
 * and their mean color.
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

/** @brief New empty octree of `max_depth` >= 1 (Open3D: Octree(max_depth)). */
O3D_API o3d_status o3d_octree_create(o3d_octree_t** out, int32_t max_depth);
/** @brief Destroy. NULL is a no-op. */
O3D_API void o3d_octree_destroy(o3d_octree_t* octree);
/**
 * @brief Rebuild from a cloud: the root cube is the cloud's bounding cube enlarged by `size_expand`
 * (a fraction >= 0, Open3D default 0.01), every point inserted. @see Octree.convert_from_point_cloud
 */
O3D_API o3d_status o3d_octree_convert_from_point_cloud(o3d_octree_t* octree, const o3d_pointcloud_t* pc,
                                                       double size_expand);
/** @brief Root origin, root edge and max depth (any output may be NULL). */
O3D_API o3d_status o3d_octree_get_root(double out_origin[3], double* out_size, int32_t* out_max_depth,
                                       const o3d_octree_t* octree);
/** @brief Number of non-empty leaves. */
O3D_API o3d_status o3d_octree_num_leaf_nodes(size_t* out_n, const o3d_octree_t* octree);
/**
 * @brief The leaf containing `point`: `*out_found` = 0 when the point is outside the root or in an empty
 * cell (Open3D returns None); else the leaf's node info, mean color (either may be NULL) and its point
 * indices (int32, ascending, copy-out convention; NULL skips them).
 * @see Octree.locate_leaf_node
 */
O3D_API o3d_status o3d_octree_locate_leaf_node(int32_t* out_found, o3d_octree_node_info_t* out_info,
                                               double out_color[3], int32_t* out_indices, size_t capacity,
                                               size_t* out_n, const o3d_octree_t* octree, const double point[3]);

O3D_END_DECL

#endif /* O3D_OCTREE_H */
