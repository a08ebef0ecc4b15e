// SPDX-License-Identifier: MIT
// TetraMesh: Delaunay tetrahedralization (empty circumspheres, volume = hull volume, Open3D 0.20 counts),
// marching-tetrahedra extraction of linear fields, the basic clean-up ops, and the bad-input errors.
#include "o3d/geometry/tetra_mesh.h"

#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <map>
#include <random>

#include "delaunay_test_points.h"
#include "o3d/geometry/convex_hull.h"
#include "o3d/geometry/mesh_topology.h"
#include "o3d/geometry/tetra_mesh_ops.h"
#include "o3d/io/triangle_mesh_io.h"
#include "o3d/utility/error.h"
#include "test_data.h"

using namespace o3d::geometry;

namespace {

double tetra_det(const TetraMesh& m, const Eigen::Vector4i& t) {
    const Eigen::Vector3d& a = m.vertices[t(0)];
    return (m.vertices[t(1)] - a).cross(m.vertices[t(2)] - a).dot(m.vertices[t(3)] - a);
}

double total_volume(const TetraMesh& m) {
    double v = 0.0;
    for (const auto& t : m.tetras) v += std::abs(tetra_det(m, t)) / 6.0;
    return v;
}

/// Circumcentre of a tetra, by solving 2 (p_i - a) . x = |p_i|^2 - |a|^2.
Eigen::Vector3d circumcentre(const TetraMesh& m, const Eigen::Vector4i& t) {
    Eigen::Matrix3d A;
    Eigen::Vector3d b;
    const Eigen::Vector3d& a = m.vertices[t(0)];
    for (int i = 0; i < 3; ++i) {
        const Eigen::Vector3d& p = m.vertices[t(i + 1)];
        A.row(i) = 2.0 * (p - a).transpose();
        b(i) = p.squaredNorm() - a.squaredNorm();
    }
    return A.fullPivLu().solve(b);
}

}  // namespace

TEST(TetraMesh, DelaunayCircumspheresAreEmpty) {
    const auto pts = o3d::test::ball_points(300, 1.0, 11);
    const TetraMeshFromPoints d = create_tetra_mesh_from_points(pts);
    ASSERT_EQ(d.mesh.vertices.size(), pts.size());  // every point of a generic set is a Delaunay vertex
    ASSERT_GT(d.mesh.tetras.size(), pts.size());
    for (size_t v = 0; v < d.point_map.size(); ++v) {
        EXPECT_EQ(d.mesh.vertices[v], pts[d.point_map[v]]);
        if (v > 0) {
            EXPECT_LT(d.point_map[v - 1], d.point_map[v]);  // ascending input order
        }
    }
    for (const auto& t : d.mesh.tetras) {
        ASSERT_GT(tetra_det(d.mesh, t), 0.0) << "tetra not positively oriented (or flat)";
        const Eigen::Vector3d c = circumcentre(d.mesh, t);
        const double r = (d.mesh.vertices[t(0)] - c).norm();
        for (const auto& p : pts) ASSERT_GE((p - c).norm(), r * (1.0 - 1e-9)) << "a point lies inside a circumsphere";
    }
}

TEST(TetraMesh, TetrasTileTheConvexHull) {
    const auto pts = o3d::test::ball_points(500, 2.0, 5);
    const TetraMeshFromPoints d = create_tetra_mesh_from_points(pts);
    const ConvexHull hull = compute_convex_hull(pts);
    EXPECT_NEAR(total_volume(d.mesh), volume(hull.mesh), 1e-9);
    // Every interior face is shared by two tetras; the faces in one tetra only are the hull's triangles.
    std::map<std::array<int, 3>, int> uses;
    for (const auto& t : d.mesh.tetras)
        for (int k = 0; k < 4; ++k) {
            std::array<int, 3> f{t((k + 1) % 4), t((k + 2) % 4), t((k + 3) % 4)};
            std::sort(f.begin(), f.end());
            ++uses[f];
        }
    size_t once = 0;
    for (const auto& [f, n] : uses) {
        EXPECT_LE(n, 2);
        once += n == 1;
    }
    EXPECT_EQ(once, hull.mesh.triangles.size());
}

TEST(TetraMesh, CubeCornersAreTetrahedralized) {
    // The 8 corners are cospherical: Open3D's Qhull options ("d Qbb Qt") reject them; "Qz" copes.
    std::vector<Eigen::Vector3d> pts;
    for (int i = 0; i < 8; ++i) pts.emplace_back(i & 1, (i >> 1) & 1, (i >> 2) & 1);
    const TetraMeshFromPoints d = create_tetra_mesh_from_points(pts);
    EXPECT_EQ(d.mesh.vertices.size(), 8u);
    EXPECT_NEAR(total_volume(d.mesh), 1.0, 1e-12);
    for (const auto& t : d.mesh.tetras) EXPECT_GE(tetra_det(d.mesh, t), 0.0);
}

TEST(TetraMesh, DuplicatePointsKeepOneVertex) {
    auto pts = o3d::test::ball_points(100, 1.0, 3);
    pts.push_back(pts[10]);
    pts.push_back(pts[20]);
    const TetraMeshFromPoints d = create_tetra_mesh_from_points(pts);
    EXPECT_EQ(d.mesh.vertices.size(), 100u);
    for (size_t v = 0; v < d.point_map.size(); ++v) EXPECT_EQ(d.mesh.vertices[v], pts[d.point_map[v]]);
}

// Numbers from tools/reference/record_alpha_shape.py with open3d 0.20.0: TetraMesh.create_from_point_cloud
// of torus_points(1500) has 9820 tetras and extract_triangle_mesh(z + 0.3 x, 0.1) 1496 vertices, 2878
// triangles; of knot.ply's 1440 vertices: 12543 tetras, and 171 vertices, 314 triangles.
// The Delaunay tetrahedralization of a generic set is unique, so only hull slivers may differ.
TEST(TetraMesh, MatchesOpen3DCountsOnTorus) {
    const auto pts = o3d::test::torus_points(1500);
    const TetraMeshFromPoints d = create_tetra_mesh_from_points(pts);
    EXPECT_EQ(d.mesh.vertices.size(), 1500u);
    EXPECT_NEAR(static_cast<double>(d.mesh.tetras.size()), 9820.0, 0.01 * 9820);
    std::vector<double> values;
    for (const auto& v : d.mesh.vertices) values.push_back(v.z() + 0.3 * v.x());
    const TriangleMesh iso = extract_triangle_mesh(d.mesh, values, 0.1);
    EXPECT_NEAR(static_cast<double>(iso.vertices.size()), 1496.0, 0.01 * 1496);
    EXPECT_NEAR(static_cast<double>(iso.triangles.size()), 2878.0, 0.01 * 2878);
}

TEST(TetraMesh, MatchesOpen3DCountsOnKnot) {
    O3D_TEST_DATA_OR_SKIP(path, "open3d/knot.ply");
    const TriangleMesh knot = o3d::io::read_triangle_mesh(path);
    const TetraMeshFromPoints d = create_tetra_mesh_from_points(knot.vertices);
    EXPECT_NEAR(static_cast<double>(d.mesh.tetras.size()), 12543.0, 0.01 * 12543);
    std::vector<double> values;
    for (const auto& v : d.mesh.vertices) values.push_back(v.z() + 0.3 * v.x());
    const TriangleMesh iso = extract_triangle_mesh(d.mesh, values, 0.1);
    EXPECT_NEAR(static_cast<double>(iso.vertices.size()), 171.0, 2.0);
    EXPECT_NEAR(static_cast<double>(iso.triangles.size()), 314.0, 4.0);
}

TEST(TetraMesh, ExtractOfLinearFieldIsThePlane) {
    const auto pts = o3d::test::ball_points(400, 1.0, 9);
    const TetraMeshFromPoints d = create_tetra_mesh_from_points(pts);
    const Eigen::Vector3d n = Eigen::Vector3d(0.3, -0.5, 0.8).normalized();
    const double level = 0.15;
    std::vector<double> values;
    for (const auto& v : d.mesh.vertices) values.push_back(n.dot(v));
    const TriangleMesh iso = extract_triangle_mesh(d.mesh, values, level);
    ASSERT_GT(iso.triangles.size(), 50u);
    double area = 0.0;
    for (const auto& v : iso.vertices) EXPECT_NEAR(n.dot(v), level, 1e-12);
    for (const auto& t : iso.triangles) {
        const Eigen::Vector3d cross =
            (iso.vertices[t(1)] - iso.vertices[t(0)]).cross(iso.vertices[t(2)] - iso.vertices[t(0)]);
        EXPECT_GE(cross.dot(n), 0.0) << "triangle faces down the gradient";
        area += 0.5 * cross.norm();
    }
    // The cut of the hull of 400 points in the unit ball: a disc of radius sqrt(1 - level^2), a bit less.
    const double disc = M_PI * (1.0 - level * level);
    EXPECT_LT(area, disc);
    EXPECT_GT(area, 0.8 * disc);
    EXPECT_TRUE(is_edge_manifold(iso, true));
    EXPECT_TRUE(is_orientable(iso));
}

TEST(TetraMesh, ExtractAtALevelOutsideTheValuesIsEmpty) {
    const TetraMeshFromPoints d = create_tetra_mesh_from_points(o3d::test::ball_points(50, 1.0, 2));
    std::vector<double> values(d.mesh.vertices.size(), 1.0);
    EXPECT_TRUE(extract_triangle_mesh(d.mesh, values, 2.0).triangles.empty());
    EXPECT_TRUE(extract_triangle_mesh(d.mesh, values, 0.5).triangles.empty());
}

TEST(TetraMesh, BadInputsThrow) {
    const double nan = std::numeric_limits<double>::quiet_NaN();
    EXPECT_THROW(create_tetra_mesh_from_points({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}), o3d::InvalidArgument);
    std::vector<Eigen::Vector3d> flat;
    std::mt19937_64 rng(4);
    std::uniform_real_distribution<double> u(0.0, 1.0);
    for (int i = 0; i < 50; ++i) flat.emplace_back(u(rng), u(rng), 2.0);
    EXPECT_THROW(create_tetra_mesh_from_points(flat), o3d::InvalidArgument);  // coplanar
    std::vector<Eigen::Vector3d> line;
    for (int i = 0; i < 10; ++i) line.emplace_back(i, 2.0 * i, -i);
    EXPECT_THROW(create_tetra_mesh_from_points(line), o3d::InvalidArgument);  // collinear
    EXPECT_THROW(create_tetra_mesh_from_points(std::vector<Eigen::Vector3d>(6, Eigen::Vector3d(1, 2, 3))),
                 o3d::InvalidArgument);  // coincident
    auto pts = o3d::test::ball_points(20, 1.0, 1);
    pts[7].y() = nan;
    EXPECT_THROW(create_tetra_mesh_from_points(pts), o3d::InvalidArgument);

    const TetraMeshFromPoints d = create_tetra_mesh_from_points(o3d::test::ball_points(30, 1.0, 1));
    std::vector<double> values(d.mesh.vertices.size(), 0.0);
    EXPECT_THROW(extract_triangle_mesh(d.mesh, std::vector<double>(3, 0.0), 0.0), o3d::InvalidArgument);
    EXPECT_THROW(extract_triangle_mesh(d.mesh, values, nan), o3d::InvalidArgument);
    values[4] = std::numeric_limits<double>::infinity();
    EXPECT_THROW(extract_triangle_mesh(d.mesh, values, 0.0), o3d::InvalidArgument);
    values[4] = 0.0;
    TetraMesh bad = d.mesh;
    bad.tetras[2](1) = static_cast<int>(bad.vertices.size());
    EXPECT_THROW(extract_triangle_mesh(bad, values, 0.0), o3d::InvalidArgument);
    bad.tetras[2](1) = -1;
    EXPECT_THROW(remove_unreferenced_vertices(bad), o3d::InvalidArgument);
}

TEST(TetraMeshOps, CleanUps) {
    TetraMesh m;
    m.vertices = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {1, 0, 0}, {5, 5, 5}, {-0.0, 0, 1}};
    //                                             4 = copy of 1    5 = unused   6 = copy of 3 (-0.0 == 0.0)
    m.tetras = {{0, 1, 2, 3}, {3, 2, 1, 0}, {0, 4, 2, 6}, {0, 0, 2, 3}};
    EXPECT_TRUE(m.has_vertices());
    EXPECT_TRUE(m.has_tetras());
    EXPECT_EQ(get_min_bound(m), Eigen::Vector3d(-0.0, 0, 0));
    EXPECT_EQ(get_max_bound(m), Eigen::Vector3d(5, 5, 5));
    EXPECT_TRUE(get_center(m).isApprox(Eigen::Vector3d(7.0 / 7, 6.0 / 7, 7.0 / 7)));

    TetraMesh a = m;
    remove_degenerate_tetras(a);
    ASSERT_EQ(a.tetras.size(), 3u);
    EXPECT_EQ(a.tetras[2], Eigen::Vector4i(0, 4, 2, 6));
    remove_duplicated_tetras(a);  // {3 2 1 0} is {0 1 2 3} reordered
    ASSERT_EQ(a.tetras.size(), 2u);
    EXPECT_EQ(a.tetras[1], Eigen::Vector4i(0, 4, 2, 6));
    remove_duplicated_vertices(a);
    ASSERT_EQ(a.vertices.size(), 5u);
    EXPECT_EQ(a.tetras[1], Eigen::Vector4i(0, 1, 2, 3));
    remove_duplicated_tetras(a);
    EXPECT_EQ(a.tetras.size(), 1u);
    remove_unreferenced_vertices(a);
    ASSERT_EQ(a.vertices.size(), 4u);  // (5, 5, 5) was used by nothing
    EXPECT_EQ(a.vertices[3], Eigen::Vector3d(0, 0, 1));
    EXPECT_EQ(a.tetras[0], Eigen::Vector4i(0, 1, 2, 3));

    TetraMesh empty;
    EXPECT_FALSE(empty.has_vertices());
    EXPECT_FALSE(empty.has_tetras());
    EXPECT_EQ(get_center(empty), Eigen::Vector3d::Zero());
}
