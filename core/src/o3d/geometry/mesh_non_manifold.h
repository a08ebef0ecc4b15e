// SPDX-License-Identifier: MIT
#pragma once
/// @file mesh_non_manifold.h
/// @brief Where a mesh fails to be a manifold (Open3D's TriangleMesh.get_non_manifold_edges / _vertices):
/// the lists behind is_edge_manifold and is_vertex_manifold (mesh_topology.h), which answer true exactly
/// when these are empty.
#include <Eigen/Core>
#include <vector>

#include "o3d/geometry/triangle_mesh.h"

namespace o3d::geometry {

/// @brief The edges used by more than two triangle sides, and also, unless `allow_boundary_edges`, those
/// used by one (boundary edges): every edge not used by exactly two sides. Sides are counted as Open3D
/// counts them: a triangle repeating a vertex counts twice on its doubled edge. Each edge is (min, max)
/// vertex index; the list is sorted ascending (Open3D returns hash order). Empty for a mesh without
/// triangles. @throws InvalidArgument on an out-of-range triangle index.
std::vector<Eigen::Vector2i> non_manifold_edges(const TriangleMesh& mesh, bool allow_boundary_edges = true);

/// @brief The vertices whose star is not a single fan: the edges opposite the vertex in its triangles (its
/// link) do not form one connected graph, e.g. the tip shared by two cones (a bow tie). Unused vertices and
/// vertices whose triangles all repeat them are manifold. Ascending (Open3D's order).
/// @throws InvalidArgument on an out-of-range triangle index.
std::vector<int> non_manifold_vertices(const TriangleMesh& mesh);

}  // namespace o3d::geometry
