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
#include "o3d/geometry/mesh_topology_detail.h"
#include "o3d/geometry/triangle_mesh_basics.h"
#include "o3d/geometry/triangle_mesh_ops.h"
#include "o3d/utility/error.h"
#include "o3d/utility/parallel.h"

namespace o3d::geometry {

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
            if (!detail::link_is_connected(mesh, around, static_cast<int>(v), ends, nodes, parent))
                manifold.store(false, std::memory_order_relaxed);
        }
    }
    return manifold.load();
}


bool is_orientable(const TriangleMesh& mesh) {
    validate_triangles(mesh);
    std::vector<int> flipped;
    return detail::consistent_orientation(mesh, flipped);
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
    if (!detail::consistent_orientation(mesh, flipped))
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
