// SPDX-License-Identifier: MIT
// Mesh processing against Open3D 0.20. Every number below was printed by
// tools/reference/record_mesh_processing.py (run with /tmp/o3dref/bin/python), on meshes built the same way
// here (mesh_processing_test_util.h). Checksums: weighted = sum_i (i + 1) (x + 2y + 3z), squares = sum |v|^2.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <vector>

#include "mesh_processing_test_util.h"
#include "o3d/geometry/mesh_poisson_disk.h"
#include "o3d/geometry/mesh_sampling.h"
#include "o3d/geometry/mesh_simplify_quadric.h"
#include "o3d/geometry/mesh_simplify_vertex_clustering.h"
#include "o3d/geometry/mesh_smoothing.h"
#include "o3d/geometry/mesh_subdivision.h"
#include "o3d/kdtree/kd_tree.h"

using namespace o3d::geometry;
using namespace o3d_test;
using Eigen::Vector3d;

namespace {

void expect_checksums(const std::vector<Eigen::Vector3d>& a, size_t rows, double weighted, double squares,
                      double rel = 1e-12) {
    ASSERT_EQ(a.size(), rows);
    const auto [w, s] = checksums(a);
    EXPECT_NEAR(w, weighted, rel * std::abs(weighted));
    EXPECT_NEAR(s, squares, rel * std::abs(squares));
}

std::vector<std::array<int, 3>> sorted_triangles(const TriangleMesh& m) {
    std::vector<std::array<int, 3>> t;
    for (const auto& tri : m.triangles) t.push_back({tri(0), tri(1), tri(2)});
    std::sort(t.begin(), t.end());
    return t;
}

double mean_nearest_neighbour_distance(const PointCloud& pc) {
    const o3d::kdtree::KDTree tree(pc.points);
    std::vector<int> idx;
    std::vector<double> d2;
    double sum = 0;
    for (const auto& p : pc.points) {
        tree.search_knn(p, 2, idx, d2);
        sum += std::sqrt(d2[1]);
    }
    return sum / double(pc.points.size());
}

}  // namespace

TEST(MeshProcessingReference, QuadricDecimationOfTheSphereIsAtLeastAsGoodAsOpen3D) {
    const TriangleMesh s = uv_sphere(1, 20);
    const double area = 12.501878921475342;  // sphere(1,20): area
    EXPECT_NEAR(surface_area(s), area, 1e-12);
    struct Case {
        size_t target, triangles, vertices;
        double open3d_area;
    };
    // Open3D: target 760 -> 760 triangles, 382 vertices, area 12.42266662494901; 300 -> 300, 152,
    // 12.150147336719979; 100 -> 100, 52, 12.290620677204581 (all watertight).
    for (const Case& c : {Case{760, 760, 382, 12.42266662494901}, Case{300, 300, 152, 12.150147336719979},
                          Case{100, 100, 52, 12.290620677204581}}) {
        const TriangleMesh d = simplify_quadric_decimation(s, c.target, INFINITY, 1.0);
        EXPECT_EQ(d.triangles.size(), c.triangles);
        EXPECT_EQ(d.vertices.size(), c.vertices);
        EXPECT_TRUE(closed_and_oriented(d));
        // o3d places vertices at the quadric optimum where Open3D mostly takes an end or the midpoint: the
        // area must be at least as close to the sphere's.
        EXPECT_LE(std::abs(surface_area(d) - area), std::abs(c.open3d_area - area) + 1e-9) << c.target;
    }
}

TEST(MeshProcessingReference, SmoothingFiltersMatchOpen3D) {
    const TriangleMesh g = bumpy_grid();
    // Open3D adds neighbours in hash-set order, o3d in ascending order: equal to rounding.
    const double rel = 1e-12;
    const TriangleMesh simple = filter_smooth_simple(g, 3, FilterScope::All);
    expect_checksums(simple.vertices, 25, 2491.631916763428, 243.1311062414775, rel);
    expect_checksums(simple.vertex_colors, 25, 1050.98611148904, 21.36217672687307, rel);
    const TriangleMesh lap = filter_smooth_laplacian(g, 3, 0.5, FilterScope::All);
    expect_checksums(lap.vertices, 25, 2597.8902311958736, 261.31614280056084, rel);
    expect_checksums(lap.vertex_colors, 25, 1073.201518841526, 22.478132336772344, rel);
    const TriangleMesh taubin = filter_smooth_taubin(g, 4, 0.5, -0.53, FilterScope::All);
    expect_checksums(taubin.vertices, 25, 2734.7638255063944, 290.22984906439257, rel);
    expect_checksums(taubin.vertex_colors, 25, 1102.2869994533633, 24.252553989561246, rel);

    const TriangleMesh one = filter_smooth_laplacian(g, 1, 0.5, FilterScope::All);
    const Vector3d interior(2.002036952540312, 1.9991604906852027, 0.2608390948619794);
    const Vector3d corner(0.31221647991946944, 0.3200126103638273, 0.07068049321682629);
    EXPECT_LT((one.vertices[12] - interior).norm(), 1e-14);
    EXPECT_LT((one.vertices[0] - corner).norm(), 1e-14);
}

TEST(MeshProcessingReference, LoopSubdivisionMatchesOpen3DVertexForVertex) {
    const TriangleMesh o = octahedron();
    const TriangleMesh once = subdivide_loop(o, 1);
    const std::vector<Vector3d> expected = {
        {0.625, 0.0, 0.0},     {-0.625, 0.0, 0.0},    {0.0, 0.625, 0.0},     {0.0, -0.625, 0.0},
        {0.0, 0.0, 0.625},     {0.0, 0.0, -0.625},    {0.375, 0.375, 0.0},   {0.0, 0.375, 0.375},
        {0.375, 0.0, 0.375},   {-0.375, 0.375, 0.0},  {-0.375, 0.0, 0.375},  {-0.375, -0.375, 0.0},
        {0.0, -0.375, 0.375},  {0.375, -0.375, 0.0},  {0.375, 0.0, -0.375},  {0.0, 0.375, -0.375},
        {-0.375, 0.0, -0.375}, {0.0, -0.375, -0.375}};
    ASSERT_EQ(once.vertices.size(), expected.size());
    for (size_t v = 0; v < expected.size(); ++v) EXPECT_LT((once.vertices[v] - expected[v]).norm(), 1e-15) << v;
    const std::vector<Eigen::Vector3i> first_triangles = {{0, 6, 8}, {6, 2, 7},  {7, 4, 8},  {6, 7, 8},
                                                          {2, 9, 7}, {9, 1, 10}, {10, 4, 7}, {9, 10, 7}};
    for (size_t t = 0; t < first_triangles.size(); ++t) EXPECT_EQ(once.triangles[t], first_triangles[t]) << t;

    expect_checksums(subdivide_loop(o, 2).vertices, 66, -576.078125, 14.69091796875);
    const TriangleMesh g = bumpy_grid();
    const TriangleMesh grid_loop = subdivide_loop(g, 1);  // an open mesh: the boundary rules
    expect_checksums(grid_loop.vertices, 81, 25339.147927092927, 921.368902923783);
    expect_checksums(grid_loop.vertex_colors, 81, 10694.375, 77.3828125);
    expect_checksums(subdivide_midpoint(g, 2).vertices, 289, 317567.2685329067, 3205.9847051147367);
}

TEST(MeshProcessingReference, VertexClusteringMatchesOpen3D) {
    const TriangleMesh g = bumpy_grid();
    const std::vector<std::array<int, 3>> triangles = {
        {0, 1, 5},   {0, 5, 4},   {1, 2, 6},   {1, 6, 5},   {2, 3, 7},    {2, 7, 6},    {4, 5, 10},
        {4, 10, 9},  {5, 6, 8},   {5, 8, 11},  {5, 11, 10}, {6, 7, 8},    {7, 12, 8},   {8, 12, 11},
        {9, 10, 14}, {9, 14, 13}, {10, 11, 15}, {10, 15, 14}, {11, 12, 16}, {11, 16, 15}};
    const TriangleMesh average = simplify_vertex_clustering(g, 1.5, SimplificationContraction::Average);
    expect_checksums(average.vertices, 17, 1392.8135454917508, 232.01705236278676);
    EXPECT_EQ(sorted_triangles(average), triangles);
    const TriangleMesh quadric = simplify_vertex_clustering(g, 1.5, SimplificationContraction::Quadric);
    expect_checksums(quadric.vertices, 17, 1386.2222632722085, 229.33984455398436, 1e-9);
    EXPECT_EQ(sorted_triangles(quadric), triangles);
}

TEST(MeshProcessingReference, PoissonDiskSpacingMatchesOpen3D) {
    // Open3D over seeds 0..9, 400 points on sphere(1,20): mean nearest-neighbour distance 0.15028701262040575
    // (spread across seeds 0.00052) for Poisson disk, 0.08916640029482907 for uniform sampling.
    const TriangleMesh s = uv_sphere(1, 20);
    double poisson = 0, uniform = 0;
    for (uint64_t seed = 0; seed < 10; ++seed) {
        poisson += mean_nearest_neighbour_distance(sample_points_poisson_disk(s, 400, 5, false, seed)) / 10;
        uniform += mean_nearest_neighbour_distance(sample_points_uniformly(s, 400, false, seed)) / 10;
    }
    // o3d runs the elimination as Open3D's source reads (radius r_max, weights (1 - max(d, r_min) / r_max)^8,
    // heaviest first); rerunning that source's steps in Python over Open3D's own KD-tree gives 0.142 here,
    // as o3d does, while the 0.20 wheel gives 0.150: hence 6 % rather than a seed-spread tolerance. Uniform
    // sampling, at 0.089, is far outside it.
    EXPECT_NEAR(poisson, 0.15028701262040575, 0.06 * 0.15028701262040575);
    EXPECT_GT(poisson, 1.5 * uniform);
    EXPECT_NEAR(uniform, 0.08916640029482907, 0.004);
}
