// SPDX-License-Identifier: MIT
#pragma once
/// @file half_edge_mesh.h
/// @brief Open3D's HalfEdgeTriangleMesh: a manifold triangle mesh with half-edges, for walking one-rings
/// and boundary loops.
#include <Eigen/Core>
#include <vector>

#include "o3d/geometry/triangle_mesh.h"

namespace o3d::geometry {

/// @brief One directed side of a triangle (Open3D's HalfEdge).
struct HalfEdge {
    int next = -1;                                  ///< the following half-edge of the same triangle
    int twin = -1;                                  ///< the opposite half-edge, -1 on a boundary
    Eigen::Vector2i vertex_indices{-1, -1};         ///< (from, to)
    int triangle_index = -1;                        ///< the triangle this half-edge bounds

    /// @brief No twin: the edge lies on the boundary.
    bool is_boundary() const { return twin == -1; }
};

/// @brief A cleaned copy of a triangle mesh with its half-edges. Half-edge 3t + k is side k of triangle t,
/// from triangles[t](k) to triangles[t]((k + 1) % 3).
struct HalfEdgeTriangleMesh {
    std::vector<Eigen::Vector3d> vertices;
    std::vector<Eigen::Vector3d> vertex_normals;
    std::vector<Eigen::Vector3d> vertex_colors;
    std::vector<Eigen::Vector3i> triangles;
    std::vector<Eigen::Vector3d> triangle_normals;
    std::vector<HalfEdge> half_edges;
    /// @brief Per vertex, its outgoing half-edges in fan order: starting at its boundary half-edge if it has
    /// one (else at the lowest-numbered one), each next one the twin of the half-edge entering the vertex in
    /// the previous one's triangle, until the walk returns or leaves the surface.
    std::vector<std::vector<int>> ordered_half_edge_from_vertex;

    bool has_vertices() const { return !vertices.empty(); }
    bool has_vertex_normals() const { return !vertices.empty() && vertex_normals.size() == vertices.size(); }
    bool has_vertex_colors() const { return !vertices.empty() && vertex_colors.size() == vertices.size(); }
    /// @brief Half-edges exist and every vertex has its ordered list (Open3D's has_half_edges).
    bool has_half_edges() const {
        return !half_edges.empty() && ordered_half_edge_from_vertex.size() == vertices.size();
    }
};

/// @brief Open3D's HalfEdgeTriangleMesh.create_from_triangle_mesh. The mesh is cleaned first as Open3D does:
/// exactly equal vertices merged, triangles equal up to a cyclic rotation (same orientation) dropped,
/// triangles repeating a vertex dropped, unreferenced vertices dropped (Open3D drops unreferenced vertices
/// before degenerate triangles and then crashes on a vertex only a degenerate triangle used; here it is
/// dropped). Vertex colors are kept when present; triangle and vertex normals (unit, area-weighted) are
/// always computed afresh, as Open3D does. A mesh without triangles gives an empty result.
/// @throws InvalidArgument on bad triangle indices, or a non-manifold input: a directed edge used twice
/// (an edge of more than two triangles, or two triangles of opposite orientation on one edge), or a vertex
/// with more than one outgoing boundary half-edge (two fans touching at it). Open3D refuses the same.
HalfEdgeTriangleMesh half_edge_mesh_from_triangle_mesh(const TriangleMesh& mesh);

/// @brief The boundary loop through `vertex` as half-edge indices, starting at the vertex's outgoing
/// boundary half-edge and following the half-edge directions; empty if the vertex is not on a boundary
/// (or has no triangle). @throws InvalidArgument if the vertex is out of range or the half-edges are broken.
std::vector<int> boundary_half_edges_from_vertex(const HalfEdgeTriangleMesh& mesh, int vertex);

/// @brief The boundary loop through `vertex` as vertex indices (the start vertex of each half-edge of
/// boundary_half_edges_from_vertex), starting with `vertex`. @throws as boundary_half_edges_from_vertex.
std::vector<int> boundary_vertices_from_vertex(const HalfEdgeTriangleMesh& mesh, int vertex);

/// @brief Every boundary loop once, as vertex indices (Open3D's get_boundaries): vertices are visited in
/// ascending order and each not yet on a found loop starts its loop. @throws as boundary_half_edges_from_vertex.
std::vector<std::vector<int>> boundaries(const HalfEdgeTriangleMesh& mesh);

/// @brief The triangle mesh of a half-edge mesh: vertices, vertex normals and colors, triangles and triangle
/// normals copied.
TriangleMesh triangle_mesh_from_half_edge_mesh(const HalfEdgeTriangleMesh& mesh);

}  // namespace o3d::geometry
