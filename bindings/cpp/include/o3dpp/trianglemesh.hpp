// SPDX-License-Identifier: MIT
#pragma once
/// @file trianglemesh.hpp
/// @brief o3dpp::TriangleMesh (move-only owner of an o3d_trianglemesh_t): arrays, textures, normals,
/// clean-up, topology queries, processing and primitives.
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <utility>
#include <vector>

#include "o3d/hull.h"
#include "o3d/trianglemesh.h"
#include "o3dpp/boundingbox.hpp"
#include "o3dpp/common.hpp"
#include "o3dpp/error.hpp"
#include "o3dpp/handle.hpp"
#include "o3dpp/image.hpp"
#include "o3dpp/pointcloud.hpp"
#include "o3dpp/span.hpp"

namespace o3dpp {

using Triangle = std::array<int32_t, 3>;  ///< three vertex indices
using Vec2 = std::array<double, 2>;       ///< a UV

/// @brief The N x 3 float64 arrays of a mesh.
enum class MeshArray : int32_t {
    Vertices = O3D_MESH_VERTICES,
    VertexNormals = O3D_MESH_VERTEX_NORMALS,
    VertexColors = O3D_MESH_VERTEX_COLORS,
    TriangleNormals = O3D_MESH_TRIANGLE_NORMALS
};

/// @brief Which vertex attributes the smoothing filters touch.
enum class FilterScope : int32_t {
    All = O3D_FILTER_SCOPE_ALL,
    Color = O3D_FILTER_SCOPE_COLOR,
    Normal = O3D_FILTER_SCOPE_NORMAL,
    Vertex = O3D_FILTER_SCOPE_VERTEX
};

/// @brief Vertex-clustering contraction.
enum class SimplificationContraction : int32_t {
    Average = O3D_SIMPLIFICATION_AVERAGE,
    Quadric = O3D_SIMPLIFICATION_QUADRIC
};

/// @brief Edge-connected triangle clusters.
struct TriangleClusters {
    std::vector<int32_t> triangle_clusters;    ///< per triangle
    std::vector<int32_t> cluster_n_triangles;  ///< per cluster
    std::vector<double> cluster_area;          ///< per cluster
};

class TriangleMesh {
public:
    /// @brief New empty mesh.
    TriangleMesh() {
        o3d_trianglemesh_t* p = nullptr;
        check(o3d_trianglemesh_create(&p));
        h_.reset(p);
    }
    /// @brief Take ownership of `owned` (must not be NULL).
    explicit TriangleMesh(o3d_trianglemesh_t* owned) : h_(owned) {
        if (!owned) throw Error(O3D_ERROR_INVALID_ARGUMENT, "o3dpp::TriangleMesh: NULL handle");
    }
    TriangleMesh(const std::vector<Vec3>& vertices, const std::vector<Triangle>& triangles) : TriangleMesh() {
        set_vertices(vertices);
        set_triangles(triangles);
    }
    TriangleMesh(TriangleMesh&&) noexcept = default;
    TriangleMesh& operator=(TriangleMesh&&) noexcept = default;
    TriangleMesh(const TriangleMesh&) = delete;
    TriangleMesh& operator=(const TriangleMesh&) = delete;

    o3d_trianglemesh_t* get() const noexcept { return h_.get(); }
    o3d_trianglemesh_t* release() noexcept { return h_.release(); }
    explicit operator bool() const noexcept { return static_cast<bool>(h_); }

    /// @brief Deep copy (textures included).
    TriangleMesh clone() const {
        return adopt([&](o3d_trianglemesh_t** o) { return o3d_trianglemesh_clone(o, get()); });
    }
    void clear() { check(o3d_trianglemesh_clear(get())); }

    std::size_t num_vertices() const { return count(&o3d_trianglemesh_num_vertices); }
    std::size_t num_triangles() const { return count(&o3d_trianglemesh_num_triangles); }
    bool has_vertices() const { return has(O3D_MESH_VERTICES); }
    bool has_triangles() const { return has(O3D_MESH_TRIANGLES); }
    bool has_vertex_normals() const { return has(O3D_MESH_VERTEX_NORMALS); }
    bool has_vertex_colors() const { return has(O3D_MESH_VERTEX_COLORS); }
    bool has_triangle_normals() const { return has(O3D_MESH_TRIANGLE_NORMALS); }
    bool has_triangle_uvs() const { return has(O3D_MESH_TRIANGLE_UVS); }
    bool has_triangle_material_ids() const { return has(O3D_MESH_TRIANGLE_MATERIAL_IDS); }

    // --- float64 arrays: setters copy once; views are borrowed until the next mutation ---
    void set_array(MeshArray which, const double* data, std::size_t rows) {
        check(o3d_trianglemesh_set_array(get(), static_cast<int32_t>(which), data, rows));
    }
    void set_array(MeshArray which, const std::vector<Vec3>& rows) {
        set_array(which, rows.empty() ? nullptr : rows.front().data(), rows.size());
    }
    std::vector<Vec3> get_array(MeshArray which) const { return copy_rows<double, 3>(static_cast<int32_t>(which)); }
    Rows3<const double> array(MeshArray which) const {
        const double* d = nullptr;
        size_t n = 0;
        check(o3d_trianglemesh_array_view(&d, &n, get(), static_cast<int32_t>(which)));
        return {d, n};
    }
    Rows3<double> array_mutable(MeshArray which) {
        double* d = nullptr;
        size_t n = 0;
        check(o3d_trianglemesh_array_mutable_view(&d, &n, get(), static_cast<int32_t>(which)));
        return {d, n};
    }
    void set_vertices(const std::vector<Vec3>& v) { set_array(MeshArray::Vertices, v); }
    void set_vertex_normals(const std::vector<Vec3>& v) { set_array(MeshArray::VertexNormals, v); }
    void set_vertex_colors(const std::vector<Vec3>& v) { set_array(MeshArray::VertexColors, v); }
    void set_triangle_normals(const std::vector<Vec3>& v) { set_array(MeshArray::TriangleNormals, v); }
    std::vector<Vec3> get_vertices() const { return get_array(MeshArray::Vertices); }
    std::vector<Vec3> get_vertex_normals() const { return get_array(MeshArray::VertexNormals); }
    std::vector<Vec3> get_vertex_colors() const { return get_array(MeshArray::VertexColors); }
    std::vector<Vec3> get_triangle_normals() const { return get_array(MeshArray::TriangleNormals); }
    Rows3<const double> vertices() const { return array(MeshArray::Vertices); }
    Rows3<const double> vertex_normals() const { return array(MeshArray::VertexNormals); }
    Rows3<const double> vertex_colors() const { return array(MeshArray::VertexColors); }
    Rows3<const double> triangle_normals() const { return array(MeshArray::TriangleNormals); }
    Rows3<double> vertices_mutable() { return array_mutable(MeshArray::Vertices); }

    /// @brief Per-corner UVs, three per triangle.
    void set_triangle_uvs(const std::vector<Vec2>& uvs) {
        check(o3d_trianglemesh_set_array(get(), O3D_MESH_TRIANGLE_UVS, uvs.empty() ? nullptr : uvs.front().data(),
                                         uvs.size()));
    }
    std::vector<Vec2> get_triangle_uvs() const { return copy_rows<double, 2>(O3D_MESH_TRIANGLE_UVS); }
    /// @brief Borrowed UVs as 2 * rows values.
    Span<const double> triangle_uvs() const {
        const double* d = nullptr;
        size_t n = 0;
        check(o3d_trianglemesh_array_view(&d, &n, get(), O3D_MESH_TRIANGLE_UVS));
        return {d, 2 * n};
    }

    // --- int32 arrays ---
    void set_triangles(const std::vector<Triangle>& t) {
        check(o3d_trianglemesh_set_index_array(get(), O3D_MESH_TRIANGLES, t.empty() ? nullptr : t.front().data(),
                                               t.size()));
    }
    std::vector<Triangle> get_triangles() const { return copy_rows<int32_t, 3>(O3D_MESH_TRIANGLES); }
    Rows3<const int32_t> triangles() const {
        const int32_t* d = nullptr;
        size_t n = 0;
        check(o3d_trianglemesh_index_array_view(&d, &n, get(), O3D_MESH_TRIANGLES));
        return {d, n};
    }
    /// @brief Writable triangles; indices are re-checked by every operation that follows them.
    Rows3<int32_t> triangles_mutable() {
        int32_t* d = nullptr;
        size_t n = 0;
        check(o3d_trianglemesh_index_array_mutable_view(&d, &n, get(), O3D_MESH_TRIANGLES));
        return {d, n};
    }
    void set_triangle_material_ids(const std::vector<int32_t>& ids) {
        check(o3d_trianglemesh_set_index_array(get(), O3D_MESH_TRIANGLE_MATERIAL_IDS, ids.data(), ids.size()));
    }
    std::vector<int32_t> get_triangle_material_ids() const {
        std::vector<int32_t> out;
        for (const auto& row : copy_rows<int32_t, 1>(O3D_MESH_TRIANGLE_MATERIAL_IDS)) out.push_back(row[0]);
        return out;
    }

    // --- textures ---
    std::size_t texture_count() const { return count(&o3d_trianglemesh_texture_count); }
    /// @brief Copy of texture `index`.
    Image texture(std::size_t index) const {
        return Image::adopt([&](o3d_image_t** o) { return o3d_trianglemesh_get_texture(o, get(), index); });
    }
    void add_texture(const Image& image) { check(o3d_trianglemesh_add_texture(get(), image.get())); }
    void clear_textures() { check(o3d_trianglemesh_clear_textures(get())); }

    /// @brief Concatenate (Open3D `mesh += other`).
    TriangleMesh& operator+=(const TriangleMesh& other) {
        check(o3d_trianglemesh_append(get(), other.get()));
        return *this;
    }
    TriangleMesh& append(const TriangleMesh& other) { return *this += other; }

    // --- normals, colors, transforms, bounds ---
    TriangleMesh& compute_vertex_normals(bool normalized = true) {
        check(o3d_trianglemesh_compute_vertex_normals(get(), normalized ? 1 : 0));
        return *this;
    }
    TriangleMesh& compute_triangle_normals(bool normalized = true) {
        check(o3d_trianglemesh_compute_triangle_normals(get(), normalized ? 1 : 0));
        return *this;
    }
    TriangleMesh& normalize_normals() { return in_place(&o3d_trianglemesh_normalize_normals); }
    TriangleMesh& paint_uniform_color(const Vec3& rgb) {
        check(o3d_trianglemesh_paint_uniform_color(get(), rgb.data()));
        return *this;
    }
    TriangleMesh& transform(const Mat4& t) {
        check(o3d_trianglemesh_transform(get(), t.data()));
        return *this;
    }
    TriangleMesh& translate(const Vec3& t, bool relative = true) {
        check(o3d_trianglemesh_translate(get(), t.data(), relative ? 1 : 0));
        return *this;
    }
    /// @brief Rotate about the mesh's center.
    TriangleMesh& rotate(const Mat3& r) {
        check(o3d_trianglemesh_rotate(get(), r.data(), nullptr));
        return *this;
    }
    TriangleMesh& rotate(const Mat3& r, const Vec3& center) {
        check(o3d_trianglemesh_rotate(get(), r.data(), center.data()));
        return *this;
    }
    TriangleMesh& scale(double s) {
        check(o3d_trianglemesh_scale(get(), s, nullptr));
        return *this;
    }
    TriangleMesh& scale(double s, const Vec3& center) {
        check(o3d_trianglemesh_scale(get(), s, center.data()));
        return *this;
    }
    Vec3 get_min_bound() const { return vec3(&o3d_trianglemesh_get_min_bound); }
    Vec3 get_max_bound() const { return vec3(&o3d_trianglemesh_get_max_bound); }
    Vec3 get_center() const { return vec3(&o3d_trianglemesh_get_center); }
    std::array<Vec3, 2> get_axis_aligned_bounding_box() const {
        std::array<Vec3, 2> box{};
        check(o3d_trianglemesh_get_axis_aligned_bounding_box(box[0].data(), box[1].data(), get()));
        return box;
    }

    // --- clean-up (in place) ---
    TriangleMesh& remove_duplicated_vertices() { return in_place(&o3d_trianglemesh_remove_duplicated_vertices); }
    TriangleMesh& remove_duplicated_triangles() { return in_place(&o3d_trianglemesh_remove_duplicated_triangles); }
    TriangleMesh& remove_degenerate_triangles() { return in_place(&o3d_trianglemesh_remove_degenerate_triangles); }
    TriangleMesh& remove_unreferenced_vertices() { return in_place(&o3d_trianglemesh_remove_unreferenced_vertices); }
    TriangleMesh& remove_non_manifold_edges() { return in_place(&o3d_trianglemesh_remove_non_manifold_edges); }
    TriangleMesh& merge_close_vertices(double eps) {
        check(o3d_trianglemesh_merge_close_vertices(get(), eps));
        return *this;
    }

    // --- queries ---
    double get_surface_area() const { return scalar(&o3d_trianglemesh_get_surface_area); }
    /// @brief Enclosed volume; not watertight and orientable → Error.
    double get_volume() const { return scalar(&o3d_trianglemesh_get_volume); }
    bool is_watertight() const { return flag(&o3d_trianglemesh_is_watertight); }
    bool is_edge_manifold(bool allow_boundary_edges = true) const {
        int32_t v = 0;
        check(o3d_trianglemesh_is_edge_manifold(&v, get(), allow_boundary_edges ? 1 : 0));
        return v != 0;
    }
    bool is_vertex_manifold() const { return flag(&o3d_trianglemesh_is_vertex_manifold); }
    bool is_self_intersecting() const { return flag(&o3d_trianglemesh_is_self_intersecting); }
    bool is_orientable() const { return flag(&o3d_trianglemesh_is_orientable); }
    int64_t euler_poincare_characteristic() const {
        int64_t v = 0;
        check(o3d_trianglemesh_euler_poincare_characteristic(&v, get()));
        return v;
    }
    TriangleClusters cluster_connected_triangles() const {
        const std::size_t cap = num_triangles();
        TriangleClusters c{std::vector<int32_t>(cap), std::vector<int32_t>(cap), std::vector<double>(cap)};
        size_t n_tri = 0, n_clusters = 0;
        check(o3d_trianglemesh_cluster_connected_triangles(c.triangle_clusters.data(), c.cluster_n_triangles.data(),
                                                           c.cluster_area.data(), cap, &n_tri, &n_clusters, get()));
        c.triangle_clusters.resize(n_tri < cap ? n_tri : cap);
        c.cluster_n_triangles.resize(n_clusters < cap ? n_clusters : cap);
        c.cluster_area.resize(n_clusters < cap ? n_clusters : cap);
        return c;
    }

    // --- processing (new cloud or mesh) ---
    PointCloud sample_points_uniformly(std::size_t number_of_points = 100, bool use_triangle_normal = false,
                                       uint64_t seed = 0) const {
        return PointCloud::adopt([&](o3d_pointcloud_t** o) {
            return o3d_trianglemesh_sample_points_uniformly(o, get(), number_of_points, use_triangle_normal ? 1 : 0,
                                                            seed);
        });
    }
    PointCloud sample_points_poisson_disk(std::size_t number_of_points, double init_factor = 5.0,
                                          bool use_triangle_normal = false, uint64_t seed = 0) const {
        return PointCloud::adopt([&](o3d_pointcloud_t** o) {
            return o3d_trianglemesh_sample_points_poisson_disk(o, get(), number_of_points, init_factor,
                                                               use_triangle_normal ? 1 : 0, seed);
        });
    }
    TriangleMesh simplify_vertex_clustering(
        double voxel_size, SimplificationContraction contraction = SimplificationContraction::Average) const {
        return adopt([&](o3d_trianglemesh_t** o) {
            return o3d_trianglemesh_simplify_vertex_clustering(o, get(), voxel_size,
                                                               static_cast<int32_t>(contraction));
        });
    }
    TriangleMesh simplify_quadric_decimation(std::size_t target_number_of_triangles,
                                             double maximum_error = std::numeric_limits<double>::infinity(),
                                             double boundary_weight = 1.0) const {
        return adopt([&](o3d_trianglemesh_t** o) {
            return o3d_trianglemesh_simplify_quadric_decimation(o, get(), target_number_of_triangles, maximum_error,
                                                                boundary_weight);
        });
    }
    TriangleMesh filter_smooth_simple(int number_of_iterations = 1, FilterScope scope = FilterScope::All) const {
        return adopt([&](o3d_trianglemesh_t** o) {
            return o3d_trianglemesh_filter_smooth_simple(o, get(), number_of_iterations, static_cast<int32_t>(scope));
        });
    }
    TriangleMesh filter_smooth_laplacian(int number_of_iterations = 1, double lambda_filter = 0.5,
                                         FilterScope scope = FilterScope::All) const {
        return adopt([&](o3d_trianglemesh_t** o) {
            return o3d_trianglemesh_filter_smooth_laplacian(o, get(), number_of_iterations, lambda_filter,
                                                            static_cast<int32_t>(scope));
        });
    }
    TriangleMesh filter_smooth_taubin(int number_of_iterations = 1, double lambda_filter = 0.5, double mu = -0.53,
                                      FilterScope scope = FilterScope::All) const {
        return adopt([&](o3d_trianglemesh_t** o) {
            return o3d_trianglemesh_filter_smooth_taubin(o, get(), number_of_iterations, lambda_filter, mu,
                                                         static_cast<int32_t>(scope));
        });
    }
    TriangleMesh subdivide_midpoint(int number_of_iterations = 1) const {
        return adopt(
            [&](o3d_trianglemesh_t** o) { return o3d_trianglemesh_subdivide_midpoint(o, get(), number_of_iterations); });
    }
    TriangleMesh subdivide_loop(int number_of_iterations = 1) const {
        return adopt(
            [&](o3d_trianglemesh_t** o) { return o3d_trianglemesh_subdivide_loop(o, get(), number_of_iterations); });
    }
    TriangleMesh crop(const Vec3& min_bound, const Vec3& max_bound) const {
        return adopt([&](o3d_trianglemesh_t** o) {
            return o3d_trianglemesh_crop_aabb(o, get(), min_bound.data(), max_bound.data());
        });
    }

    /// @brief Triangles whose three vertices lie inside `obb` (unused vertices dropped).
    TriangleMesh crop(const OrientedBoundingBox& obb) const {
        const o3d_obb_t c = obb.to_c();
        return adopt([&](o3d_trianglemesh_t** o) { return o3d_trianglemesh_crop_obb(o, get(), &c); });
    }
    /// @brief Oriented box of the vertices.
    OrientedBoundingBox get_oriented_bounding_box(bool robust = false) const {
        o3d_obb_t c{};
        check(o3d_trianglemesh_get_oriented_bounding_box(&c, get(), robust ? 1 : 0));
        return OrientedBoundingBox::from_c(c);
    }
    /// @brief Convex hull of the vertices: {hull (outward triangles), per hull vertex the index of its vertex}.
    std::pair<TriangleMesh, std::vector<int32_t>> compute_convex_hull(bool joggle_inputs = false) const {
        std::vector<int32_t> indices(num_vertices());
        o3d_trianglemesh_t* hull = nullptr;
        size_t n = 0;
        const o3d_status status = o3d_trianglemesh_compute_convex_hull(&hull, indices.data(), indices.size(), &n,
                                                                       get(), joggle_inputs ? 1 : 0);
        return adopt_with_indices(status, hull, std::move(indices), n);
    }

    /// @brief Own a mesh a C call wrote (even when it failed, so nothing leaks), then check its status.
    static std::pair<TriangleMesh, std::vector<int32_t>> adopt_with_indices(o3d_status status,
                                                                           o3d_trianglemesh_t* mesh,
                                                                           std::vector<int32_t> indices,
                                                                           std::size_t n) {
        UniqueHandle<o3d_trianglemesh_t, &o3d_trianglemesh_destroy> owned(mesh);
        check(status);
        indices.resize(n < indices.size() ? n : indices.size());
        return {TriangleMesh(owned.release()), std::move(indices)};
    }

    // --- primitives (Open3D's defaults) ---
    static TriangleMesh create_box(double width = 1.0, double height = 1.0, double depth = 1.0) {
        return adopt([&](o3d_trianglemesh_t** o) { return o3d_trianglemesh_create_box(o, width, height, depth); });
    }
    static TriangleMesh create_sphere(double radius = 1.0, int resolution = 20) {
        return adopt([&](o3d_trianglemesh_t** o) { return o3d_trianglemesh_create_sphere(o, radius, resolution); });
    }
    static TriangleMesh create_cylinder(double radius = 1.0, double height = 2.0, int resolution = 20, int split = 4) {
        return adopt([&](o3d_trianglemesh_t** o) {
            return o3d_trianglemesh_create_cylinder(o, radius, height, resolution, split);
        });
    }
    static TriangleMesh create_cone(double radius = 1.0, double height = 2.0, int resolution = 20, int split = 1) {
        return adopt(
            [&](o3d_trianglemesh_t** o) { return o3d_trianglemesh_create_cone(o, radius, height, resolution, split); });
    }
    static TriangleMesh create_torus(double torus_radius = 1.0, double tube_radius = 0.5, int radial_resolution = 30,
                                     int tubular_resolution = 20) {
        return adopt([&](o3d_trianglemesh_t** o) {
            return o3d_trianglemesh_create_torus(o, torus_radius, tube_radius, radial_resolution, tubular_resolution);
        });
    }
    static TriangleMesh create_arrow(double cylinder_radius = 1.0, double cone_radius = 1.5,
                                     double cylinder_height = 5.0, double cone_height = 4.0, int resolution = 20,
                                     int cylinder_split = 4, int cone_split = 1) {
        return adopt([&](o3d_trianglemesh_t** o) {
            return o3d_trianglemesh_create_arrow(o, cylinder_radius, cone_radius, cylinder_height, cone_height,
                                                 resolution, cylinder_split, cone_split);
        });
    }
    static TriangleMesh create_coordinate_frame(double size = 1.0, const Vec3& origin = {0, 0, 0}) {
        return adopt(
            [&](o3d_trianglemesh_t** o) { return o3d_trianglemesh_create_coordinate_frame(o, size, origin.data()); });
    }
    static TriangleMesh create_tetrahedron(double radius = 1.0) {
        return adopt([&](o3d_trianglemesh_t** o) { return o3d_trianglemesh_create_tetrahedron(o, radius); });
    }
    static TriangleMesh create_octahedron(double radius = 1.0) {
        return adopt([&](o3d_trianglemesh_t** o) { return o3d_trianglemesh_create_octahedron(o, radius); });
    }
    static TriangleMesh create_icosahedron(double radius = 1.0) {
        return adopt([&](o3d_trianglemesh_t** o) { return o3d_trianglemesh_create_icosahedron(o, radius); });
    }

    /// @brief Run `create(o3d_trianglemesh_t**)` and own what it returns.
    template <typename F>
    static TriangleMesh adopt(F&& create) {
        o3d_trianglemesh_t* p = nullptr;
        check(create(&p));
        return TriangleMesh(p);
    }

private:
    bool has(int32_t which) const {
        int32_t v = 0;
        check(o3d_trianglemesh_has_array(&v, get(), which));
        return v != 0;
    }
    std::size_t count(o3d_status (*fn)(const o3d_trianglemesh_t*, size_t*)) const {
        size_t n = 0;
        check(fn(get(), &n));
        return n;
    }
    bool flag(o3d_status (*fn)(const o3d_trianglemesh_t*, int32_t*)) const {
        int32_t v = 0;
        check(fn(get(), &v));
        return v != 0;
    }
    double scalar(o3d_status (*fn)(const o3d_trianglemesh_t*, double*)) const {
        double v = 0.0;
        check(fn(get(), &v));
        return v;
    }
    Vec3 vec3(o3d_status (*fn)(const o3d_trianglemesh_t*, double*)) const {
        Vec3 out{};
        check(fn(get(), out.data()));
        return out;
    }
    TriangleMesh& in_place(o3d_status (*fn)(o3d_trianglemesh_t*)) {
        check(fn(get()));
        return *this;
    }
    /// @brief Copy of array `which` as rows of N values of T (the query-then-copy convention).
    template <typename T, std::size_t N>
    std::vector<std::array<T, N>> copy_rows(int32_t which) const {
        static_assert(sizeof(std::array<T, N>) == N * sizeof(T), "std::array must be packed");
        size_t n = 0;
        query_rows(which, static_cast<T*>(nullptr), 0, &n);
        std::vector<std::array<T, N>> out(n);
        query_rows(which, n ? out.front().data() : static_cast<T*>(nullptr), n, &n);
        out.resize(n);
        return out;
    }
    void query_rows(int32_t which, double* out, size_t cap, size_t* n) const {
        check(o3d_trianglemesh_get_array(out, cap, n, get(), which));
    }
    void query_rows(int32_t which, int32_t* out, size_t cap, size_t* n) const {
        check(o3d_trianglemesh_get_index_array(out, cap, n, get(), which));
    }

    UniqueHandle<o3d_trianglemesh_t, &o3d_trianglemesh_destroy> h_;
};

}  // namespace o3dpp
