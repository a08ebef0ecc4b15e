// SPDX-License-Identifier: MIT
// C API: the container, normals/transforms/bounds, clean-up and query sections of trianglemesh.h.
#include <Eigen/Core>
#include <memory>
#include <string>

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
using o3d::geometry::TriangleMesh;

namespace {

TriangleMesh& mesh_of(o3d_trianglemesh_t* m, const char* name = "mesh") { return require(m, name)->mesh; }
const TriangleMesh& mesh_of(const o3d_trianglemesh_t* m, const char* name = "mesh") {
    return require(m, name)->mesh;
}

/// @brief A float64 array of the mesh seen as rows of `cols` doubles.
struct DoubleArray {
    double* data;
    size_t rows;
    size_t cols;
};

template <typename Vec>
DoubleArray as_array(std::vector<Vec>& v) {
    return {v.empty() ? nullptr : v[0].data(), v.size(), static_cast<size_t>(Vec::RowsAtCompileTime)};
}

DoubleArray double_array(TriangleMesh& m, int32_t which) {
    switch (which) {
        case O3D_MESH_VERTICES: return as_array(m.vertices);
        case O3D_MESH_VERTEX_NORMALS: return as_array(m.vertex_normals);
        case O3D_MESH_VERTEX_COLORS: return as_array(m.vertex_colors);
        case O3D_MESH_TRIANGLE_NORMALS: return as_array(m.triangle_normals);
        case O3D_MESH_TRIANGLE_UVS: return as_array(m.triangle_uvs);
        default:
            throw o3d::InvalidArgument("which " + std::to_string(which) +
                                       " is not a float64 mesh array (O3D_MESH_VERTICES .. O3D_MESH_TRIANGLE_UVS)");
    }
}

DoubleArray double_array(const TriangleMesh& m, int32_t which) { return double_array(const_cast<TriangleMesh&>(m), which); }

template <typename Vec>
void set_rows(std::vector<Vec>& dst, const double* data, size_t rows) {
    constexpr int cols = Vec::RowsAtCompileTime;
    std::vector<Vec> out(rows);
    for (size_t i = 0; i < rows; ++i)
        for (int k = 0; k < cols; ++k) out[i](k) = data[cols * i + k];
    dst = std::move(out);
}

struct IntArray {
    int32_t* data;
    size_t rows;
    size_t cols;
};

IntArray int_array(TriangleMesh& m, int32_t which) {
    switch (which) {
        case O3D_MESH_TRIANGLES:
            return {m.triangles.empty() ? nullptr : m.triangles[0].data(), m.triangles.size(), 3};
        case O3D_MESH_TRIANGLE_MATERIAL_IDS:
            return {m.triangle_material_ids.empty() ? nullptr : m.triangle_material_ids.data(),
                    m.triangle_material_ids.size(), 1};
        default:
            throw o3d::InvalidArgument("which " + std::to_string(which) +
                                       " is not an int32 mesh array (O3D_MESH_TRIANGLES, O3D_MESH_TRIANGLE_MATERIAL_IDS)");
    }
}

IntArray int_array(const TriangleMesh& m, int32_t which) { return int_array(const_cast<TriangleMesh&>(m), which); }

void check_input(const void* data, size_t rows, size_t cols, const char* name) {
    if (rows > 0 && !data) throw o3d::InvalidArgument(std::string(name) + " is NULL but rows = " + std::to_string(rows));
    if (rows > SIZE_MAX / (cols * sizeof(double)))
        throw o3d::InvalidArgument(std::string(name) + ": rows = " + std::to_string(rows) + " is too large");
}

void write3(double* out, const char* name, const Eigen::Vector3d& v) {
    require(out, name);
    out[0] = v.x();
    out[1] = v.y();
    out[2] = v.z();
}

Eigen::Vector3d vec3(const double* v, const char* name) {
    require(v, name);
    return Eigen::Vector3d(v[0], v[1], v[2]);
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

O3D_API o3d_status o3d_trianglemesh_num_vertices(const o3d_trianglemesh_t* mesh, size_t* out_n) {
    return guard(__func__, [&] {
        const TriangleMesh& m = mesh_of(mesh);
        *require(out_n, "out_n") = m.vertices.size();
    });
}

O3D_API o3d_status o3d_trianglemesh_num_triangles(const o3d_trianglemesh_t* mesh, size_t* out_n) {
    return guard(__func__, [&] {
        const TriangleMesh& m = mesh_of(mesh);
        *require(out_n, "out_n") = m.triangles.size();
    });
}

O3D_API o3d_status o3d_trianglemesh_has_array(const o3d_trianglemesh_t* mesh, int32_t which, int32_t* out) {
    return guard(__func__, [&] {
        const TriangleMesh& m = mesh_of(mesh);
        require(out, "out");
        switch (which) {
            case O3D_MESH_VERTICES: *out = flag(m.has_vertices()); break;
            case O3D_MESH_VERTEX_NORMALS: *out = flag(m.has_vertex_normals()); break;
            case O3D_MESH_VERTEX_COLORS: *out = flag(m.has_vertex_colors()); break;
            case O3D_MESH_TRIANGLE_NORMALS: *out = flag(m.has_triangle_normals()); break;
            case O3D_MESH_TRIANGLE_UVS: *out = flag(m.has_triangle_uvs()); break;
            case O3D_MESH_TRIANGLES: *out = flag(m.has_triangles()); break;
            case O3D_MESH_TRIANGLE_MATERIAL_IDS: *out = flag(m.has_triangle_material_ids()); break;
            default: throw o3d::InvalidArgument("which " + std::to_string(which) + " is not an O3D_MESH_* array");
        }
    });
}

O3D_API o3d_status o3d_trianglemesh_set_array(o3d_trianglemesh_t* mesh, int32_t which, const double* data,
                                              size_t rows) {
    return guard(__func__, [&] {
        TriangleMesh& m = mesh_of(mesh);
        const DoubleArray target = double_array(m, which);  // validates `which`
        check_input(data, rows, target.cols, "data");
        switch (which) {
            case O3D_MESH_VERTICES: set_rows(m.vertices, data, rows); break;
            case O3D_MESH_VERTEX_NORMALS: set_rows(m.vertex_normals, data, rows); break;
            case O3D_MESH_VERTEX_COLORS: set_rows(m.vertex_colors, data, rows); break;
            case O3D_MESH_TRIANGLE_NORMALS: set_rows(m.triangle_normals, data, rows); break;
            default: set_rows(m.triangle_uvs, data, rows); break;
        }
    });
}

O3D_API o3d_status o3d_trianglemesh_get_array(const o3d_trianglemesh_t* mesh, int32_t which, double* out,
                                              size_t capacity, size_t* out_rows) {
    return guard(__func__, [&] {
        const DoubleArray a = double_array(mesh_of(mesh), which);
        require(out_rows, "out_rows");
        o3d::capi::copy_out<double>(a.data, a.rows, out, capacity, out_rows, a.cols);
    });
}

O3D_API o3d_status o3d_trianglemesh_array_view(const o3d_trianglemesh_t* mesh, int32_t which,
                                               const double** out_data, size_t* out_rows) {
    return guard(__func__, [&] {
        const DoubleArray a = double_array(mesh_of(mesh), which);
        *require(out_data, "out_data") = a.data;
        *require(out_rows, "out_rows") = a.rows;
    });
}

O3D_API o3d_status o3d_trianglemesh_array_mutable_view(o3d_trianglemesh_t* mesh, int32_t which, double** out_data,
                                                       size_t* out_rows) {
    return guard(__func__, [&] {
        const DoubleArray a = double_array(mesh_of(mesh), which);
        *require(out_data, "out_data") = a.data;
        *require(out_rows, "out_rows") = a.rows;
    });
}

O3D_API o3d_status o3d_trianglemesh_set_index_array(o3d_trianglemesh_t* mesh, int32_t which, const int32_t* data,
                                                    size_t rows) {
    return guard(__func__, [&] {
        TriangleMesh& m = mesh_of(mesh);
        const IntArray target = int_array(m, which);  // validates `which`
        check_input(data, rows, target.cols, "data");
        if (which == O3D_MESH_TRIANGLES) {
            std::vector<Eigen::Vector3i> tris(rows);
            for (size_t i = 0; i < rows; ++i) tris[i] = Eigen::Vector3i(data[3 * i], data[3 * i + 1], data[3 * i + 2]);
            m.triangles = std::move(tris);
        } else {
            m.triangle_material_ids.assign(data, data + rows);
        }
    });
}

O3D_API o3d_status o3d_trianglemesh_get_index_array(const o3d_trianglemesh_t* mesh, int32_t which, int32_t* out,
                                                    size_t capacity, size_t* out_rows) {
    return guard(__func__, [&] {
        const IntArray a = int_array(mesh_of(mesh), which);
        require(out_rows, "out_rows");
        o3d::capi::copy_out<int32_t>(a.data, a.rows, out, capacity, out_rows, a.cols);
    });
}

O3D_API o3d_status o3d_trianglemesh_index_array_view(const o3d_trianglemesh_t* mesh, int32_t which,
                                                     const int32_t** out_data, size_t* out_rows) {
    return guard(__func__, [&] {
        const IntArray a = int_array(mesh_of(mesh), which);
        *require(out_data, "out_data") = a.data;
        *require(out_rows, "out_rows") = a.rows;
    });
}

O3D_API o3d_status o3d_trianglemesh_index_array_mutable_view(o3d_trianglemesh_t* mesh, int32_t which,
                                                             int32_t** out_data, size_t* out_rows) {
    return guard(__func__, [&] {
        const IntArray a = int_array(mesh_of(mesh), which);
        *require(out_data, "out_data") = a.data;
        *require(out_rows, "out_rows") = a.rows;
    });
}

O3D_API o3d_status o3d_trianglemesh_texture_count(const o3d_trianglemesh_t* mesh, size_t* out_n) {
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

O3D_API o3d_status o3d_trianglemesh_get_min_bound(const o3d_trianglemesh_t* mesh, double out[3]) {
    return guard(__func__, [&] {
        const TriangleMesh& m = mesh_of(mesh);
        write3(out, "out", o3d::geometry::min_bound(m));
    });
}

O3D_API o3d_status o3d_trianglemesh_get_max_bound(const o3d_trianglemesh_t* mesh, double out[3]) {
    return guard(__func__, [&] {
        const TriangleMesh& m = mesh_of(mesh);
        write3(out, "out", o3d::geometry::max_bound(m));
    });
}

O3D_API o3d_status o3d_trianglemesh_get_center(const o3d_trianglemesh_t* mesh, double out[3]) {
    return guard(__func__, [&] {
        const TriangleMesh& m = mesh_of(mesh);
        write3(out, "out", o3d::geometry::center(m));
    });
}

O3D_API o3d_status o3d_trianglemesh_get_axis_aligned_bounding_box(const o3d_trianglemesh_t* mesh,
                                                                  double out_min[3], double out_max[3]) {
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

O3D_API o3d_status o3d_trianglemesh_get_surface_area(const o3d_trianglemesh_t* mesh, double* out) {
    return guard(__func__, [&] {
        const TriangleMesh& m = mesh_of(mesh);
        *require(out, "out") = o3d::geometry::surface_area(m);
    });
}

O3D_API o3d_status o3d_trianglemesh_get_volume(const o3d_trianglemesh_t* mesh, double* out) {
    return guard(__func__, [&] {
        const TriangleMesh& m = mesh_of(mesh);
        *require(out, "out") = o3d::geometry::volume(m);
    });
}

O3D_API o3d_status o3d_trianglemesh_is_watertight(const o3d_trianglemesh_t* mesh, int32_t* out) {
    return guard(__func__, [&] {
        const TriangleMesh& m = mesh_of(mesh);
        *require(out, "out") = flag(o3d::geometry::is_watertight(m));
    });
}

O3D_API o3d_status o3d_trianglemesh_is_edge_manifold(const o3d_trianglemesh_t* mesh, int32_t allow_boundary_edges,
                                                     int32_t* out) {
    return guard(__func__, [&] {
        const TriangleMesh& m = mesh_of(mesh);
        *require(out, "out") = flag(o3d::geometry::is_edge_manifold(m, allow_boundary_edges != 0));
    });
}

O3D_API o3d_status o3d_trianglemesh_is_vertex_manifold(const o3d_trianglemesh_t* mesh, int32_t* out) {
    return guard(__func__, [&] {
        const TriangleMesh& m = mesh_of(mesh);
        *require(out, "out") = flag(o3d::geometry::is_vertex_manifold(m));
    });
}

O3D_API o3d_status o3d_trianglemesh_is_self_intersecting(const o3d_trianglemesh_t* mesh, int32_t* out) {
    return guard(__func__, [&] {
        const TriangleMesh& m = mesh_of(mesh);
        *require(out, "out") = flag(o3d::geometry::is_self_intersecting(m));
    });
}

O3D_API o3d_status o3d_trianglemesh_is_orientable(const o3d_trianglemesh_t* mesh, int32_t* out) {
    return guard(__func__, [&] {
        const TriangleMesh& m = mesh_of(mesh);
        *require(out, "out") = flag(o3d::geometry::is_orientable(m));
    });
}

O3D_API o3d_status o3d_trianglemesh_euler_poincare_characteristic(const o3d_trianglemesh_t* mesh, int64_t* out) {
    return guard(__func__, [&] {
        const TriangleMesh& m = mesh_of(mesh);
        *require(out, "out") = o3d::geometry::euler_poincare_characteristic(m);
    });
}

O3D_API o3d_status o3d_trianglemesh_cluster_connected_triangles(const o3d_trianglemesh_t* mesh,
                                                                int32_t* out_triangle_clusters,
                                                                int32_t* out_cluster_n_triangles,
                                                                double* out_cluster_area, size_t capacity,
                                                                size_t* out_num_triangles, size_t* out_num_clusters) {
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
