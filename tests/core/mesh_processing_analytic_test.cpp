// SPDX-License-Identifier: MIT
// Mesh processing against analytic answers: sampling a square, subdividing solids, smoothing flat grids,
// decimating closed and flat meshes, clustering a cube, cropping; thread-count independence; bad input.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>

#include "mesh_processing_test_util.h"
#include "o3d/geometry/mesh_crop.h"
#include "o3d/geometry/mesh_poisson_disk.h"
#include "o3d/geometry/mesh_sampling.h"
#include "o3d/geometry/mesh_simplify_quadric.h"
#include "o3d/geometry/mesh_simplify_vertex_clustering.h"
#include "o3d/geometry/mesh_smoothing.h"
#include "o3d/geometry/mesh_subdivision.h"
#include "o3d/utility/error.h"

using namespace o3d::geometry;
using namespace o3d_test;
using Eigen::Vector3d;

namespace {

TriangleMesh unit_square() {
    TriangleMesh m;
    m.vertices = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}};
    m.triangles = {{0, 1, 2}, {0, 2, 3}};
    return m;
}

TriangleMesh flat_grid(int n) {
    return grid(n, [](double, double) { return 0.0; });
}

}  // namespace

// ---- uniform sampling ----

TEST(MeshSampling, UnitSquarePointsLieOnItWithTheFaceNormal) {
    const size_t n = 20000;
    const PointCloud pc = sample_points_uniformly(unit_square(), n, true, 7);
    ASSERT_EQ(pc.points.size(), n);
    ASSERT_TRUE(pc.has_normals());
    EXPECT_FALSE(pc.has_colors());
    Vector3d mean = Vector3d::Zero();
    size_t left = 0, corner = 0;
    for (size_t i = 0; i < n; ++i) {
        const Vector3d& p = pc.points[i];
        ASSERT_EQ(p.z(), 0.0);
        ASSERT_TRUE(p.x() >= 0 && p.x() <= 1 && p.y() >= 0 && p.y() <= 1) << p.transpose();
        EXPECT_EQ(pc.normals[i], Vector3d(0, 0, 1));
        mean += p;
        left += p.x() < 0.5;
        corner += p.x() + p.y() < 0.5;  // a triangle of area 1/8
    }
    mean /= double(n);
    // Standard error of each mean is 0.29 / sqrt(20000) = 0.002: 0.01 is five of them.
    EXPECT_NEAR(mean.x(), 0.5, 0.01);
    EXPECT_NEAR(mean.y(), 0.5, 0.01);
    EXPECT_NEAR(double(left) / n, 0.5, 0.015);
    EXPECT_NEAR(double(corner) / n, 0.125, 0.012);
}

TEST(MeshSampling, TrianglesArePickedByArea) {
    // Two separate triangles of areas 1 and 3 (plus one of zero area, never picked): each point picks the
    // first with probability 1/4 (Open3D 0.20 draws the triangle per point). 100000 draws: sd 0.0014.
    TriangleMesh m;
    m.vertices = {{0, 0, 0}, {2, 0, 0}, {0, 1, 0}, {0, 0, 5}, {6, 0, 5}, {0, 1, 5}, {0, 0, 9}, {1, 0, 9}, {2, 0, 9}};
    m.triangles = {{0, 1, 2}, {6, 7, 8}, {3, 4, 5}};
    const size_t n = 100000;
    const PointCloud pc = sample_points_uniformly(m, n, true, 3);
    ASSERT_EQ(pc.points.size(), n);
    size_t first = 0, switches = 0;
    for (size_t i = 0; i < n; ++i) {
        const double z = pc.points[i].z();
        ASSERT_TRUE(z == 0.0 || std::abs(z - 5.0) < 1e-12) << z;
        first += z == 0.0;
        if (i > 0) switches += (z == 0.0) != (pc.points[i - 1].z() == 0.0);
    }
    EXPECT_NEAR(double(first) / n, 0.25, 0.007);
    // Independent picks, not grouped by triangle: 2 p (1 - p) n = 37500 switches expected.
    EXPECT_NEAR(double(switches), 37500, 1500);
}

TEST(MeshSampling, InterpolatesVertexNormalsAndColorsLinearly) {
    // Attributes linear in position come back exactly as that linear function at each sample.
    TriangleMesh m = unit_square();
    for (const auto& v : m.vertices) {
        m.vertex_normals.emplace_back(v.x(), v.y(), 1);
        m.vertex_colors.emplace_back(v.x(), v.y(), 0.25);
    }
    const PointCloud pc = sample_points_uniformly(m, 500, false, 11);
    ASSERT_TRUE(pc.has_normals());
    ASSERT_TRUE(pc.has_colors());
    for (size_t i = 0; i < pc.points.size(); ++i) {
        const Vector3d& p = pc.points[i];
        EXPECT_LT((pc.normals[i] - Vector3d(p.x(), p.y(), 1)).norm(), 1e-12);
        EXPECT_LT((pc.colors[i] - Vector3d(p.x(), p.y(), 0.25)).norm(), 1e-12);
    }
    // Without vertex normals and without use_triangle_normal there are no normals.
    m.vertex_normals.clear();
    EXPECT_FALSE(sample_points_uniformly(m, 10, false, 1).has_normals());
    // Given triangle normals win over computed ones.
    m.triangle_normals = {{0, 0, -1}, {0, 0, -1}};
    for (const auto& nrm : sample_points_uniformly(m, 50, true, 1).normals) EXPECT_EQ(nrm, Vector3d(0, 0, -1));
}

TEST(MeshSampling, TexturedMeshTakesTheNearestTexel) {
    // A 2 x 2 RGB texture over the square (UV = xy): Open3D 0.20 reads texel (floor(u W), floor(v H)), no
    // flip (tools/reference/record_mesh_processing.py, "texture colors"): red, green / blue, white.
    TriangleMesh m = unit_square();
    m.triangle_uvs = {{0, 0}, {1, 0}, {1, 1}, {0, 0}, {1, 1}, {0, 1}};
    m.triangle_material_ids = {0, 0};
    Image tex;
    tex.width = tex.height = 2;
    tex.num_channels = 3;
    tex.bytes_per_channel = 1;
    tex.data = {255, 0, 0, 0, 255, 0, 0, 0, 255, 255, 255, 255};
    m.textures.push_back(tex);
    m.vertex_colors.assign(4, Vector3d(0.5, 0.5, 0.5));  // the texture wins
    const PointCloud pc = sample_points_uniformly(m, 2000, false, 4);
    ASSERT_TRUE(pc.has_colors());
    for (size_t i = 0; i < pc.points.size(); ++i) {
        const bool right = pc.points[i].x() >= 0.5, top = pc.points[i].y() >= 0.5;
        const Vector3d expect = top ? (right ? Vector3d(1, 1, 1) : Vector3d(0, 0, 1))
                                    : (right ? Vector3d(0, 1, 0) : Vector3d(1, 0, 0));
        EXPECT_EQ(pc.colors[i], expect) << pc.points[i].transpose();
    }
}

TEST(MeshSampling, SameSeedSameCloudOnAnyThreadCount) {
    const TriangleMesh s = uv_sphere(1, 20);
    const PointCloud a = sample_points_uniformly(s, 5000, false, 42, 1);
    const PointCloud b = sample_points_uniformly(s, 5000, false, 42, 4);
    const PointCloud c = sample_points_uniformly(s, 5000, false, 43, 4);
    EXPECT_EQ(a.points, b.points);
    EXPECT_NE(a.points, c.points);
}

TEST(MeshSampling, RejectsBadInput) {
    TriangleMesh m = unit_square();
    EXPECT_THROW(sample_points_uniformly(m, 0, false, 1), o3d::InvalidArgument);
    EXPECT_THROW(sample_points_uniformly(TriangleMesh(), 10, false, 1), o3d::InvalidArgument);
    TriangleMesh flat;
    flat.vertices = {{0, 0, 0}, {1, 0, 0}, {2, 0, 0}};
    flat.triangles = {{0, 1, 2}};
    EXPECT_THROW(sample_points_uniformly(flat, 10, false, 1), o3d::InvalidArgument);  // zero area
    m.triangles[1](2) = 4;
    EXPECT_THROW(sample_points_uniformly(m, 10, false, 1), o3d::InvalidArgument);
    m.triangles[1](2) = -1;
    EXPECT_THROW(sample_points_uniformly(m, 10, false, 1), o3d::InvalidArgument);
}

// ---- Poisson disk ----

TEST(MeshPoissonDisk, KeepsTheCountOnTheSurfaceAndSpreadsPoints) {
    const TriangleMesh s = uv_sphere(1, 20);
    const PointCloud pc = sample_points_poisson_disk(s, 400, 5, false, 9);
    ASSERT_EQ(pc.points.size(), 400u);
    // On the facets: inside the unit sphere, outside the inscribed one of a res-20 UV sphere.
    for (const auto& p : pc.points) {
        EXPECT_LE(p.norm(), 1 + 1e-12);
        EXPECT_GE(p.norm(), std::cos(M_PI / 20) - 1e-9);
    }
    EXPECT_EQ(pc.points, sample_points_poisson_disk(s, 400, 5, false, 9, 1).points);
    EXPECT_EQ(pc.points, sample_points_poisson_disk(s, 400, 5, false, 9, 3).points);
    // init_factor 1: nothing to eliminate, the uniform sample itself.
    EXPECT_EQ(sample_points_poisson_disk(s, 300, 1, false, 5).points, sample_points_uniformly(s, 300, false, 5).points);
}

TEST(MeshPoissonDisk, RejectsBadInput) {
    const TriangleMesh m = unit_square();
    EXPECT_THROW(sample_points_poisson_disk(m, 10, 0.5, false, 1), o3d::InvalidArgument);
    EXPECT_THROW(sample_points_poisson_disk(m, 10, std::nan(""), false, 1), o3d::InvalidArgument);
    EXPECT_THROW(sample_points_poisson_disk(m, 10, INFINITY, false, 1), o3d::InvalidArgument);
    EXPECT_THROW(sample_points_poisson_disk(m, 0, 5, false, 1), o3d::InvalidArgument);
    EXPECT_THROW(sample_points_poisson_disk(TriangleMesh(), 10, 5, false, 1), o3d::InvalidArgument);
}

// ---- vertex clustering ----

TEST(MeshVertexClustering, LargeVoxelMergesACubeIntoItsCentre) {
    for (auto c : {SimplificationContraction::Average, SimplificationContraction::Quadric}) {
        TriangleMesh cube = unit_cube();
        for (const auto& v : cube.vertices) cube.vertex_colors.push_back(v);
        // Voxel 3 on the grid from min - 1.5: [-1.5, 1.5) holds the whole cube.
        const TriangleMesh out = simplify_vertex_clustering(cube, 3.0, c);
        ASSERT_EQ(out.vertices.size(), 1u);
        EXPECT_TRUE(out.triangles.empty());
        EXPECT_LT((out.vertices[0] - Vector3d(0.5, 0.5, 0.5)).norm(), 1e-12);
        ASSERT_EQ(out.vertex_colors.size(), 1u);
        EXPECT_LT((out.vertex_colors[0] - Vector3d(0.5, 0.5, 0.5)).norm(), 1e-12);
    }
}

TEST(MeshVertexClustering, SmallVoxelKeepsTheCube) {
    const TriangleMesh cube = unit_cube();
    const TriangleMesh out = simplify_vertex_clustering(cube, 0.6, SimplificationContraction::Average);
    EXPECT_EQ(out.vertices, cube.vertices);
    EXPECT_EQ(out.triangles.size(), 12u);
    EXPECT_TRUE(closed_and_oriented(out));
    EXPECT_NEAR(signed_volume(out), 1.0, 1e-12);
}

TEST(MeshVertexClustering, RejectsBadInput) {
    const TriangleMesh cube = unit_cube();
    EXPECT_THROW(simplify_vertex_clustering(cube, 0, SimplificationContraction::Average), o3d::InvalidArgument);
    EXPECT_THROW(simplify_vertex_clustering(cube, -1, SimplificationContraction::Average), o3d::InvalidArgument);
    EXPECT_THROW(simplify_vertex_clustering(cube, std::nan(""), SimplificationContraction::Average),
                 o3d::InvalidArgument);
    EXPECT_THROW(simplify_vertex_clustering(cube, 1e-300, SimplificationContraction::Average), o3d::InvalidArgument);
    EXPECT_THROW(simplify_vertex_clustering(cube, 1, static_cast<SimplificationContraction>(5)), o3d::InvalidArgument);
    EXPECT_THROW(simplify_vertex_clustering(TriangleMesh(), 1, SimplificationContraction::Average),
                 o3d::InvalidArgument);
}

// ---- quadric decimation ----

TEST(MeshQuadricDecimation, SphereReachesTheTargetAndStaysClosed) {
    const TriangleMesh s = uv_sphere(1, 20);
    const double area = surface_area(s), volume = signed_volume(s);
    // (target, relative area tolerance): quadric placement hugs the sphere; a 30-triangle solid cannot.
    const std::pair<size_t, double> cases[] = {{1000, 0.003}, {301, 0.01}, {100, 0.03}, {30, 0.08}};
    for (const auto& [target, tolerance] : cases) {
        const TriangleMesh d = simplify_quadric_decimation(s, target, INFINITY, 1.0);
        // Each interior collapse removes two triangles: the count lands on target or target - 1.
        EXPECT_LE(d.triangles.size(), target);
        EXPECT_GE(d.triangles.size() + 1, target);
        EXPECT_TRUE(closed_and_oriented(d)) << target;
        EXPECT_EQ(euler_characteristic(d), 2) << target;
        EXPECT_EQ(d.vertices.size(), d.triangles.size() / 2 + 2);  // V = F/2 + 2 on a closed genus-0 surface
        EXPECT_NEAR(surface_area(d), area, tolerance * area) << target;
        EXPECT_NEAR(signed_volume(d), volume, 2 * tolerance * volume) << target;
        for (const auto& v : d.vertices) EXPECT_NEAR(v.norm(), 1.0, 0.15) << target;
    }
}

TEST(MeshQuadricDecimation, FlatGridStaysFlatWithItsBorder) {
    TriangleMesh g = flat_grid(11);  // [0,10]^2, 200 triangles
    for (const auto& v : g.vertices) g.vertex_colors.emplace_back(0.25, 0.5, 0.75);
    g.triangle_normals.assign(g.triangles.size(), Vector3d(0, 0, 1));
    const TriangleMesh d = simplify_quadric_decimation(g, 20, INFINITY, 1.0);
    EXPECT_LE(d.triangles.size(), 20u);
    EXPECT_NEAR(surface_area(d), 100.0, 1e-9);  // the boundary quadrics keep the square's outline
    for (const auto& [edge, uses] : edge_use(d)) EXPECT_LE(uses, 2);
    EXPECT_EQ(euler_characteristic(d), 1);  // still a disk
    for (const auto& v : d.vertices) EXPECT_NEAR(v.z(), 0.0, 1e-12);
    ASSERT_EQ(d.vertex_colors.size(), d.vertices.size());
    for (const auto& c : d.vertex_colors) EXPECT_LT((c - Vector3d(0.25, 0.5, 0.75)).norm(), 1e-15);
    ASSERT_EQ(d.triangle_normals.size(), d.triangles.size());
    for (const auto& n : d.triangle_normals) EXPECT_LT((n - Vector3d(0, 0, 1)).norm(), 1e-12);  // none flipped
    // The four corners survive exactly.
    for (const Vector3d corner : {Vector3d(0, 0, 0), Vector3d(10, 0, 0), Vector3d(0, 10, 0), Vector3d(10, 10, 0)})
        EXPECT_TRUE(std::any_of(d.vertices.begin(), d.vertices.end(),
                                [&](const Vector3d& v) { return (v - corner).norm() < 1e-9; }))
            << corner.transpose();
}

TEST(MeshQuadricDecimation, MaximumErrorStopsEarly) {
    const TriangleMesh s = uv_sphere(1, 20);
    EXPECT_EQ(simplify_quadric_decimation(s, 100, 1e-12, 1.0).triangles.size(), s.triangles.size());
    const size_t some = simplify_quadric_decimation(s, 100, 1e-5, 1.0).triangles.size();
    EXPECT_LT(some, s.triangles.size());
    EXPECT_GT(some, 100u);
    // A target at or above the count returns the mesh unchanged.
    const TriangleMesh same = simplify_quadric_decimation(s, s.triangles.size(), INFINITY, 1.0);
    EXPECT_EQ(same.vertices, s.vertices);
    EXPECT_EQ(same.triangles, s.triangles);
}

TEST(MeshQuadricDecimation, TetrahedronIsNotCollapsedAway) {
    const TriangleMesh t = tetrahedron();
    const TriangleMesh d = simplify_quadric_decimation(t, 0, INFINITY, 1.0);
    EXPECT_EQ(d.triangles.size(), 4u);
    EXPECT_TRUE(closed_and_oriented(d));
}

TEST(MeshQuadricDecimation, RejectsBadInput) {
    const TriangleMesh s = uv_sphere(1, 5);
    EXPECT_THROW(simplify_quadric_decimation(s, 10, std::nan(""), 1), o3d::InvalidArgument);
    EXPECT_THROW(simplify_quadric_decimation(s, 10, -1, 1), o3d::InvalidArgument);
    EXPECT_THROW(simplify_quadric_decimation(s, 10, INFINITY, -1), o3d::InvalidArgument);
    EXPECT_THROW(simplify_quadric_decimation(s, 10, INFINITY, INFINITY), o3d::InvalidArgument);
    EXPECT_THROW(simplify_quadric_decimation(TriangleMesh(), 10, INFINITY, 1), o3d::InvalidArgument);
    TriangleMesh bad = s;
    bad.vertices[3].x() = std::nan("");
    EXPECT_THROW(simplify_quadric_decimation(bad, 10, INFINITY, 1), o3d::InvalidArgument);
    bad = s;
    bad.triangles[0](1) = 1000;
    EXPECT_THROW(simplify_quadric_decimation(bad, 10, INFINITY, 1), o3d::InvalidArgument);
}

// ---- smoothing ----

TEST(MeshSmoothing, FlatGridStaysFlat) {
    TriangleMesh g = grid(6, [](double x, double y) { return 0.0 * x * y; });
    for (auto& v : g.vertices) v += Vector3d(0.1 * std::sin(7 * v.y()), 0.1 * std::cos(5 * v.x()), 0);  // in-plane
    for (const TriangleMesh& out : {filter_smooth_laplacian(g, 10, 0.5, FilterScope::All),
                                    filter_smooth_taubin(g, 10, 0.5, -0.53, FilterScope::All),
                                    filter_smooth_simple(g, 10, FilterScope::All)}) {
        ASSERT_EQ(out.vertices.size(), g.vertices.size());
        EXPECT_NE(out.vertices, g.vertices);
        for (const auto& v : out.vertices) EXPECT_EQ(v.z(), 0.0);
        EXPECT_EQ(out.triangles, g.triangles);
    }
}

TEST(MeshSmoothing, SimpleFilterMovesATriangleToItsCentroid) {
    TriangleMesh t;
    t.vertices = {{0, 0, 0}, {3, 0, 0}, {0, 6, 3}};
    t.triangles = {{0, 1, 2}};
    t.vertex_colors = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
    const TriangleMesh out = filter_smooth_simple(t, 1, FilterScope::All);
    for (int k = 0; k < 3; ++k) {
        EXPECT_LT((out.vertices[k] - Vector3d(1, 2, 1)).norm(), 1e-15);
        EXPECT_LT((out.vertex_colors[k] - Vector3d::Constant(1.0 / 3)).norm(), 1e-15);
    }
    // Scope Color leaves the positions alone; Vertex leaves the colors.
    const TriangleMesh colors = filter_smooth_simple(t, 1, FilterScope::Color);
    EXPECT_EQ(colors.vertices, t.vertices);
    EXPECT_LT((colors.vertex_colors[0] - Vector3d::Constant(1.0 / 3)).norm(), 1e-15);
    const TriangleMesh positions = filter_smooth_simple(t, 1, FilterScope::Vertex);
    EXPECT_EQ(positions.vertex_colors, t.vertex_colors);
    // Zero iterations: a copy (Open3D returns uninitialised vertices).
    EXPECT_EQ(filter_smooth_laplacian(t, 0, 0.5, FilterScope::All).vertices, t.vertices);
}

TEST(MeshSmoothing, LaplacianUsesInverseDistanceWeights) {
    // Vertex 0 with neighbours at distance 1 and 3 (and they with each other): the weighted mean is
    // (1 * p1 + p2 / 3) / (1 + 1/3).
    TriangleMesh t;
    t.vertices = {{0, 0, 0}, {1, 0, 0}, {0, 3, 0}};
    t.triangles = {{0, 1, 2}};
    const TriangleMesh out = filter_smooth_laplacian(t, 1, 1.0, FilterScope::Vertex);
    const Vector3d expect = (Vector3d(1, 0, 0) + Vector3d(0, 3, 0) / 3) / (1 + 1.0 / 3);
    EXPECT_LT((out.vertices[0] - expect).norm(), 1e-9);
}

TEST(MeshSmoothing, ThreadCountDoesNotChangeTheResult) {
    const TriangleMesh b = bumpy_grid();
    EXPECT_EQ(filter_smooth_taubin(b, 5, 0.5, -0.53, FilterScope::All, 1).vertices,
              filter_smooth_taubin(b, 5, 0.5, -0.53, FilterScope::All, 4).vertices);
}

TEST(MeshSmoothing, RejectsBadInput) {
    const TriangleMesh b = bumpy_grid();
    EXPECT_THROW(filter_smooth_simple(b, -1, FilterScope::All), o3d::InvalidArgument);
    EXPECT_THROW(filter_smooth_simple(b, 1, static_cast<FilterScope>(4)), o3d::InvalidArgument);
    EXPECT_THROW(filter_smooth_laplacian(b, 1, std::nan(""), FilterScope::All), o3d::InvalidArgument);
    EXPECT_THROW(filter_smooth_taubin(b, 1, 0.5, INFINITY, FilterScope::All), o3d::InvalidArgument);
    EXPECT_THROW(filter_smooth_taubin(TriangleMesh(), 1, 0.5, -0.53, FilterScope::All), o3d::InvalidArgument);
    TriangleMesh bad = b;
    bad.triangles[2](0) = 25;
    EXPECT_THROW(filter_smooth_simple(bad, 1, FilterScope::All), o3d::InvalidArgument);
}

// ---- subdivision ----

TEST(MeshSubdivision, MidpointQuadruplesTheTetrahedronKeepingItsShape) {
    const TriangleMesh t = tetrahedron();
    const TriangleMesh once = subdivide_midpoint(t, 1);
    EXPECT_EQ(once.triangles.size(), 16u);
    EXPECT_EQ(once.vertices.size(), 10u);  // 4 + 6 edges
    const TriangleMesh twice = subdivide_midpoint(t, 2);
    EXPECT_EQ(twice.triangles.size(), 64u);
    EXPECT_EQ(twice.vertices.size(), 34u);  // 10 + 24 edges
    for (const TriangleMesh* m : {&once, &twice}) {
        EXPECT_NEAR(surface_area(*m), surface_area(t), 1e-12);
        EXPECT_NEAR(signed_volume(*m), signed_volume(t), 1e-12);
        EXPECT_TRUE(closed_and_oriented(*m));
        EXPECT_EQ(euler_characteristic(*m), 2);
    }
    // The original vertices keep their indices and positions; edge vertices are midpoints.
    for (int v = 0; v < 4; ++v) EXPECT_EQ(once.vertices[v], t.vertices[v]);
    EXPECT_EQ(once.vertices[4], 0.5 * (t.vertices[0] + t.vertices[1]));
    EXPECT_EQ(subdivide_midpoint(t, 0).triangles, t.triangles);
}

TEST(MeshSubdivision, MidpointSplitsUvsAndKeepsMaterialIds) {
    TriangleMesh t;
    t.vertices = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
    t.triangles = {{0, 1, 2}};
    t.triangle_uvs = {{0, 0}, {1, 0}, {0, 1}};
    t.triangle_material_ids = {3};
    t.triangle_normals = {{0, 0, 1}};
    const TriangleMesh out = subdivide_midpoint(t, 1);
    ASSERT_EQ(out.triangle_uvs.size(), 12u);
    // A vertex at position (x, y, 0) has UV (x, y) here: every corner must agree.
    for (size_t t4 = 0; t4 < 4; ++t4)
        for (int k = 0; k < 3; ++k) {
            const Vector3d& p = out.vertices[out.triangles[t4](k)];
            EXPECT_EQ(out.triangle_uvs[3 * t4 + k], Eigen::Vector2d(p.x(), p.y()));
        }
    EXPECT_EQ(out.triangle_material_ids, std::vector<int>(4, 3));
    ASSERT_EQ(out.triangle_normals.size(), 4u);
    for (const auto& n : out.triangle_normals) EXPECT_EQ(n, Vector3d(0, 0, 1));
}

TEST(MeshSubdivision, LoopKeepsClosedMeshesClosed) {
    for (const TriangleMesh& m : {tetrahedron(), octahedron(), uv_sphere(1, 6)}) {
        for (int it = 1; it <= 2; ++it) {
            const TriangleMesh out = subdivide_loop(m, it);
            EXPECT_EQ(out.triangles.size(), m.triangles.size() << (2 * it));
            EXPECT_TRUE(closed_and_oriented(out));
            EXPECT_EQ(euler_characteristic(out), 2);
            // Loop shrinks a convex solid (a tetrahedron to a few % of its volume): it drops but stays positive.
            EXPECT_LT(signed_volume(out), signed_volume(m));
            EXPECT_GT(signed_volume(out), 0.0);
        }
    }
}

TEST(MeshSubdivision, LoopKeepsAFlatOpenGridFlatAndItsBorderOnTheBorder) {
    const TriangleMesh g = flat_grid(4);  // [0,3]^2
    const TriangleMesh out = subdivide_loop(g, 2);
    EXPECT_EQ(out.triangles.size(), g.triangles.size() * 16);
    for (const auto& v : out.vertices) {
        EXPECT_EQ(v.z(), 0.0);
        EXPECT_TRUE(v.x() >= -1e-12 && v.x() <= 3 + 1e-12 && v.y() >= -1e-12 && v.y() <= 3 + 1e-12);
    }
    // The boundary rule keeps the border: x = 0 edge vertices stay at x = 0, so the area only loses the
    // corners' rounding: 3/4 of each corner moves along the border, nothing leaves the plane.
    EXPECT_EQ(euler_characteristic(out), 1);
    EXPECT_GT(surface_area(out), 8.0);
    EXPECT_LT(surface_area(out), 9.0 + 1e-12);
}

TEST(MeshSubdivision, RejectsBadInput) {
    const TriangleMesh t = tetrahedron();
    EXPECT_THROW(subdivide_midpoint(t, -1), o3d::InvalidArgument);
    EXPECT_THROW(subdivide_loop(t, -2), o3d::InvalidArgument);
    EXPECT_THROW(subdivide_loop(TriangleMesh(), 1), o3d::InvalidArgument);
    EXPECT_THROW(subdivide_loop(t, 40), o3d::InvalidArgument);  // 4^40 triangles
    TriangleMesh bad = t;
    bad.triangles[3](2) = -7;
    EXPECT_THROW(subdivide_midpoint(bad, 1), o3d::InvalidArgument);
}

// ---- crop ----

TEST(MeshCrop, KeepsExactlyTheTrianglesInside) {
    TriangleMesh b = bumpy_grid();
    b.triangle_material_ids.assign(b.triangles.size(), 0);
    for (size_t t = 0; t < b.triangles.size(); ++t) b.triangle_material_ids[t] = static_cast<int>(t);
    const TriangleMesh out = crop_aabb(b, Vector3d(0, 0, -1), Vector3d(2, 2, 1));
    // Cells (i, j) with i, j < 2: 8 triangles over the 3 x 3 vertices with x, y <= 2.
    ASSERT_EQ(out.triangles.size(), 8u);
    ASSERT_EQ(out.vertices.size(), 9u);
    ASSERT_EQ(out.vertex_colors.size(), 9u);
    std::vector<int> kept;
    for (size_t t = 0; t < b.triangles.size(); ++t) {
        bool in = true;
        for (int k = 0; k < 3; ++k) {
            const Vector3d& v = b.vertices[b.triangles[t](k)];
            in = in && v.x() <= 2 && v.y() <= 2;
        }
        if (in) kept.push_back(static_cast<int>(t));
    }
    EXPECT_EQ(out.triangle_material_ids, kept);
    for (size_t t = 0; t < out.triangles.size(); ++t)
        for (int k = 0; k < 3; ++k)
            EXPECT_EQ(out.vertices[out.triangles[t](k)], b.vertices[b.triangles[kept[t]](k)]);
    for (size_t v = 0; v < out.vertices.size(); ++v)
        EXPECT_EQ(out.vertex_colors[v], Vector3d(out.vertices[v].x() / 4, out.vertices[v].y() / 4, 0.5));
    // A box around nothing gives an empty mesh; one around everything gives the mesh back.
    EXPECT_TRUE(crop_aabb(b, Vector3d(10, 10, 10), Vector3d(11, 11, 11)).vertices.empty());
    EXPECT_EQ(crop_aabb(b, Vector3d(-1, -1, -1), Vector3d(5, 5, 5)).triangles, b.triangles);
}

TEST(MeshCrop, RejectsBadBoxes) {
    const TriangleMesh b = bumpy_grid();
    EXPECT_THROW(crop_aabb(b, Vector3d(0, 0, std::nan("")), Vector3d(1, 1, 1)), o3d::InvalidArgument);
    EXPECT_THROW(crop_aabb(b, Vector3d(2, 0, 0), Vector3d(1, 1, 1)), o3d::InvalidArgument);
    EXPECT_THROW(crop_aabb(b, Vector3d(0, 0, 0), Vector3d(1, 1, INFINITY)), o3d::InvalidArgument);
    EXPECT_THROW(crop_aabb(TriangleMesh(), Vector3d(0, 0, 0), Vector3d(1, 1, 1)), o3d::InvalidArgument);
}
