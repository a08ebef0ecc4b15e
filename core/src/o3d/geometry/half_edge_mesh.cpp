// SPDX-License-Identifier: MIT
#include "o3d/geometry/half_edge_mesh.h"

#include <algorithm>
#include <cstdint>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

#include "o3d/geometry/mesh_cleanup.h"
#include "o3d/geometry/triangle_mesh_basics.h"
#include "o3d/geometry/triangle_mesh_ops.h"
#include "o3d/utility/error.h"

namespace o3d::geometry {
namespace {

/// @brief Drop triangles equal to an earlier one up to a cyclic rotation of its corners (Open3D's
/// remove_duplicated_triangles; core's version also drops the reversed triangle, which Open3D keeps).
void remove_rotated_duplicate_triangles(TriangleMesh& mesh) {
    const size_t m = mesh.triangles.size();
    std::vector<std::pair<Eigen::Vector3i, size_t>> keyed(m);
    for (size_t t = 0; t < m; ++t) {
        const Eigen::Vector3i& tri = mesh.triangles[t];
        int lowest = 0;
        for (int k = 1; k < 3; ++k)
            if (tri(k) < tri(lowest)) lowest = k;
        keyed[t] = {Eigen::Vector3i(tri(lowest), tri((lowest + 1) % 3), tri((lowest + 2) % 3)), t};
    }
    auto less = [](const std::pair<Eigen::Vector3i, size_t>& a, const std::pair<Eigen::Vector3i, size_t>& b) {
        return std::make_tuple(a.first(0), a.first(1), a.first(2), a.second) <
               std::make_tuple(b.first(0), b.first(1), b.first(2), b.second);
    };
    std::sort(keyed.begin(), keyed.end(), less);
    std::vector<uint8_t> keep(m, 1);
    for (size_t i = 1; i < m; ++i)
        if (keyed[i].first == keyed[i - 1].first) keep[keyed[i].second] = 0;
    if (std::find(keep.begin(), keep.end(), 0) == keep.end()) return;
    // Only the triangle arrays matter here (the copy has no per-triangle attributes besides normals,
    // which are recomputed).
    std::vector<Eigen::Vector3i> kept;
    for (size_t t = 0; t < m; ++t)
        if (keep[t]) kept.push_back(mesh.triangles[t]);
    mesh.triangles = std::move(kept);
    mesh.triangle_normals.clear();
    mesh.triangle_uvs.clear();
    mesh.triangle_material_ids.clear();
}

/// @brief The half-edge before `h` in its triangle (it ends where `h` starts).
int previous_half_edge(int h) { return 3 * (h / 3) + (h % 3 + 2) % 3; }

void check_vertex(const HalfEdgeTriangleMesh& mesh, int vertex) {
    if (vertex < 0 || static_cast<size_t>(vertex) >= mesh.vertices.size())
        throw InvalidArgument("half-edge mesh: vertex " + std::to_string(vertex) + " out of range [0, " +
                              std::to_string(mesh.vertices.size()) + ")");
    if (mesh.ordered_half_edge_from_vertex.size() != mesh.vertices.size())
        throw InvalidArgument("half-edge mesh: ordered_half_edge_from_vertex has " +
                              std::to_string(mesh.ordered_half_edge_from_vertex.size()) + " lists for " +
                              std::to_string(mesh.vertices.size()) + " vertices");
}

const HalfEdge& half_edge_at(const HalfEdgeTriangleMesh& mesh, int h) {
    if (h < 0 || static_cast<size_t>(h) >= mesh.half_edges.size())
        throw InvalidArgument("half-edge mesh: half-edge index " + std::to_string(h) + " out of range");
    return mesh.half_edges[h];
}

}  // namespace

HalfEdgeTriangleMesh half_edge_mesh_from_triangle_mesh(const TriangleMesh& mesh) {
    validate_triangles(mesh);
    TriangleMesh clean;
    clean.vertices = mesh.vertices;
    if (mesh.has_vertex_colors()) clean.vertex_colors = mesh.vertex_colors;
    clean.triangles = mesh.triangles;
    remove_duplicated_vertices(clean);
    remove_rotated_duplicate_triangles(clean);
    remove_degenerate_triangles(clean);
    remove_unreferenced_vertices(clean);
    compute_vertex_normals(clean, true);

    HalfEdgeTriangleMesh out;
    out.vertices = std::move(clean.vertices);
    out.vertex_normals = std::move(clean.vertex_normals);
    out.vertex_colors = std::move(clean.vertex_colors);
    out.triangles = std::move(clean.triangles);
    out.triangle_normals = std::move(clean.triangle_normals);
    if (out.triangles.empty()) return out;

    const size_t nv = out.vertices.size();
    const int nh = static_cast<int>(3 * out.triangles.size());
    out.half_edges.resize(nh);
    std::vector<std::pair<uint64_t, int>> directed(nh);
    for (int h = 0; h < nh; ++h) {
        const Eigen::Vector3i& tri = out.triangles[h / 3];
        const int k = h % 3;
        HalfEdge& e = out.half_edges[h];
        e.next = 3 * (h / 3) + (k + 1) % 3;
        e.vertex_indices = Eigen::Vector2i(tri(k), tri((k + 1) % 3));
        e.triangle_index = h / 3;
        directed[h] = {static_cast<uint64_t>(e.vertex_indices(0)) * nv + static_cast<uint64_t>(e.vertex_indices(1)), h};
    }
    std::sort(directed.begin(), directed.end());
    for (int i = 1; i < nh; ++i)
        if (directed[i].first == directed[i - 1].first) {
            const HalfEdge& e = out.half_edges[directed[i].second];
            throw InvalidArgument("half_edge_mesh_from_triangle_mesh: the mesh is not manifold: directed edge (" +
                                  std::to_string(e.vertex_indices(0)) + ", " + std::to_string(e.vertex_indices(1)) +
                                  ") is used by triangles " + std::to_string(directed[i - 1].second / 3) + " and " +
                                  std::to_string(directed[i].second / 3));
        }
    for (HalfEdge& e : out.half_edges) {
        const uint64_t key = static_cast<uint64_t>(e.vertex_indices(1)) * nv + static_cast<uint64_t>(e.vertex_indices(0));
        const auto it = std::lower_bound(directed.begin(), directed.end(), std::make_pair(key, 0));
        if (it != directed.end() && it->first == key) e.twin = it->second;
    }

    // Outgoing half-edges of every vertex, ascending (CSR).
    std::vector<int> offsets(nv + 1, 0), outgoing(nh);
    for (const HalfEdge& e : out.half_edges) ++offsets[e.vertex_indices(0) + 1];
    for (size_t v = 0; v < nv; ++v) offsets[v + 1] += offsets[v];
    std::vector<int> fill(offsets.begin(), offsets.end() - 1);
    for (int h = 0; h < nh; ++h) outgoing[fill[out.half_edges[h].vertex_indices(0)]++] = h;

    out.ordered_half_edge_from_vertex.resize(nv);
    for (size_t v = 0; v < nv; ++v) {
        int start = -1, boundary_count = 0;
        for (int p = offsets[v]; p < offsets[v + 1]; ++p)
            if (out.half_edges[outgoing[p]].is_boundary()) {
                ++boundary_count;
                start = outgoing[p];
            }
        if (boundary_count > 1)
            throw InvalidArgument("half_edge_mesh_from_triangle_mesh: the mesh is not manifold: vertex " +
                                  std::to_string(v) + " starts " + std::to_string(boundary_count) +
                                  " boundary half-edges");
        // Open3D starts an interior vertex at the first element of a hash set, which for its build is the
        // lowest-numbered half-edge; every vertex has one, since unreferenced vertices were removed.
        if (start < 0) start = outgoing[offsets[v]];
        std::vector<int>& fan = out.ordered_half_edge_from_vertex[v];
        // Rotating to the twin of the entering half-edge is injective, so the walk returns to `start` or
        // leaves the surface, within the vertex's outgoing count.
        for (int h = start; h != -1 && fan.size() < static_cast<size_t>(offsets[v + 1] - offsets[v]);) {
            fan.push_back(h);
            h = out.half_edges[previous_half_edge(h)].twin;
            if (h == start) break;
        }
    }
    return out;
}

std::vector<int> boundary_half_edges_from_vertex(const HalfEdgeTriangleMesh& mesh, int vertex) {
    check_vertex(mesh, vertex);
    const std::vector<int>& fan = mesh.ordered_half_edge_from_vertex[vertex];
    if (fan.empty() || !half_edge_at(mesh, fan[0]).is_boundary()) return {};
    std::vector<int> loop;
    const int start = fan[0];
    for (int h = start; h != -1;) {
        if (loop.size() >= mesh.half_edges.size())
            throw InvalidArgument("half-edge mesh: the boundary through vertex " + std::to_string(vertex) +
                                  " does not close (broken half-edges)");
        loop.push_back(h);
        // The next boundary half-edge starts where this one ends: it is the first of that vertex's fan.
        const int end = half_edge_at(mesh, h).vertex_indices(1);
        check_vertex(mesh, end);
        h = -1;
        for (const int g : mesh.ordered_half_edge_from_vertex[end])
            if (half_edge_at(mesh, g).is_boundary()) {
                h = g;
                break;
            }
        if (h == start) break;
    }
    return loop;
}

std::vector<int> boundary_vertices_from_vertex(const HalfEdgeTriangleMesh& mesh, int vertex) {
    std::vector<int> loop = boundary_half_edges_from_vertex(mesh, vertex);
    for (int& h : loop) h = mesh.half_edges[h].vertex_indices(0);
    return loop;
}

std::vector<std::vector<int>> boundaries(const HalfEdgeTriangleMesh& mesh) {
    std::vector<std::vector<int>> loops;
    std::vector<uint8_t> visited(mesh.vertices.size(), 0);
    for (int v = 0; v < static_cast<int>(mesh.vertices.size()); ++v) {
        if (visited[v]) continue;
        std::vector<int> loop = boundary_vertices_from_vertex(mesh, v);
        for (const int u : loop) {
            if (u < 0 || static_cast<size_t>(u) >= visited.size())
                throw InvalidArgument("half-edge mesh: a boundary half-edge starts at vertex " + std::to_string(u) +
                                      ", out of range");
            visited[u] = 1;
        }
        if (!loop.empty()) loops.push_back(std::move(loop));
    }
    return loops;
}

TriangleMesh triangle_mesh_from_half_edge_mesh(const HalfEdgeTriangleMesh& mesh) {
    TriangleMesh out;
    out.vertices = mesh.vertices;
    out.vertex_normals = mesh.vertex_normals;
    out.vertex_colors = mesh.vertex_colors;
    out.triangles = mesh.triangles;
    out.triangle_normals = mesh.triangle_normals;
    return out;
}

}  // namespace o3d::geometry
