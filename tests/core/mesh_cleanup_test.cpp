// SPDX-License-Identifier: MIT
// Mesh clean-up: duplicated vertices and triangles, degenerate triangles, unreferenced vertices, non-manifold
// edges, merging close vertices. knot.ply numbers come from tools/reference/record_mesh.py (Open3D 0.20).
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "o3d/geometry/mesh_cleanup.h"
#include "o3d/geometry/mesh_topology.h"
#include "o3d/geometry/triangle_mesh_ops.h"
#include "o3d/utility/error.h"
#include "test_data.h"
#include "triangle_mesh_test_util.h"

using namespace o3d::geometry;
using o3d::test::unit_cube;

TEST(MeshCleanup, DuplicatedVertexIsMergedIntoTheFirst) {
    TriangleMesh m = unit_cube();
    m.vertex_colors.assign(8, Eigen::Vector3d(0.5, 0.5, 0.5));
    m.vertices.push_back(m.vertices[6]);  // vertex 8 repeats vertex 6
    m.vertex_colors.emplace_back(1, 0, 0);
    m.triangles[2] = Eigen::Vector3i(4, 5, 8);
    EXPECT_FALSE(is_edge_manifold(m, false));  // the split corner opens the surface
    remove_duplicated_vertices(m);
    EXPECT_EQ(m.vertices.size(), 8u);
    EXPECT_EQ(m.vertex_colors.size(), 8u);
    EXPECT_EQ(m.vertex_colors[6], Eigen::Vector3d(0.5, 0.5, 0.5));
    EXPECT_EQ(m.triangles[2], Eigen::Vector3i(4, 5, 6));
    EXPECT_TRUE(is_watertight(m));
}

TEST(MeshCleanup, NegativeZeroMergesAndNaNNever) {
    TriangleMesh m;
    m.vertices = {{0, 0, 0}, {-0.0, 0, 0}, {NAN, 0, 0}, {NAN, 0, 0}, {1, 2, 3}};
    m.triangles = {{0, 1, 2}, {3, 4, 1}};
    remove_duplicated_vertices(m);
    ASSERT_EQ(m.vertices.size(), 4u);
    EXPECT_EQ(m.triangles[0], Eigen::Vector3i(0, 0, 1));
    EXPECT_EQ(m.triangles[1], Eigen::Vector3i(2, 3, 0));

    TriangleMesh many;  // 200k NaN vertices: each is its own vertex, in linear time
    many.vertices.assign(200000, Eigen::Vector3d(NAN, NAN, NAN));
    remove_duplicated_vertices(many);
    EXPECT_EQ(many.vertices.size(), 200000u);
}

TEST(MeshCleanup, DuplicatedTrianglesInAnyOrderKeepTheFirst) {
    TriangleMesh m = unit_cube();
    m.triangles.emplace_back(1, 0, 2);  // triangle 0 reversed
    m.triangles.emplace_back(5, 6, 4);  // triangle 2 rotated
    compute_triangle_normals(m);
    m.triangle_material_ids = {0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13};
    m.triangle_uvs.assign(42, Eigen::Vector2d::Zero());
    m.triangle_uvs[3 * 11] = Eigen::Vector2d(0.25, 0.75);
    remove_duplicated_triangles(m);
    ASSERT_EQ(m.triangles.size(), 12u);
    EXPECT_EQ(m.triangle_material_ids.back(), 11);
    EXPECT_EQ(m.triangle_normals.size(), 12u);
    ASSERT_EQ(m.triangle_uvs.size(), 36u);
    EXPECT_EQ(m.triangle_uvs[33], Eigen::Vector2d(0.25, 0.75));
    EXPECT_TRUE(is_watertight(m));
}

TEST(MeshCleanup, DegenerateTrianglesAndUnreferencedVertices) {
    TriangleMesh m = unit_cube();
    m.vertices.emplace_back(9, 9, 9);  // vertex 8, used only by a degenerate triangle
    m.vertex_normals.assign(9, Eigen::Vector3d::UnitX());
    m.vertex_normals[7] = Eigen::Vector3d::UnitY();
    m.triangles.emplace_back(8, 8, 2);
    m.triangles.insert(m.triangles.begin(), Eigen::Vector3i(1, 3, 1));
    remove_degenerate_triangles(m);
    EXPECT_EQ(m.triangles, unit_cube().triangles);
    remove_unreferenced_vertices(m);
    EXPECT_EQ(m.vertices.size(), 8u);
    EXPECT_EQ(m.vertex_normals.size(), 8u);
    EXPECT_EQ(m.vertex_normals[7], Eigen::Vector3d::UnitY());

    TriangleMesh holes;  // vertices 0 and 2 unused: the triangle is renumbered
    holes.vertices = {{0, 0, 0}, {1, 0, 0}, {5, 5, 5}, {0, 1, 0}, {0, 0, 1}};
    holes.triangles = {{1, 3, 4}};
    remove_unreferenced_vertices(holes);
    ASSERT_EQ(holes.vertices.size(), 3u);
    EXPECT_EQ(holes.triangles[0], Eigen::Vector3i(0, 1, 2));
    EXPECT_EQ(holes.vertices[0], Eigen::Vector3d(1, 0, 0));
}

// Both results are what Open3D 0.20 gives (record_mesh.py: fin_small.after, fin_big.after).
TEST(MeshCleanup, NonManifoldEdgeLosesItsSmallestTriangles) {
    TriangleMesh m = unit_cube();
    m.vertices.emplace_back(0.5, -0.1, 0.0);  // a small fin on the cube's edge (0, 1)
    m.triangles.emplace_back(0, 1, 8);
    EXPECT_FALSE(is_edge_manifold(m, true));
    remove_non_manifold_edges(m);
    EXPECT_EQ(m.triangles, unit_cube().triangles);
    EXPECT_TRUE(is_edge_manifold(m, false));

    TriangleMesh big = unit_cube();  // a fin larger than the cube's triangles: a cube triangle goes instead
    big.vertices.emplace_back(0.5, -5, 0.0);
    big.triangles.emplace_back(0, 1, 8);
    remove_non_manifold_edges(big);
    EXPECT_EQ(big.triangles.size(), 12u);
    EXPECT_EQ(big.triangles.back(), Eigen::Vector3i(0, 1, 8));
    EXPECT_EQ(big.triangles[0], Eigen::Vector3i(0, 3, 2));  // (0,2,1) and (0,1,5) tie: the lower index goes
    EXPECT_TRUE(is_edge_manifold(big, true));
}

TEST(MeshCleanup, MergeCloseVerticesAveragesAttributes) {
    TriangleMesh m;
    m.vertices = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {1.05, 0, 0}, {1, 1, 0}};
    m.vertex_normals = {{0, 0, 1}, {0, 0, 1}, {0, 0, 1}, {0, 1, 0}, {0, 0, 1}};
    m.vertex_colors = {{0, 0, 0}, {1, 0, 0}, {0, 0, 0}, {0, 0, 1}, {0, 0, 0}};
    m.triangles = {{0, 1, 2}, {3, 4, 2}};
    m.triangle_normals.assign(2, Eigen::Vector3d::Zero());
    TriangleMesh strict = m;
    merge_close_vertices(strict, 0.05);  // |v1 - v3| = 0.05 is not closer than 0.05
    EXPECT_EQ(strict.vertices.size(), 5u);
    merge_close_vertices(m, 0.1);
    ASSERT_EQ(m.vertices.size(), 4u);
    EXPECT_NEAR(m.vertices[1].x(), 1.025, 1e-15);
    EXPECT_EQ(m.vertex_normals[1], Eigen::Vector3d(0, 0.5, 0.5));
    EXPECT_EQ(m.vertex_colors[1], Eigen::Vector3d(0.5, 0, 0.5));
    EXPECT_EQ(m.triangles[1], Eigen::Vector3i(1, 3, 2));
    EXPECT_NEAR(m.triangle_normals[0].z(), 1.0, 1e-15);  // recomputed because the mesh had them
    EXPECT_THROW(merge_close_vertices(m, -1), o3d::InvalidArgument);
    EXPECT_THROW(merge_close_vertices(m, NAN), o3d::InvalidArgument);

    TriangleMesh nan;  // non-finite vertices are never merged and do not break the grid
    nan.vertices = {{NAN, 0, 0}, {0, 0, 0}, {INFINITY, 0, 0}, {0, 0, 1e-3}};
    nan.triangles = {{0, 1, 2}, {1, 2, 3}};
    merge_close_vertices(nan, 0.01);
    EXPECT_EQ(nan.vertices.size(), 3u);
    EXPECT_EQ(nan.triangles[1], Eigen::Vector3i(1, 2, 1));

    TriangleMesh huge;  // the coordinate range overflows to infinity
    huge.vertices = {{-1e308, 0, 0}, {1e308, 0, 0}, {1e308, 0, 1}, {0, 0, 0}};
    huge.triangles = {{0, 1, 3}};
    merge_close_vertices(huge, 2.0);
    EXPECT_EQ(huge.vertices.size(), 3u);
    EXPECT_EQ(huge.vertices[1].z(), 0.5);  // x overflows in the sum, as in Open3D (sum / count)
}

TEST(MeshCleanup, EveryOperationChecksTriangleIndices) {
    TriangleMesh bad = unit_cube();
    bad.triangles[5](2) = 100;
    const TriangleMesh before = bad;
    for (auto op : {remove_duplicated_vertices, remove_duplicated_triangles, remove_degenerate_triangles,
                    remove_unreferenced_vertices, remove_non_manifold_edges}) {
        TriangleMesh m = bad;
        EXPECT_THROW(op(m), o3d::InvalidArgument);
        EXPECT_EQ(m.triangles, before.triangles);
    }
    EXPECT_THROW(merge_close_vertices(bad, 0.1), o3d::InvalidArgument);
}

TEST(MeshCleanup, KnotMatchesOpen3D) {
    O3D_TEST_DATA_OR_SKIP(path, "open3d/knot.ply");
    TriangleMesh knot;
    ASSERT_TRUE(o3d::test::read_simple_ply(path, knot));
    TriangleMesh dedup = knot;
    remove_duplicated_vertices(dedup);
    EXPECT_EQ(dedup.vertices.size(), 1440u);
    EXPECT_EQ(o3d::test::fingerprint(dedup.triangles), 35594024400.0);
    struct Case {
        double eps;
        size_t vertices;
        double fp_vertices, fp_triangles;
    };
    for (const Case c : {Case{4.0, 1385, -362270909.752734, 34028029923.0},
                         Case{9.0, 885, -153031736.03457174, 21812592477.0}}) {
        TriangleMesh m = knot;
        merge_close_vertices(m, c.eps);
        EXPECT_EQ(m.vertices.size(), c.vertices) << c.eps;
        EXPECT_EQ(m.triangles.size(), 2880u);
        EXPECT_NEAR(o3d::test::fingerprint(m.vertices), c.fp_vertices, 1e-9 * std::abs(c.fp_vertices)) << c.eps;
        EXPECT_EQ(o3d::test::fingerprint(m.triangles), c.fp_triangles) << c.eps;
    }
}
