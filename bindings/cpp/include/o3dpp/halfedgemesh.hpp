// SPDX-License-Identifier: MIT
#pragma once
/// @file halfedgemesh.hpp
/// @brief o3dpp::HalfEdgeTriangleMesh (move-only owner of an o3d_halfedgemesh_t): a cleaned, manifold copy of a
/// triangle mesh with its half-edges, for walking one-rings and boundary loops. It never changes once made; its
/// arrays are copied out.
#include <array>
#include <cstdint>
#include <vector>

#include "o3d/halfedgemesh.h"
#include "o3dpp/error.hpp"
#include "o3dpp/generated/enums.hpp"
#include "o3dpp/handle.hpp"
#include "o3dpp/indexlists.hpp"
#include "o3dpp/span.hpp"
#include "o3dpp/trianglemesh.hpp"

namespace o3dpp {

/// @brief o3d.geometry.HalfEdge: half-edge 3t + k is side k of triangle t, from vertex_indices[0] to
/// vertex_indices[1].
struct HalfEdge {
    int next = -1;                          ///< the next half-edge of the same triangle
    int twin = -1;                          ///< the opposite half-edge, -1 on a boundary
    std::array<int, 2> vertex_indices{-1, -1};  ///< from, to
    int triangle_index = -1;                ///< the triangle it belongs to
    /// @brief Whether it lies on a boundary (has no twin).
    bool is_boundary() const { return twin == -1; }
};

/// @brief o3d.geometry.HalfEdgeTriangleMesh. Move-only; made by create_from_triangle_mesh.
class HalfEdgeTriangleMesh : public Owner<HalfEdgeTriangleMesh, o3d_halfedgemesh_t, &o3d_halfedgemesh_destroy> {
    using A = HalfEdgeTriangleMeshArray;

public:
    /// @brief Take ownership of `owned` (must not be NULL).
    explicit HalfEdgeTriangleMesh(o3d_halfedgemesh_t* owned) : Owner(owned) {}

    /// @brief Open3D's create_from_triangle_mesh: the mesh cleaned first (equal vertices merged, duplicated and
    /// degenerate triangles and unreferenced vertices dropped), normals computed afresh, colors kept. Throws on a
    /// non-manifold mesh.
    static HalfEdgeTriangleMesh create_from_triangle_mesh(const TriangleMesh& mesh) {
        return create(&o3d_halfedgemesh_create_from_triangle_mesh, mesh.get());
    }

    std::vector<Vec3> vertices() const { return array(A::Vertices); }
    std::vector<Vec3> vertex_normals() const { return array(A::VertexNormals); }
    /// @brief Empty when the mesh had no colors.
    std::vector<Vec3> vertex_colors() const { return array(A::VertexColors); }
    std::vector<Vec3> triangle_normals() const { return array(A::TriangleNormals); }
    std::vector<std::array<int32_t, 3>> triangles() const {
        return copy_out<std::array<int32_t, 3>>(&o3d_halfedgemesh_get_triangles);
    }
    bool has_vertices() const { return !vertices().empty(); }
    bool has_half_edges() const { return !half_edges().empty(); }
    bool has_vertex_colors() const { return !vertex_colors().empty(); }
    /// @brief The half-edges, half-edge 3t + k being side k of triangle t.
    std::vector<HalfEdge> half_edges() const {
        const auto rows = copy_out<std::array<int32_t, 5>>(&o3d_halfedgemesh_get_half_edges);
        std::vector<HalfEdge> out;
        out.reserve(rows.size());
        for (const auto& r : rows) out.push_back(HalfEdge{r[0], r[1], {r[2], r[3]}, r[4]});
        return out;
    }
    /// @brief Per vertex, its outgoing half-edges in fan order (from its boundary half-edge when it has one).
    IndexLists ordered_half_edge_from_vertex() const {
        return detail::index_lists(
            [&](o3d_index_lists_t** out) { return o3d_halfedgemesh_get_ordered_half_edge_from_vertex(out, get()); });
    }
    /// @brief The boundary loop through `vertex_index` as half-edge indices (empty when it is not on a boundary).
    std::vector<int32_t> boundary_half_edges_from_vertex(int vertex_index) const {
        return copy_out<int32_t>(&o3d_halfedgemesh_boundary_half_edges_from_vertex, vertex_index);
    }
    /// @brief The same loop as vertex indices, starting with `vertex_index`.
    std::vector<int32_t> boundary_vertices_from_vertex(int vertex_index) const {
        return copy_out<int32_t>(&o3d_halfedgemesh_boundary_vertices_from_vertex, vertex_index);
    }
    /// @brief Every boundary loop once, as vertex indices.
    IndexLists get_boundaries() const {
        return detail::index_lists([&](o3d_index_lists_t** out) { return o3d_halfedgemesh_get_boundaries(out, get()); });
    }

private:
    std::vector<Vec3> array(A which) const {
        return copy_out<Vec3>(&o3d_halfedgemesh_get_array, static_cast<int32_t>(which));
    }
};

}  // namespace o3dpp
