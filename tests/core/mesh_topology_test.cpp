// SPDX-License-Identifier: MIT
// Mesh topology queries: manifoldness, orientability, watertightness, Euler characteristic, volume,
// self-intersection (narrow and broad phase) and connected clusters. knot.ply numbers come from
// tools/reference/record_mesh.py (Open3D 0.20).
#include <Eigen/Geometry>
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "o3d/geometry/mesh_clusters.h"
#include "o3d/geometry/mesh_self_intersection.h"
#include "o3d/geometry/mesh_topology.h"
#include "o3d/geometry/triangle_mesh_ops.h"
#include "o3d/utility/error.h"
#include "o3d/utility/parallel.h"
#include "test_data.h"
#include "triangle_mesh_test_util.h"

using namespace o3d::geometry;
using o3d::test::corner_tetrahedron;
using o3d::test::unit_cube;
using V = Eigen::Vector3d;

namespace {

/// @brief A Moebius strip of n quads: a single-sided surface.
TriangleMesh moebius(int n) {
    TriangleMesh m;
    for (int i = 0; i < n; ++i) {
        const double u = 2 * M_PI * i / n;
        for (const double s : {-0.3, 0.3}) {
            const double r = 1 + s * std::cos(u / 2);
            m.vertices.emplace_back(r * std::cos(u), r * std::sin(u), s * std::sin(u / 2));
        }
    }
    for (int i = 0; i < n; ++i) {
        const int a = 2 * i, b = 2 * i + 1;
        // The last quad joins the first with the two sides exchanged: the half twist.
        const int c = i + 1 < n ? 2 * (i + 1) : 1, d = i + 1 < n ? 2 * (i + 1) + 1 : 0;
        m.triangles.emplace_back(a, c, d);
        m.triangles.emplace_back(a, d, b);
    }
    return m;
}

bool brute_force_self_intersecting(const TriangleMesh& m) {
    for (size_t i = 0; i < m.triangles.size(); ++i)
        for (size_t j = i + 1; j < m.triangles.size(); ++j) {
            const Eigen::Vector3i &a = m.triangles[i], &b = m.triangles[j];
            bool shared = false;
            for (int p = 0; p < 3; ++p)
                for (int q = 0; q < 3; ++q) shared = shared || a(p) == b(q);
            if (shared) continue;
            const auto& v = m.vertices;
            if (triangles_intersect(v[a(0)], v[a(1)], v[a(2)], v[b(0)], v[b(1)], v[b(2)])) return true;
        }
    return false;
}

}  // namespace

TEST(MeshTopology, UnitCube) {
    const TriangleMesh cube = unit_cube();
    EXPECT_TRUE(is_edge_manifold(cube, false));
    EXPECT_TRUE(is_vertex_manifold(cube));
    EXPECT_FALSE(is_self_intersecting(cube));
    EXPECT_TRUE(is_watertight(cube));
    EXPECT_TRUE(is_orientable(cube));
    EXPECT_EQ(euler_poincare_characteristic(cube), 2);
    EXPECT_NEAR(volume(cube), 1.0, 1e-15);
    EXPECT_DOUBLE_EQ(surface_area(cube), 6.0);
}

TEST(MeshTopology, Tetrahedron) {
    const TriangleMesh tet = corner_tetrahedron(V(10, -3, 7));
    EXPECT_TRUE(is_watertight(tet));
    EXPECT_EQ(euler_poincare_characteristic(tet), 2);
    EXPECT_NEAR(volume(tet), 1.0 / 6.0, 1e-14);
}

TEST(MeshTopology, VolumeOfAnOrientableMeshStoredWithMixedOrientations) {
    TriangleMesh cube = unit_cube();
    std::swap(cube.triangles[3](1), cube.triangles[3](2));
    EXPECT_TRUE(is_orientable(cube));
    EXPECT_NEAR(volume(cube), 1.0, 1e-15);
}

TEST(MeshTopology, OpenMeshHasBoundaryAndNoVolume) {
    TriangleMesh open = unit_cube();
    open.triangles.pop_back();
    EXPECT_TRUE(is_edge_manifold(open, true));
    EXPECT_FALSE(is_edge_manifold(open, false));
    EXPECT_FALSE(is_watertight(open));
    EXPECT_TRUE(is_orientable(open));
    EXPECT_EQ(euler_poincare_characteristic(open), 1);
    EXPECT_THROW(volume(open), o3d::InvalidArgument);
}

TEST(MeshTopology, NonManifoldEdgeAndVertex) {
    TriangleMesh fin = unit_cube();
    fin.vertices.emplace_back(0.5, -1, 0);
    fin.triangles.emplace_back(0, 1, 8);
    EXPECT_FALSE(is_edge_manifold(fin, true));
    EXPECT_FALSE(is_orientable(fin));
    EXPECT_FALSE(is_watertight(fin));

    TriangleMesh bowtie = corner_tetrahedron();  // two tetrahedra joined at one vertex
    TriangleMesh second = corner_tetrahedron(V(-1, -1, -1));
    second.vertices[3] = V(0, 0, 0);
    append(bowtie, second);
    for (Eigen::Vector3i& t : bowtie.triangles)
        for (int k = 0; k < 3; ++k)
            if (t(k) == 7) t(k) = 0;
    EXPECT_TRUE(is_edge_manifold(bowtie, false));
    EXPECT_FALSE(is_vertex_manifold(bowtie));
    EXPECT_FALSE(is_watertight(bowtie));
    EXPECT_THROW(volume(bowtie), o3d::InvalidArgument);
}

// Open3D 0.20 agrees (record_mesh.py: moebius = (True, False, 0)).
TEST(MeshTopology, MoebiusStripIsNotOrientable) {
    const TriangleMesh strip = moebius(24);
    EXPECT_TRUE(is_edge_manifold(strip, true));
    EXPECT_FALSE(is_orientable(strip));
    EXPECT_EQ(euler_poincare_characteristic(strip), 0);
}

TEST(MeshTopology, TriangleTriangleTest) {
    const V a(0, 0, 0), b(2, 0, 0), c(0, 2, 0);
    // A triangle piercing the plane z = 0 inside abc.
    EXPECT_TRUE(triangles_intersect(a, b, c, V(0.5, 0.5, -1), V(0.5, 0.5, 1), V(1.5, 1.5, 1)));
    // Crossing the plane outside abc.
    EXPECT_FALSE(triangles_intersect(a, b, c, V(3, 3, -1), V(3, 3, 1), V(4, 4, 1)));
    // Parallel planes.
    EXPECT_FALSE(triangles_intersect(a, b, c, V(0, 0, 0.1), V(2, 0, 0.1), V(0, 2, 0.1)));
    // Coplanar: overlapping, containing, disjoint.
    EXPECT_TRUE(triangles_intersect(a, b, c, V(1, -1, 0), V(1, 1, 0), V(3, 0, 0)));
    EXPECT_TRUE(triangles_intersect(a, b, c, V(0.2, 0.2, 0), V(0.5, 0.2, 0), V(0.2, 0.5, 0)));
    EXPECT_FALSE(triangles_intersect(a, b, c, V(3, 3, 0), V(4, 3, 0), V(3, 4, 0)));
    // Touching at a point counts (closed triangles); a gap does not.
    EXPECT_TRUE(triangles_intersect(a, b, c, V(1, 0.5, 0), V(1, 0.5, 1), V(2, 0.5, 1)));
    EXPECT_FALSE(triangles_intersect(a, b, c, V(1, 0.5, 1e-3), V(1, 0.5, 1), V(2, 0.5, 1)));
    // Zero-area triangles never intersect.
    EXPECT_FALSE(triangles_intersect(a, b, c, V(0.5, 0.5, -1), V(0.5, 0.5, 1), V(0.5, 0.5, 0)));
}

TEST(MeshTopology, SelfIntersectionSkipsNeighboursOnly) {
    TriangleMesh pair;
    pair.vertices = {V(0, 0, 0), V(2, 0, 0), V(0, 2, 0), V(0.5, 0.5, -1), V(0.5, 0.5, 1), V(1.5, 1.5, 1)};
    pair.triangles = {{0, 1, 2}, {3, 4, 5}};
    EXPECT_TRUE(is_self_intersecting(pair));
    pair.vertices[3] = V(0.5, 0.5, 0.5);  // lifted clear of the first triangle
    EXPECT_FALSE(is_self_intersecting(pair));

    // Two faces of the cube folded through each other but sharing a vertex: neighbours are not tested.
    TriangleMesh fold;
    fold.vertices = {V(0, 0, 0), V(2, 0, 0), V(0, 2, 0), V(1, 1, -1), V(1, 1, 1)};
    fold.triangles = {{0, 1, 2}, {0, 3, 4}};
    EXPECT_FALSE(is_self_intersecting(fold));
    // Adjacent faces of a closed box touch along edges only.
    EXPECT_FALSE(is_self_intersecting(unit_cube()));

    TriangleMesh two = unit_cube();  // a cube and a tetrahedron poking into it
    append(two, corner_tetrahedron(V(0.5, 0.5, 0.5)));
    EXPECT_TRUE(is_self_intersecting(two));
    EXPECT_FALSE(is_watertight(two));
}

TEST(MeshTopology, BroadPhaseAgreesWithBruteForce) {
    std::mt19937 rng(7);
    std::uniform_real_distribution<double> off(-0.8, 0.8);
    int intersecting = 0;
    for (int trial = 0; trial < 40; ++trial) {
        std::uniform_real_distribution<double> pos(0, 3 + trial / 4.0);  // from crowded to sparse
        TriangleMesh soup;
        const int n = 30 + trial;
        for (int t = 0; t < n; ++t) {
            const V c(pos(rng), pos(rng), pos(rng));
            for (int k = 0; k < 3; ++k) soup.vertices.push_back(c + V(off(rng), off(rng), off(rng)));
            soup.triangles.emplace_back(3 * t, 3 * t + 1, 3 * t + 2);
        }
        const bool expected = brute_force_self_intersecting(soup);
        intersecting += expected;
        EXPECT_EQ(is_self_intersecting(soup), expected) << trial;
    }
    EXPECT_GT(intersecting, 5);  // both answers occur
    EXPECT_LT(intersecting, 35);
}

TEST(MeshTopology, LargeMeshIsThreadIndependent) {
    // 120k triangles: an O(M^2) pair test would take minutes here (speed is measured in bench/, not asserted).
    TriangleMesh torus = o3d::test::grid_torus(400, 150);
    EXPECT_TRUE(is_watertight(torus));
    EXPECT_EQ(euler_poincare_characteristic(torus), 0);
    EXPECT_NEAR(volume(torus), 2 * M_PI * M_PI * 3, 0.01 * 2 * M_PI * M_PI * 3);  // 2 pi^2 R r^2

    // One extra triangle cutting through the tube.
    const int base = static_cast<int>(torus.vertices.size());
    torus.vertices.insert(torus.vertices.end(), {V(3, 0, -2), V(3, 0.1, 2), V(3.1, -0.1, 2)});
    torus.triangles.emplace_back(base, base + 1, base + 2);
    for (const int threads : {1, 4}) {
        o3d::utility::set_default_num_threads(threads);
        EXPECT_TRUE(is_self_intersecting(torus)) << threads;
    }
    o3d::utility::set_default_num_threads(0);
}

TEST(MeshTopology, ClustersNumberedByLowestTriangle) {
    TriangleMesh m = corner_tetrahedron(V(5, 0, 0));
    append(m, unit_cube());
    m.triangles.insert(m.triangles.begin() + 2, m.triangles.back());  // a cube triangle at index 2
    m.triangles.pop_back();
    // A triangle joined to the tetrahedron by a single vertex is its own cluster.
    m.vertices.insert(m.vertices.end(), {V(9, 9, 9), V(9, 8, 9)});
    m.triangles.emplace_back(0, 12, 13);
    const TriangleClusters c = cluster_connected_triangles(m);
    ASSERT_EQ(c.cluster_size.size(), 3u);
    EXPECT_EQ(c.triangle_cluster[0], 0);
    EXPECT_EQ(c.triangle_cluster[2], 1);
    EXPECT_EQ(c.triangle_cluster[3], 0);
    EXPECT_EQ(c.triangle_cluster.back(), 2);
    EXPECT_EQ(c.cluster_size, (std::vector<int>{4, 12, 1}));
    EXPECT_NEAR(c.cluster_area[0], 1.5 + std::sqrt(3.0) / 2, 1e-14);
    EXPECT_NEAR(c.cluster_area[1], 6.0, 1e-14);
    EXPECT_TRUE(cluster_connected_triangles(TriangleMesh{}).cluster_size.empty());
}

TEST(MeshTopology, QueriesCheckTriangleIndices) {
    TriangleMesh bad = unit_cube();
    bad.triangles[7](0) = 8;
    EXPECT_THROW(is_edge_manifold(bad, true), o3d::InvalidArgument);
    EXPECT_THROW(is_vertex_manifold(bad), o3d::InvalidArgument);
    EXPECT_THROW(is_self_intersecting(bad), o3d::InvalidArgument);
    EXPECT_THROW(is_orientable(bad), o3d::InvalidArgument);
    EXPECT_THROW(is_watertight(bad), o3d::InvalidArgument);
    EXPECT_THROW(euler_poincare_characteristic(bad), o3d::InvalidArgument);
    EXPECT_THROW(volume(bad), o3d::InvalidArgument);
    EXPECT_THROW(cluster_connected_triangles(bad), o3d::InvalidArgument);
}

TEST(MeshTopology, EmptyMesh) {
    const TriangleMesh empty;
    EXPECT_TRUE(is_edge_manifold(empty, false));
    EXPECT_TRUE(is_vertex_manifold(empty));
    EXPECT_FALSE(is_self_intersecting(empty));
    EXPECT_TRUE(is_watertight(empty));  // as Open3D: nothing violates the conditions
    EXPECT_EQ(volume(empty), 0.0);
    EXPECT_EQ(euler_poincare_characteristic(empty), 0);
}

TEST(MeshTopology, ExtremeCoordinatesDoNotBreakTheGrid) {
    TriangleMesh m = unit_cube();
    append(m, corner_tetrahedron(V(-1e308, -1e308, -1e308)));
    append(m, corner_tetrahedron(V(1e308, 1e308, 1e308)));
    m.vertices[9] = V(-1e308, 1e308, -1e308);
    EXPECT_FALSE(is_self_intersecting(m));
    TriangleMesh nan = unit_cube();
    nan.vertices[0] = V(NAN, 0, 0);
    EXPECT_FALSE(is_self_intersecting(nan));  // the triangles at vertex 0 are skipped; the rest are a box
}

TEST(MeshTopology, KnotMatchesOpen3D) {
    O3D_TEST_DATA_OR_SKIP(path, "open3d/knot.ply");
    TriangleMesh knot;
    ASSERT_TRUE(o3d::test::read_simple_ply(path, knot));
    EXPECT_TRUE(is_edge_manifold(knot, true));
    EXPECT_TRUE(is_edge_manifold(knot, false));
    EXPECT_TRUE(is_vertex_manifold(knot));
    EXPECT_FALSE(is_self_intersecting(knot));
    EXPECT_TRUE(is_watertight(knot));
    EXPECT_TRUE(is_orientable(knot));
    EXPECT_EQ(euler_poincare_characteristic(knot), 0);
    EXPECT_NEAR(volume(knot), 1053504.8262222065, 1e-9 * 1053504.8262222065);
    const TriangleClusters c = cluster_connected_triangles(knot);
    ASSERT_EQ(c.cluster_size.size(), 1u);
    EXPECT_EQ(c.cluster_size[0], 2880);
    EXPECT_NEAR(c.cluster_area[0], 112072.27793102189, 1e-9 * 112072.3);
}
