// SPDX-License-Identifier: MIT
#pragma once
/// @file tetramesh.hpp
/// @brief o3dpp::TetraMesh (move-only owner of an o3d_tetramesh_t): vertices and tetrahedra, the Delaunay
/// tetrahedralization of a point cloud and iso-surfaces of per-vertex values; and TriangleMesh's alpha shape over
/// a tetra mesh, which needs this class.
#include <array>
#include <cstdint>
#include <utility>
#include <vector>

#include "o3d/tetramesh.h"
#include "o3dpp/arrays.hpp"
#include "o3dpp/common.hpp"
#include "o3dpp/error.hpp"
#include "o3dpp/generated/enums.hpp"
#include "o3dpp/generated/options.hpp"
#include "o3dpp/generated/tetramesh.hpp"
#include "o3dpp/handle.hpp"
#include "o3dpp/pointcloud.hpp"
#include "o3dpp/span.hpp"
#include "o3dpp/trianglemesh.hpp"

namespace o3dpp {

using Tetra = std::array<int32_t, 4>;  ///< four vertex indices

namespace detail {
using TetraMeshArrayFns =
    ArrayFns<&o3d_tetramesh_has_array, &o3d_tetramesh_array_shape, &o3d_tetramesh_get_array,
             &o3d_tetramesh_array_view, &o3d_tetramesh_array_mutable_view, &o3d_tetramesh_set_array,
             &o3d_tetramesh_set_array_f32, &o3d_tetramesh_get_index_array, &o3d_tetramesh_index_array_view,
             &o3d_tetramesh_index_array_mutable_view, &o3d_tetramesh_set_index_array>;
}  // namespace detail

/// @brief o3d.geometry.TetraMesh. Tetra indices may hold any value; operations that follow them check them.
/// num_vertices() and num_tetras() are generated (detail::TetraMeshCalls).
class TetraMesh : public Owner<TetraMesh, o3d_tetramesh_t, &o3d_tetramesh_destroy>,
                  public Arrays<TetraMesh, TetraMeshArray, detail::TetraMeshArrayFns>,
                  public detail::TetraMeshCalls<TetraMesh> {
    friend class detail::TetraMeshCalls<TetraMesh>;  // checks its calls with done
    using A = TetraMeshArray;

public:
    /// @brief New empty tetra mesh.
    TetraMesh() : Owner(make(&o3d_tetramesh_create)) {}
    /// @brief Take ownership of `owned` (must not be NULL).
    explicit TetraMesh(o3d_tetramesh_t* owned) : Owner(owned) {}
    TetraMesh(const std::vector<Vec3>& vertices, const std::vector<Tetra>& tetras) : TetraMesh() {
        set_vertices(vertices);
        set_tetras(tetras);
    }

    /// @brief Deep copy.
    TetraMesh clone() const { return derive(&o3d_tetramesh_clone); }

    // --- named arrays (see Arrays for the generic accessor); views are borrowed until the next mutation ---
    bool has_vertices() const { return has_array(A::Vertices); }
    bool has_tetras() const { return has_array(A::Tetras); }
    void set_vertices(const std::vector<Vec3>& v) { set_array(A::Vertices, v); }
    void set_tetras(const std::vector<Tetra>& t) { set_array(A::Tetras, t); }
    std::vector<Vec3> get_vertices() const { return get_array(A::Vertices); }
    std::vector<Tetra> get_tetras() const { return get_array<Tetra>(A::Tetras); }
    Rows3<const double> vertices() const { return array(A::Vertices); }
    /// @brief Borrowed tetras: row i is the four vertex indices of tetra i.
    Rows<const int32_t> tetras() const { return array<int32_t>(A::Tetras); }
    Rows3<double> vertices_mutable() { return array_mutable(A::Vertices); }
    Rows<int32_t> tetras_mutable() { return array_mutable<int32_t>(A::Tetras); }

    /// @brief The 3-D Delaunay tetrahedralization of the cloud's points (>= 4, not flat): {tetra mesh, per vertex
    /// the index of its input point}. The pair feeds TriangleMesh::create_from_point_cloud_alpha_shape.
    static std::pair<TetraMesh, std::vector<int32_t>> create_from_point_cloud(const PointCloud& cloud) {
        // Each vertex is a distinct input point: room for one index per point is always enough.
        std::vector<int32_t> point_map(cloud.size());
        o3d_tetramesh_t* raw = nullptr;
        size_t n = 0;
        const o3d_status status =
            o3d_tetramesh_create_from_point_cloud(&raw, point_map.data(), point_map.size(), &n, cloud.get());
        UniqueHandle<o3d_tetramesh_t, &o3d_tetramesh_destroy> owned(raw);
        check(status);
        point_map.resize(n < point_map.size() ? n : point_map.size());
        return {TetraMesh(owned.release()), std::move(point_map)};
    }

    /// @brief The iso-surface `values == level` of one value per vertex, linear on each tetrahedron (marching
    /// tetrahedra).
    TriangleMesh extract_triangle_mesh(const std::vector<double>& values, double level) const {
        return derive<TriangleMesh>(&o3d_tetramesh_extract_triangle_mesh, values.data(), values.size(), level);
    }
};

inline TriangleMesh TriangleMesh::create_from_point_cloud_alpha_shape(const PointCloud& cloud, double alpha,
                                                                      const TetraMesh& tetra_mesh,
                                                                      const std::vector<int32_t>& point_map,
                                                                      const ProgressOptions& options) {
    return alpha_shape(cloud, alpha, tetra_mesh.get(), point_map, options);
}

}  // namespace o3dpp
