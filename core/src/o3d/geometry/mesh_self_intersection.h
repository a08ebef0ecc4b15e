// SPDX-License-Identifier: MIT
#pragma once
/// @file mesh_self_intersection.h
/// @brief Triangle-triangle intersection (Moller 1997, "A fast triangle-triangle intersection test") and
/// the mesh self-intersection query built on it with a uniform-grid broad phase.
#include <Eigen/Core>

#include "o3d/geometry/triangle_mesh.h"

namespace o3d::geometry {

/// @brief Whether the closed triangles (p0, p1, p2) and (q0, q1, q2) share a point. Touching counts;
/// signed distances below 1e-10 of the triangles' size count as touching. Zero-area triangles never
/// intersect anything.
bool triangles_intersect(const Eigen::Vector3d& p0, const Eigen::Vector3d& p1, const Eigen::Vector3d& p2,
                         const Eigen::Vector3d& q0, const Eigen::Vector3d& q1, const Eigen::Vector3d& q2);

/// @brief Whether two triangles that share no vertex index intersect (Open3D's is_self_intersecting).
/// Triangles with a non-finite coordinate or zero area are ignored. Expected O(M) on surface meshes.
/// @throws InvalidArgument on an out-of-range triangle index.
bool is_self_intersecting(const TriangleMesh& mesh);

}  // namespace o3d::geometry
