// SPDX-License-Identifier: MIT
#include "o3d/geometry/mesh_topology.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <atomic>
#include <cmath>
#include <queue>
#include <vector>

#include "o3d/geometry/mesh_adjacency.h"
#include "o3d/geometry/mesh_self_intersection.h"
#include "o3d/geometry/triangle_mesh_basics.h"
#include "o3d/geometry/triangle_mesh_ops.h"
#include "o3d/utility/error.h"
#include "o3d/utility/parallel.h"

namespace o3d::geometry {
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

/// @brief Whether the link of vertex v (the edges opposite v in its triangles) is one connected graph.
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

}  // namespace

bool is_edge_manifold(const TriangleMesh& mesh, bool allow_boundary_edges) {
    validate_triangles(mesh);
    const MeshEdges edges = mesh_edges(mesh);
    std::vector<int> sides(edges.size(), 0);
    for (const int e : edges.side_edge) ++sides[e];
    for (const int c : sides)
        if (allow_boundary_edges ? c > 2 : c != 2) return false;
    return true;
}

bool is_vertex_manifold(const TriangleMesh& mesh) {
    validate_triangles(mesh);
    const VertexTriangles around = vertex_triangles(mesh);
    const long long n = static_cast<long long>(mesh.vertices.size());
    std::atomic<bool> manifold{true};
#pragma omp parallel num_threads(o3d::utility::resolve_num_threads()) if (n > 20000)
    {
        std::vector<int> ends, nodes, parent;
#pragma omp for schedule(static)
        for (long long v = 0; v < n; ++v) {
            if (!manifold.load(std::memory_order_relaxed)) continue;
            if (!link_is_connected(mesh, around, static_cast<int>(v), ends, nodes, parent))
                manifold.store(false, std::memory_order_relaxed);
        }
    }
    return manifold.load();
}

namespace {

/// @brief A consistent orientation: `flipped[t]` = 1 for the triangles to turn over; false when none exists.
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

}  // namespace

bool is_orientable(const TriangleMesh& mesh) {
    validate_triangles(mesh);
    std::vector<int> flipped;
    return consistent_orientation(mesh, flipped);
}

bool is_watertight(const TriangleMesh& mesh) {
    return is_edge_manifold(mesh, false) && is_vertex_manifold(mesh) && !is_self_intersecting(mesh);
}

int64_t euler_poincare_characteristic(const TriangleMesh& mesh) {
    validate_triangles(mesh);
    const MeshEdges edges = mesh_edges(mesh);
    return static_cast<int64_t>(mesh.vertices.size()) - static_cast<int64_t>(edges.size()) +
           static_cast<int64_t>(mesh.triangles.size());
}

double volume(const TriangleMesh& mesh) {
    if (!is_watertight(mesh)) throw InvalidArgument("the mesh is not watertight, so it has no volume");
    std::vector<int> flipped;
    if (!consistent_orientation(mesh, flipped))
        throw InvalidArgument("the mesh is not orientable, so it has no volume");
    // Tetrahedra to the vertex mean rather than the origin: the same sum for a closed mesh, with less
    // cancellation when the mesh is far from the origin.
    const Eigen::Vector3d ref = center(mesh);
    double six_volume = 0.0;
    // Open3D sums the triangles as stored; turning them consistently first also gives the right volume for
    // an orientable mesh stored with mixed orientations.
    for (size_t t = 0; t < mesh.triangles.size(); ++t) {
        const Eigen::Vector3i& tri = mesh.triangles[t];
        const Eigen::Vector3d a = mesh.vertices[tri(0)] - ref, b = mesh.vertices[tri(1)] - ref,
                              c = mesh.vertices[tri(2)] - ref;
        const double signed_six = a.dot(b.cross(c));
        six_volume += flipped[t] ? -signed_six : signed_six;
    }
    return std::abs(six_volume / 6.0);
}

}  // namespace o3d::geometry
