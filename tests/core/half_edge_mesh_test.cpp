// SPDX-License-Identifier: MIT
// Half-edge triangle mesh (Open3D's HalfEdgeTriangleMesh). The boundary loops and fan orders marked
// "open3d 0.20" were recorded with HalfEdgeTriangleMesh.create_from_triangle_mesh on the same inputs:
//   H = o3d.geometry.HalfEdgeTriangleMesh.create_from_triangle_mesh
//   strip: V = [[x, y, 0] for y in range(2) for x in range(4)], quads (x, x+1, x+5), (x, x+5, x+4);
//     [list(b) for b in H(strip).get_boundaries()], list(H(strip).boundary_half_edges_from_vertex(5)),
//     [list(o) for o in H(strip).ordered_half_edge_from_vertex]
//   sphere: create_sphere(1.0, 5) without triangle 7 (and 30): get_boundaries(), ordered_half_edge_from_vertex[:4]
#include <gtest/gtest.h>

#include <algorithm>
#include <vector>

#include "o3d/geometry/half_edge_mesh.h"
#include "o3d/geometry/mesh_primitives.h"
#include "o3d/utility/error.h"

using namespace o3d::geometry;
using V = Eigen::Vector3d;
using Loops = std::vector<std::vector<int>>;

namespace {

TriangleMesh strip() {
    TriangleMesh m;
    for (int y = 0; y < 2; ++y)
        for (int x = 0; x < 4; ++x) m.vertices.emplace_back(x, y, 0);
    for (int x = 0; x < 3; ++x) {
        m.triangles.emplace_back(x, x + 1, x + 5);
        m.triangles.emplace_back(x, x + 5, x + 4);
    }
    return m;
}

TriangleMesh without_triangles(TriangleMesh m, std::vector<int> drop) {
    std::vector<Eigen::Vector3i> kept;
    for (size_t t = 0; t < m.triangles.size(); ++t)
        if (std::find(drop.begin(), drop.end(), static_cast<int>(t)) == drop.end()) kept.push_back(m.triangles[t]);
    m.triangles = kept;
    return m;
}

/// @brief The structural invariants of a half-edge mesh built from a manifold mesh.
void expect_consistent(const HalfEdgeTriangleMesh& h) {
    ASSERT_EQ(h.half_edges.size(), 3 * h.triangles.size());
    for (size_t i = 0; i < h.half_edges.size(); ++i) {
        const HalfEdge& e = h.half_edges[i];
        const Eigen::Vector3i& tri = h.triangles[i / 3];
        const int k = static_cast<int>(i % 3);
        EXPECT_EQ(e.triangle_index, static_cast<int>(i / 3));
        EXPECT_EQ(e.vertex_indices, Eigen::Vector2i(tri(k), tri((k + 1) % 3)));
        EXPECT_EQ(h.half_edges[h.half_edges[h.half_edges[i].next].next].next, static_cast<int>(i));
        EXPECT_EQ(h.half_edges[e.next].vertex_indices(0), e.vertex_indices(1));
        if (!e.is_boundary()) {
            EXPECT_EQ(h.half_edges[e.twin].twin, static_cast<int>(i));
            EXPECT_EQ(h.half_edges[e.twin].vertex_indices, Eigen::Vector2i(e.vertex_indices(1), e.vertex_indices(0)));
        }
    }
    ASSERT_EQ(h.ordered_half_edge_from_vertex.size(), h.vertices.size());
    for (size_t v = 0; v < h.vertices.size(); ++v)
        for (const int i : h.ordered_half_edge_from_vertex[v]) EXPECT_EQ(h.half_edges[i].vertex_indices(0), int(v));
}

}  // namespace

TEST(HalfEdgeMesh, ClosedSphereHasNoBoundary) {
    const TriangleMesh sphere = create_sphere(1.0, 6);
    const HalfEdgeTriangleMesh h = half_edge_mesh_from_triangle_mesh(sphere);
    EXPECT_TRUE(h.has_half_edges());
    EXPECT_EQ(h.vertices.size(), sphere.vertices.size());
    EXPECT_EQ(h.triangles, sphere.triangles);
    expect_consistent(h);
    size_t fans = 0;
    for (const HalfEdge& e : h.half_edges) EXPECT_FALSE(e.is_boundary());
    // A closed manifold: every outgoing half-edge appears in its vertex's fan, which starts at the lowest.
    for (const std::vector<int>& fan : h.ordered_half_edge_from_vertex) {
        fans += fan.size();
        EXPECT_EQ(fan.front(), *std::min_element(fan.begin(), fan.end()));
    }
    EXPECT_EQ(fans, h.half_edges.size());
    EXPECT_TRUE(boundaries(h).empty());
    EXPECT_TRUE(boundary_half_edges_from_vertex(h, 0).empty());
    // Normals are computed (unit, outward on the sphere), as Open3D does.
    ASSERT_TRUE(h.has_vertex_normals());
    ASSERT_EQ(h.triangle_normals.size(), h.triangles.size());
    for (size_t v = 0; v < h.vertices.size(); ++v) EXPECT_GT(h.vertex_normals[v].dot(h.vertices[v]), 0.9);
    EXPECT_EQ(triangle_mesh_from_half_edge_mesh(h).triangles, sphere.triangles);
}

TEST(HalfEdgeMesh, StripBoundaryAsOpen3D) {
    const HalfEdgeTriangleMesh h = half_edge_mesh_from_triangle_mesh(strip());
    expect_consistent(h);
    // open3d 0.20
    EXPECT_EQ(boundaries(h), (Loops{{0, 1, 2, 3, 7, 6, 5, 4}}));
    EXPECT_EQ(boundary_half_edges_from_vertex(h, 5), (std::vector<int>{4, 5, 0, 6, 12, 13, 16, 10}));
    EXPECT_EQ(boundary_vertices_from_vertex(h, 5), (std::vector<int>{5, 4, 0, 1, 2, 3, 7, 6}));
    EXPECT_EQ(h.ordered_half_edge_from_vertex,
              (Loops{{0, 3}, {6, 9, 1}, {12, 15, 7}, {13}, {5}, {4, 2, 11}, {10, 8, 17}, {16, 14}}));
    EXPECT_FALSE(h.has_vertex_colors());
}

TEST(HalfEdgeMesh, SphereWithHolesAsOpen3D) {
    const TriangleMesh sphere = create_sphere(1.0, 5);
    ASSERT_EQ(sphere.triangles[7], Eigen::Vector3i(1, 36, 35));
    const HalfEdgeTriangleMesh one = half_edge_mesh_from_triangle_mesh(without_triangles(sphere, {7}));
    expect_consistent(one);
    // open3d 0.20: the loop runs along the half-edges, opposite to the removed triangle's winding.
    EXPECT_EQ(boundaries(one), (Loops{{1, 35, 36}}));
    EXPECT_EQ(one.ordered_half_edge_from_vertex[0], (std::vector<int>{0, 6, 12, 18, 21, 27, 33, 39, 45, 51}));
    EXPECT_EQ(one.ordered_half_edge_from_vertex[1], (std::vector<int>{15, 9, 3, 54, 48, 42, 36, 30, 24}));
    EXPECT_EQ(one.ordered_half_edge_from_vertex[2], (std::vector<int>{1, 53, 112, 116, 59}));
    EXPECT_EQ(one.ordered_half_edge_from_vertex[3], (std::vector<int>{2, 58, 62, 65, 7}));
    EXPECT_TRUE(boundary_vertices_from_vertex(one, 0).empty());
    EXPECT_EQ(boundary_vertices_from_vertex(one, 36), (std::vector<int>{36, 1, 35}));

    const HalfEdgeTriangleMesh two = half_edge_mesh_from_triangle_mesh(without_triangles(sphere, {7, 30}));
    expect_consistent(two);
    EXPECT_EQ(boundaries(two), (Loops{{1, 35, 36}, {7, 8, 17}}));  // open3d 0.20
    EXPECT_EQ(two.ordered_half_edge_from_vertex[2], (std::vector<int>{1, 53, 109, 113, 59}));
}

TEST(HalfEdgeMesh, CleansAsOpen3D) {
    // open3d 0.20: a duplicated vertex is merged, a rotated copy of a triangle dropped, an unreferenced
    // vertex dropped; the reversed triangle is kept (a closed two-sided triangle).
    TriangleMesh m;
    m.vertices = {V(0, 0, 0), V(1, 0, 0), V(0, 1, 0), V(1, 1, 0), V(1, 0, 0), V(5, 5, 5)};
    m.vertex_colors = {V(1, 0, 0), V(0, 1, 0), V(0, 0, 1), V(1, 1, 0), V(0, 1, 0), V(1, 1, 1)};
    m.triangles = {{0, 1, 2}, {4, 3, 2}, {1, 2, 0}};
    const HalfEdgeTriangleMesh h = half_edge_mesh_from_triangle_mesh(m);
    EXPECT_EQ(h.vertices.size(), 4u);
    EXPECT_EQ(h.triangles, (std::vector<Eigen::Vector3i>{{0, 1, 2}, {1, 3, 2}}));
    ASSERT_TRUE(h.has_vertex_colors());
    EXPECT_EQ(h.vertex_colors[3], V(1, 1, 0));
    EXPECT_EQ(boundaries(h), (Loops{{0, 1, 3, 2}}));

    TriangleMesh two_sided;
    two_sided.vertices = {V(0, 0, 0), V(1, 0, 0), V(0, 1, 0)};
    two_sided.triangles = {{0, 1, 2}, {0, 2, 1}};
    const HalfEdgeTriangleMesh t = half_edge_mesh_from_triangle_mesh(two_sided);
    EXPECT_EQ(t.triangles.size(), 2u);
    EXPECT_EQ(t.ordered_half_edge_from_vertex, (Loops{{0, 3}, {1, 5}, {2, 4}}));  // open3d 0.20
    expect_consistent(t);

    // A vertex only a degenerate triangle uses is dropped (Open3D crashes there).
    TriangleMesh degenerate;
    degenerate.vertices = {V(0, 0, 0), V(1, 0, 0), V(0, 1, 0), V(3, 3, 3)};
    degenerate.triangles = {{0, 0, 3}, {0, 1, 2}};
    const HalfEdgeTriangleMesh d = half_edge_mesh_from_triangle_mesh(degenerate);
    EXPECT_EQ(d.vertices.size(), 3u);
    EXPECT_EQ(d.triangles.size(), 1u);
    EXPECT_EQ(boundaries(d), (Loops{{0, 1, 2}}));

    TriangleMesh empty;
    empty.vertices = {V(0, 0, 0)};
    const HalfEdgeTriangleMesh e = half_edge_mesh_from_triangle_mesh(empty);
    EXPECT_FALSE(e.has_half_edges());
    EXPECT_TRUE(e.vertices.empty());
}

TEST(HalfEdgeMesh, RefusesNonManifold) {
    TriangleMesh m;
    m.vertices = {V(0, 0, 0), V(1, 0, 0), V(0, 1, 0), V(1, 1, 0), V(0, 0, 1)};
    // Open3D 0.20 refuses each: "Duplicated half-edges" for the first two, "Invalid vertex" for the bow tie.
    for (const std::vector<Eigen::Vector3i>& tris : {std::vector<Eigen::Vector3i>{{0, 1, 2}, {1, 2, 3}},
                                                      std::vector<Eigen::Vector3i>{{0, 1, 2}, {1, 3, 2}, {1, 2, 4}},
                                                      std::vector<Eigen::Vector3i>{{0, 1, 2}, {0, 3, 4}}}) {
        m.triangles = tris;
        EXPECT_THROW(half_edge_mesh_from_triangle_mesh(m), o3d::InvalidArgument);
    }
    m.triangles = {{0, 1, 7}};
    EXPECT_THROW(half_edge_mesh_from_triangle_mesh(m), o3d::InvalidArgument);
}

TEST(HalfEdgeMesh, QueriesCheckTheirInput) {
    const HalfEdgeTriangleMesh h = half_edge_mesh_from_triangle_mesh(strip());
    EXPECT_THROW(boundary_half_edges_from_vertex(h, -1), o3d::InvalidArgument);
    EXPECT_THROW(boundary_vertices_from_vertex(h, 8), o3d::InvalidArgument);
    HalfEdgeTriangleMesh broken = h;
    broken.half_edges[0].vertex_indices(1) = 99;
    EXPECT_THROW(boundaries(broken), o3d::InvalidArgument);
    broken = h;
    broken.ordered_half_edge_from_vertex[0][0] = 1000;
    EXPECT_THROW(boundary_half_edges_from_vertex(broken, 0), o3d::InvalidArgument);
}
