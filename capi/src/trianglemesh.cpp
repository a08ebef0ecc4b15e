// SPDX-License-Identifier: MIT
// C API: the container, normals/transforms/bounds, clean-up and query sections of trianglemesh.h.
#include <Eigen/Core>
#include <memory>
#include <string>

#include "array_family.h"
#include "internal.h"
#include "o3d/geometry/mesh_cleanup.h"
#include "o3d/geometry/mesh_clusters.h"
#include "o3d/geometry/mesh_self_intersection.h"
#include "o3d/geometry/mesh_topology.h"
#include "o3d/geometry/triangle_mesh_basics.h"
#include "o3d/geometry/triangle_mesh_ops.h"
#include "o3d/trianglemesh.h"

using o3d::capi::guard;
using o3d::capi::require;
using o3d::capi::vec3;
using o3d::capi::write3;
using o3d::geometry::TriangleMesh;

namespace {

TriangleMesh& mesh_of(o3d_trianglemesh_t* m, const char* name = "mesh") { return require(m, name)->mesh; }
const TriangleMesh& mesh_of(const o3d_trianglemesh_t* m, const char* name = "mesh") {
    return require(m, name)->mesh;
}

o3d::capi::ArraySlot<double> mesh_slot(o3d_trianglemesh_t* h, int32_t which) {
    TriangleMesh& m = mesh_of(h);
    switch (which) {
        case O3D_MESH_VERTICES: return o3d::capi::eigen_slot(m.vertices, m.has_vertices());
        case O3D_MESH_VERTEX_NORMALS: return o3d::capi::eigen_slot(m.vertex_normals, m.has_vertex_normals());
        case O3D_MESH_VERTEX_COLORS: return o3d::capi::eigen_slot(m.vertex_colors, m.has_vertex_colors());
        case O3D_MESH_TRIANGLE_NORMALS: return o3d::capi::eigen_slot(m.triangle_normals, m.has_triangle_normals());
        case O3D_MESH_TRIANGLE_UVS: return o3d::capi::eigen_slot(m.triangle_uvs, m.has_triangle_uvs());
        default:
            o3d::capi::bad_which(which, "a float64 mesh array (O3D_MESH_VERTICES .. O3D_MESH_TRIANGLE_UVS)");
    }
}

o3d::capi::ArraySlot<int32_t> mesh_index_slot(o3d_trianglemesh_t* h, int32_t which) {
    TriangleMesh& m = mesh_of(h);
    switch (which) {
        case O3D_MESH_TRIANGLES: return o3d::capi::eigen_slot(m.triangles, m.has_triangles());
        case O3D_MESH_TRIANGLE_MATERIAL_IDS:
            return o3d::capi::flat_slot(m.triangle_material_ids, 1, m.has_triangle_material_ids());
        default:
            o3d::capi::bad_which(which, "an int32 mesh array (O3D_MESH_TRIANGLES, O3D_MESH_TRIANGLE_MATERIAL_IDS)");
    }
}



o3d_status give(o3d_trianglemesh_t** out, TriangleMesh mesh) {
    auto handle = std::make_unique<o3d_trianglemesh>();
    handle->mesh = std::move(mesh);
    *out = handle.release();
    return O3D_OK;
}

o3d_trianglemesh_t** require_out(o3d_trianglemesh_t** out) {
    require(out, "out");
    *out = nullptr;
    return out;
}

int32_t flag(bool b) { return b ? 1 : 0; }

}  // namespace

extern "C" {

O3D_CAPI_ARRAYS_F64(trianglemesh, o3d_trianglemesh_t, mesh_slot)
O3D_CAPI_ARRAY_QUERIES(trianglemesh, o3d_trianglemesh_t, mesh_slot, mesh_index_slot)
O3D_CAPI_INDEX_ARRAYS(trianglemesh, o3d_trianglemesh_t, mesh_index_slot)

/* ---- Container ---- */

O3D_API o3d_status o3d_trianglemesh_create(o3d_trianglemesh_t** out) {
    return guard(__func__, [&] { give(require_out(out), TriangleMesh{}); });
}

O3D_API void o3d_trianglemesh_destroy(o3d_trianglemesh_t* mesh) { delete mesh; }

O3D_API o3d_status o3d_trianglemesh_clone(o3d_trianglemesh_t** out, const o3d_trianglemesh_t* src) {
    return guard(__func__, [&] {
        require_out(out);
        give(out, mesh_of(src, "src"));
    });
}

O3D_API o3d_status o3d_trianglemesh_clear(o3d_trianglemesh_t* mesh) {
    return guard(__func__, [&] { mesh_of(mesh).clear(); });
}

O3D_API o3d_status o3d_trianglemesh_num_vertices(size_t* out_n, const o3d_trianglemesh_t* mesh) {
    return guard(__func__, [&] {
        const TriangleMesh& m = mesh_of(mesh);
        *require(out_n, "out_n") = m.vertices.size();
    });
}

O3D_API o3d_status o3d_trianglemesh_num_triangles(size_t* out_n, const o3d_trianglemesh_t* mesh) {
    return guard(__func__, [&] {
        const TriangleMesh& m = mesh_of(mesh);
        *require(out_n, "out_n") = m.triangles.size();
    });
}

O3D_API o3d_status o3d_trianglemesh_texture_count(size_t* out_n, const o3d_trianglemesh_t* mesh) {
    return guard(__func__, [&] {
        const TriangleMesh& m = mesh_of(mesh);
        *require(out_n, "out_n") = m.textures.size();
    });
}

O3D_API o3d_status o3d_trianglemesh_get_texture(o3d_image_t** out, const o3d_trianglemesh_t* mesh, size_t index) {
    return guard(__func__, [&] {
        require(out, "out");
        *out = nullptr;
        const TriangleMesh& m = mesh_of(mesh);
        if (index >= m.textures.size())
            throw o3d::InvalidArgument("texture " + std::to_string(index) + " is out of range: the mesh has " +
                                       std::to_string(m.textures.size()));
        auto handle = std::make_unique<o3d_image>();
        handle->image = m.textures[index];
        *out = handle.release();
    });
}

O3D_API o3d_status o3d_trianglemesh_add_texture(o3d_trianglemesh_t* mesh, const o3d_image_t* image) {
    return guard(__func__, [&] {
        TriangleMesh& m = mesh_of(mesh);
        const o3d::geometry::Image copy = require(image, "image")->image;  // the image may be a texture of m
        m.textures.push_back(copy);
    });
}

O3D_API o3d_status o3d_trianglemesh_clear_textures(o3d_trianglemesh_t* mesh) {
    return guard(__func__, [&] { mesh_of(mesh).textures.clear(); });
}

O3D_API o3d_status o3d_trianglemesh_append(o3d_trianglemesh_t* mesh, const o3d_trianglemesh_t* other) {
    return guard(__func__, [&] {
        TriangleMesh& target = mesh_of(mesh);
        const TriangleMesh& source = mesh_of(other, "other");
        if (&target == &source) {
            const TriangleMesh copy = source;  // `mesh += mesh` must not read what it is growing
            o3d::geometry::append(target, copy);
        } else {
            o3d::geometry::append(target, source);
        }
    });
}

/* ---- Normals, colors, transforms, bounds ---- */

O3D_API o3d_status o3d_trianglemesh_compute_vertex_normals(o3d_trianglemesh_t* mesh, int32_t normalized) {
    return guard(__func__, [&] { o3d::geometry::compute_vertex_normals(mesh_of(mesh), normalized != 0); });
}

O3D_API o3d_status o3d_trianglemesh_compute_triangle_normals(o3d_trianglemesh_t* mesh, int32_t normalized) {
    return guard(__func__, [&] { o3d::geometry::compute_triangle_normals(mesh_of(mesh), normalized != 0); });
}

O3D_API o3d_status o3d_trianglemesh_normalize_normals(o3d_trianglemesh_t* mesh) {
    return guard(__func__, [&] { o3d::geometry::normalize_normals(mesh_of(mesh)); });
}

O3D_API o3d_status o3d_trianglemesh_paint_uniform_color(o3d_trianglemesh_t* mesh, const double rgb[3]) {
    return guard(__func__, [&] {
        TriangleMesh& m = mesh_of(mesh);
        o3d::geometry::paint_uniform_color(m, vec3(rgb, "rgb"));
    });
}

O3D_API o3d_status o3d_trianglemesh_transform(o3d_trianglemesh_t* mesh, const double transform[16]) {
    return guard(__func__, [&] {
        TriangleMesh& m = mesh_of(mesh);
        require(transform, "transform");
        o3d::geometry::transform(m, Eigen::Map<const Eigen::Matrix<double, 4, 4, Eigen::RowMajor>>(transform));
    });
}

O3D_API o3d_status o3d_trianglemesh_translate(o3d_trianglemesh_t* mesh, const double translation[3],
                                              int32_t relative) {
    return guard(__func__, [&] {
        TriangleMesh& m = mesh_of(mesh);
        o3d::geometry::translate(m, vec3(translation, "translation"), relative != 0);
    });
}

O3D_API o3d_status o3d_trianglemesh_rotate(o3d_trianglemesh_t* mesh, const double rotation[9],
                                           const double center[3]) {
    return guard(__func__, [&] {
        TriangleMesh& m = mesh_of(mesh);
        require(rotation, "rotation");
        const Eigen::Vector3d about = center ? vec3(center, "center") : o3d::geometry::center(m);
        o3d::geometry::rotate(m, Eigen::Map<const Eigen::Matrix<double, 3, 3, Eigen::RowMajor>>(rotation), about);
    });
}

O3D_API o3d_status o3d_trianglemesh_scale(o3d_trianglemesh_t* mesh, double scale, const double center[3]) {
    return guard(__func__, [&] {
        TriangleMesh& m = mesh_of(mesh);
        const Eigen::Vector3d about = center ? vec3(center, "center") : o3d::geometry::center(m);
        o3d::geometry::scale(m, scale, about);
    });
}

O3D_API o3d_status o3d_trianglemesh_get_min_bound(double out[3], const o3d_trianglemesh_t* mesh) {
    return guard(__func__, [&] {
        const TriangleMesh& m = mesh_of(mesh);
        write3(out, "out", o3d::geometry::min_bound(m));
    });
}

O3D_API o3d_status o3d_trianglemesh_get_max_bound(double out[3], const o3d_trianglemesh_t* mesh) {
    return guard(__func__, [&] {
        const TriangleMesh& m = mesh_of(mesh);
        write3(out, "out", o3d::geometry::max_bound(m));
    });
}

O3D_API o3d_status o3d_trianglemesh_get_center(double out[3], const o3d_trianglemesh_t* mesh) {
    return guard(__func__, [&] {
        const TriangleMesh& m = mesh_of(mesh);
        write3(out, "out", o3d::geometry::center(m));
    });
}

O3D_API o3d_status o3d_trianglemesh_get_axis_aligned_bounding_box(double out_min[3], double out_max[3],
                                                                  const o3d_trianglemesh_t* mesh) {
    return guard(__func__, [&] {
        const TriangleMesh& m = mesh_of(mesh);
        require(out_min, "out_min");
        require(out_max, "out_max");
        write3(out_min, "out_min", o3d::geometry::min_bound(m));
        write3(out_max, "out_max", o3d::geometry::max_bound(m));
    });
}

/* ---- Clean-up ---- */

O3D_API o3d_status o3d_trianglemesh_remove_duplicated_vertices(o3d_trianglemesh_t* mesh) {
    return guard(__func__, [&] { o3d::geometry::remove_duplicated_vertices(mesh_of(mesh)); });
}

O3D_API o3d_status o3d_trianglemesh_remove_duplicated_triangles(o3d_trianglemesh_t* mesh) {
    return guard(__func__, [&] { o3d::geometry::remove_duplicated_triangles(mesh_of(mesh)); });
}

O3D_API o3d_status o3d_trianglemesh_remove_degenerate_triangles(o3d_trianglemesh_t* mesh) {
    return guard(__func__, [&] { o3d::geometry::remove_degenerate_triangles(mesh_of(mesh)); });
}

O3D_API o3d_status o3d_trianglemesh_remove_unreferenced_vertices(o3d_trianglemesh_t* mesh) {
    return guard(__func__, [&] { o3d::geometry::remove_unreferenced_vertices(mesh_of(mesh)); });
}

O3D_API o3d_status o3d_trianglemesh_remove_non_manifold_edges(o3d_trianglemesh_t* mesh) {
    return guard(__func__, [&] { o3d::geometry::remove_non_manifold_edges(mesh_of(mesh)); });
}

O3D_API o3d_status o3d_trianglemesh_merge_close_vertices(o3d_trianglemesh_t* mesh, double eps) {
    return guard(__func__, [&] { o3d::geometry::merge_close_vertices(mesh_of(mesh), eps); });
}

/* ---- Queries ---- */

O3D_API o3d_status o3d_trianglemesh_get_surface_area(double* out, const o3d_trianglemesh_t* mesh) {
    return guard(__func__, [&] {
        const TriangleMesh& m = mesh_of(mesh);
        *require(out, "out") = o3d::geometry::surface_area(m);
    });
}

O3D_API o3d_status o3d_trianglemesh_get_volume(double* out, const o3d_trianglemesh_t* mesh) {
    return guard(__func__, [&] {
        const TriangleMesh& m = mesh_of(mesh);
        *require(out, "out") = o3d::geometry::volume(m);
    });
}

O3D_API o3d_status o3d_trianglemesh_is_watertight(int32_t* out, const o3d_trianglemesh_t* mesh) {
    return guard(__func__, [&] {
        const TriangleMesh& m = mesh_of(mesh);
        *require(out, "out") = flag(o3d::geometry::is_watertight(m));
    });
}

O3D_API o3d_status o3d_trianglemesh_is_edge_manifold(int32_t* out, const o3d_trianglemesh_t* mesh,
                                                     int32_t allow_boundary_edges) {
    return guard(__func__, [&] {
        const TriangleMesh& m = mesh_of(mesh);
        *require(out, "out") = flag(o3d::geometry::is_edge_manifold(m, allow_boundary_edges != 0));
    });
}

O3D_API o3d_status o3d_trianglemesh_is_vertex_manifold(int32_t* out, const o3d_trianglemesh_t* mesh) {
    return guard(__func__, [&] {
        const TriangleMesh& m = mesh_of(mesh);
        *require(out, "out") = flag(o3d::geometry::is_vertex_manifold(m));
    });
}

O3D_API o3d_status o3d_trianglemesh_is_self_intersecting(int32_t* out, const o3d_trianglemesh_t* mesh) {
    return guard(__func__, [&] {
        const TriangleMesh& m = mesh_of(mesh);
        *require(out, "out") = flag(o3d::geometry::is_self_intersecting(m));
    });
}

O3D_API o3d_status o3d_trianglemesh_is_orientable(int32_t* out, const o3d_trianglemesh_t* mesh) {
    return guard(__func__, [&] {
        const TriangleMesh& m = mesh_of(mesh);
        *require(out, "out") = flag(o3d::geometry::is_orientable(m));
    });
}

O3D_API o3d_status o3d_trianglemesh_euler_poincare_characteristic(int64_t* out, const o3d_trianglemesh_t* mesh) {
    return guard(__func__, [&] {
        const TriangleMesh& m = mesh_of(mesh);
        *require(out, "out") = o3d::geometry::euler_poincare_characteristic(m);
    });
}

O3D_API o3d_status o3d_trianglemesh_cluster_connected_triangles(int32_t* out_triangle_clusters,
                                                                int32_t* out_cluster_n_triangles,
                                                                double* out_cluster_area, size_t capacity,
                                                                size_t* out_num_triangles, size_t* out_num_clusters,
                                                                const o3d_trianglemesh_t* mesh) {
    return guard(__func__, [&] {
        const TriangleMesh& m = mesh_of(mesh);
        require(out_num_triangles, "out_num_triangles");
        require(out_num_clusters, "out_num_clusters");
        const o3d::geometry::TriangleClusters c = o3d::geometry::cluster_connected_triangles(m);
        const size_t num_triangles = c.triangle_cluster.size(), num_clusters = c.cluster_size.size();
        *out_num_triangles = num_triangles;
        *out_num_clusters = num_clusters;
        size_t unused = 0;
        o3d::capi::copy_out(c.triangle_cluster.data(), num_triangles, out_triangle_clusters, capacity, &unused);
        o3d::capi::copy_out(c.cluster_size.data(), num_clusters, out_cluster_n_triangles, capacity, &unused);
        o3d::capi::copy_out(c.cluster_area.data(), num_clusters, out_cluster_area, capacity, &unused);
    });
}

}  // extern "C"
