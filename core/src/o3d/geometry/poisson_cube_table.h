// SPDX-License-Identifier: MIT
#pragma once
/// @file poisson_cube_table.h
/// @brief Internal to Poisson reconstruction: the marching-cubes case table used on octree leaves whose
/// faces and edges are not subdivided by finer neighbours.
#include <array>
#include <cstdint>
#include <vector>

namespace o3d::geometry::poisson {

/// Corner k = (k&1, k>>1&1, k>>2&1). Edge id = axis*4 + j, j = bit of axis+1 + 2 * bit of axis+2.
/// @returns the corner at the lower end of edge `e`.
int edge_lower_corner(int e);

struct CaseTable {
    /// Per case (bit k set = corner k inside, i.e. below the iso-value): triangles as cube-edge ids.
    std::array<std::vector<std::array<int8_t, 3>>, 256> tris;
    /// Whether the triangles were reversed from "fan of the loop that runs from each face's exit crossing
    /// to its entry crossing, faces seen counter-clockwise from outside", so they face towards larger chi.
    /// Leaves triangulated outside the table follow the same rule and apply the same flip.
    bool flipped = false;
    CaseTable();
};

const CaseTable& case_table();

}  // namespace o3d::geometry::poisson
