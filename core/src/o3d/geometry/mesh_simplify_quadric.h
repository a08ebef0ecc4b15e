// SPDX-License-Identifier: MIT
#pragma once
/// @file mesh_simplify_quadric.h
/// @brief Quadric edge-collapse decimation (Garland & Heckbert 1997), Open3D's simplify_quadric_decimation.
#include <cstddef>

#include "o3d/geometry/triangle_mesh.h"

namespace o3d::geometry {

/// @brief Collapse the cheapest edge, again and again, until at most `target_number_of_triangles` remain,
/// no collapse is allowed, or the cheapest costs more than `maximum_error`.
///
/// As in Open3D: each vertex starts with the area-weighted quadrics of its triangles' planes, plus, for each
/// boundary edge, the plane through that edge perpendicular to its triangle, weighted by area *
/// `boundary_weight`; an edge (a, b) costs Q(x) for Q = Q_a + Q_b at x = argmin Q when Q is well conditioned,
/// else the cheapest of a, b and their midpoint; the lower-indexed vertex survives, at x, with the mean of
/// the two normals and colors. Collapses that would flip a triangle are skipped.
/// Where o3d differs, on purpose: the boundary plane contains the edge (Open3D builds it from a normal
/// vector used as a point); a collapse must keep the surface a manifold (the link condition, and no edge
/// joining two boundary vertices across the interior), so a closed mesh stays closed; the flip test covers
/// the triangles of both endpoints; the optimum is used only when the quadric is well conditioned relative to
/// its own scale and lies within one edge length of the edge's midpoint (Open3D's fixed |det A| > 1e-4 calls
/// every quadric of a finely tessellated unit mesh singular).
/// Output: the surviving vertices in input order (with normals and colors), the surviving triangles in input
/// order (with their material ids; textures kept), triangle normals recomputed when the input had them;
/// triangle UVs are dropped (as Open3D), and so are triangles that repeat a vertex (they have no area).
/// Equal costs pop in the order they were queued: the result is deterministic. A target at or above the
/// triangle count returns the mesh unchanged.
/// @throws InvalidArgument on bad triangle indices, no vertices, a non-finite vertex, a NaN or negative
/// `maximum_error`, or a `boundary_weight` that is not finite and >= 0.
TriangleMesh simplify_quadric_decimation(const TriangleMesh& mesh, size_t target_number_of_triangles,
                                         double maximum_error, double boundary_weight);

}  // namespace o3d::geometry
