// SPDX-License-Identifier: MIT
// HalfEdgeTriangleMesh and mesh topology through the wrapper: half-edges, fans and boundary loops of a triangle and a
// square (worked out by hand), a closed tetrahedron without boundaries, the adjacency list (IndexLists), non-manifold
// edges and vertices, self-intersecting and intersecting triangles, orient_triangles; bad input throws.
#include <algorithm>
#include <array>
#include <map>
#include <utility>
#include <vector>

#include "test_util.hpp"

using o3dpp::HalfEdge;
using o3dpp::HalfEdgeTriangleMesh;
using o3dpp::IndexLists;
using o3dpp::TriangleMesh;
using o3dpp::Vec3;
using Edge = std::array<int32_t, 2>;

namespace {
/// The unit square as two triangles (0, 1, 2) and (0, 2, 3).
TriangleMesh square() { return TriangleMesh({{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}}, {{0, 1, 2}, {0, 2, 3}}); }
}  // namespace

TEST(HalfEdgeTriangleMesh, OneTriangle) {
    const TriangleMesh mesh({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}, {{0, 1, 2}});
    const auto he = HalfEdgeTriangleMesh::create_from_triangle_mesh(mesh);
    ASSERT_EQ(he.vertices().size(), 3u);
    ASSERT_EQ(he.triangles().size(), 1u);
    EXPECT_FALSE(he.has_vertex_colors());
    for (const Vec3& n : he.vertex_normals()) EXPECT_NEAR(n[2], 1.0, 1e-12);
    ASSERT_EQ(he.triangle_normals().size(), 1u);
    EXPECT_NEAR(he.triangle_normals()[0][2], 1.0, 1e-12);

    const std::vector<HalfEdge> edges = he.half_edges();
    ASSERT_EQ(edges.size(), 3u);
    for (int k = 0; k < 3; ++k) {  // half-edge k: side k, from vertex k to k + 1, all on the boundary
        EXPECT_EQ(edges[k].next, (k + 1) % 3);
        EXPECT_EQ(edges[k].twin, -1);
        EXPECT_TRUE(edges[k].is_boundary());
        EXPECT_EQ(edges[k].vertex_indices, (std::array<int, 2>{k, (k + 1) % 3}));
        EXPECT_EQ(edges[k].triangle_index, 0);
    }
    EXPECT_EQ(he.ordered_half_edge_from_vertex(), (IndexLists{{0}, {1}, {2}}));
    EXPECT_EQ(he.boundary_half_edges_from_vertex(0), (std::vector<int32_t>{0, 1, 2}));
    EXPECT_EQ(he.boundary_vertices_from_vertex(1), (std::vector<int32_t>{1, 2, 0}));
    EXPECT_EQ(he.get_boundaries(), (IndexLists{{0, 1, 2}}));
}

TEST(HalfEdgeTriangleMesh, SquareTwinsAndFans) {
    const auto he = HalfEdgeTriangleMesh::create_from_triangle_mesh(square());
    const std::vector<HalfEdge> edges = he.half_edges();
    ASSERT_EQ(edges.size(), 6u);
    // The diagonal: side 2 of triangle 0 (2 -> 0) and side 0 of triangle 1 (0 -> 2) are twins.
    EXPECT_EQ(edges[2].twin, 3);
    EXPECT_EQ(edges[3].twin, 2);
    EXPECT_EQ(edges[3].vertex_indices, (std::array<int, 2>{0, 2}));
    EXPECT_EQ(std::count_if(edges.begin(), edges.end(), [](const HalfEdge& e) { return e.is_boundary(); }), 4);
    // Vertex 0's fan starts at its boundary half-edge 0 -> 1, then turns to 0 -> 2.
    const IndexLists fans = he.ordered_half_edge_from_vertex();
    ASSERT_EQ(fans.size(), 4u);
    EXPECT_EQ(fans[0], (std::vector<int>{0, 3}));
    EXPECT_EQ(he.get_boundaries(), (IndexLists{{0, 1, 2, 3}}));
    EXPECT_EQ(he.boundary_vertices_from_vertex(2), (std::vector<int32_t>{2, 3, 0, 1}));
}

TEST(HalfEdgeTriangleMesh, ClosedMeshHasNoBoundary) {
    const auto he = HalfEdgeTriangleMesh::create_from_triangle_mesh(TriangleMesh::create_tetrahedron());
    EXPECT_EQ(he.half_edges().size(), 12u);
    for (const HalfEdge& e : he.half_edges()) EXPECT_FALSE(e.is_boundary());
    EXPECT_TRUE(he.get_boundaries().empty());
    EXPECT_TRUE(he.boundary_vertices_from_vertex(0).empty());
    for (const auto& fan : he.ordered_half_edge_from_vertex()) EXPECT_EQ(fan.size(), 3u);
}

TEST(HalfEdgeTriangleMesh, CleansDuplicatesAndRejectsBadInput) {
    // A repeated vertex is merged and a repeated triangle dropped.
    const TriangleMesh dup({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {1, 0, 0}}, {{0, 1, 2}, {0, 3, 2}});
    const auto he = HalfEdgeTriangleMesh::create_from_triangle_mesh(dup);
    EXPECT_EQ(he.vertices().size(), 3u);
    EXPECT_EQ(he.triangles().size(), 1u);
    EXPECT_THROW(he.boundary_vertices_from_vertex(3), o3dpp::Error);
    EXPECT_THROW(he.boundary_half_edges_from_vertex(-1), o3dpp::Error);
    // Three triangles on the edge (0, 1): not manifold.
    const TriangleMesh fin({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}}, {{0, 1, 2}, {1, 0, 3}, {0, 1, 4}});
    EXPECT_THROW(HalfEdgeTriangleMesh::create_from_triangle_mesh(fin), o3dpp::Error);
    const TriangleMesh bad({{0, 0, 0}}, {{0, 1, 2}});
    EXPECT_THROW(HalfEdgeTriangleMesh::create_from_triangle_mesh(bad), o3dpp::Error);
}

TEST(MeshTopology, AdjacencyList) {
    const IndexLists tetra = TriangleMesh::create_tetrahedron().compute_adjacency_list();
    ASSERT_EQ(tetra.size(), 4u);
    for (int v = 0; v < 4; ++v) {
        std::vector<int> others;
        for (int u = 0; u < 4; ++u)
            if (u != v) others.push_back(u);
        EXPECT_EQ(tetra[v], others);
    }
    EXPECT_EQ(square().compute_adjacency_list(), (IndexLists{{1, 2, 3}, {0, 2}, {0, 1, 3}, {0, 2}}));
    const TriangleMesh bad({{0, 0, 0}}, {{0, 1, 2}});
    EXPECT_THROW(bad.compute_adjacency_list(), o3dpp::Error);
}

TEST(MeshTopology, NonManifoldEdgesAndVertices) {
    EXPECT_TRUE(TriangleMesh::create_tetrahedron().get_non_manifold_edges(false).empty());
    EXPECT_TRUE(square().get_non_manifold_edges().empty());
    EXPECT_EQ(square().get_non_manifold_edges(false),
              (std::vector<Edge>{{0, 1}, {0, 3}, {1, 2}, {2, 3}}));
    const TriangleMesh fin({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}}, {{0, 1, 2}, {1, 0, 3}, {0, 1, 4}});
    EXPECT_EQ(fin.get_non_manifold_edges(), (std::vector<Edge>{{0, 1}}));
    // Two triangles touching only at vertex 0 (a bow tie).
    const TriangleMesh bowtie({{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {-1, 0, 0}, {-1, -1, 0}}, {{0, 1, 2}, {0, 3, 4}});
    EXPECT_EQ(bowtie.get_non_manifold_vertices(), (std::vector<int32_t>{0}));
    EXPECT_TRUE(square().get_non_manifold_vertices().empty());
    const TriangleMesh bad({{0, 0, 0}}, {{0, 1, 2}});
    EXPECT_THROW(bad.get_non_manifold_edges(), o3dpp::Error);
    EXPECT_THROW(bad.get_non_manifold_vertices(), o3dpp::Error);
}

TEST(MeshTopology, IntersectionsAndOrientation) {
    // Triangle 1 pierces triangle 0 and shares no vertex with it.
    const TriangleMesh crossing({{0, 0, 0}, {2, 0, 0}, {0, 2, 0}, {0.5, 0.5, -1}, {0.5, 0.5, 1}, {1.5, 1.5, 1}},
                                {{0, 1, 2}, {3, 4, 5}});
    EXPECT_EQ(crossing.get_self_intersecting_triangles(), (std::vector<Edge>{{0, 1}}));
    EXPECT_TRUE(square().get_self_intersecting_triangles().empty());

    TriangleMesh box = TriangleMesh::create_box();
    TriangleMesh near_box = TriangleMesh::create_box();
    near_box.translate({0.5, 0.5, 0.5});
    TriangleMesh far_box = TriangleMesh::create_box();
    far_box.translate({5, 0, 0});
    EXPECT_TRUE(box.is_intersecting(near_box));
    EXPECT_FALSE(box.is_intersecting(far_box));

    // The second triangle of the square turned over: orienting turns it back.
    TriangleMesh flipped({{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}}, {{0, 1, 2}, {0, 3, 2}});
    EXPECT_TRUE(flipped.orient_triangles());
    std::map<std::pair<int, int>, int> directed;
    for (const auto& t : flipped.get_triangles())
        for (int k = 0; k < 3; ++k) ++directed[{t[k], t[(k + 1) % 3]}];
    for (const auto& kv : directed) EXPECT_EQ(kv.second, 1);
    EXPECT_EQ(flipped.get_triangles()[0], (o3dpp::Triangle{0, 1, 2}));
    TriangleMesh mobius = TriangleMesh::create_mobius();
    EXPECT_FALSE(mobius.orient_triangles());
    TriangleMesh bad({{0, 0, 0}}, {{0, 1, 2}});
    EXPECT_THROW(bad.orient_triangles(), o3dpp::Error);
    EXPECT_THROW(bad.get_self_intersecting_triangles(), o3dpp::Error);
}
