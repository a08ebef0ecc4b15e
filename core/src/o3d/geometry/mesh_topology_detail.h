// SPDX-License-Identifier: MIT
#pragma once
/// @file mesh_topology_detail.h
/// @brief Internal: the vertex-link and orientation tests behind is_vertex_manifold / is_orientable, shared
/// with the queries that list or repair what those tests find (mesh_non_manifold, mesh_orientation), so
/// that the answers agree. Each assumes validated triangles.
#include <vector>

#include "o3d/geometry/mesh_adjacency.h"
#include "o3d/geometry/triangle_mesh.h"

namespace o3d::geometry::detail {

/// @brief Whether the link of vertex v (the edges opposite v in its triangles, chosen as Open3D chooses
/// them; a triangle holding v twice has none) is one connected graph; true for an empty link.
/// `ends`, `nodes` and `parent` are scratch space, reused across calls.
bool link_is_connected(const TriangleMesh& mesh, const VertexTriangles& around, int v, std::vector<int>& ends,
                       std::vector<int>& nodes, std::vector<int>& parent);

/// @brief A consistent orientation: `flipped[t]` = 1 for the triangles to turn over, 0 otherwise. Triangles
/// tied by an edge with exactly two sides form components; each component's lowest-index triangle keeps
/// its winding (flipped = 0). False (flipped unspecified) when no such orientation exists, including
/// when an edge carries more than two sides.
bool consistent_orientation(const TriangleMesh& mesh, std::vector<int>& flipped);

}  // namespace o3d::geometry::detail
