// SPDX-License-Identifier: MIT
#include "o3d/geometry/mesh_adjacency.h"

#include <algorithm>
#include <cstdint>
#include <utility>

#include "o3d/geometry/radix_sort.h"

namespace o3d::geometry {
namespace {

int bit_width(uint64_t v) {
    int bits = 0;
    for (; v; v >>= 1) ++bits;
    return bits;
}

}  // namespace

MeshEdges mesh_edges(const TriangleMesh& mesh) {
    const size_t num_sides = 3 * mesh.triangles.size();
    const uint64_t n = mesh.vertices.size();
    // Sort the sides by (min, max) key; the radix sort is stable, so within an edge sides stay ascending
    // and the first one is where the edge first appears.
    std::vector<std::pair<uint64_t, size_t>> keyed(num_sides);
    for (size_t s = 0; s < num_sides; ++s) {
        const Eigen::Vector3i& tri = mesh.triangles[s / 3];
        const int k = static_cast<int>(s % 3);
        const uint64_t a = static_cast<uint64_t>(tri(k)), b = static_cast<uint64_t>(tri((k + 1) % 3));
        keyed[s] = {std::min(a, b) * n + std::max(a, b), s};
    }
    radix_sort_by_key(keyed, bit_width(n * n));

    // Group runs of equal keys; number the groups by their first side.
    std::vector<int> group_of_side(num_sides);
    std::vector<size_t> group_first_side;
    for (size_t i = 0; i < num_sides; ++i) {
        if (i == 0 || keyed[i].first != keyed[i - 1].first) group_first_side.push_back(keyed[i].second);
        group_of_side[keyed[i].second] = static_cast<int>(group_first_side.size() - 1);
    }
    const size_t num_edges = group_first_side.size();
    std::vector<int> edge_of_group(num_edges, -1);
    MeshEdges out;
    out.endpoints.resize(num_edges);
    out.side_edge.resize(num_sides);
    int next = 0;
    for (size_t s = 0; s < num_sides; ++s) {
        const int g = group_of_side[s];
        if (edge_of_group[g] < 0) {
            edge_of_group[g] = next;
            const Eigen::Vector3i& tri = mesh.triangles[s / 3];
            const int k = static_cast<int>(s % 3);
            const int a = tri(k), b = tri((k + 1) % 3);
            out.endpoints[next] = Eigen::Vector2i(std::min(a, b), std::max(a, b));
            ++next;
        }
        out.side_edge[s] = edge_of_group[g];
    }
    // Triangles per edge, ascending (sides are visited in triangle order). A triangle with two sides on
    // the same edge (a repeated vertex) is listed once.
    out.triangle_offsets.assign(num_edges + 1, 0);
    for (size_t s = 0; s < num_sides; ++s) {
        const int e = out.side_edge[s];
        const size_t t = s / 3;
        bool repeat = false;
        for (size_t p = 3 * t; p < s; ++p) repeat = repeat || out.side_edge[p] == e;
        if (!repeat) ++out.triangle_offsets[e + 1];
    }
    for (size_t e = 0; e < num_edges; ++e) out.triangle_offsets[e + 1] += out.triangle_offsets[e];
    out.triangles.resize(out.triangle_offsets[num_edges]);
    std::vector<int> fill(out.triangle_offsets.begin(), out.triangle_offsets.end() - 1);
    for (size_t s = 0; s < num_sides; ++s) {
        const int e = out.side_edge[s];
        const size_t t = s / 3;
        bool repeat = false;
        for (size_t p = 3 * t; p < s; ++p) repeat = repeat || out.side_edge[p] == e;
        if (!repeat) out.triangles[fill[e]++] = static_cast<int>(t);
    }
    return out;
}

VertexNeighbours vertex_neighbours(const MeshEdges& edges, size_t num_vertices) {
    VertexNeighbours out;
    out.offsets.assign(num_vertices + 1, 0);
    for (const Eigen::Vector2i& e : edges.endpoints)
        if (e(0) != e(1)) {
            ++out.offsets[e(0) + 1];
            ++out.offsets[e(1) + 1];
        }
    for (size_t v = 0; v < num_vertices; ++v) out.offsets[v + 1] += out.offsets[v];
    out.neighbours.resize(out.offsets[num_vertices]);
    std::vector<int> fill(out.offsets.begin(), out.offsets.end() - 1);
    for (const Eigen::Vector2i& e : edges.endpoints)
        if (e(0) != e(1)) {
            out.neighbours[fill[e(0)]++] = e(1);
            out.neighbours[fill[e(1)]++] = e(0);
        }
    // Each undirected edge is listed once, so the lists hold no duplicates; sort for a fixed summation order.
    for (size_t v = 0; v < num_vertices; ++v)
        std::sort(out.neighbours.begin() + out.offsets[v], out.neighbours.begin() + out.offsets[v + 1]);
    return out;
}

VertexTriangles vertex_triangles(const TriangleMesh& mesh) {
    const size_t nv = mesh.vertices.size();
    VertexTriangles out;
    out.offsets.assign(nv + 1, 0);
    auto distinct = [](const Eigen::Vector3i& tri, int k) {
        for (int j = 0; j < k; ++j)
            if (tri(j) == tri(k)) return false;
        return true;
    };
    for (const Eigen::Vector3i& tri : mesh.triangles)
        for (int k = 0; k < 3; ++k)
            if (distinct(tri, k)) ++out.offsets[tri(k) + 1];
    for (size_t v = 0; v < nv; ++v) out.offsets[v + 1] += out.offsets[v];
    out.triangles.resize(out.offsets[nv]);
    std::vector<int> fill(out.offsets.begin(), out.offsets.end() - 1);
    for (size_t t = 0; t < mesh.triangles.size(); ++t) {
        const Eigen::Vector3i& tri = mesh.triangles[t];
        for (int k = 0; k < 3; ++k)
            if (distinct(tri, k)) out.triangles[fill[tri(k)]++] = static_cast<int>(t);
    }
    return out;
}

}  // namespace o3d::geometry
