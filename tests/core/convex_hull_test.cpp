// SPDX-License-Identifier: MIT
// Convex hulls and hidden-point removal: analytic shapes, Open3D 0.20 reference numbers, errors.
#include "o3d/geometry/convex_hull.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <set>

#include "o3d/geometry/hidden_point_removal.h"
#include "o3d/geometry/mesh_topology.h"
#include "o3d/geometry/triangle_mesh_basics.h"
#include "o3d/geometry/triangle_mesh_ops.h"
#include "o3d/io/point_cloud_io.h"
#include "o3d/utility/error.h"
#include "test_data.h"

using namespace o3d::geometry;

namespace {

std::vector<Eigen::Vector3d> unit_cube_with_interior(size_t interior, uint64_t seed) {
    std::vector<Eigen::Vector3d> pts;
    for (int i = 0; i < 8; ++i) pts.emplace_back(i & 1, (i >> 1) & 1, (i >> 2) & 1);
    std::mt19937_64 rng(seed);
    std::uniform_real_distribution<double> u(0.05, 0.95);
    for (size_t i = 0; i < interior; ++i) pts.emplace_back(u(rng), u(rng), u(rng));
    // Interleave the corners among interior points so that index mapping is exercised.
    std::shuffle(pts.begin(), pts.end(), rng);
    return pts;
}

std::vector<Eigen::Vector3d> sphere_points(size_t n, double radius, uint64_t seed) {
    std::mt19937_64 rng(seed);
    std::normal_distribution<double> g;
    std::vector<Eigen::Vector3d> pts;
    for (size_t i = 0; i < n; ++i) pts.push_back(Eigen::Vector3d(g(rng), g(rng), g(rng)).normalized() * radius);
    return pts;
}

/// Signed volume of the triangles against the origin: positive iff they are wound outward.
double signed_volume(const TriangleMesh& m) {
    double v = 0.0;
    for (const auto& t : m.triangles) v += m.vertices[t(0)].dot(m.vertices[t(1)].cross(m.vertices[t(2)])) / 6.0;
    return v;
}

void expect_outward(const TriangleMesh& m) {
    Eigen::Vector3d c = Eigen::Vector3d::Zero();
    for (const auto& v : m.vertices) c += v;
    c /= static_cast<double>(m.vertices.size());
    for (size_t t = 0; t < m.triangles.size(); ++t) {
        const Eigen::Vector3d centroid =
            (m.vertices[m.triangles[t](0)] + m.vertices[m.triangles[t](1)] + m.vertices[m.triangles[t](2)]) / 3.0;
        EXPECT_GE(triangle_cross(m, t).dot(centroid - c), 0.0) << "triangle " << t << " faces inward";
    }
}

}  // namespace

TEST(ConvexHull, CubeCornersWithInteriorPoints) {
    const auto pts = unit_cube_with_interior(200, 3);
    const ConvexHull hull = compute_convex_hull(pts);
    ASSERT_EQ(hull.mesh.vertices.size(), 8u);
    EXPECT_EQ(hull.mesh.triangles.size(), 12u);
    ASSERT_EQ(hull.point_indices.size(), 8u);
    std::set<std::tuple<double, double, double>> corners;
    for (size_t v = 0; v < 8; ++v) {
        const Eigen::Vector3d& p = pts[static_cast<size_t>(hull.point_indices[v])];
        EXPECT_EQ(p, hull.mesh.vertices[v]);  // the index maps back to the very input point
        for (int k = 0; k < 3; ++k) EXPECT_TRUE(p(k) == 0.0 || p(k) == 1.0) << "not a corner";
        corners.insert({p.x(), p.y(), p.z()});
    }
    EXPECT_EQ(corners.size(), 8u);
    EXPECT_NEAR(signed_volume(hull.mesh), 1.0, 1e-12);
    EXPECT_NEAR(volume(hull.mesh), 1.0, 1e-12);
    EXPECT_NEAR(surface_area(hull.mesh), 6.0, 1e-12);
    expect_outward(hull.mesh);
}

TEST(ConvexHull, SpherePointsGiveAWatertightOutwardHull) {
    const auto pts = sphere_points(2000, 2.0, 5);
    const ConvexHull hull = compute_convex_hull(pts);
    EXPECT_EQ(hull.mesh.vertices.size(), pts.size());  // every point on a sphere is extreme
    EXPECT_EQ(hull.mesh.triangles.size(), 2 * pts.size() - 4);  // Euler: closed triangulated sphere
    EXPECT_TRUE(is_watertight(hull.mesh));
    EXPECT_EQ(euler_poincare_characteristic(hull.mesh), 2);
    const double v = signed_volume(hull.mesh);
    EXPECT_GT(v, 0.0);
    EXPECT_LT(v, 4.0 / 3.0 * M_PI * 8.0);
    EXPECT_GT(v, 0.97 * 4.0 / 3.0 * M_PI * 8.0);
    expect_outward(hull.mesh);
}

TEST(ConvexHull, CoplanarNeedsJoggle) {
    std::vector<Eigen::Vector3d> square = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {1, 1, 0}, {0.5, 0.5, 0}};
    EXPECT_THROW(compute_convex_hull(square, false), o3d::InvalidArgument);
    const ConvexHull hull = compute_convex_hull(square, true);
    EXPECT_GE(hull.mesh.vertices.size(), 4u);
    for (size_t v = 0; v < hull.mesh.vertices.size(); ++v)  // joggling never moves the output vertices
        EXPECT_EQ(hull.mesh.vertices[v], square[static_cast<size_t>(hull.point_indices[v])]);
}

TEST(ConvexHull, Errors) {
    EXPECT_THROW(compute_convex_hull({}), o3d::InvalidArgument);
    EXPECT_THROW(compute_convex_hull({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}), o3d::InvalidArgument);
    std::vector<Eigen::Vector3d> pts = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
    pts[2].y() = NAN;
    EXPECT_THROW(compute_convex_hull(pts), o3d::InvalidArgument);
    pts[2].y() = INFINITY;
    EXPECT_THROW(compute_convex_hull(pts, true), o3d::InvalidArgument);
}

// Numbers from tools/reference/record_hull_obb.py (Open3D 0.20).
TEST(ConvexHull, MatchesOpen3DOnCloudBin0) {
    O3D_TEST_DATA_OR_SKIP(path, "open3d/Feature/cloud_bin_0.pcd");
    const PointCloud cloud = o3d::io::read_point_cloud(path);
    ASSERT_EQ(cloud.size(), 3903u);
    const ConvexHull hull = compute_convex_hull(cloud.points);
    EXPECT_EQ(hull.mesh.vertices.size(), 85u);
    EXPECT_EQ(hull.mesh.triangles.size(), 166u);
    EXPECT_NEAR(surface_area(hull.mesh), 10.292362572, 1e-8);
    EXPECT_NEAR(volume(hull.mesh), 2.30335298548, 1e-8);
    EXPECT_NEAR(signed_volume(hull.mesh), 2.30335298548, 1e-8);
    int64_t index_sum = 0;
    for (int i : hull.point_indices) index_sum += i;
    EXPECT_EQ(index_sum, 126738);  // the same 85 input points as Open3D
    const ConvexHull joggled = compute_convex_hull(cloud.points, true);
    EXPECT_EQ(joggled.mesh.vertices.size(), 85u);
    EXPECT_NEAR(surface_area(joggled.mesh), 10.2923625719, 1e-6);
}

TEST(HiddenPointRemoval, SphereFromFarAwayKeepsTheFacingHalf) {
    const auto pts = sphere_points(4000, 1.0, 9);
    const Eigen::Vector3d camera(0, 0, 100);
    const ConvexHull visible = hidden_point_removal(pts, camera, 100.0 * 1000.0);
    const size_t n = visible.point_indices.size();
    // From distance 100 the visible cap is z > 0.01; HPR with a large radius also keeps a thin band past the
    // horizon, so "about half": every clearly facing point, no clearly hidden one.
    EXPECT_GT(n, 0.45 * pts.size());
    EXPECT_LT(n, 0.56 * pts.size());
    std::vector<uint8_t> kept(pts.size(), 0);
    for (size_t v = 0; v < n; ++v) {
        const Eigen::Vector3d& p = pts[static_cast<size_t>(visible.point_indices[v])];
        kept[static_cast<size_t>(visible.point_indices[v])] = 1;
        EXPECT_EQ(p, visible.mesh.vertices[v]);
        EXPECT_GT(p.z(), -0.1) << "a point on the far side is visible";  // normal = p on the unit sphere
    }
    for (size_t i = 0; i < pts.size(); ++i)
        if (pts[i].z() > 0.2) EXPECT_TRUE(kept[i]) << "facing point " << i << " was removed";
    for (const auto& t : visible.mesh.triangles) EXPECT_LT(t.maxCoeff(), static_cast<int>(n));
}

TEST(HiddenPointRemoval, MatchesOpen3DOnCloudBin0) {
    O3D_TEST_DATA_OR_SKIP(path, "open3d/Feature/cloud_bin_0.pcd");
    const PointCloud cloud = o3d::io::read_point_cloud(path);
    const ConvexHull visible = hidden_point_removal(cloud.points, Eigen::Vector3d(0, 0, 5), 500.0);
    EXPECT_EQ(visible.point_indices.size(), 1318u);
    EXPECT_EQ(visible.mesh.triangles.size(), 2599u);
}

TEST(HiddenPointRemoval, Errors) {
    const auto pts = sphere_points(100, 1.0, 1);
    EXPECT_THROW(hidden_point_removal(pts, Eigen::Vector3d(0, 0, 5), 0.0), o3d::InvalidArgument);
    EXPECT_THROW(hidden_point_removal(pts, Eigen::Vector3d(0, 0, 5), -1.0), o3d::InvalidArgument);
    EXPECT_THROW(hidden_point_removal(pts, Eigen::Vector3d(0, 0, 5), NAN), o3d::InvalidArgument);
    EXPECT_THROW(hidden_point_removal(pts, Eigen::Vector3d(0, NAN, 5), 10.0), o3d::InvalidArgument);
    EXPECT_THROW(hidden_point_removal(pts, pts[3], 10.0), o3d::InvalidArgument);  // a point at the camera
    EXPECT_THROW(hidden_point_removal({{1, 0, 0}, {0, 1, 0}}, Eigen::Vector3d(0, 0, 5), 10.0),
                 o3d::InvalidArgument);
}
