// SPDX-License-Identifier: MIT
// C API: the mesh queries of trianglemesh.h that describe its connectivity (adjacency, non-manifold
// elements, intersections, orientation), with sharpening and the ellipsoid primitive.
#include <string>

#include "internal.h"
#include "o3d/geometry/mesh_adjacency.h"
#include "o3d/geometry/mesh_intersection_queries.h"
#include "o3d/geometry/mesh_non_manifold.h"
#include "o3d/geometry/mesh_orientation.h"
#include "o3d/geometry/mesh_primitives_bounded.h"
#include "o3d/geometry/mesh_sharpen.h"
#include "o3d/geometry/triangle_mesh_basics.h"
#include "o3d/indexlists.h"
#include "o3d/trianglemesh.h"

using o3d::capi::copy_out;
using o3d::capi::emit_handle;
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

O3D_API o3d_status o3d_trianglemesh_get_non_manifold_edges(int32_t* out, size_t capacity, size_t* out_n,
                                                           const o3d_trianglemesh_t* mesh,
                                                           o3d_bool allow_boundary_edges) {
    return guard(__func__, [&] {
        require(out_n, "out_n");
        const auto edges = o3d::geometry::non_manifold_edges(mesh_of(mesh), allow_boundary_edges != 0);
        copy_out(edges.empty() ? nullptr : edges.front().data(), edges.size(), out, capacity, out_n, 2);
    });
}

O3D_API o3d_status o3d_trianglemesh_get_non_manifold_vertices(int32_t* out, size_t capacity, size_t* out_n,
                                                              const o3d_trianglemesh_t* mesh) {
    return guard(__func__, [&] {
        require(out_n, "out_n");
        const auto vertices = o3d::geometry::non_manifold_vertices(mesh_of(mesh));
        copy_out(vertices.data(), vertices.size(), out, capacity, out_n);
    });
}

O3D_API o3d_status o3d_trianglemesh_get_self_intersecting_triangles(int32_t* out, size_t capacity, size_t* out_n,
                                                                    const o3d_trianglemesh_t* mesh) {
    return guard(__func__, [&] {
        require(out_n, "out_n");
        const auto pairs = o3d::geometry::self_intersecting_triangles(mesh_of(mesh));
        copy_out(pairs.empty() ? nullptr : pairs.front().data(), pairs.size(), out, capacity, out_n, 2);
    });
}

O3D_API o3d_status o3d_trianglemesh_is_intersecting(int32_t* out, const o3d_trianglemesh_t* mesh,
                                                    const o3d_trianglemesh_t* other) {
    return guard(__func__, [&] {
        require(out, "out");
        *out = o3d::geometry::meshes_intersect(mesh_of(mesh), mesh_of(other, "other")) ? 1 : 0;
    });
}

O3D_API o3d_status o3d_trianglemesh_orient_triangles(int32_t* out_success, o3d_trianglemesh_t* mesh) {
    return guard(__func__, [&] {
        require(out_success, "out_success");
        *out_success = o3d::geometry::orient_triangles(require(mesh, "mesh")->mesh) ? 1 : 0;
    });
}

O3D_API o3d_status o3d_trianglemesh_filter_sharpen(o3d_trianglemesh_t** out, const o3d_trianglemesh_t* mesh,
                                                   int32_t number_of_iterations, double strength,
                                                   o3d_filter_scope filter_scope) {
    return guard(__func__, [&] {
        require_out_handle(out);
        if (filter_scope < O3D_FILTER_SCOPE_ALL || filter_scope > O3D_FILTER_SCOPE_VERTEX)
            throw o3d::InvalidArgument("filter_scope " + std::to_string(filter_scope) +
                                       " is not one of O3D_FILTER_SCOPE_ALL, _COLOR, _NORMAL, _VERTEX");
        emit_handle(out, o3d::geometry::filter_sharpen(mesh_of(mesh), number_of_iterations, strength,
                                                       static_cast<o3d::geometry::FilterScope>(filter_scope)));
    });
}

O3D_API o3d_status o3d_trianglemesh_create_ellipsoid(o3d_trianglemesh_t** out, double radius_x, double radius_y,
                                                     double radius_z, int32_t resolution, o3d_bool create_uv_map) {
    return guard(__func__, [&] {
        require_out_handle(out);
        emit_handle(out, o3d::geometry::create_ellipsoid(radius_x, radius_y, radius_z, resolution, create_uv_map != 0));
    });
}
