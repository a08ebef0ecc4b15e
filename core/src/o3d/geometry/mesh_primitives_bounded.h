// SPDX-License-Identifier: MIT
#pragma once
/// @file mesh_primitives_bounded.h
/// @brief Closed meshes of ellipsoids and of oriented bounding volumes (Open3D 0.20's
/// TriangleMesh.create_ellipsoid, create_from_oriented_bounding_box, create_from_oriented_bounding_ellipsoid):
/// the same vertex and triangle order, winding (outward) and UV maps as the wheel.
#include <Eigen/Core>

#include "o3d/geometry/oriented_bounding_box.h"
#include "o3d/geometry/oriented_bounding_ellipsoid.h"
#include "o3d/geometry/triangle_mesh.h"

namespace o3d::geometry {

/// @brief UV ellipsoid about the origin with semi-axes radius_x, radius_y, radius_z along x, y, z: the poles
/// (0, 0, +-radius_z), then resolution - 1 rings of 2 * resolution vertices from the top; 2 + 2r(r - 1)
/// vertices, 4r(r - 1) triangles. Open3D computes it as create_sphere scaled per axis (equal radii give its
/// sphere bit for bit). `create_uv_map` adds Open3D's per-corner UVs (u = ring / resolution, v = column /
/// (2 resolution), a seam at v = 1). @throws InvalidArgument on a radius <= 0 or not finite, a resolution
/// < 2 (Open3D indexes past its vertices at 1) or one whose vertices int32 indices cannot reach.
TriangleMesh create_ellipsoid(double radius_x = 1.0, double radius_y = 1.0, double radius_z = 1.0,
                              int resolution = 20, bool create_uv_map = false);

/// @brief The box as a mesh: create_box(extent * scale) (8 vertices, 12 triangles, in create_box's order),
/// turned by R about its middle and centred on the box's centre; with `scale` 1 its vertices are the box's
/// corners (in create_box's order, not box_points'). `create_uv_map` adds Open3D's cube-net UVs.
/// @throws InvalidArgument on an invalid box (validate_obb), a scale not finite, or a scaled extent <= 0.
TriangleMesh mesh_from_oriented_bounding_box(const OrientedBoundingBox& box,
                                             const Eigen::Vector3d& scale = Eigen::Vector3d::Ones(),
                                             bool create_uv_map = false);

/// @brief The ellipsoid as a mesh: create_ellipsoid(radii * scale, resolution, create_uv_map) mapped by
/// R v + center. Every vertex gets the color (1, 1, 1): Open3D paints the ellipsoid's color, white unless set,
/// and OrientedBoundingEllipsoid carries none here. @throws InvalidArgument on a non-finite centre or R, an
/// R that is not orthonormal (1e-6), or what create_ellipsoid throws for the scaled radii.
TriangleMesh mesh_from_oriented_bounding_ellipsoid(const OrientedBoundingEllipsoid& ellipsoid,
                                                   const Eigen::Vector3d& scale = Eigen::Vector3d::Ones(),
                                                   int resolution = 20, bool create_uv_map = false);

}  // namespace o3d::geometry
