// SPDX-License-Identifier: MIT
// C API: halfedgemesh.h (the half-edge triangle mesh: construction, arrays, fans and boundary loops).
#include <string>
#include <vector>

#include "internal.h"
#include "o3d/halfedgemesh.h"
#include "o3d/indexlists.h"

using o3d::capi::copy_out;
using o3d::capi::emit_handle;
using o3d::capi::guard;
using o3d::capi::require;
using o3d::capi::require_out_handle;
using o3d::geometry::HalfEdgeTriangleMesh;

namespace {

const HalfEdgeTriangleMesh& half_edges_of(const o3d_halfedgemesh_t* mesh) { return require(mesh, "mesh")->mesh; }

const std::vector<Eigen::Vector3d>& array_of(const HalfEdgeTriangleMesh& m, o3d_halfedgemesh_array which) {
    switch (which) {
        case O3D_HALFEDGEMESH_VERTICES: return m.vertices;
        case O3D_HALFEDGEMESH_VERTEX_NORMALS: return m.vertex_normals;
        case O3D_HALFEDGEMESH_VERTEX_COLORS: return m.vertex_colors;
        case O3D_HALFEDGEMESH_TRIANGLE_NORMALS: return m.triangle_normals;
        default:
            throw o3d::InvalidArgument("which " + std::to_string(which) +
                                       " is not an O3D_HALFEDGEMESH_* array (VERTICES, VERTEX_NORMALS, "
                                       "VERTEX_COLORS, TRIANGLE_NORMALS)");
    }
}

}  // namespace

O3D_API o3d_status o3d_halfedgemesh_create_from_triangle_mesh(o3d_halfedgemesh_t** out, const o3d_trianglemesh_t* mesh) {
    return guard(__func__, [&] {
        require_out_handle(out);
        emit_handle(out, o3d::geometry::half_edge_mesh_from_triangle_mesh(require(mesh, "mesh")->mesh));
    });
}

O3D_API void o3d_halfedgemesh_destroy(o3d_halfedgemesh_t* mesh) { delete mesh; }

O3D_API o3d_status o3d_halfedgemesh_get_array(double* out, size_t capacity, size_t* out_rows,
                                              const o3d_halfedgemesh_t* mesh, o3d_halfedgemesh_array which) {
    return guard(__func__, [&] {
        require(out_rows, "out_rows");
        const auto& rows = array_of(half_edges_of(mesh), which);
        copy_out(rows.empty() ? nullptr : rows.front().data(), rows.size(), out, capacity, out_rows, 3);
    });
}

O3D_API o3d_status o3d_halfedgemesh_get_triangles(int32_t* out, size_t capacity, size_t* out_rows,
                                                  const o3d_halfedgemesh_t* mesh) {
    return guard(__func__, [&] {
        require(out_rows, "out_rows");
        const auto& rows = half_edges_of(mesh).triangles;
        copy_out(rows.empty() ? nullptr : rows.front().data(), rows.size(), out, capacity, out_rows, 3);
    });
}

O3D_API o3d_status o3d_halfedgemesh_get_half_edges(int32_t* out, size_t capacity, size_t* out_rows,
                                                   const o3d_halfedgemesh_t* mesh) {
    return guard(__func__, [&] {
        require(out_rows, "out_rows");
        const auto& half_edges = half_edges_of(mesh).half_edges;
        std::vector<int32_t> rows;
        if (out && capacity >= half_edges.size()) {
            rows.reserve(5 * half_edges.size());
            for (const auto& h : half_edges)
                rows.insert(rows.end(), {h.next, h.twin, h.vertex_indices(0), h.vertex_indices(1), h.triangle_index});
        }
        copy_out(rows.data(), half_edges.size(), out, capacity, out_rows, 5);
    });
}

O3D_API o3d_status o3d_halfedgemesh_get_ordered_half_edge_from_vertex(o3d_index_lists_t** out,
                                                                      const o3d_halfedgemesh_t* mesh) {
    return guard(__func__, [&] {
        require_out_handle(out);
        *out = o3d::capi::make_index_lists(half_edges_of(mesh).ordered_half_edge_from_vertex);
    });
}

O3D_API o3d_status o3d_halfedgemesh_boundary_half_edges_from_vertex(int32_t* out, size_t capacity, size_t* out_n,
                                                                    const o3d_halfedgemesh_t* mesh,
                                                                    int32_t vertex_index) {
    return guard(__func__, [&] {
        require(out_n, "out_n");
        const auto loop = o3d::geometry::boundary_half_edges_from_vertex(half_edges_of(mesh), vertex_index);
        copy_out(loop.data(), loop.size(), out, capacity, out_n);
    });
}

O3D_API o3d_status o3d_halfedgemesh_boundary_vertices_from_vertex(int32_t* out, size_t capacity, size_t* out_n,
                                                                  const o3d_halfedgemesh_t* mesh,
                                                                  int32_t vertex_index) {
    return guard(__func__, [&] {
        require(out_n, "out_n");
        const auto loop = o3d::geometry::boundary_vertices_from_vertex(half_edges_of(mesh), vertex_index);
        copy_out(loop.data(), loop.size(), out, capacity, out_n);
    });
}

O3D_API o3d_status o3d_halfedgemesh_get_boundaries(o3d_index_lists_t** out, const o3d_halfedgemesh_t* mesh) {
    return guard(__func__, [&] {
        require_out_handle(out);
        *out = o3d::capi::make_index_lists(o3d::geometry::boundaries(half_edges_of(mesh)));
    });
}
