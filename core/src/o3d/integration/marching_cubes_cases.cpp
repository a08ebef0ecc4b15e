// SPDX-License-Identifier: MIT
// The marching cubes patterns, traced from the cube's faces: on every face the crossing edges pair up into
// segments; around the cube the segments close into loops; each loop is fanned into triangles and wound so
// that its normal points from the inside corners to the outside ones.
#include "o3d/integration/marching_cubes_cases.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <vector>

namespace o3d::integration::detail {
namespace {

Eigen::Vector3d corner_position(int corner) {
    return Eigen::Vector3d(corner & 1, (corner >> 1) & 1, (corner >> 2) & 1);
}

int edge_between(int a, int b) {
    for (int e = 0; e < 12; ++e) {
        const int c = edge_corner(e), d = c | (1 << edge_axis(e));
        if ((c == a && d == b) || (c == b && d == a)) return e;
    }
    return -1;
}

/// The four corners of face (axis, side) in cyclic order.
std::array<int, 4> face_corners(int axis, int side) {
    const int b = (axis + 1) % 3, c = (axis + 2) % 3;
    const int base = side << axis;
    return {base, base | (1 << b), base | (1 << b) | (1 << c), base | (1 << c)};
}

CubeCase trace_case(int pattern) {
    auto inside = [pattern](int corner) { return ((pattern >> corner) & 1) != 0; };
    // partner[e] lists the edges joined to e by a segment (two per crossing edge: one on each of its faces).
    std::array<std::vector<int>, 12> partner;
    for (int axis = 0; axis < 3; ++axis) {
        for (int side = 0; side < 2; ++side) {
            const std::array<int, 4> q = face_corners(axis, side);
            std::array<int, 4> edge{};  // edge k joins q[k] and q[k + 1]
            std::vector<int> crossing;
            for (int k = 0; k < 4; ++k) {
                edge[k] = edge_between(q[k], q[(k + 1) % 4]);
                if (inside(q[k]) != inside(q[(k + 1) % 4])) crossing.push_back(k);
            }
            auto join = [&](int k0, int k1) {
                partner[edge[k0]].push_back(edge[k1]);
                partner[edge[k1]].push_back(edge[k0]);
            };
            if (crossing.size() == 2) {
                join(crossing[0], crossing[1]);
            } else if (crossing.size() == 4) {
                // Two diagonal inside corners: cut each off on its own (edges 3,0 meet at q[0]; 0,1 at q[1]).
                if (inside(q[0])) {
                    join(3, 0);
                    join(1, 2);
                } else {
                    join(0, 1);
                    join(2, 3);
                }
            }
        }
    }
    CubeCase out;
    std::array<bool, 12> visited{};
    for (int start = 0; start < 12; ++start) {
        if (visited[start] || partner[start].empty()) continue;
        std::vector<int> loop;
        int previous = -1, current = start;
        while (!visited[current]) {
            visited[current] = true;
            loop.push_back(current);
            const int next = partner[current][0] != previous ? partner[current][0] : partner[current][1];
            previous = current;
            current = next;
        }
        // Wind the loop so that its normal (Newell's, over the edge midpoints) points outward.
        Eigen::Vector3d normal = Eigen::Vector3d::Zero(), outward = Eigen::Vector3d::Zero();
        for (size_t i = 0; i < loop.size(); ++i) {
            const int e = loop[i], f = loop[(i + 1) % loop.size()];
            const int a = edge_corner(e), b = a | (1 << edge_axis(e));
            const Eigen::Vector3d pa = 0.5 * (corner_position(a) + corner_position(b));
            const int c = edge_corner(f), d = c | (1 << edge_axis(f));
            const Eigen::Vector3d pb = 0.5 * (corner_position(c) + corner_position(d));
            normal += pa.cross(pb);
            outward += inside(a) ? corner_position(b) - corner_position(a) : corner_position(a) - corner_position(b);
        }
        if (normal.dot(outward) < 0) std::reverse(loop.begin(), loop.end());
        for (size_t i = 1; i + 1 < loop.size(); ++i) {
            const int t = out.num_triangles++;
            out.edges[size_t(3 * t)] = int8_t(loop[0]);
            out.edges[size_t(3 * t + 1)] = int8_t(loop[i]);
            out.edges[size_t(3 * t + 2)] = int8_t(loop[i + 1]);
        }
    }
    return out;
}

}  // namespace

int edge_corner(int edge) {
    const int axis = edge / 4, k = edge % 4;
    // The k-th of the four corners whose bit `axis` is 0: spread k's two bits over the other two axes.
    const int low = k & 1, high = (k >> 1) & 1;
    const int b = axis == 0 ? 1 : 0, c = axis == 2 ? 1 : 2;
    return (low << b) | (high << c);
}

const std::array<CubeCase, 256>& cube_cases() {
    static const std::array<CubeCase, 256> cases = [] {
        std::array<CubeCase, 256> all{};
        for (int pattern = 1; pattern < 255; ++pattern) all[size_t(pattern)] = trace_case(pattern);
        return all;
    }();
    return cases;
}

}  // namespace o3d::integration::detail
