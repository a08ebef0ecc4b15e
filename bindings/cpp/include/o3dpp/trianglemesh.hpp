// SPDX-License-Identifier: MIT
#pragma once
/// @file trianglemesh.hpp
/// @brief o3dpp::TriangleMesh (move-only owner of an o3d_trianglemesh_t): arrays, textures, normals,
/// clean-up, topology queries, processing, primitives, convex hulls and hidden-point removal.
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <utility>
#include <vector>

#include "o3d/trianglemesh.h"
#include "o3dpp/arrays.hpp"
#include "o3dpp/boundingbox.hpp"
#include "o3dpp/common.hpp"
#include "o3dpp/error.hpp"
#include "o3dpp/generated/options.hpp"
#include "o3dpp/handle.hpp"
#include "o3dpp/image.hpp"
#include "o3dpp/pointcloud.hpp"
#include "o3dpp/span.hpp"

namespace o3dpp {

using Triangle = std::array<int32_t, 3>;  ///< three vertex indices
using Vec2 = std::array<double, 2>;       ///< a UV

namespace detail {
using MeshArrayFns =
    ArrayFns<&o3d_trianglemesh_has_array, &o3d_trianglemesh_array_shape, &o3d_trianglemesh_get_array,
             &o3d_trianglemesh_array_view, &o3d_trianglemesh_array_mutable_view, &o3d_trianglemesh_set_array,
             &o3d_trianglemesh_set_array_f32, &o3d_trianglemesh_get_index_array, &o3d_trianglemesh_index_array_view,
             &o3d_trianglemesh_index_array_mutable_view, &o3d_trianglemesh_set_index_array>;
}  // namespace detail

/// @brief Edge-connected triangle clusters.
struct TriangleClusters {
    std::vector<int32_t> triangle_clusters;    ///< per triangle
    std::vector<int32_t> cluster_n_triangles;  ///< per cluster
    std::vector<double> cluster_area;          ///< per cluster
};

class TriangleMesh : public Owner<TriangleMesh, o3d_trianglemesh_t, &o3d_trianglemesh_destroy>,
                     public Arrays<TriangleMesh, MeshArray, detail::MeshArrayFns> {
    using A = MeshArray;

public:
    /// @brief New empty mesh.
    TriangleMesh() : Owner(make(&o3d_trianglemesh_create)) {}
    /// @brief Take ownership of `owned` (must not be NULL).
    explicit TriangleMesh(o3d_trianglemesh_t* owned) : Owner(owned) {}
    TriangleMesh(const std::vector<Vec3>& vertices, const std::vector<Triangle>& triangles) : TriangleMesh() {
        set_vertices(vertices);
        set_triangles(triangles);
    }

    /// @brief Deep copy (textures included).
    TriangleMesh clone() const { return derive(&o3d_trianglemesh_clone); }
    void clear() { check(o3d_trianglemesh_clear(get())); }

    std::size_t num_vertices() const { return query(&o3d_trianglemesh_num_vertices); }
    std::size_t num_triangles() const { return query(&o3d_trianglemesh_num_triangles); }

    // --- named arrays (see Arrays for the generic accessor): setters copy once; views are borrowed until
    // the next mutation. Triangles may hold any index: every operation that follows them checks them. ---
    bool has_vertices() const { return has_array(A::Vertices); }
    bool has_triangles() const { return has_array(A::Triangles); }
    bool has_vertex_normals() const { return has_array(A::VertexNormals); }
    bool has_vertex_colors() const { return has_array(A::VertexColors); }
    bool has_triangle_normals() const { return has_array(A::TriangleNormals); }
    bool has_triangle_uvs() const { return has_array(A::TriangleUvs); }
    bool has_triangle_material_ids() const { return has_array(A::TriangleMaterialIds); }
    void set_vertices(const std::vector<Vec3>& v) { set_array(A::Vertices, v); }
    void set_vertex_normals(const std::vector<Vec3>& v) { set_array(A::VertexNormals, v); }
    void set_vertex_colors(const std::vector<Vec3>& v) { set_array(A::VertexColors, v); }
    void set_triangle_normals(const std::vector<Vec3>& v) { set_array(A::TriangleNormals, v); }
    /// @brief Per-corner UVs, three per triangle.
    void set_triangle_uvs(const std::vector<Vec2>& uvs) { set_array(A::TriangleUvs, uvs); }
    void set_triangles(const std::vector<Triangle>& t) { set_array(A::Triangles, t); }
    void set_triangle_material_ids(const std::vector<int32_t>& ids) { set_array(A::TriangleMaterialIds, ids); }
    std::vector<Vec3> get_vertices() const { return get_array(A::Vertices); }
    std::vector<Vec3> get_vertex_normals() const { return get_array(A::VertexNormals); }
    std::vector<Vec3> get_vertex_colors() const { return get_array(A::VertexColors); }
    std::vector<Vec3> get_triangle_normals() const { return get_array(A::TriangleNormals); }
    std::vector<Vec2> get_triangle_uvs() const { return get_array<Vec2>(A::TriangleUvs); }
    std::vector<Triangle> get_triangles() const { return get_array<Triangle>(A::Triangles); }
    std::vector<int32_t> get_triangle_material_ids() const { return get_array<int32_t>(A::TriangleMaterialIds); }
    Rows3<const double> vertices() const { return array(A::Vertices); }
    Rows3<const double> vertex_normals() const { return array(A::VertexNormals); }
    Rows3<const double> vertex_colors() const { return array(A::VertexColors); }
    Rows3<const double> triangle_normals() const { return array(A::TriangleNormals); }
    /// @brief Borrowed UVs as 2 * rows values.
    Span<const double> triangle_uvs() const { return array(A::TriangleUvs).flat(); }
    Rows3<const int32_t> triangles() const { return array<int32_t>(A::Triangles); }
    Rows3<double> vertices_mutable() { return array_mutable(A::Vertices); }
    Rows3<int32_t> triangles_mutable() { return array_mutable<int32_t>(A::Triangles); }

    // --- textures ---
    std::size_t texture_count() const { return query(&o3d_trianglemesh_texture_count); }
    /// @brief Copy of texture `index`.
    Image texture(std::size_t index) const { return derive<Image>(&o3d_trianglemesh_get_texture, index); }
    void add_texture(const Image& image) { check(o3d_trianglemesh_add_texture(get(), image.get())); }
    void clear_textures() { check(o3d_trianglemesh_clear_textures(get())); }


    /// @brief Concatenate `other` (Open3D `mesh += other`).
    TriangleMesh& operator+=(const TriangleMesh& other) { return done(o3d_trianglemesh_append(get(), other.get())); }
    TriangleMesh& append(const TriangleMesh& other) { return *this += other; }
    TriangleMesh& transform(const Mat4& t) { return done(o3d_trianglemesh_transform(get(), t.data())); }
    TriangleMesh& translate(const Vec3& t, bool relative = true) {
        return done(o3d_trianglemesh_translate(get(), t.data(), relative ? 1 : 0));
    }
    /// @brief Rotate about the center.
    TriangleMesh& rotate(const Mat3& r) { return done(o3d_trianglemesh_rotate(get(), r.data(), nullptr)); }
    TriangleMesh& rotate(const Mat3& r, const Vec3& center) {
        return done(o3d_trianglemesh_rotate(get(), r.data(), center.data()));
    }
    /// @brief Scale about the center.
    TriangleMesh& scale(double s) { return done(o3d_trianglemesh_scale(get(), s, nullptr)); }
    TriangleMesh& scale(double s, const Vec3& center) { return done(o3d_trianglemesh_scale(get(), s, center.data())); }
    Vec3 get_min_bound() const { return query3(&o3d_trianglemesh_get_min_bound); }
    Vec3 get_max_bound() const { return query3(&o3d_trianglemesh_get_max_bound); }
    Vec3 get_center() const { return query3(&o3d_trianglemesh_get_center); }
    /// @brief {min corner, max corner}.
    std::array<Vec3, 2> get_axis_aligned_bounding_box() const {
        std::array<Vec3, 2> box{};
        check(o3d_trianglemesh_get_axis_aligned_bounding_box(box[0].data(), box[1].data(), get()));
        return box;
    }
    TriangleMesh& paint_uniform_color(const Vec3& rgb) {
        return done(o3d_trianglemesh_paint_uniform_color(get(), rgb.data()));
    }

    // --- normals ---
    TriangleMesh& compute_vertex_normals(bool normalized = true) {
        return done(o3d_trianglemesh_compute_vertex_normals(get(), normalized ? 1 : 0));
    }
    TriangleMesh& compute_triangle_normals(bool normalized = true) {
        return done(o3d_trianglemesh_compute_triangle_normals(get(), normalized ? 1 : 0));
    }
    TriangleMesh& normalize_normals() { return done(o3d_trianglemesh_normalize_normals(get())); }

    // --- clean-up (in place) ---
    TriangleMesh& remove_duplicated_vertices() { return done(o3d_trianglemesh_remove_duplicated_vertices(get())); }
    TriangleMesh& remove_duplicated_triangles() { return done(o3d_trianglemesh_remove_duplicated_triangles(get())); }
    TriangleMesh& remove_degenerate_triangles() { return done(o3d_trianglemesh_remove_degenerate_triangles(get())); }
    TriangleMesh& remove_unreferenced_vertices() { return done(o3d_trianglemesh_remove_unreferenced_vertices(get())); }
    TriangleMesh& remove_non_manifold_edges() { return done(o3d_trianglemesh_remove_non_manifold_edges(get())); }
    TriangleMesh& merge_close_vertices(double eps) { return done(o3d_trianglemesh_merge_close_vertices(get(), eps)); }

    // --- queries ---
    double get_surface_area() const { return query(&o3d_trianglemesh_get_surface_area); }
    /// @brief Enclosed volume; not watertight and orientable → Error.
    double get_volume() const { return query(&o3d_trianglemesh_get_volume); }
    bool is_watertight() const { return flag(&o3d_trianglemesh_is_watertight); }
    bool is_edge_manifold(bool allow_boundary_edges = true) const {
        int32_t v = 0;
        check(o3d_trianglemesh_is_edge_manifold(&v, get(), allow_boundary_edges ? 1 : 0));
        return v != 0;
    }
    bool is_vertex_manifold() const { return flag(&o3d_trianglemesh_is_vertex_manifold); }
    bool is_self_intersecting() const { return flag(&o3d_trianglemesh_is_self_intersecting); }
    bool is_orientable() const { return flag(&o3d_trianglemesh_is_orientable); }
    int64_t euler_poincare_characteristic() const { return query(&o3d_trianglemesh_euler_poincare_characteristic); }
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
        return derive<PointCloud>(&o3d_trianglemesh_sample_points_uniformly, number_of_points,
                                  use_triangle_normal ? 1 : 0, seed);
    }
    PointCloud sample_points_poisson_disk(std::size_t number_of_points, double init_factor = 5.0,
                                          bool use_triangle_normal = false, uint64_t seed = 0) const {
        return derive<PointCloud>(&o3d_trianglemesh_sample_points_poisson_disk, number_of_points, init_factor,
                                  use_triangle_normal ? 1 : 0, seed);
    }
    TriangleMesh simplify_vertex_clustering(
        double voxel_size, SimplificationContraction contraction = SimplificationContraction::Average) const {
        return derive(&o3d_trianglemesh_simplify_vertex_clustering, voxel_size, static_cast<int32_t>(contraction));
    }
    TriangleMesh simplify_quadric_decimation(std::size_t target_number_of_triangles,
                                             double maximum_error = std::numeric_limits<double>::infinity(),
                                             double boundary_weight = 1.0) const {
        return derive(&o3d_trianglemesh_simplify_quadric_decimation, target_number_of_triangles, maximum_error,
                      boundary_weight);
    }
    TriangleMesh filter_smooth_simple(int number_of_iterations = 1, FilterScope scope = FilterScope::All) const {
        return derive(&o3d_trianglemesh_filter_smooth_simple, number_of_iterations, static_cast<int32_t>(scope));
    }
    TriangleMesh filter_smooth_laplacian(int number_of_iterations = 1, double lambda_filter = 0.5,
                                         FilterScope scope = FilterScope::All) const {
        return derive(&o3d_trianglemesh_filter_smooth_laplacian, number_of_iterations, lambda_filter,
                      static_cast<int32_t>(scope));
    }
    TriangleMesh filter_smooth_taubin(int number_of_iterations = 1, double lambda_filter = 0.5, double mu = -0.53,
                                      FilterScope scope = FilterScope::All) const {
        return derive(&o3d_trianglemesh_filter_smooth_taubin, number_of_iterations, lambda_filter, mu,
                      static_cast<int32_t>(scope));
    }
    TriangleMesh subdivide_midpoint(int number_of_iterations = 1) const {
        return derive(&o3d_trianglemesh_subdivide_midpoint, number_of_iterations);
    }
    TriangleMesh subdivide_loop(int number_of_iterations = 1) const {
        return derive(&o3d_trianglemesh_subdivide_loop, number_of_iterations);
    }
    TriangleMesh crop(const Vec3& min_bound, const Vec3& max_bound) const {
        return derive(&o3d_trianglemesh_crop_aabb, min_bound.data(), max_bound.data());
    }

    /// @brief Triangles whose three vertices lie inside `obb` (unused vertices dropped).
    TriangleMesh crop(const OrientedBoundingBox& obb) const {
        const o3d_obb_t c = obb.to_c();
        return derive(&o3d_trianglemesh_crop_obb, &c);
    }
    /// @brief Oriented box of the vertices.
    OrientedBoundingBox get_oriented_bounding_box(bool robust = false) const {
        o3d_obb_t c{};
        check(o3d_trianglemesh_get_oriented_bounding_box(&c, get(), robust ? 1 : 0));
        return OrientedBoundingBox::from_c(c);
    }
    /// @brief Convex hull of the vertices: {hull (outward triangles), per hull vertex the index of its vertex}.
    std::pair<TriangleMesh, std::vector<int32_t>> compute_convex_hull(bool joggle_inputs = false) const {
        return with_indices(num_vertices(), [&](o3d_trianglemesh_t** o, int32_t* idx, size_t cap, size_t* n) {
            return o3d_trianglemesh_compute_convex_hull(o, idx, cap, n, get(), joggle_inputs ? 1 : 0);
        });
    }
    /// @brief Run `fn(mesh**, indices, capacity, &n)` with room for `capacity` indices; own the mesh it
    /// wrote (even when it failed, so nothing leaks), then check its status.
    template <typename F>
    static std::pair<TriangleMesh, std::vector<int32_t>> with_indices(std::size_t capacity, F&& fn) {
        std::vector<int32_t> indices(capacity);
        o3d_trianglemesh_t* mesh = nullptr;
        size_t n = 0;
        const o3d_status status = fn(&mesh, indices.data(), indices.size(), &n);
        UniqueHandle<o3d_trianglemesh_t, &o3d_trianglemesh_destroy> owned(mesh);
        check(status);
        indices.resize(n < capacity ? n : capacity);
        return {TriangleMesh(owned.release()), std::move(indices)};
    }

    // --- primitives (Open3D's defaults) ---
    static TriangleMesh create_box(double width = 1.0, double height = 1.0, double depth = 1.0) {
        return create(&o3d_trianglemesh_create_box, width, height, depth);
    }
    static TriangleMesh create_sphere(double radius = 1.0, int resolution = 20) {
        return create(&o3d_trianglemesh_create_sphere, radius, resolution);
    }
    static TriangleMesh create_cylinder(double radius = 1.0, double height = 2.0, int resolution = 20, int split = 4) {
        return create(&o3d_trianglemesh_create_cylinder, radius, height, resolution, split);
    }
    static TriangleMesh create_cone(double radius = 1.0, double height = 2.0, int resolution = 20, int split = 1) {
        return create(&o3d_trianglemesh_create_cone, radius, height, resolution, split);
    }
    static TriangleMesh create_torus(double torus_radius = 1.0, double tube_radius = 0.5, int radial_resolution = 30,
                                     int tubular_resolution = 20) {
        return create(&o3d_trianglemesh_create_torus, torus_radius, tube_radius, radial_resolution, tubular_resolution);
    }
    static TriangleMesh create_arrow(double cylinder_radius = 1.0, double cone_radius = 1.5,
                                     double cylinder_height = 5.0, double cone_height = 4.0, int resolution = 20,
                                     int cylinder_split = 4, int cone_split = 1) {
        return create(&o3d_trianglemesh_create_arrow, cylinder_radius, cone_radius, cylinder_height, cone_height,
                      resolution, cylinder_split, cone_split);
    }
    static TriangleMesh create_coordinate_frame(double size = 1.0, const Vec3& origin = {0, 0, 0}) {
        return create(&o3d_trianglemesh_create_coordinate_frame, size, origin.data());
    }
    static TriangleMesh create_tetrahedron(double radius = 1.0) {
        return create(&o3d_trianglemesh_create_tetrahedron, radius);
    }
    static TriangleMesh create_octahedron(double radius = 1.0) {
        return create(&o3d_trianglemesh_create_octahedron, radius);
    }
    /// @brief A twisted band about the z axis (a Moebius strip with an odd `twists`).
    static TriangleMesh create_mobius(const MobiusOptions& options = {}) {
        const o3d_mobius_options_t c = options.to_c();
        return create(&o3d_trianglemesh_create_mobius, &c);
    }
    static TriangleMesh create_icosahedron(double radius = 1.0) {
        return create(&o3d_trianglemesh_create_icosahedron, radius);
    }

private:
    bool flag(o3d_status (*fn)(int32_t*, const o3d_trianglemesh_t*)) const { return query(fn) != 0; }
};

// --- convex hulls (Qhull) and hidden-point removal (Katz, Tal, Basri 2007): free functions, since a cloud
// cannot return a mesh from a member. Each returns {mesh with outward triangles, per mesh vertex the index of
// the input point it came from}. ---

/// @brief Convex hull of the points (>= 4, not all coplanar unless `joggle_inputs`, Qhull's "QJ").
inline std::pair<TriangleMesh, std::vector<int32_t>> compute_convex_hull(const PointCloud& cloud,
                                                                         bool joggle_inputs = false) {
    return TriangleMesh::with_indices(cloud.size(), [&](o3d_trianglemesh_t** o, int32_t* idx, size_t cap, size_t* n) {
        return o3d_pointcloud_compute_convex_hull(o, idx, cap, n, cloud.get(), joggle_inputs ? 1 : 0);
    });
}
/// @brief Convex hull of a mesh's vertices (TriangleMesh::compute_convex_hull).
inline std::pair<TriangleMesh, std::vector<int32_t>> compute_convex_hull(const TriangleMesh& mesh,
                                                                         bool joggle_inputs = false) {
    return mesh.compute_convex_hull(joggle_inputs);
}
/// @brief The points visible from `camera_location`: spherical flipping with `radius` (> 0; larger keeps
/// more points), then the hull of the flipped points and the camera.
inline std::pair<TriangleMesh, std::vector<int32_t>> hidden_point_removal(const PointCloud& cloud,
                                                                          const Vec3& camera_location, double radius) {
    return TriangleMesh::with_indices(cloud.size(), [&](o3d_trianglemesh_t** o, int32_t* idx, size_t cap, size_t* n) {
        return o3d_pointcloud_hidden_point_removal(o, idx, cap, n, cloud.get(), camera_location.data(), radius);
    });
}

}  // namespace o3dpp
