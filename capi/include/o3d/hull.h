/* SPDX-License-Identifier: MIT */
/**
 * @file hull.h
 * @brief Convex hulls (through Qhull) and hidden-point removal (Katz, Tal, Basri 2007).
 *
 * Each writes a new triangle mesh (outward-facing triangles) to `*out_mesh` and, for each mesh vertex,
 * the index (int32) of the input point it came from to `out_point_indices` (capacity values; the input's
 * size always fits; `*out_n` always gets the count; NULL skips them).
 */
#ifndef O3D_HULL_H
#define O3D_HULL_H

#include "o3d/common.h"
#include "o3d/pointcloud.h"
#include "o3d/trianglemesh.h"

O3D_BEGIN_DECL

/**
 * @brief Convex hull of the points (>= 4, not all coplanar unless joggle_inputs != 0, which makes Qhull
 * perturb the input ("QJ") so degenerate sets still give a hull). @see PointCloud.compute_convex_hull
 */
O3D_API o3d_status o3d_pointcloud_compute_convex_hull(o3d_trianglemesh_t** out_mesh, const o3d_pointcloud_t* pc,
                                                      int32_t joggle_inputs, int32_t* out_point_indices,
                                                      size_t capacity, size_t* out_n);
/** @brief Convex hull of a mesh's vertices. @see TriangleMesh.compute_convex_hull */
O3D_API o3d_status o3d_trianglemesh_compute_convex_hull(o3d_trianglemesh_t** out_mesh,
                                                        const o3d_trianglemesh_t* mesh, int32_t joggle_inputs,
                                                        int32_t* out_point_indices, size_t capacity,
                                                        size_t* out_n);
/**
 * @brief The points visible from `camera_location`: spherical flipping with radius `radius` (> 0,
 * Open3D's parameter: larger keeps more points) then the convex hull of the flipped points and the camera.
 * @see PointCloud.hidden_point_removal
 */
O3D_API o3d_status o3d_pointcloud_hidden_point_removal(o3d_trianglemesh_t** out_mesh, const o3d_pointcloud_t* pc,
                                                       const double camera_location[3], double radius,
                                                       int32_t* out_point_indices, size_t capacity,
                                                       size_t* out_n);

O3D_END_DECL

#endif /* O3D_HULL_H */
