// SPDX-License-Identifier: MIT
/// @file poisson_cube_table.cpp
/// @brief Marching-cubes case table, generated rather than typed in: on every cube face the iso-line segments
/// cut off the inside corners (a rule that depends on the face alone, so both cells sharing a face agree); the
/// segments chain into loops around the cube and each loop is fanned into triangles.
#include "o3d/geometry/poisson_cube_table.h"

#include <Eigen/Geometry>
#include <utility>

namespace o3d::geometry::poisson {

int edge_lower_corner(int e) {
    const int axis = e / 4, j = e % 4;
    return ((j & 1) << ((axis + 1) % 3)) | (((j >> 1) & 1) << ((axis + 2) % 3));
}

namespace {

// Corner k = (k&1, k>>1&1, k>>2&1). Edge id = axis*4 + j, j = bit of axis+1 + 2 * bit of axis+2.
int edge_id(int c0, int c1) {
    const int diff = c0 ^ c1;
    const int axis = diff == 1 ? 0 : (diff == 2 ? 1 : 2);
    const int b = (c0 >> ((axis + 1) % 3)) & 1, c = (c0 >> ((axis + 2) % 3)) & 1;
    return axis * 4 + b + 2 * c;
}

// Two cube edges lie on a common face when they are parallel and differ in one bit, or perpendicular and
// touch (share a corner).
bool share_face(int e0, int e1) {
    const int a0 = e0 / 4, a1 = e1 / 4;
    const int c0 = edge_lower_corner(e0), c1 = edge_lower_corner(e1);
    if (a0 == a1) {
        const int d = c0 ^ c1;
        return d != 0 && (d & (d - 1)) == 0;
    }
    const int c0b = c0 | (1 << a0), c1b = c1 | (1 << a1);
    return c0 == c1 || c0 == c1b || c0b == c1 || c0b == c1b;
}

}  // namespace

CaseTable::CaseTable() {
    for (int cs = 0; cs < 256; ++cs) {
        auto inside = [cs](int k) { return ((cs >> k) & 1) != 0; };
        std::array<int, 12> next;
        next.fill(-1);
        for (int axis = 0; axis < 3; ++axis)
            for (int side = 0; side < 2; ++side) {
                const int b = (axis + 1) % 3, c = (axis + 2) % 3;
                // Counter-clockwise seen from outside the cube: (b,c) = 00,10,11,01 on the + side.
                int p[4];
                const int bc[4][2] = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
                for (int i = 0; i < 4; ++i) {
                    const int q = side ? i : 3 - i;
                    p[i] = (side << axis) | (bc[q][0] << b) | (bc[q][1] << c);
                }
                for (int k = 0; k < 4; ++k) {
                    if (!(inside(p[k]) && !inside(p[(k + 1) % 4]))) continue;
                    // Exit edge: join it to the closest earlier crossing, keeping the inside on the left.
                    for (int m = k + 3; m > k; --m) {
                        const int a0 = p[m % 4], a1 = p[(m + 1) % 4];
                        if (inside(a0) != inside(a1)) {
                            next[size_t(edge_id(p[k], p[(k + 1) % 4]))] = edge_id(a0, a1);
                            break;
                        }
                    }
                }
            }
        std::array<bool, 12> used{};
        for (int e0 = 0; e0 < 12; ++e0) {
            if (next[size_t(e0)] < 0 || used[size_t(e0)]) continue;
            std::vector<int> loop;
            for (int e = e0; !used[size_t(e)]; e = next[size_t(e)]) {
                used[size_t(e)] = true;
                loop.push_back(e);
            }
            // Fan from a vertex none of whose diagonals joins two crossings on one cube face: the cell
            // across that face could draw the same diagonal and the edge would carry four triangles.
            const size_t m = loop.size();
            size_t start = 0;
            for (size_t s0 = 0; s0 < m; ++s0) {
                bool ok = true;
                for (size_t i = 2; i + 1 < m && ok; ++i)
                    if (share_face(loop[s0], loop[(s0 + i) % m])) ok = false;
                if (ok) {
                    start = s0;
                    break;
                }
            }
            for (size_t i = 1; i + 1 < m; ++i)
                tris[size_t(cs)].push_back({int8_t(loop[start]), int8_t(loop[(start + i) % m]),
                                            int8_t(loop[(start + i + 1) % m])});
        }
    }
    // Orientation: with only corner 0 inside the normal must point away from it.
    auto mid = [](int e) {
        const int c = edge_lower_corner(e);
        Eigen::Vector3d p(c & 1, (c >> 1) & 1, (c >> 2) & 1);
        p[e / 4] += 0.5;
        return p;
    };
    const auto& t = tris[1][0];
    const Eigen::Vector3d n = (mid(t[1]) - mid(t[0])).cross(mid(t[2]) - mid(t[0]));
    if (n.dot(Eigen::Vector3d(1, 1, 1)) < 0)
        for (auto& list : tris)
            for (auto& tri : list) std::swap(tri[1], tri[2]);
    flipped = n.dot(Eigen::Vector3d(1, 1, 1)) < 0;
}

const CaseTable& case_table() {
    static const CaseTable table;
    return table;
}

}  // namespace o3d::geometry::poisson
