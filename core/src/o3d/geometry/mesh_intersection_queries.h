// SPDX-License-Identifier: MIT
#pragma once
/// @file mesh_intersection_queries.h
/// @brief Which triangles of a mesh cross each other, and whether two meshes touch (Open3D's
/// TriangleMesh.get_self_intersecting_triangles / is_intersecting), on triangles_intersect
/// (mesh_self_intersection.h) with a uniform-grid broad phase instead of Open3D's all-pairs loop.
#include <Eigen/Core>
#include <vector>

#include "o3d/geometry/triangle_mesh.h"

namespace o3d::geometry {

/// @brief The pairs (i, j), i < j, of triangles that share no vertex index and intersect (touching counts),
/// sorted ascending. Triangles with a non-finite coordinate or zero area are left out, as
/// is_self_intersecting leaves them out, so it answers true exactly when this list is not empty. Empty for
/// fewer than two triangles (Open3D 0.20 reads past the end of an empty mesh). Expected O(M + pairs) on
/// surface meshes. @throws InvalidArgument on an out-of-range triangle index.
std::vector<Eigen::Vector2i> self_intersecting_triangles(const TriangleMesh& mesh);

/// @brief Whether any triangle of `a` intersects any triangle of `b` (touching counts; shared vertex indices
/// mean nothing across two meshes). Triangles with a non-finite coordinate or zero area are left out; a mesh
/// without triangles intersects nothing. A surface strictly inside the other's enclosed volume does not
/// intersect it. @throws InvalidArgument on an out-of-range triangle index in either mesh.
bool meshes_intersect(const TriangleMesh& a, const TriangleMesh& b);

}  // namespace o3d::geometry
