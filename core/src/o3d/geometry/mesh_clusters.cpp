// SPDX-License-Identifier: MIT
#include "o3d/geometry/mesh_clusters.h"

#include <algorithm>
#include <numeric>

#include "o3d/geometry/mesh_adjacency.h"
#include "o3d/geometry/triangle_mesh_ops.h"

namespace o3d::geometry {
namespace {

int find_root(std::vector<int>& parent, int x) {
    while (parent[x] != x) {
        parent[x] = parent[parent[x]];
        x = parent[x];
    }
    return x;
}

}  // namespace

TriangleClusters cluster_connected_triangles(const TriangleMesh& mesh) {
    const std::vector<double> areas = triangle_areas(mesh);  // validates
    const MeshEdges edges = mesh_edges(mesh);
    const size_t m = mesh.triangles.size();
    std::vector<int> parent(m);
    std::iota(parent.begin(), parent.end(), 0);
    for (size_t e = 0; e < edges.size(); ++e) {
        const int first = edges.triangles[edges.triangle_offsets[e]];
        for (int i = edges.triangle_offsets[e] + 1; i < edges.triangle_offsets[e + 1]; ++i) {
            const int a = find_root(parent, first), b = find_root(parent, edges.triangles[i]);
            if (a != b) parent[std::max(a, b)] = std::min(a, b);  // the root stays the lowest triangle
        }
    }
    TriangleClusters out;
    out.triangle_cluster.assign(m, -1);
    for (size_t t = 0; t < m; ++t) {
        const int root = find_root(parent, static_cast<int>(t));
        if (root == static_cast<int>(t)) {
            out.triangle_cluster[t] = static_cast<int>(out.cluster_size.size());
            out.cluster_size.push_back(0);
            out.cluster_area.push_back(0.0);
        } else {
            out.triangle_cluster[t] = out.triangle_cluster[root];
        }
        ++out.cluster_size[out.triangle_cluster[t]];
        out.cluster_area[out.triangle_cluster[t]] += areas[t];
    }
    return out;
}

}  // namespace o3d::geometry
