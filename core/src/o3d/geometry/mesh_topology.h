// SPDX-License-Identifier: MIT
#pragma once
/// @file mesh_topology.h
/// @brief Topology queries with Open3D's semantics (TriangleMesh.is_* , euler_poincare_characteristic,
/// get_volume). Each validates the triangle indices first (InvalidArgument).
#include <cstdint>

#include "o3d/geometry/triangle_mesh.h"

namespace o3d::geometry {

/// @brief Every edge is used by one or two triangle sides (exactly two unless `allow_boundary_edges`).
/// Sides are counted as Open3D does: a triangle repeating a vertex counts twice on its doubled edge.
bool is_edge_manifold(const TriangleMesh& mesh, bool allow_boundary_edges = true);
/// @brief For every vertex, the edges opposite it in its triangles (its link) form one connected graph.
bool is_vertex_manifold(const TriangleMesh& mesh);
/// @brief The triangles can be flipped so that every edge shared by two sides is walked once each way.
/// An edge used by more than two sides cannot be (Open3D's greedy walk may still answer true there).
bool is_orientable(const TriangleMesh& mesh);
/// @brief Edge manifold without boundary, vertex manifold and not self-intersecting.
bool is_watertight(const TriangleMesh& mesh);
/// @brief V - E + F, with V every vertex (used or not) and E the distinct edges.
int64_t euler_poincare_characteristic(const TriangleMesh& mesh);
/// @brief |sum of the signed tetrahedra (triangle, vertex mean)| / 6, with the triangles consistently
/// oriented first (Open3D sums them as stored, which is wrong for an orientable mesh stored with mixed
/// orientations). @throws InvalidArgument unless the mesh is watertight and orientable.
double volume(const TriangleMesh& mesh);

}  // namespace o3d::geometry
