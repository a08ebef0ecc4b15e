// SPDX-License-Identifier: MIT
#pragma once
/// @file mesh_subdivision.h
/// @brief 1-to-4 triangle subdivision: midpoint, and Loop's (1987) smooth scheme (Open3D's subdivide_*).
#include "o3d/geometry/triangle_mesh.h"

namespace o3d::geometry {

/// @brief Split every triangle (a, b, c) into (a, ab, ca), (ab, b, bc), (bc, c, ca), (ab, bc, ca), where
/// ab is a new vertex at the midpoint of edge ab, `number_of_iterations` times. The input vertices keep their
/// indices; edge vertices follow, numbered in order of first use as Open3D numbers them, with the mean
/// normal and color of the edge's ends. Triangle UVs are split the same way (each new corner at the mean of
/// its edge's corner UVs), material ids are inherited, textures kept, triangle normals recomputed when the
/// input had them (Open3D drops UVs and material ids).
/// @throws InvalidArgument on bad triangle indices, no vertices, a negative iteration count, or a result
/// of more than 2^31 - 1 vertices or triangles.
TriangleMesh subdivide_midpoint(const TriangleMesh& mesh, int number_of_iterations);

/// @brief Loop subdivision with Open3D's rules: the same split and numbering as subdivide_midpoint; an edge
/// vertex is 3/8 of each end plus 1/8 of the opposite vertex of each triangle on the edge (the midpoint on a
/// boundary edge); an old vertex with n neighbours becomes (1 - n beta) v + beta * sum of neighbours with
/// beta = 3/16 for n = 3, else 3 / (8 n); on the boundary (two or more boundary neighbours) 3/4 v + 1/8 of
/// each boundary neighbour. Normals and colors follow the same weights; a vertex without neighbours stays.
/// @throws as subdivide_midpoint.
TriangleMesh subdivide_loop(const TriangleMesh& mesh, int number_of_iterations);

}  // namespace o3d::geometry
