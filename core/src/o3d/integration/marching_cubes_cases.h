// SPDX-License-Identifier: MIT
#pragma once
/// @file marching_cubes_cases.h
/// @brief Marching cubes (Lorensen & Cline 1987): the triangles of each of the 256 inside/outside patterns
/// of a cube's corners, derived at start-up from the cube's topology rather than typed in as a table.
///
/// Corner i sits at offset (i & 1, (i >> 1) & 1, (i >> 2) & 1). Edge e joins corner kEdgeCorner[e] to that
/// corner plus one step along axis kEdgeAxis[e]; the edge's vertex lives on the lower corner's voxel.
#include <array>
#include <cstdint>

namespace o3d::integration::detail {

/// Edge e = 4 * axis + k: the k-th corner (in increasing order) whose bit `axis` is 0, stepped along `axis`.
int edge_corner(int edge);
inline int edge_axis(int edge) { return edge / 4; }

/// @brief The triangles of one pattern (bit i set: corner i is inside, tsdf < 0), as edge indices, three
/// per triangle. A triangle's winding makes its normal point from inside to outside (toward free space).
struct CubeCase {
    std::array<int8_t, 30> edges{};  // a loop per group of crossing edges: at most 12 - 2 = 10 triangles
    int8_t num_triangles = 0;
};

/// @brief The 256 patterns. Faces with two diagonal inside corners are split so that the inside corners are
/// kept apart, the same choice from both cubes sharing the face, so the surface has no cracks.
const std::array<CubeCase, 256>& cube_cases();

}  // namespace o3d::integration::detail
