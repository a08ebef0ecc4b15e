// SPDX-License-Identifier: MIT
// Mesh queries and repairs: non-manifold edges and vertices, self-intersecting triangle pairs, mesh-mesh
// intersection, triangle orientation, sharpening, and the ellipsoid / oriented-box / oriented-ellipsoid
// meshes. Reference values come from Open3D 0.20 (tools/reference/record_mesh_queries.py, same inputs).
#include <Eigen/Geometry>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>
#include <vector>

#include "o3d/geometry/mesh_intersection_queries.h"
#include "o3d/geometry/mesh_non_manifold.h"
#include "o3d/geometry/mesh_orientation.h"
#include "o3d/geometry/mesh_primitives.h"
#include "o3d/geometry/mesh_primitives_bounded.h"
#include "o3d/geometry/mesh_self_intersection.h"
#include "o3d/geometry/mesh_sharpen.h"
#include "o3d/geometry/mesh_topology.h"
#include "o3d/utility/error.h"
#include "o3d/utility/parallel.h"
#include "triangle_mesh_test_util.h"

using namespace o3d::geometry;
using o3d::test::fingerprint;
using V = Eigen::Vector3d;
using E = Eigen::Vector2i;
using Edges = std::vector<E>;

namespace {

TriangleMesh make(std::vector<V> v, std::vector<Eigen::Vector3i> t) {
    TriangleMesh m;
    m.vertices = std::move(v);
    m.triangles = std::move(t);
    return m;
}

/// Three triangles on the edge (0, 1).
TriangleMesh fan() {
    return make({{0, 0, 0}, {1, 0, 0}, {0.5, 1, 0}, {0.5, -1, 0}, {0.5, 0, 1}}, {{0, 1, 2}, {1, 0, 3}, {0, 1, 4}});
}

/// An open strip of 4 triangles over a 3 x 2 grid.
TriangleMesh strip() {
    return make({{0, 0, 0}, {1, 0, 0}, {2, 0, 0}, {0, 1, 0}, {1, 1, 0}, {2, 1, 0}},
                {{0, 1, 4}, {0, 4, 3}, {1, 2, 5}, {1, 5, 4}});
}

/// Two closed tetrahedra sharing vertex 0.
TriangleMesh bow_tie() {
    return make({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {-1, 0, 0}, {0, -1, 0}, {0, 0, -1}},
                {{0, 2, 1}, {0, 1, 3}, {0, 3, 2}, {1, 2, 3}, {0, 5, 4}, {0, 4, 6}, {0, 6, 5}, {4, 5, 6}});
}

/// The rotation of record_mesh_queries.py: get_rotation_matrix_from_xyz([0.3, -0.2, 0.7]).
Eigen::Matrix3d rotation() {
    Eigen::Matrix3d R;
    R << 0.7495962650805187, -0.6313762241158432, -0.19866933079506122, 0.5705401655735413, 0.76850418681858,
        -0.28962947762551555, 0.33554337848429205, 0.10375634179910923, 0.9362933635841992;
    return R;
}

/// The unit box, and a 0.8 x 0.9 x 1.1 box turned and moved into it (vertices as Open3D computed them).
TriangleMesh crossing_box() {
    TriangleMesh b = create_box(0.8, 0.9, 1.1);
    b.vertices = {{0.37, 0.21, 0.43},
                  {1.1501362617614528, 0.33303359839117136, 0.30252393655361765},
                  {0.5885362638745674, -0.10859242538806715, 1.4599226999426191},
                  {1.3686725256360202, 0.014441173003104213, 1.3324466364962368},
                  {0.28194094449346985, 1.060232237395405, 0.7116926432069212},
                  {1.0620772062549226, 1.1832658357865762, 0.5842165797605388},
                  {0.5004772083680372, 0.7416398120073378, 1.7416153431495403},
                  {1.28061347012949, 0.864673410398509, 1.614139279703158}};
    return b;
}

TriangleMesh merged(const TriangleMesh& a, const TriangleMesh& b) {
    TriangleMesh m = a;
    const int n = static_cast<int>(a.vertices.size());
    m.vertices.insert(m.vertices.end(), b.vertices.begin(), b.vertices.end());
    for (const auto& t : b.triangles) m.triangles.emplace_back(t + Eigen::Vector3i::Constant(n));
    return m;
}

std::vector<E> brute_force_pairs(const TriangleMesh& m) {
    std::vector<E> out;
    for (size_t i = 0; i < m.triangles.size(); ++i)
        for (size_t j = i + 1; j < m.triangles.size(); ++j) {
            const Eigen::Vector3i &a = m.triangles[i], &b = m.triangles[j];
            bool shared = false;
            for (int p = 0; p < 3; ++p)
                for (int q = 0; q < 3; ++q) shared = shared || a(p) == b(q);
            const auto& v = m.vertices;
            if (!shared && triangles_intersect(v[a(0)], v[a(1)], v[a(2)], v[b(0)], v[b(1)], v[b(2)]))
                out.emplace_back(static_cast<int>(i), static_cast<int>(j));
        }
    return out;
}

/// Whether two triangles list the same corners in the same cyclic order.
bool same_winding(const Eigen::Vector3i& a, const Eigen::Vector3i& b) {
    for (int r = 0; r < 3; ++r)
        if (a(0) == b(r) && a(1) == b((r + 1) % 3) && a(2) == b((r + 2) % 3)) return true;
    return false;
}

void expect_near(const std::vector<V>& got, const std::vector<V>& want, double tol) {
    ASSERT_EQ(got.size(), want.size());
    for (size_t i = 0; i < got.size(); ++i) EXPECT_LE((got[i] - want[i]).cwiseAbs().maxCoeff(), tol) << "row " << i;
}

}  // namespace

// --- non-manifold edges and vertices ---------------------------------------------------------------

TEST(NonManifold, FanOfThreeOnOneEdge) {
    const TriangleMesh m = fan();
    // Open3D 0.20 (sorted): [(0, 1)] and, without boundary, every edge.
    EXPECT_EQ(non_manifold_edges(m, true), (Edges{{0, 1}}));
    EXPECT_EQ(non_manifold_edges(m, false), (Edges{{0, 1}, {0, 2}, {0, 3}, {0, 4}, {1, 2}, {1, 3}, {1, 4}}));
    EXPECT_TRUE(non_manifold_vertices(m).empty());  // Open3D: [] (each link is a star about the other end)
    EXPECT_FALSE(is_edge_manifold(m, true));
}

TEST(NonManifold, OpenStripBoundary) {
    const TriangleMesh m = strip();
    EXPECT_TRUE(non_manifold_edges(m, true).empty());
    // Open3D 0.20: the six boundary edges.
    EXPECT_EQ(non_manifold_edges(m, false), (Edges{{0, 1}, {0, 3}, {1, 2}, {2, 5}, {3, 4}, {4, 5}}));
    EXPECT_TRUE(non_manifold_vertices(m).empty());
}

TEST(NonManifold, BowTieVertex) {
    const TriangleMesh m = bow_tie();
    EXPECT_EQ(non_manifold_vertices(m), std::vector<int>{0});  // Open3D 0.20: [0]
    EXPECT_TRUE(non_manifold_edges(m, false).empty());
    EXPECT_FALSE(is_vertex_manifold(m));
}

TEST(NonManifold, AgreesWithTopologyQueries) {
    TriangleMesh fin = o3d::test::unit_cube();
    fin.vertices.emplace_back(0.5, -0.1, 0.0);
    fin.triangles.emplace_back(0, 1, 8);
    TriangleMesh doubled = o3d::test::corner_tetrahedron();
    doubled.triangles.emplace_back(0, 0, 1);  // a repeated vertex counts twice on its doubled edge
    for (const TriangleMesh& m : {fan(), strip(), bow_tie(), o3d::test::unit_cube(), fin, doubled,
                                  create_mobius(20, 3), merged(bow_tie(), fan())}) {
        for (const bool allow : {true, false})
            EXPECT_EQ(non_manifold_edges(m, allow).empty(), is_edge_manifold(m, allow));
        EXPECT_EQ(non_manifold_vertices(m).empty(), is_vertex_manifold(m));
    }
    EXPECT_EQ(non_manifold_edges(fin), (Edges{{0, 1}}));
}

TEST(NonManifold, ManyVerticesSameForAnyThreadCount) {
    // Bow ties side by side: past the parallel threshold, every shared tip is reported, ascending.
    const TriangleMesh b = bow_tie();
    TriangleMesh m;
    for (int k = 0; k < 3000; ++k) {
        for (const V& v : b.vertices) m.vertices.push_back(v + V(3.0 * k, 0, 0));
        for (const auto& t : b.triangles) m.triangles.emplace_back(t + Eigen::Vector3i::Constant(7 * k));
    }
    std::vector<int> want;
    for (int k = 0; k < 3000; ++k) want.push_back(7 * k);
    o3d::utility::set_default_num_threads(1);
    EXPECT_EQ(non_manifold_vertices(m), want);
    o3d::utility::set_default_num_threads(2);
    EXPECT_EQ(non_manifold_vertices(m), want);
    o3d::utility::set_default_num_threads(0);
}

// --- self-intersections and mesh-mesh intersection ------------------------------------------------------

TEST(IntersectionQueries, TwoCrossingTriangles) {
    const TriangleMesh m = make({{0, 0, 0}, {2, 0, 0}, {0, 2, 0}, {0.5, 0.5, -1}, {0.5, 0.5, 1}, {1.5, -0.5, 0.2},
                                 {5, 5, 5}, {6, 5, 5}, {5, 6, 5}},
                                {{0, 1, 2}, {3, 4, 5}, {6, 7, 8}});
    EXPECT_EQ(self_intersecting_triangles(m), (Edges{{0, 1}}));  // Open3D 0.20: [[0, 1]]
    EXPECT_TRUE(is_self_intersecting(m));
}

TEST(IntersectionQueries, CrossingBoxes) {
    const TriangleMesh a = create_box(), b = crossing_box();
    const TriangleMesh m = merged(a, b);
    // Open3D 0.20's get_self_intersecting_triangles on the same mesh.
    const Edges want{{0, 23}, {1, 12}, {1, 13}, {1, 14}, {1, 15}, {1, 22}, {1, 23}, {6, 22}, {6, 23}, {7, 16},
                     {7, 17}, {7, 22}, {8, 14}, {8, 16}, {8, 17}, {9, 12}, {9, 13}, {9, 14}, {9, 15}};
    EXPECT_EQ(self_intersecting_triangles(m), want);
    EXPECT_EQ(brute_force_pairs(m), want);
    EXPECT_TRUE(meshes_intersect(a, b));  // Open3D: True
    EXPECT_TRUE(meshes_intersect(b, a));
    EXPECT_TRUE(self_intersecting_triangles(a).empty());
}

TEST(IntersectionQueries, Spheres) {
    // Open3D 0.20 (create_sphere(r, 10)): overlapping True, apart False, one inside the other False.
    const TriangleMesh s = create_sphere(1.0, 10);
    auto moved = [](double radius, double x) {
        TriangleMesh o = create_sphere(radius, 10);
        for (V& v : o.vertices) v.x() += x;
        return o;
    };
    EXPECT_TRUE(meshes_intersect(s, moved(1.0, 1.5)));
    EXPECT_TRUE(meshes_intersect(moved(1.0, 1.5), s));
    EXPECT_FALSE(meshes_intersect(s, moved(1.0, 2.5)));
    EXPECT_FALSE(meshes_intersect(moved(0.3, 0.1), s));
    EXPECT_FALSE(meshes_intersect(s, moved(0.3, 0.1)));
    EXPECT_TRUE(self_intersecting_triangles(s).empty());
    // Two copies of one sphere in one mesh: every triangle meets its copy and the copy's neighbours.
    const TriangleMesh twice = merged(s, s);
    const Edges pairs = self_intersecting_triangles(twice);
    EXPECT_EQ(pairs, brute_force_pairs(twice));
    EXPECT_GE(pairs.size(), s.triangles.size());
}

TEST(IntersectionQueries, RandomSoupMatchesBruteForceForAnyThreadCount) {
    std::mt19937 rng(7);
    std::uniform_real_distribution<double> pos(0, 10), off(-0.6, 0.6);
    TriangleMesh m;
    for (int t = 0; t < 600; ++t) {
        const V c(pos(rng), pos(rng), pos(rng));
        const int n = static_cast<int>(m.vertices.size());
        for (int k = 0; k < 3; ++k) m.vertices.push_back(c + V(off(rng), off(rng), off(rng)));
        m.triangles.emplace_back(n, n + 1, n + 2);
    }
    const Edges want = brute_force_pairs(m);
    ASSERT_GT(want.size(), 10u);
    o3d::utility::set_default_num_threads(1);
    EXPECT_EQ(self_intersecting_triangles(m), want);
    o3d::utility::set_default_num_threads(2);
    EXPECT_EQ(self_intersecting_triangles(m), want);
    o3d::utility::set_default_num_threads(0);
    // Split into two meshes: they intersect exactly when some pair straddles the split.
    TriangleMesh first = m, second = m;
    first.triangles.resize(300);
    second.triangles.erase(second.triangles.begin(), second.triangles.begin() + 300);
    const bool straddles = std::any_of(want.begin(), want.end(), [](const E& p) { return p(0) < 300 && p(1) >= 300; });
    EXPECT_EQ(meshes_intersect(first, second), straddles);
}

TEST(IntersectionQueries, DegenerateAndNonFiniteTrianglesIgnored) {
    // The first triangle crosses the second but is collinear; the third has a NaN corner.
    const double nan = std::numeric_limits<double>::quiet_NaN();
    const TriangleMesh m = make({{0, 0, 0}, {1, 1, 1}, {2, 2, 2}, {1, 0, 1}, {1, 2, 1}, {1, 1, -1}, {nan, 0, 0}},
                                {{0, 1, 2}, {3, 4, 5}, {6, 3, 4}});
    EXPECT_TRUE(self_intersecting_triangles(m).empty());
    EXPECT_FALSE(is_self_intersecting(m));
}

// --- orientation --------------------------------------------------------------------------------------

TEST(Orientation, BoxWithFlippedTriangles) {
    const TriangleMesh box = create_box(1, 2, 3);
    TriangleMesh m = box;
    for (const int t : {1, 4, 7, 10}) std::swap(m.triangles[t](1), m.triangles[t](2));
    m.triangle_normals.assign(12, V(0, 0, 1));
    for (int t = 0; t < 12; ++t) m.triangle_uvs.insert(m.triangle_uvs.end(), {{t, 0}, {t, 1}, {t, 2}});
    EXPECT_TRUE(is_orientable(m));
    ASSERT_TRUE(orient_triangles(m));
    // Triangle 0 keeps its winding, so the box is outward again: the original triangles, corners turned back.
    EXPECT_EQ(m.triangles, box.triangles);
    // Open3D 0.20 lists the same windings (its triangle 1 as (7, 4, 6), a rotation of (4, 6, 7)).
    const std::vector<Eigen::Vector3i> open3d = {{4, 7, 5}, {7, 4, 6}, {0, 2, 4}, {2, 6, 4}, {1, 2, 0}, {1, 3, 2},
                                                 {1, 5, 7}, {7, 3, 1}, {2, 3, 7}, {2, 7, 6}, {0, 4, 1}, {1, 4, 5}};
    for (int t = 0; t < 12; ++t) EXPECT_TRUE(same_winding(m.triangles[t], open3d[t])) << t;
    EXPECT_NEAR(volume(m), 6.0, 1e-12);  // Open3D: 6.0
    for (int t = 0; t < 12; ++t) {
        const bool turned = t == 1 || t == 4 || t == 7 || t == 10;
        EXPECT_EQ(m.triangle_normals[t], V(0, 0, turned ? -1 : 1));
        EXPECT_EQ(m.triangle_uvs[3 * t + 1], Eigen::Vector2d(t, turned ? 2 : 1));
    }
    // Outward: the signed volume of the oriented box is positive.
    double six = 0;
    for (const auto& t : m.triangles) six += m.vertices[t(0)].dot(m.vertices[t(1)].cross(m.vertices[t(2)]));
    EXPECT_NEAR(six / 6, 6.0, 1e-12);
}

TEST(Orientation, FirstTriangleOfEachComponentKeepsItsWinding) {
    // A torus with random flips, then a second torus stored inside out: each follows its own first triangle.
    TriangleMesh a = o3d::test::grid_torus(12, 8), b = o3d::test::grid_torus(6, 5);
    for (auto& t : b.triangles) std::swap(t(0), t(1));
    TriangleMesh m = merged(a, b);
    const TriangleMesh original = m;
    std::mt19937 rng(3);
    for (size_t t = 1; t < m.triangles.size(); ++t)
        if (t != a.triangles.size() && rng() % 3 == 0) std::swap(m.triangles[t](0), m.triangles[t](2));
    ASSERT_TRUE(orient_triangles(m));
    ASSERT_EQ(m.triangles.size(), original.triangles.size());
    for (size_t t = 0; t < m.triangles.size(); ++t) EXPECT_TRUE(same_winding(m.triangles[t], original.triangles[t]));
    EXPECT_TRUE(is_orientable(m));
}

TEST(Orientation, MoebiusIsNotOrientableAndStaysUnchanged) {
    TriangleMesh m = create_mobius();
    m.triangle_normals.assign(m.triangles.size(), V(1, 0, 0));
    const TriangleMesh before = m;
    EXPECT_FALSE(is_orientable(m));
    EXPECT_FALSE(orient_triangles(m));  // Open3D 0.20: False
    EXPECT_EQ(m.triangles, before.triangles);
    EXPECT_EQ(m.triangle_normals, before.triangle_normals);
    // An edge with three triangles cannot be oriented either.
    TriangleMesh f = fan();
    EXPECT_FALSE(orient_triangles(f));
    EXPECT_EQ(f.triangles, fan().triangles);
}

// --- sharpening -------------------------------------------------------------------------------------------

namespace {

TriangleMesh two_triangles() {
    TriangleMesh m = make({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {1, 1, 0.5}}, {{0, 1, 2}, {1, 3, 2}});
    m.vertex_colors = {{0.1, 0.2, 0.3}, {0.9, 0.5, 0.5}, {0.5, 0.5, 0.5}, {0.2, 0.2, 0.9}};
    m.vertex_normals = {{0, 0, 1}, {0, 0.1, 1}, {0.1, 0, 1}, {0, 0, 1}};
    return m;
}

}  // namespace

TEST(Sharpen, OneIterationByHandAndOpen3D) {
    const TriangleMesh m = two_triangles();
    const TriangleMesh s = filter_sharpen(m, 1, 1.0, FilterScope::All);
    // By hand: vertex 0 has neighbours 1, 2: 0 + 1 * (2 * 0 - (1,0,0) - (0,1,0)) = (-1, -1, 0);
    // vertex 1 has neighbours 0, 2, 3: (1,0,0) + 3 (1,0,0) - (0,0,0) - (0,1,0) - (1,1,0.5) = (3, -2, -0.5).
    // Open3D 0.20 gives the same, and leaves colors outside [0, 1].
    expect_near(s.vertices, {{-1, -1, 0}, {3, -2, -0.5}, {-2, 3, -0.5}, {2, 2, 1.5}}, 1e-15);
    expect_near(s.vertex_normals, {{-0.1, -0.1, 1}, {-0.1, 0.4, 1}, {0.4, -0.1, 1}, {-0.1, -0.1, 1}}, 1e-15);
    expect_near(s.vertex_colors, {{-1.1, -0.4, -0.1}, {2.8, 1.1, 0.3}, {0.8, 1.1, 0.3}, {-0.8, -0.4, 1.7}}, 1e-15);
    EXPECT_EQ(s.triangles, m.triangles);
}

TEST(Sharpen, TwoIterationsMatchOpen3D) {
    const TriangleMesh s = filter_sharpen(two_triangles(), 2, 0.5, FilterScope::All);
    expect_near(s.vertices, {{-1.5, -1.5, 0.25}, {5, -4, -1}, {-4, 5, -1}, {2.5, 2.5, 2.25}}, 1e-14);
    expect_near(s.vertex_normals, {{-0.2, -0.2, 1}, {-0.2, 0.7, 1}, {0.7, -0.2, 1}, {-0.2, -0.2, 1}}, 1e-14);
    expect_near(s.vertex_colors, {{-2.25, -1, -0.2}, {4.7, 1.7, 0.1}, {1.1, 1.7, 0.1}, {-1.85, -1, 2.2}}, 1e-14);
}

TEST(Sharpen, SphereMatchesOpen3D) {
    // Open3D 0.20: create_sphere(1, 6).filter_sharpen(3, 0.1).
    const TriangleMesh s = filter_sharpen(create_sphere(1.0, 6), 3, 0.1, FilterScope::All);
    EXPECT_NEAR(fingerprint(s.vertices), -2666.680326594121, 1e-9);
    expect_near({s.vertices[5]}, {{-0.1759893451431882, 0.4432227094365421, 1.0220525092997585}}, 1e-13);
}

TEST(Sharpen, ScopeZeroIterationsAndTriangleNormals) {
    TriangleMesh m = two_triangles();
    m.triangle_normals = {{0, 0, 1}, {0, 0, 1}};
    const TriangleMesh colors_only = filter_sharpen(m, 2, 0.5, FilterScope::Color);
    EXPECT_EQ(colors_only.vertices, m.vertices);
    EXPECT_EQ(colors_only.vertex_normals, m.vertex_normals);
    EXPECT_EQ(colors_only.triangle_normals, m.triangle_normals);
    expect_near(colors_only.vertex_colors, filter_sharpen(m, 2, 0.5, FilterScope::All).vertex_colors, 0);
    const TriangleMesh positions = filter_sharpen(m, 1, 1.0, FilterScope::Vertex);
    EXPECT_EQ(positions.vertex_colors, m.vertex_colors);
    // Triangle normals follow the moved vertices: triangle 0 is now (-1,-1,0), (3,-2,-0.5), (-2,3,-0.5).
    const V n = (positions.vertices[1] - positions.vertices[0]).cross(positions.vertices[2] - positions.vertices[0]);
    expect_near({positions.triangle_normals[0]}, {n.normalized()}, 1e-15);
    const TriangleMesh same = filter_sharpen(m, 0, 1.0, FilterScope::All);
    EXPECT_EQ(same.vertices, m.vertices);
    EXPECT_EQ(same.vertex_colors, m.vertex_colors);
    // A lone vertex has no neighbours and stays.
    TriangleMesh lone = m;
    lone.vertices.emplace_back(7, 7, 7);
    EXPECT_EQ(filter_sharpen(lone, 3, 1.0, FilterScope::Vertex).vertices.back(), V(7, 7, 7));
    // The same for any thread count.
    const TriangleMesh big = create_sphere(1.0, 40);
    EXPECT_EQ(filter_sharpen(big, 2, 0.3, FilterScope::All, 1).vertices,
              filter_sharpen(big, 2, 0.3, FilterScope::All, 2).vertices);
}

// --- ellipsoid and bounded-volume meshes --------------------------------------------------------------

TEST(BoundedPrimitives, EllipsoidMatchesOpen3D) {
    const TriangleMesh e = create_ellipsoid(1.0, 2.0, 3.0, 3, true);
    // Open3D 0.20: create_ellipsoid(1, 2, 3, 3, True).
    const std::vector<V> want = {{0.0, 0.0, 3.0},
                                 {0.0, 0.0, -3.0},
                                 {0.8660254037844386, 0.0, 1.5000000000000004},
                                 {0.4330127018922194, 1.4999999999999998, 1.5000000000000004},
                                 {-0.43301270189221913, 1.5, 1.5000000000000004},
                                 {-0.8660254037844386, 2.1211504774498136e-16, 1.5000000000000004},
                                 {-0.4330127018922197, -1.4999999999999993, 1.5000000000000004},
                                 {0.43301270189221874, -1.5000000000000007, 1.5000000000000004},
                                 {0.8660254037844387, 0.0, -1.4999999999999993},
                                 {0.43301270189221946, 1.5, -1.4999999999999993},
                                 {-0.4330127018922192, 1.5000000000000002, -1.4999999999999993},
                                 {-0.8660254037844387, 2.1211504774498138e-16, -1.4999999999999993},
                                 {-0.43301270189221974, -1.4999999999999996, -1.4999999999999993},
                                 {0.4330127018922188, -1.5000000000000009, -1.4999999999999993}};
    expect_near(e.vertices, want, 1e-15);
    const std::vector<Eigen::Vector3i> tris = {
        {0, 2, 3},   {1, 9, 8},  {0, 3, 4},  {1, 10, 9}, {0, 4, 5},  {1, 11, 10}, {0, 5, 6},  {1, 12, 11},
        {0, 6, 7},   {1, 13, 12}, {0, 7, 2}, {1, 8, 13}, {8, 3, 2},  {8, 9, 3},   {9, 4, 3},  {9, 10, 4},
        {10, 5, 4},  {10, 11, 5}, {11, 6, 5}, {11, 12, 6}, {12, 7, 6}, {12, 13, 7}, {13, 2, 7}, {13, 8, 2}};
    EXPECT_EQ(e.triangles, tris);
    ASSERT_EQ(e.triangle_uvs.size(), 72u);
    EXPECT_DOUBLE_EQ(fingerprint(e.triangle_uvs), 5673.0);
    EXPECT_EQ(e.triangle_uvs[0], Eigen::Vector2d(0.0, 1.0 / 12));
    EXPECT_EQ(e.triangle_uvs[4], Eigen::Vector2d(2.0 / 3, 1.0 / 6));
    EXPECT_EQ(e.triangle_uvs[70], Eigen::Vector2d(2.0 / 3, 1.0));  // the seam
    // Default resolution: counts and fingerprints of Open3D 0.20's create_ellipsoid(0.5, 1.5, 0.7, 20, True).
    const TriangleMesh d = create_ellipsoid(0.5, 1.5, 0.7, 20, true);
    EXPECT_EQ(d.vertices.size(), 762u);
    EXPECT_EQ(d.triangles.size(), 1520u);
    EXPECT_NEAR(fingerprint(d.vertices), -254225.60681381682, 1e-8);
    EXPECT_DOUBLE_EQ(fingerprint(d.triangles), 5083286400.0);
    EXPECT_NEAR(fingerprint(d.triangle_uvs), 23769276.0, 1e-6);  // numpy sums in another order
    EXPECT_TRUE(create_ellipsoid(1, 2, 3, 5).triangle_uvs.empty());
}

TEST(BoundedPrimitives, EllipsoidOnTheSurfaceAndClosed) {
    const double a = 0.5, b = 1.5, c = 0.7;
    const TriangleMesh e = create_ellipsoid(a, b, c, 12);
    EXPECT_EQ(e.vertices.size(), 2u + 2 * 12 * 11);
    EXPECT_EQ(e.triangles.size(), 4u * 12 * 11);
    for (const V& v : e.vertices)
        EXPECT_NEAR(std::pow(v.x() / a, 2) + std::pow(v.y() / b, 2) + std::pow(v.z() / c, 2), 1, 1e-14);
    EXPECT_TRUE(is_watertight(e));
    EXPECT_TRUE(is_orientable(e));
    // Outward, and close to the ellipsoid's volume 4/3 pi abc from below.
    double six = 0;
    for (const auto& t : e.triangles) six += e.vertices[t(0)].dot(e.vertices[t(1)].cross(e.vertices[t(2)]));
    const double exact = 4.0 / 3.0 * M_PI * a * b * c;
    EXPECT_LT(six / 6, exact);
    EXPECT_GT(six / 6, 0.95 * exact);
    // Equal radii: Open3D's ellipsoid is its sphere, so counts and order match create_sphere.
    const TriangleMesh s = create_ellipsoid(2, 2, 2, 7), sphere = create_sphere(2, 7);
    EXPECT_EQ(s.triangles, sphere.triangles);
    expect_near(s.vertices, sphere.vertices, 4e-15);  // create_sphere rounds its angles differently
}

TEST(BoundedPrimitives, OrientedBoxMeshMatchesOpen3D) {
    OrientedBoundingBox box;
    box.center = V(1.0, -2.0, 0.5);
    box.R = rotation();
    box.extent = V(2.0, 1.0, 0.5);
    const TriangleMesh m = mesh_from_oriented_bounding_box(box, V(1.0, 1.5, 2.0), true);
    // Open3D 0.20: create_from_oriented_bounding_box(obox, [1, 1.5, 2], True).
    expect_near(m.vertices,
                {{0.8232705684038943, -3.0021035668747182, -0.38150731662572357},
                 {2.3224630985649317, -1.861023235727636, 0.28957944034286054},
                 {0.624601237608833, -3.291733044500234, 0.5547860469584757},
                 {2.1237937677698704, -2.1506527133531517, 1.2258728039270599},
                 {-0.12379376776987039, -1.8493472866468486, -0.22587280392705977},
                 {1.375398762391167, -0.708266955499766, 0.44521395304152434},
                 {-0.3224630985649317, -2.138976764272364, 0.7104205596571395},
                 {1.1767294315961057, -0.9978964331252818, 1.3815073166257235}},
                1e-14);
    EXPECT_EQ(m.triangles, create_box().triangles);
    ASSERT_EQ(m.triangle_uvs.size(), 36u);
    EXPECT_DOUBLE_EQ(fingerprint(m.triangle_uvs), 1161.0);
    // With scale 1 the vertices are the box's corners.
    const TriangleMesh plain = mesh_from_oriented_bounding_box(box);
    const auto corners = box_points(box);
    for (const V& v : plain.vertices) {
        double nearest = INFINITY;
        for (const V& c : corners) nearest = std::min(nearest, (v - c).norm());
        EXPECT_LT(nearest, 1e-14);
    }
    EXPECT_TRUE(plain.triangle_uvs.empty());
    EXPECT_NEAR(volume(plain), 1.0, 1e-12);
}

TEST(BoundedPrimitives, OrientedEllipsoidMeshMatchesOpen3D) {
    OrientedBoundingEllipsoid el;
    el.center = V(1.0, 2.0, 3.0);
    el.R = rotation();
    el.radii = V(0.5, 1.0, 2.0);
    const TriangleMesh m = mesh_from_oriented_bounding_ellipsoid(el, V(2.0, 1.0, 0.5), 4);
    ASSERT_EQ(m.vertices.size(), 26u);  // Open3D 0.20: 26 vertices, 48 triangles, white, no UVs
    EXPECT_EQ(m.triangles.size(), 48u);
    EXPECT_TRUE(m.triangle_uvs.empty());
    ASSERT_EQ(m.vertex_colors.size(), 26u);
    for (const V& c : m.vertex_colors) EXPECT_EQ(c, V(1, 1, 1));
    const std::vector<V> head = {{0.8013306692049388, 1.7103705223744845, 3.9362933635841992},
                                 {1.1986693307950613, 2.2896294776255157, 2.0637066364158008},
                                 {1.3895641711715623, 2.1986338523558273, 3.8993243848788364},
                                 {0.9186295894633566, 2.464723208535541, 3.8817092467120498},
                                 {0.4130691594287488, 2.338615554209152, 3.735426199447608},
                                 {0.1690333243828379, 1.894183042962, 3.5461658682277575}};
    expect_near(std::vector<V>(m.vertices.begin(), m.vertices.begin() + 6), head, 1e-14);
    expect_near({m.vertices[25]}, {{1.830966675617162, 2.105816957038, 2.4538341317722425}}, 1e-14);
    // Every vertex on the scaled ellipsoid: |R^T (v - c) / (radii * scale)| = 1.
    const V radii(1.0, 1.0, 1.0);
    for (const V& v : m.vertices)
        EXPECT_NEAR((el.R.transpose() * (v - el.center)).cwiseQuotient(radii).norm(), 1.0, 1e-14);
}

// --- bad input ------------------------------------------------------------------------------------------

TEST(MeshQueriesBadInput, OutOfRangeTrianglesThrow) {
    TriangleMesh bad = fan();
    bad.triangles.emplace_back(0, 1, 5);
    EXPECT_THROW(non_manifold_edges(bad), o3d::InvalidArgument);
    EXPECT_THROW(non_manifold_vertices(bad), o3d::InvalidArgument);
    EXPECT_THROW(self_intersecting_triangles(bad), o3d::InvalidArgument);
    EXPECT_THROW(meshes_intersect(bad, fan()), o3d::InvalidArgument);
    EXPECT_THROW(meshes_intersect(fan(), bad), o3d::InvalidArgument);
    bad.triangles.back() = Eigen::Vector3i(-1, 0, 1);
    const TriangleMesh before = bad;
    EXPECT_THROW(orient_triangles(bad), o3d::InvalidArgument);
    EXPECT_EQ(bad.triangles, before.triangles);
    EXPECT_THROW(filter_sharpen(bad, 1, 1.0, FilterScope::All), o3d::InvalidArgument);
}

TEST(MeshQueriesBadInput, EmptyMeshes) {
    const TriangleMesh empty;
    EXPECT_TRUE(non_manifold_edges(empty, false).empty());
    EXPECT_TRUE(non_manifold_vertices(empty).empty());
    EXPECT_TRUE(self_intersecting_triangles(empty).empty());
    EXPECT_FALSE(meshes_intersect(empty, fan()));
    EXPECT_FALSE(meshes_intersect(fan(), empty));
    TriangleMesh e = empty;
    EXPECT_TRUE(orient_triangles(e));
    // Sharpening follows the smoothing filters: a mesh without vertices is an error.
    EXPECT_THROW(filter_sharpen(empty, 1, 1.0, FilterScope::All), o3d::InvalidArgument);
    // Vertices without triangles: nothing to report, nothing moves.
    const TriangleMesh points = make({{0, 0, 0}, {1, 2, 3}}, {});
    EXPECT_TRUE(non_manifold_vertices(points).empty());
    EXPECT_EQ(filter_sharpen(points, 2, 1.0, FilterScope::All).vertices, points.vertices);
}

TEST(MeshQueriesBadInput, BadParametersThrow) {
    const TriangleMesh m = two_triangles();
    EXPECT_THROW(filter_sharpen(m, -1, 1.0, FilterScope::All), o3d::InvalidArgument);
    EXPECT_THROW(filter_sharpen(m, 1, NAN, FilterScope::All), o3d::InvalidArgument);
    EXPECT_THROW(filter_sharpen(m, 1, INFINITY, FilterScope::All), o3d::InvalidArgument);
    EXPECT_THROW(filter_sharpen(m, 1, 1.0, static_cast<FilterScope>(7)), o3d::InvalidArgument);
    for (const double bad : {0.0, -1.0, double(NAN), double(INFINITY)}) {
        EXPECT_THROW(create_ellipsoid(bad, 1, 1), o3d::InvalidArgument);
        EXPECT_THROW(create_ellipsoid(1, bad, 1), o3d::InvalidArgument);
        EXPECT_THROW(create_ellipsoid(1, 1, bad), o3d::InvalidArgument);
    }
    for (const int bad : {-5, 0, 1}) EXPECT_THROW(create_ellipsoid(1, 1, 1, bad), o3d::InvalidArgument);
    EXPECT_THROW(create_ellipsoid(1, 1, 1, 40000), o3d::InvalidArgument);  // past int32 vertex indices
    EXPECT_EQ(create_ellipsoid(1, 1, 1, 2).vertices.size(), 6u);

    OrientedBoundingBox box;
    box.extent = V(1, 2, 3);
    EXPECT_THROW(mesh_from_oriented_bounding_box(box, V(1, -1, 1)), o3d::InvalidArgument);
    EXPECT_THROW(mesh_from_oriented_bounding_box(box, V(1, NAN, 1)), o3d::InvalidArgument);
    box.extent = V(1, 0, 3);
    EXPECT_THROW(mesh_from_oriented_bounding_box(box), o3d::InvalidArgument);
    box.extent = V(1, 2, 3);
    box.R(0, 1) = 0.5;
    EXPECT_THROW(mesh_from_oriented_bounding_box(box), o3d::InvalidArgument);

    OrientedBoundingEllipsoid el;
    el.radii = V(1, 2, 3);
    EXPECT_EQ(mesh_from_oriented_bounding_ellipsoid(el, V(1, 1, 1), 5).vertices.size(), 42u);
    EXPECT_THROW(mesh_from_oriented_bounding_ellipsoid(el, V(1, 1, 1), 0), o3d::InvalidArgument);
    EXPECT_THROW(mesh_from_oriented_bounding_ellipsoid(el, V(0, 1, 1)), o3d::InvalidArgument);
    el.radii = V(1, -2, 3);
    EXPECT_THROW(mesh_from_oriented_bounding_ellipsoid(el), o3d::InvalidArgument);
    el.radii = V(1, 2, 3);
    el.center = V(NAN, 0, 0);
    EXPECT_THROW(mesh_from_oriented_bounding_ellipsoid(el), o3d::InvalidArgument);
    el.center = V(0, 0, 0);
    el.R = 2 * Eigen::Matrix3d::Identity();
    EXPECT_THROW(mesh_from_oriented_bounding_ellipsoid(el), o3d::InvalidArgument);
}
