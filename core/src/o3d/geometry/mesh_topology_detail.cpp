// SPDX-License-Identifier: MIT
// The vertex-link and orientation tests of mesh_topology.cpp, as shared functions (see mesh_topology_detail.h).
#include "o3d/geometry/mesh_topology_detail.h"

#include <algorithm>
#include <vector>

namespace o3d::geometry::detail {
namespace {

/// @brief The sides (3 t + k) on each edge, in side order (CSR over MeshEdges' numbering).
struct EdgeSides {
    std::vector<int> offsets, sides;
    int count(size_t e) const { return offsets[e + 1] - offsets[e]; }
};

EdgeSides edge_sides(const MeshEdges& edges) {
    EdgeSides out;
    out.offsets.assign(edges.size() + 1, 0);
    for (const int e : edges.side_edge) ++out.offsets[e + 1];
    for (size_t e = 0; e < edges.size(); ++e) out.offsets[e + 1] += out.offsets[e];
    out.sides.resize(edges.side_edge.size());
    std::vector<int> fill(out.offsets.begin(), out.offsets.end() - 1);
    for (size_t s = 0; s < edges.side_edge.size(); ++s) out.sides[fill[edges.side_edge[s]]++] = static_cast<int>(s);
    return out;
}

int find_root(std::vector<int>& parent, int x) {
    while (parent[x] != x) x = parent[x] = parent[parent[x]];
    return x;
}

}  // namespace

bool link_is_connected(const TriangleMesh& mesh, const VertexTriangles& around, int v, std::vector<int>& ends,
                       std::vector<int>& nodes, std::vector<int>& parent) {
    ends.clear();
    for (int i = around.offsets[v]; i < around.offsets[v + 1]; ++i) {
        const Eigen::Vector3i& tri = mesh.triangles[around.triangles[i]];
        // The side opposite v, as Open3D picks it; a triangle holding v twice has none.
        if (tri(0) != v && tri(1) != v) {
            ends.push_back(tri(0));
            ends.push_back(tri(1));
        } else if (tri(0) != v && tri(2) != v) {
            ends.push_back(tri(0));
            ends.push_back(tri(2));
        } else if (tri(1) != v && tri(2) != v) {
            ends.push_back(tri(1));
            ends.push_back(tri(2));
        }
    }
    if (ends.empty()) return true;
    nodes.assign(ends.begin(), ends.end());
    std::sort(nodes.begin(), nodes.end());
    nodes.erase(std::unique(nodes.begin(), nodes.end()), nodes.end());
    parent.resize(nodes.size());
    for (size_t i = 0; i < nodes.size(); ++i) parent[i] = static_cast<int>(i);
    auto local = [&](int x) { return static_cast<int>(std::lower_bound(nodes.begin(), nodes.end(), x) - nodes.begin()); };
    size_t components = nodes.size();
    for (size_t i = 0; i < ends.size(); i += 2) {
        const int a = find_root(parent, local(ends[i])), b = find_root(parent, local(ends[i + 1]));
        if (a != b) {
            parent[a] = b;
            --components;
        }
    }
    return components == 1;
}

bool consistent_orientation(const TriangleMesh& mesh, std::vector<int>& flipped) {
    const MeshEdges edges = mesh_edges(mesh);
    const EdgeSides sides = edge_sides(edges);
    const size_t m = mesh.triangles.size();
    // Two sides on one edge tie their triangles: the same orientation when they walk the edge in opposite
    // directions, opposite orientations otherwise. Each triangle has at most three such ties.
    std::vector<int> tie_offsets(m + 1, 0);
    std::vector<Eigen::Vector2i> ties(3 * m, Eigen::Vector2i(-1, 0));  // (other triangle, 1 = flip)
    auto forward = [&](int side, size_t e) { return mesh.triangles[side / 3](side % 3) == edges.endpoints[e](0); };
    for (size_t e = 0; e < edges.size(); ++e) {
        if (edges.endpoints[e](0) == edges.endpoints[e](1)) continue;  // a repeated vertex has no direction
        const int count = sides.count(e);
        if (count > 2) return false;
        if (count < 2) continue;
        const int s = sides.sides[sides.offsets[e]], r = sides.sides[sides.offsets[e] + 1];
        const int flip = forward(s, e) == forward(r, e) ? 1 : 0;
        if (s / 3 == r / 3) {
            if (flip) return false;
            continue;
        }
        ties[s] = Eigen::Vector2i(r / 3, flip);
        ties[r] = Eigen::Vector2i(s / 3, flip);
    }
    flipped.assign(m, -1);
    std::vector<int> queue;
    for (size_t start = 0; start < m; ++start) {
        if (flipped[start] >= 0) continue;
        flipped[start] = 0;
        queue.assign(1, static_cast<int>(start));
        for (size_t q = 0; q < queue.size(); ++q) {
            const int t = queue[q];
            for (int k = 0; k < 3; ++k) {
                const Eigen::Vector2i& tie = ties[3 * t + k];
                if (tie(0) < 0) continue;
                const int want = flipped[t] ^ tie(1);
                if (flipped[tie(0)] < 0) {
                    flipped[tie(0)] = want;
                    queue.push_back(tie(0));
                } else if (flipped[tie(0)] != want) {
                    return false;
                }
            }
        }
    }
    return true;
}

}  // namespace o3d::geometry::detail
