// SPDX-License-Identifier: MIT
// Alpha shapes: convex hull at a huge alpha, a watertight ball at a moderate one, Open3D 0.20 counts,
// attributes, determinism and the bad-input errors.
#include "o3d/geometry/alpha_shape.h"

#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <map>
#include <random>
#include <set>

#include "delaunay_test_points.h"
#include "o3d/geometry/convex_hull.h"
#include "o3d/geometry/mesh_topology.h"
#include "o3d/geometry/triangle_mesh_basics.h"
#include "o3d/geometry/triangle_mesh_ops.h"
#include "o3d/io/triangle_mesh_io.h"
#include "o3d/utility/error.h"
#include "o3d/utility/parallel.h"
#include "test_data.h"

using namespace o3d::geometry;

namespace {

PointCloud cloud_of(const std::vector<Eigen::Vector3d>& pts) {
    PointCloud c;
    c.points = pts;
    return c;
}

/// The triangles as sets of input-point indices (vertices looked up by their exact coordinates).
std::set<std::array<size_t, 3>> triangle_set(const TriangleMesh& m, const std::vector<Eigen::Vector3d>& pts) {
    std::map<std::array<double, 3>, size_t> index;
    for (size_t i = 0; i < pts.size(); ++i) index[{pts[i].x(), pts[i].y(), pts[i].z()}] = i;
    std::set<std::array<size_t, 3>> out;
    for (const auto& t : m.triangles) {
        std::array<size_t, 3> f;
        for (int k = 0; k < 3; ++k) {
            const Eigen::Vector3d& v = m.vertices[t(k)];
            f[k] = index.at({v.x(), v.y(), v.z()});
        }
        std::sort(f.begin(), f.end());
        out.insert(f);
    }
    return out;
}

/// Sum of the signed tetrahedra (origin, triangle): the enclosed volume when wound outward.
double signed_volume(const TriangleMesh& m) {
    double v = 0.0;
    for (const auto& t : m.triangles) v += m.vertices[t(0)].dot(m.vertices[t(1)].cross(m.vertices[t(2)])) / 6.0;
    return v;
}

}  // namespace

TEST(AlphaShape, HugeAlphaGivesTheConvexHull) {
    auto pts = o3d::test::sphere_points(150, 1.0, 0.02, 21);
    const auto inside = o3d::test::ball_points(250, 0.9, 22);
    pts.insert(pts.end(), inside.begin(), inside.end());
    const TriangleMesh shape = create_from_point_cloud_alpha_shape(cloud_of(pts), 1e6);
    const ConvexHull hull = compute_convex_hull(pts);
    EXPECT_EQ(triangle_set(shape, pts), triangle_set(hull.mesh, pts));
    EXPECT_EQ(shape.vertices.size(), hull.mesh.vertices.size());  // unused (interior) points are dropped
    // Wound outward: the hull is convex, so every triangle faces away from the centroid.
    for (size_t t = 0; t < shape.triangles.size(); ++t) {
        const Eigen::Vector3i& f = shape.triangles[t];
        const Eigen::Vector3d centre = (shape.vertices[f(0)] + shape.vertices[f(1)] + shape.vertices[f(2)]) / 3.0;
        EXPECT_GT(triangle_cross(shape, t).dot(centre), 0.0) << "triangle " << t << " faces inward";
    }
    EXPECT_NEAR(signed_volume(shape), volume(hull.mesh), 1e-12);
}

TEST(AlphaShape, CubeWithInteriorAtHugeAlphaIsTheCube) {
    // The corners are cospherical and the faces' corner pairs coplanar: the triangulation of each face is
    // arbitrary, but the area and volume are not.
    std::vector<Eigen::Vector3d> pts;
    for (int i = 0; i < 8; ++i) pts.emplace_back(i & 1, (i >> 1) & 1, (i >> 2) & 1);
    std::mt19937_64 rng(8);
    std::uniform_real_distribution<double> u(0.05, 0.95);
    for (int i = 0; i < 200; ++i) pts.emplace_back(u(rng), u(rng), u(rng));
    const TriangleMesh shape = create_from_point_cloud_alpha_shape(cloud_of(pts), 100.0);
    EXPECT_EQ(shape.vertices.size(), 8u);
    EXPECT_EQ(shape.triangles.size(), 12u);
    EXPECT_NEAR(surface_area(shape), 6.0, 1e-12);
    EXPECT_NEAR(signed_volume(shape), 1.0, 1e-12);
    EXPECT_TRUE(is_watertight(shape));
}

TEST(AlphaShape, BallAtModerateAlphaIsWatertightWithTheRightSize) {
    // A solid ball sampling (interior + a thin shell on the surface): at alpha a few spacings wide, the
    // interior tetras are kept and the flat caps between surface points (circumradius ~ 1) are not.
    const double radius = 1.0;
    auto pts = o3d::test::sphere_points(2000, radius, 0.003, 31);
    const auto inside = o3d::test::ball_points(3000, 0.97 * radius, 32);
    pts.insert(pts.end(), inside.begin(), inside.end());
    const TriangleMesh shape = create_from_point_cloud_alpha_shape(cloud_of(pts), 0.3);
    ASSERT_GT(shape.triangles.size(), 1000u);
    EXPECT_TRUE(is_edge_manifold(shape, false));
    EXPECT_TRUE(is_vertex_manifold(shape));
    EXPECT_TRUE(is_watertight(shape));
    EXPECT_TRUE(is_orientable(shape));
    const double area = 4.0 * M_PI * radius * radius, vol = 4.0 / 3.0 * M_PI * radius * radius * radius;
    EXPECT_NEAR(surface_area(shape), area, 0.03 * area);
    EXPECT_NEAR(signed_volume(shape), vol, 0.03 * vol);  // positive: wound outward
    // A sphere polytope is inscribed: slightly smaller than the sphere.
    EXPECT_LT(signed_volume(shape), vol * 1.01);
}

TEST(AlphaShape, TinyAlphaGivesAnEmptyMesh) {
    const TriangleMesh shape = create_from_point_cloud_alpha_shape(cloud_of(o3d::test::ball_points(200, 1.0, 4)), 1e-6);
    EXPECT_TRUE(shape.triangles.empty());
    EXPECT_TRUE(shape.vertices.empty());
}

// Numbers from tools/reference/record_alpha_shape.py with open3d 0.20.0
// (TriangleMesh.create_from_point_cloud_alpha_shape; vertices, triangles).
TEST(AlphaShape, MatchesOpen3DCountsOnTorus) {
    const auto pts = o3d::test::torus_points(1500);
    const PointCloud cloud = cloud_of(pts);
    const TetraMeshFromPoints d = create_tetra_mesh_from_points(pts);
    const struct {
        double alpha;
        size_t vertices, triangles;
        bool watertight;
    } expected[] = {{0.1, 1209, 2212, false}, {0.2, 1493, 4222, false}, {0.5, 1431, 2862, true}};
    for (const auto& e : expected) {
        const TriangleMesh m = create_from_point_cloud_alpha_shape(cloud, e.alpha, &d.mesh, &d.point_map);
        EXPECT_NEAR(static_cast<double>(m.vertices.size()), e.vertices, 0.01 * e.vertices) << "alpha " << e.alpha;
        EXPECT_NEAR(static_cast<double>(m.triangles.size()), e.triangles, 0.01 * e.triangles) << "alpha " << e.alpha;
        EXPECT_EQ(is_watertight(m), e.watertight) << "alpha " << e.alpha;
    }
    // At 0.5 the torus is closed: its volume is near 2 pi^2 R r^2 (a bit less, inscribed).
    const TriangleMesh closed = create_from_point_cloud_alpha_shape(cloud, 0.5, &d.mesh, &d.point_map);
    const double torus_volume = 2.0 * M_PI * M_PI * 1.0 * 0.35 * 0.35;
    EXPECT_NEAR(signed_volume(closed), torus_volume, 0.06 * torus_volume);
}

TEST(AlphaShape, MatchesOpen3DCountsOnKnot) {
    O3D_TEST_DATA_OR_SKIP(path, "open3d/knot.ply");
    const TriangleMesh knot = o3d::io::read_triangle_mesh(path);
    const PointCloud cloud = cloud_of(knot.vertices);
    const TetraMeshFromPoints d = create_tetra_mesh_from_points(cloud.points);
    const struct {
        double alpha;
        size_t vertices, triangles;
    } expected[] = {{10.0, 677, 1424}, {15.0, 955, 1994}, {20.0, 839, 1822}, {1e6, 165, 326}};
    for (const auto& e : expected) {
        const TriangleMesh m = create_from_point_cloud_alpha_shape(cloud, e.alpha, &d.mesh, &d.point_map);
        EXPECT_NEAR(static_cast<double>(m.vertices.size()), e.vertices, 0.01 * e.vertices) << "alpha " << e.alpha;
        EXPECT_NEAR(static_cast<double>(m.triangles.size()), e.triangles, 0.01 * e.triangles) << "alpha " << e.alpha;
    }
}

TEST(AlphaShape, ReusesTheTetraMeshAndCarriesAttributes) {
    auto pts = o3d::test::torus_points(800);
    pts.push_back(pts[5]);  // a duplicate: the tetra mesh has fewer vertices than the cloud
    PointCloud cloud = cloud_of(pts);
    for (size_t i = 0; i < pts.size(); ++i) {
        cloud.normals.push_back(pts[i].normalized());
        cloud.colors.emplace_back(static_cast<double>(i) / pts.size(), 0.5, 0.25);
    }
    const TriangleMesh direct = create_from_point_cloud_alpha_shape(cloud, 0.4);
    const TetraMeshFromPoints d = create_tetra_mesh_from_points(pts);
    ASSERT_EQ(d.mesh.vertices.size(), 800u);
    const TriangleMesh reused = create_from_point_cloud_alpha_shape(cloud, 0.4, &d.mesh, &d.point_map);
    EXPECT_EQ(direct.vertices, reused.vertices);
    EXPECT_EQ(direct.triangles, reused.triangles);
    ASSERT_TRUE(direct.has_vertex_normals());
    ASSERT_TRUE(direct.has_vertex_colors());
    EXPECT_FALSE(direct.has_triangle_normals());
    // Vertices keep the input order, and each carries its own point's normal and color.
    double last_color = -1.0;
    for (size_t v = 0; v < direct.vertices.size(); ++v) {
        EXPECT_EQ(direct.vertex_normals[v], direct.vertices[v].normalized());
        EXPECT_GT(direct.vertex_colors[v].x(), last_color);
        last_color = direct.vertex_colors[v].x();
        const size_t i = static_cast<size_t>(std::lround(last_color * pts.size()));
        EXPECT_EQ(direct.vertices[v], pts[i]);
    }
}

TEST(AlphaShape, SameResultOnAnyThreadCount) {
    auto pts = o3d::test::sphere_points(1500, 1.0, 0.01, 41);
    const auto inside = o3d::test::ball_points(1500, 0.95, 42);
    pts.insert(pts.end(), inside.begin(), inside.end());
    const PointCloud cloud = cloud_of(pts);
    o3d::utility::set_default_num_threads(1);
    const TriangleMesh one = create_from_point_cloud_alpha_shape(cloud, 0.25);
    o3d::utility::set_default_num_threads(4);
    const TriangleMesh four = create_from_point_cloud_alpha_shape(cloud, 0.25);
    o3d::utility::set_default_num_threads(0);
    EXPECT_EQ(one.vertices, four.vertices);
    EXPECT_EQ(one.triangles, four.triangles);
}

TEST(AlphaShape, BadInputsThrow) {
    const double nan = std::numeric_limits<double>::quiet_NaN(), inf = std::numeric_limits<double>::infinity();
    const PointCloud good = cloud_of(o3d::test::ball_points(50, 1.0, 6));
    for (double alpha : {0.0, -1.0, nan, inf})
        EXPECT_THROW(create_from_point_cloud_alpha_shape(good, alpha), o3d::InvalidArgument) << alpha;
    EXPECT_THROW(create_from_point_cloud_alpha_shape(cloud_of({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}), 1.0),
                 o3d::InvalidArgument);
    EXPECT_THROW(create_from_point_cloud_alpha_shape(PointCloud{}, 1.0), o3d::InvalidArgument);
    std::vector<Eigen::Vector3d> flat;
    for (int i = 0; i < 10; ++i)
        for (int j = 0; j < 10; ++j) flat.emplace_back(0.1 * i + 0.01 * j * j, 0.1 * j, 0.0);
    EXPECT_THROW(create_from_point_cloud_alpha_shape(cloud_of(flat), 1.0), o3d::InvalidArgument);  // coplanar
    PointCloud with_nan = good;
    with_nan.points[3].z() = nan;
    EXPECT_THROW(create_from_point_cloud_alpha_shape(with_nan, 1.0), o3d::InvalidArgument);

    const TetraMeshFromPoints d = create_tetra_mesh_from_points(good.points);
    std::vector<size_t> short_map(d.point_map.begin(), d.point_map.end() - 1);
    EXPECT_THROW(create_from_point_cloud_alpha_shape(good, 1.0, &d.mesh, &short_map), o3d::InvalidArgument);
    std::vector<size_t> far_map = d.point_map;
    far_map[0] = good.size();
    EXPECT_THROW(create_from_point_cloud_alpha_shape(good, 1.0, &d.mesh, &far_map), o3d::InvalidArgument);
    TetraMesh bad = d.mesh;
    bad.tetras[0](3) = static_cast<int>(bad.vertices.size());
    EXPECT_THROW(create_from_point_cloud_alpha_shape(good, 1.0, &bad, &d.point_map), o3d::InvalidArgument);
    TetraMesh fewer = d.mesh;
    fewer.vertices.pop_back();
    fewer.tetras.clear();
    EXPECT_THROW(create_from_point_cloud_alpha_shape(good, 1.0, &fewer, nullptr), o3d::InvalidArgument);
    // Without a map, a tetra mesh with one vertex per point is taken as the identity.
    EXPECT_EQ(create_from_point_cloud_alpha_shape(good, 1.0, &d.mesh, nullptr).triangles,
              create_from_point_cloud_alpha_shape(good, 1.0).triangles);
}
