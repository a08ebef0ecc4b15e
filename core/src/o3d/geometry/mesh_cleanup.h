// SPDX-License-Identifier: MIT
#pragma once
/// @file mesh_cleanup.h
/// @brief In-place mesh clean-up with Open3D's semantics (TriangleMesh.remove_* and merge_close_vertices).
/// Each keeps the attributes (normals, colors, UVs, material ids) of the vertices and triangles it keeps,
/// in their original order. Each validates the triangle indices first (InvalidArgument).
#include "o3d/geometry/triangle_mesh.h"

namespace o3d::geometry {

/// @brief Merge vertices with exactly equal coordinates (0.0 == -0.0; NaN never merges) into the first
/// of them, re-indexing the triangles.
void remove_duplicated_vertices(TriangleMesh& mesh);
/// @brief Remove triangles with the same three vertex indices as an earlier one, in any order.
void remove_duplicated_triangles(TriangleMesh& mesh);
/// @brief Remove triangles that repeat a vertex index.
void remove_degenerate_triangles(TriangleMesh& mesh);
/// @brief Remove vertices no triangle uses, re-indexing the triangles.
void remove_unreferenced_vertices(TriangleMesh& mesh);
/// @brief On every edge shared by more than two triangles, remove the smallest-area ones (ties: the lowest
/// index first) until two remain; edges are visited in order of first appearance.
void remove_non_manifold_edges(TriangleMesh& mesh);
/// @brief Greedy merge in vertex order: each vertex not yet merged takes every not-yet-merged vertex within
/// `eps` (distance <= eps) and they become one vertex at their mean, with the mean normal and color.
/// Triangle normals, when present, are recomputed (unit length). @throws InvalidArgument if eps is
/// negative or not finite.
void merge_close_vertices(TriangleMesh& mesh, double eps);

}  // namespace o3d::geometry
