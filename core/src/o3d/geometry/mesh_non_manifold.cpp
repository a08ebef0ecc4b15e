// SPDX-License-Identifier: MIT
#include "o3d/geometry/mesh_non_manifold.h"

#include <algorithm>
#include <cstdint>

#include "o3d/geometry/mesh_adjacency.h"
#include "o3d/geometry/mesh_topology_detail.h"
#include "o3d/geometry/triangle_mesh_basics.h"
#include "o3d/utility/parallel.h"

namespace o3d::geometry {

std::vector<Eigen::Vector2i> non_manifold_edges(const TriangleMesh& mesh, bool allow_boundary_edges) {
    validate_triangles(mesh);
    const MeshEdges edges = mesh_edges(mesh);
    // Sides, not triangles, as is_edge_manifold counts them.
    std::vector<int> sides(edges.size(), 0);
    for (const int e : edges.side_edge) ++sides[e];
    std::vector<Eigen::Vector2i> out;
    for (size_t e = 0; e < edges.size(); ++e)
        if (allow_boundary_edges ? sides[e] > 2 : sides[e] != 2) out.push_back(edges.endpoints[e]);
    std::sort(out.begin(), out.end(), [](const Eigen::Vector2i& a, const Eigen::Vector2i& b) {
        return a(0) != b(0) ? a(0) < b(0) : a(1) < b(1);
    });
    return out;
}

std::vector<int> non_manifold_vertices(const TriangleMesh& mesh) {
    validate_triangles(mesh);
    const VertexTriangles around = vertex_triangles(mesh);
    const int64_t n = static_cast<int64_t>(mesh.vertices.size());
    std::vector<uint8_t> bad(mesh.vertices.size(), 0);
    // Each vertex writes only its own flag, so the list is the same for any thread count.
#pragma omp parallel num_threads(o3d::utility::resolve_num_threads()) if (n > 20000)
    {
        std::vector<int> ends, nodes, parent;
#pragma omp for schedule(static)
        for (int64_t v = 0; v < n; ++v)
            bad[v] = !detail::link_is_connected(mesh, around, static_cast<int>(v), ends, nodes, parent);
    }
    std::vector<int> out;
    for (int64_t v = 0; v < n; ++v)
        if (bad[v]) out.push_back(static_cast<int>(v));
    return out;
}

}  // namespace o3d::geometry
