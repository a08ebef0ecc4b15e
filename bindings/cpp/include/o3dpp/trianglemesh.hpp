// SPDX-License-Identifier: MIT
#pragma once
/// @file trianglemesh.hpp
/// @brief o3dpp::TriangleMesh (move-only owner of an o3d_trianglemesh_t): arrays, textures, normals,
/// clean-up, topology queries, processing, primitives, surface reconstruction from point clouds (Poisson, ball
/// pivoting, alpha shapes), convex hulls and hidden-point removal.
#include <array>
#include <cstdint>
#include <utility>
#include <vector>

#include "o3d/trianglemesh.h"
#include "o3dpp/arrays.hpp"
#include "o3dpp/boundingbox.hpp"
#include "o3dpp/common.hpp"
#include "o3dpp/error.hpp"
#include "o3dpp/feature.hpp"
#include "o3dpp/generated/options.hpp"
#include "o3dpp/generated/trianglemesh.hpp"
#include "o3dpp/handle.hpp"
#include "o3dpp/image.hpp"
#include "o3dpp/indexlists.hpp"
#include "o3dpp/pointcloud.hpp"
#include "o3dpp/span.hpp"

namespace o3dpp {

using Triangle = std::array<int32_t, 3>;  ///< three vertex indices
using Vec2 = std::array<double, 2>;       ///< a UV

class TetraMesh;  // tetramesh.hpp (included at the end of this file)

namespace detail {
using MeshArrayFns =
    ArrayFns<&o3d_trianglemesh_has_array, &o3d_trianglemesh_array_shape, &o3d_trianglemesh_get_array,
             &o3d_trianglemesh_array_view, &o3d_trianglemesh_array_mutable_view, &o3d_trianglemesh_set_array,
             &o3d_trianglemesh_set_array_f32, &o3d_trianglemesh_get_index_array, &o3d_trianglemesh_index_array_view,
             &o3d_trianglemesh_index_array_mutable_view, &o3d_trianglemesh_set_index_array>;
/// @brief A mask as the C API takes it: one byte per entry (std::vector<bool> packs bits).
inline std::vector<uint8_t> mask_bytes(const std::vector<bool>& mask) { return {mask.begin(), mask.end()}; }
}  // namespace detail

/// @brief Edge-connected triangle clusters.
struct TriangleClusters {
    std::vector<int32_t> triangle_clusters;    ///< per triangle
    std::vector<int32_t> cluster_n_triangles;  ///< per cluster
    std::vector<double> cluster_area;          ///< per cluster
};

/// @brief A triangle mesh. Move-only. The methods that pass their arguments to one C function are generated
/// (detail::TriangleMeshCalls).
class TriangleMesh : public Owner<TriangleMesh, o3d_trianglemesh_t, &o3d_trianglemesh_destroy>,
                     public Arrays<TriangleMesh, MeshArray, detail::MeshArrayFns>,
                     public detail::TriangleMeshCalls<TriangleMesh> {
    friend class detail::TriangleMeshCalls<TriangleMesh>;  // checks its calls with done
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
    using TriangleMeshCalls::crop;  // and crop(obb) below

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

    // --- removal by index or mask: what stays keeps its order and attributes; a bad index or a mask of the wrong
    // size throws and leaves the mesh unchanged ---

    /// @brief Remove the vertices at `indices` and every triangle that uses one of them.
    TriangleMesh& remove_vertices_by_index(const std::vector<int32_t>& indices) {
        return done(o3d_trianglemesh_remove_vertices_by_index(get(), indices.data(), indices.size()));
    }
    /// @brief Remove the vertices whose mask entry is true (one per vertex) and every triangle that uses one; e.g.
    /// the low-density vertices of a Poisson surface.
    TriangleMesh& remove_vertices_by_mask(const std::vector<bool>& mask) {
        const std::vector<uint8_t> bytes = detail::mask_bytes(mask);
        return done(o3d_trianglemesh_remove_vertices_by_mask(get(), bytes.data(), bytes.size()));
    }
    /// @brief Remove the triangles at `indices`; every vertex stays.
    TriangleMesh& remove_triangles_by_index(const std::vector<int32_t>& indices) {
        return done(o3d_trianglemesh_remove_triangles_by_index(get(), indices.data(), indices.size()));
    }
    /// @brief Remove the triangles whose mask entry is true (one per triangle); every vertex stays.
    TriangleMesh& remove_triangles_by_mask(const std::vector<bool>& mask) {
        const std::vector<uint8_t> bytes = detail::mask_bytes(mask);
        return done(o3d_trianglemesh_remove_triangles_by_mask(get(), bytes.data(), bytes.size()));
    }

    /// @brief Concatenate `other` (Open3D `mesh += other`).
    TriangleMesh& operator+=(const TriangleMesh& other) { return append(other); }
    /// @brief {min corner, max corner}.
    std::array<Vec3, 2> get_axis_aligned_bounding_box() const {
        std::array<Vec3, 2> box{};
        check(o3d_trianglemesh_get_axis_aligned_bounding_box(box[0].data(), box[1].data(), get()));
        return box;
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
    /// @brief The minimum-volume oriented box of the vertices (OrientedBoundingBox::create_from_points_minimal).
    OrientedBoundingBox get_minimal_oriented_bounding_box(bool robust = false) const {
        o3d_obb_t c{};
        check(o3d_trianglemesh_get_minimal_oriented_bounding_box(&c, get(), robust ? 1 : 0));
        return OrientedBoundingBox::from_c(c);
    }
    /// @brief The minimum-volume enclosing ellipsoid of the vertices (OrientedBoundingEllipsoid::create_from_points).
    OrientedBoundingEllipsoid get_oriented_bounding_ellipsoid(bool robust = false) const {
        o3d_obe_t c{};
        check(o3d_trianglemesh_get_oriented_bounding_ellipsoid(&c, get(), robust ? 1 : 0));
        return OrientedBoundingEllipsoid::from_c(c);
    }
    /// @brief The box as a closed mesh of 8 vertices (get_box_points order) and 12 outward triangles, its extents
    /// multiplied by `scale` about the centre.
    static TriangleMesh create_from_oriented_bounding_box(const OrientedBoundingBox& obox,
                                                          const Vec3& scale = {1.0, 1.0, 1.0},
                                                          bool create_uv_map = false) {
        const o3d_obb_t c = obox.to_c();
        return create(&o3d_trianglemesh_create_from_oriented_bounding_box, &c, scale.data(), create_uv_map ? 1 : 0);
    }
    /// @brief The ellipsoid as a mesh (create_ellipsoid of its radii times `scale`, rotated and moved; white).
    static TriangleMesh create_from_oriented_bounding_ellipsoid(const OrientedBoundingEllipsoid& obel,
                                                                const Vec3& scale = {1.0, 1.0, 1.0},
                                                                int resolution = 20, bool create_uv_map = false) {
        const o3d_obe_t c = obel.to_c();
        return create(&o3d_trianglemesh_create_from_oriented_bounding_ellipsoid, &c, scale.data(), resolution,
                      create_uv_map ? 1 : 0);
    }

    // --- topology ---

    /// @brief Per vertex, the vertices joined to it by a triangle side (ascending; empty for an unused vertex).
    IndexLists compute_adjacency_list() const {
        return detail::index_lists([&](o3d_index_lists_t** out) { return o3d_trianglemesh_compute_adjacency_list(out, get()); });
    }
    /// @brief Edges (min, max vertex index; ascending) of more than two triangles, and of one unless
    /// `allow_boundary_edges`.
    std::vector<std::array<int32_t, 2>> get_non_manifold_edges(bool allow_boundary_edges = true) const {
        return copy_out<std::array<int32_t, 2>>(&o3d_trianglemesh_get_non_manifold_edges, allow_boundary_edges ? 1 : 0);
    }
    /// @brief Vertices whose triangles do not form one fan (ascending).
    std::vector<int32_t> get_non_manifold_vertices() const {
        return copy_out<int32_t>(&o3d_trianglemesh_get_non_manifold_vertices);
    }
    /// @brief Pairs (i < j, ascending) of triangles that share no vertex and intersect.
    std::vector<std::array<int32_t, 2>> get_self_intersecting_triangles() const {
        return copy_out<std::array<int32_t, 2>>(&o3d_trianglemesh_get_self_intersecting_triangles);
    }

    /// @brief As-rigid-as-possible deformation (Sorkine & Alexa 2007): the constrained vertices moved to their
    /// positions (one per index), the others so that every one-ring turns as rigidly as it can; `max_iter`
    /// alternations. The new mesh holds vertices and triangles only.
    TriangleMesh deform_as_rigid_as_possible(const std::vector<int32_t>& constraint_vertex_indices,
                                             const std::vector<Vec3>& constraint_vertex_positions, int max_iter,
                                             DeformAsRigidAsPossibleEnergy energy = DeformAsRigidAsPossibleEnergy::Spokes,
                                             double smoothed_alpha = 0.01) const {
        return derive(&o3d_trianglemesh_deform_as_rigid_as_possible, constraint_vertex_indices.data(),
                      constraint_vertex_indices.size(),
                      constraint_vertex_positions.empty() ? nullptr : constraint_vertex_positions.front().data(),
                      constraint_vertex_positions.size(), max_iter, static_cast<int32_t>(energy), smoothed_alpha);
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

    /// @brief A twisted band about the z axis (a Moebius strip with an odd `twists`).
    static TriangleMesh create_mobius(const MobiusOptions& options = {}) {
        const o3d_mobius_options_t c = options.to_c();
        return create(&o3d_trianglemesh_create_mobius, &c);
    }

    // --- surface reconstruction from point clouds; options.progress gets the fraction done (false cancels:
    // Error O3D_ERROR_CANCELLED) ---

    /// @brief Screened Poisson reconstruction (Kazhdan & Hoppe 2013) of a cloud with normals: {a watertight mesh,
    /// per vertex the sampling density there (trim low-density vertices with a quantile of it)}.
    static std::pair<TriangleMesh, std::vector<double>> create_from_point_cloud_poisson(
        const PointCloud& cloud, const PoissonOptions& options = {}) {
        // Both outputs are owned as soon as the call wrote them, so a throwing callback leaks nothing.
        UniqueHandle<o3d_trianglemesh_t, &o3d_trianglemesh_destroy> mesh;
        UniqueHandle<o3d_feature_t, &o3d_feature_destroy> densities;
        check(detail::with_progress(options.to_c(), options.progress, [&](const o3d_poisson_options_t* c) {
            o3d_trianglemesh_t* m = nullptr;
            o3d_feature_t* d = nullptr;
            const o3d_status status = o3d_trianglemesh_create_from_point_cloud_poisson(&m, &d, cloud.get(), c);
            mesh.reset(m);
            densities.reset(d);
            return status;
        }));
        std::vector<double> values = Feature(densities.release()).get_data();
        return {TriangleMesh(mesh.release()), std::move(values)};
    }
    /// @brief Ball pivoting (Bernardini et al. 1999) over a cloud with normals, one ball radius after the other
    /// (each > 0): the mesh's vertices are the cloud's points, its triangles wound to agree with the normals.
    static TriangleMesh create_from_point_cloud_ball_pivoting(const PointCloud& cloud, const std::vector<double>& radii,
                                                              const ProgressOptions& options = {}) {
        return adopt([&](o3d_trianglemesh_t** out) {
            return detail::with_progress(options.to_c(), options.progress, [&](const o3d_progress_options_t* c) {
                return o3d_trianglemesh_create_from_point_cloud_ball_pivoting(out, cloud.get(), radii.data(),
                                                                              radii.size(), c);
            });
        });
    }
    /// @brief Alpha shape (Edelsbrunner & Muecke 1994): the boundary of the Delaunay tetrahedra of circumradius
    /// below `alpha` (> 0), wound outwards; a huge alpha gives the convex hull.
    static TriangleMesh create_from_point_cloud_alpha_shape(const PointCloud& cloud, double alpha,
                                                            const ProgressOptions& options = {}) {
        return alpha_shape(cloud, alpha, nullptr, {}, options);
    }
    /// @brief The same, reusing `tetra_mesh` and `point_map` from TetraMesh::create_from_point_cloud(cloud)
    /// (for several alphas over one cloud). Defined in tetramesh.hpp.
    static TriangleMesh create_from_point_cloud_alpha_shape(const PointCloud& cloud, double alpha,
                                                            const TetraMesh& tetra_mesh,
                                                            const std::vector<int32_t>& point_map,
                                                            const ProgressOptions& options = {});

private:
    static TriangleMesh alpha_shape(const PointCloud& cloud, double alpha, const o3d_tetramesh_t* tetra_mesh,
                                    const std::vector<int32_t>& point_map, const ProgressOptions& options) {
        return adopt([&](o3d_trianglemesh_t** out) {
            return detail::with_progress(options.to_c(), options.progress, [&](const o3d_progress_options_t* c) {
                return o3d_trianglemesh_create_from_point_cloud_alpha_shape(out, cloud.get(), alpha, tetra_mesh,
                                                                            point_map.data(), point_map.size(), c);
            });
        });
    }
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

// TetraMesh needs TriangleMesh complete and completes TriangleMesh's alpha shape over a tetra mesh: whichever of
// the two headers comes first, both classes are then defined.
#include "o3dpp/tetramesh.hpp"
