// SPDX-License-Identifier: MIT
// C API: the mesh queries of trianglemesh.h that describe its connectivity (adjacency, non-manifold
// elements, intersections, orientation).
#include "internal.h"
#include "o3d/geometry/mesh_adjacency.h"
#include "o3d/geometry/triangle_mesh_basics.h"
#include "o3d/indexlists.h"
#include "o3d/trianglemesh.h"

using o3d::capi::guard;
using o3d::capi::require;
using o3d::capi::require_out_handle;
using o3d::geometry::TriangleMesh;

namespace {

const TriangleMesh& mesh_of(const o3d_trianglemesh_t* mesh, const char* name = "mesh") {
    return require(mesh, name)->mesh;
}

}  // namespace

O3D_API o3d_status o3d_trianglemesh_compute_adjacency_list(o3d_index_lists_t** out, const o3d_trianglemesh_t* mesh) {
    return guard(__func__, [&] {
        require_out_handle(out);
        const TriangleMesh& m = mesh_of(mesh);
        o3d::geometry::validate_triangles(m);
        const auto neighbours = o3d::geometry::vertex_neighbours(o3d::geometry::mesh_edges(m), m.vertices.size());
        *out = o3d::capi::make_index_lists(neighbours.offsets, neighbours.neighbours);
    });
}
