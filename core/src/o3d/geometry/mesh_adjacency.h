// SPDX-License-Identifier: MIT
#pragma once
/// @file mesh_adjacency.h
/// @brief Edge and vertex-neighbour tables of a triangle mesh, in flat (CSR) arrays with a fixed order, so
/// every algorithm built on them is deterministic (Open3D keeps these in hash sets of unspecified order).
#include <Eigen/Core>
#include <vector>

#include "o3d/geometry/triangle_mesh.h"

namespace o3d::geometry {

/// @brief The undirected edges of a mesh. Edges are numbered in order of first appearance when the
/// triangles are scanned in order, each through its sides (0,1), (1,2), (2,0): the order in which Open3D's
/// subdivision creates edge vertices.
struct MeshEdges {
    std::vector<Eigen::Vector2i> endpoints;  ///< (min, max) vertex of each edge
    std::vector<int> side_edge;              ///< 3 * t + k -> edge of side k of triangle t
    std::vector<int> triangle_offsets;       ///< triangles of edge e: triangles[offsets[e] .. offsets[e + 1])
    std::vector<int> triangles;              ///< ascending within each edge

    size_t size() const { return endpoints.size(); }
    int triangle_count(size_t e) const { return triangle_offsets[e + 1] - triangle_offsets[e]; }
};

/// @brief Build the edge table. Assumes validated triangles (validate_triangles).
MeshEdges mesh_edges(const TriangleMesh& mesh);

/// @brief Distinct neighbours of every vertex (joined by a triangle side), ascending; a vertex is never
/// its own neighbour. Neighbours of v: neighbours[offsets[v] .. offsets[v + 1]).
struct VertexNeighbours {
    std::vector<int> offsets;
    std::vector<int> neighbours;

    int count(size_t v) const { return offsets[v + 1] - offsets[v]; }
    const int* begin(size_t v) const { return neighbours.data() + offsets[v]; }
    const int* end(size_t v) const { return neighbours.data() + offsets[v + 1]; }
};

/// @brief Neighbour table from an edge table of the same mesh.
VertexNeighbours vertex_neighbours(const MeshEdges& edges, size_t num_vertices);

/// @brief Triangles around every vertex (CSR, ascending; a triangle repeating a vertex is listed once).
struct VertexTriangles {
    std::vector<int> offsets;
    std::vector<int> triangles;
};

VertexTriangles vertex_triangles(const TriangleMesh& mesh);

}  // namespace o3d::geometry
