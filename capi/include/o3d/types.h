/* SPDX-License-Identifier: MIT */
/**
 * @file types.h
 * @brief The opaque handle types, declared once so that each module header can name the others' handles.
 *
 * Every handle is created by an `o3d_<noun>_create*` function (or another function writing a `T** out`),
 * belongs to the caller, and is destroyed with `o3d_<noun>_destroy` (NULL is a no-op). Handles are
 * independent of one another and may be destroyed in any order.
 */
#ifndef O3D_TYPES_H
#define O3D_TYPES_H

#include "o3d/common.h"

O3D_BEGIN_DECL

typedef struct o3d_camera_trajectory o3d_camera_trajectory_t; /**< opaque handle */
typedef struct o3d_feature o3d_feature_t; /**< opaque handle */
typedef struct o3d_halfedgemesh o3d_halfedgemesh_t; /**< opaque handle */
typedef struct o3d_image o3d_image_t; /**< opaque handle */
typedef struct o3d_index_lists o3d_index_lists_t; /**< opaque handle */
typedef struct o3d_kdtree o3d_kdtree_t; /**< opaque handle */
typedef struct o3d_lineset o3d_lineset_t; /**< opaque handle */
typedef struct o3d_octree o3d_octree_t; /**< opaque handle */
typedef struct o3d_offscreen_renderer o3d_offscreen_renderer_t; /**< opaque handle */
typedef struct o3d_pointcloud o3d_pointcloud_t; /**< opaque handle */
typedef struct o3d_pose_graph o3d_pose_graph_t; /**< opaque handle */
typedef struct o3d_registration_result o3d_registration_result_t; /**< opaque handle */
typedef struct o3d_rgbd_image o3d_rgbd_image_t; /**< opaque handle */
typedef struct o3d_search_result o3d_search_result_t; /**< opaque handle */
typedef struct o3d_selection_polygon_volume o3d_selection_polygon_volume_t; /**< opaque handle */
typedef struct o3d_tetramesh o3d_tetramesh_t; /**< opaque handle */
typedef struct o3d_trianglemesh o3d_trianglemesh_t; /**< opaque handle */
typedef struct o3d_tsdf_volume o3d_tsdf_volume_t; /**< opaque handle */
typedef struct o3d_visualizer o3d_visualizer_t; /**< opaque handle */
typedef struct o3d_voxelgrid o3d_voxelgrid_t; /**< opaque handle */

O3D_END_DECL

#endif /* O3D_TYPES_H */
