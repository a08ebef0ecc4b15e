// SPDX-License-Identifier: MIT
// Ball pivoting: analytic surfaces (sphere, torus, plane), Open3D 0.20 reference counts, degenerate
// input, progress and errors.
#include "o3d/geometry/ball_pivoting.h"

#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cmath>
#include <cstdint>
#include <map>
#include <utility>

#include "o3d/geometry/mesh_topology.h"
#include "o3d/geometry/triangle_mesh_basics.h"
#include "o3d/geometry/triangle_mesh_ops.h"
#include "o3d/io/triangle_mesh_io.h"
#include "o3d/utility/error.h"
#include "o3d/utility/random.h"
#include "test_data.h"

using namespace o3d::geometry;

namespace {

/// o3d::utility::random::SplitMix64 (uniform: 53 bits in [0, 1)), repeated in
/// tools/reference/record_ball_pivoting.py so Open3D sees the same clouds.
using o3d::utility::random::SplitMix64;

/// Uniform points on a sphere about the origin, with their exact outward normals.
PointCloud sphere_cloud(size_t n, double radius, uint64_t seed) {
    SplitMix64 rng{seed};
    PointCloud cloud;
    for (size_t i = 0; i < n; ++i) {
        const double z = 2.0 * rng.uniform() - 1.0;
        const double phi = 2.0 * M_PI * rng.uniform();
        const double s = std::sqrt(std::max(0.0, 1.0 - z * z));
        const Eigen::Vector3d d(s * std::cos(phi), s * std::sin(phi), z);
        cloud.normals.push_back(d);
        cloud.points.push_back(radius * d);
    }
    return cloud;
}

/// Area-uniform points on a torus about the z axis (tube angle accepted with probability
/// (R + r cos t) / (R + r)), with exact outward normals.
PointCloud torus_cloud(size_t n, double major, double minor, uint64_t seed) {
    SplitMix64 rng{seed};
    PointCloud cloud;
    while (cloud.points.size() < n) {
        const double t = 2.0 * M_PI * rng.uniform();
        const double p = 2.0 * M_PI * rng.uniform();
        if (rng.uniform() * (major + minor) > major + minor * std::cos(t)) continue;
        const double ring = major + minor * std::cos(t);
        cloud.points.emplace_back(ring * std::cos(p), ring * std::sin(p), minor * std::sin(t));
        cloud.normals.emplace_back(std::cos(t) * std::cos(p), std::cos(t) * std::sin(p), std::sin(t));
    }
    return cloud;
}

double area(const TriangleMesh& mesh) {
    double a = 0.0;
    for (size_t t = 0; t < mesh.triangles.size(); ++t) a += triangle_area(mesh, t);
    return a;
}

/// Edges used by exactly one triangle.
size_t boundary_edges(const TriangleMesh& mesh) {
    std::map<std::pair<int, int>, int> uses;
    for (const auto& t : mesh.triangles)
        for (int k = 0; k < 3; ++k) ++uses[std::minmax(t(k), t((k + 1) % 3))];
    size_t n = 0;
    for (const auto& [edge, count] : uses) n += count == 1;
    return n;
}

size_t used_vertices(const TriangleMesh& mesh) {
    std::vector<char> used(mesh.vertices.size(), 0);
    for (const auto& t : mesh.triangles) used[t(0)] = used[t(1)] = used[t(2)] = 1;
    size_t n = 0;
    for (const char u : used) n += u;
    return n;
}

/// The output keeps every input point, normal and color in order, and its triangle normals are the
/// unit normals of the windings, which agree with every (non-zero) point normal.
void expect_consistent_with_cloud(const TriangleMesh& mesh, const PointCloud& cloud) {
    ASSERT_EQ(mesh.vertices, cloud.points);
    ASSERT_EQ(mesh.vertex_normals, cloud.normals);
    EXPECT_EQ(mesh.vertex_colors, cloud.colors);
    ASSERT_EQ(mesh.triangle_normals.size(), mesh.triangles.size());
    validate_triangles(mesh);
    for (size_t t = 0; t < mesh.triangles.size(); ++t) {
        const Eigen::Vector3d d = triangle_cross(mesh, t);
        EXPECT_NEAR((mesh.triangle_normals[t] - d.normalized()).norm(), 0.0, 1e-12);
        for (int k = 0; k < 3; ++k)
            EXPECT_GE(d.dot(cloud.normals[mesh.triangles[t](k)]), 0.0) << "triangle " << t << " faces inward";
    }
    EXPECT_TRUE(is_edge_manifold(mesh, true));
    EXPECT_TRUE(is_orientable(mesh));
}

/// Depth of a chord plane below a sphere of radius `curvature_radius` over a circle of radius rho:
/// a triangle whose circumradius is at most rho lies within it of a surface that curved.
double sagitta(double rho, double curvature_radius) {
    return curvature_radius - std::sqrt(curvature_radius * curvature_radius - rho * rho);
}

Eigen::Vector3d centroid(const TriangleMesh& mesh, size_t t) {
    const auto& tri = mesh.triangles[t];
    return (mesh.vertices[tri(0)] + mesh.vertices[tri(1)] + mesh.vertices[tri(2)]) / 3.0;
}

}  // namespace

// Reference counts: tools/reference/record_ball_pivoting.py with Open3D 0.20.0 on the same clouds.
TEST(BallPivoting, SphereTwoRadiiIsClosed) {
    const size_t n = 3000;
    const double r = 1.5 * std::sqrt(4.0 * M_PI / n);
    const PointCloud cloud = sphere_cloud(n, 1.0, 1);
    const TriangleMesh mesh = create_from_point_cloud_ball_pivoting(cloud, {r, 2.0 * r});
    expect_consistent_with_cloud(mesh, cloud);
    // A closed triangulated sphere through every point: F = 2V - 4 (Open3D: 5996 as well).
    EXPECT_EQ(used_vertices(mesh), n);
    EXPECT_EQ(mesh.triangles.size(), 2 * n - 4);
    EXPECT_TRUE(is_edge_manifold(mesh, false));
    EXPECT_TRUE(is_vertex_manifold(mesh));
    EXPECT_TRUE(is_watertight(mesh));
    EXPECT_EQ(euler_poincare_characteristic(mesh), 2);
    // An inscribed polyhedron: slightly less area than the sphere (Open3D: 12.5408).
    EXPECT_LT(area(mesh), 4.0 * M_PI);
    EXPECT_GT(area(mesh), 0.98 * 4.0 * M_PI);
    // Vertices are on the sphere; centroids below it by at most the sagitta of the largest ball.
    const double bound = sagitta(2.0 * r, 1.0);
    for (size_t t = 0; t < mesh.triangles.size(); ++t) {
        const double depth = 1.0 - centroid(mesh, t).norm();
        EXPECT_GE(depth, -1e-12);
        EXPECT_LE(depth, bound);
    }
}

TEST(BallPivoting, SphereOneRadiusLeavesFewHoles) {
    const size_t n = 3000;
    const double r = 1.5 * std::sqrt(4.0 * M_PI / n);
    const PointCloud cloud = sphere_cloud(n, 1.0, 1);
    const TriangleMesh mesh = create_from_point_cloud_ball_pivoting(cloud, {r});
    expect_consistent_with_cloud(mesh, cloud);
    EXPECT_NEAR(static_cast<double>(mesh.triangles.size()), 5957.0, 0.01 * 5957.0);  // Open3D: 5957
    EXPECT_LT(boundary_edges(mesh), 0.01 * 3 * n);
    EXPECT_GT(area(mesh), 0.95 * 4.0 * M_PI);  // Open3D: 12.2034
    const double bound = sagitta(r, 1.0);
    for (size_t t = 0; t < mesh.triangles.size(); ++t) EXPECT_LE(1.0 - centroid(mesh, t).norm(), bound);
}

TEST(BallPivoting, TorusCoversTheSurface) {
    const size_t n = 4000;
    const double major = 1.0, minor = 0.4;
    const double true_area = 4.0 * M_PI * M_PI * major * minor;
    const double r = 1.5 * std::sqrt(true_area / n);
    const PointCloud cloud = torus_cloud(n, major, minor, 2);
    const TriangleMesh mesh = create_from_point_cloud_ball_pivoting(cloud, {r, 2.0 * r});
    expect_consistent_with_cloud(mesh, cloud);
    EXPECT_NEAR(static_cast<double>(mesh.triangles.size()), 7982.0, 0.01 * 7982.0);  // Open3D: 7982
    EXPECT_LE(mesh.triangles.size(), 2 * n);  // a closed torus has exactly 2V
    EXPECT_GE(used_vertices(mesh), n - 5);
    EXPECT_LT(boundary_edges(mesh), 0.005 * 3 * n);
    EXPECT_NEAR(area(mesh), true_area, 0.03 * true_area);  // Open3D: 15.5999
    // Centroids stay within the sagitta of the tightest curvature (the tube) of the torus.
    const double bound = sagitta(2.0 * r, minor);
    for (size_t t = 0; t < mesh.triangles.size(); ++t) {
        const Eigen::Vector3d c = centroid(mesh, t);
        const double tube = std::hypot(std::hypot(c.x(), c.y()) - major, c.z());
        EXPECT_LE(std::abs(tube - minor), bound) << "triangle " << t;
    }
}

TEST(BallPivoting, KnotVerticesMatchOpen3D) {
    O3D_TEST_DATA_OR_SKIP(path, "open3d/knot.ply");
    TriangleMesh knot = o3d::io::read_triangle_mesh(path);
    compute_vertex_normals(knot);
    PointCloud cloud;
    cloud.points = knot.vertices;
    cloud.normals = knot.vertex_normals;
    const TriangleMesh mesh = create_from_point_cloud_ball_pivoting(cloud, {8.0, 16.0});
    expect_consistent_with_cloud(mesh, cloud);
    // Open3D: 2681 triangles using 1422 of the 1440 vertices, area 106434.7.
    EXPECT_NEAR(static_cast<double>(mesh.triangles.size()), 2681.0, 0.03 * 2681.0);
    EXPECT_NEAR(static_cast<double>(used_vertices(mesh)), 1422.0, 0.01 * 1422.0);
    EXPECT_NEAR(area(mesh), 106434.7, 0.03 * 106434.7);
}

TEST(BallPivoting, PlanarGridIsTriangulatedExactly) {
    // Every unit square's corners are cocircular: contacts at pivot angle 0 must neither be lost nor
    // produce overlapping triangles.
    const int side = 20;
    PointCloud cloud;
    for (int y = 0; y < side; ++y)
        for (int x = 0; x < side; ++x) {
            cloud.points.emplace_back(x, y, 0.0);
            cloud.normals.emplace_back(0.0, 0.0, 1.0);
        }
    // sqrt(1/2) is the squares' circumradius itself: the ball passes through the plane's points.
    for (const double radius : {0.8, std::sqrt(0.5), 3.0}) {
        const TriangleMesh mesh = create_from_point_cloud_ball_pivoting(cloud, {radius});
        expect_consistent_with_cloud(mesh, cloud);
        EXPECT_EQ(mesh.triangles.size(), static_cast<size_t>(2 * (side - 1) * (side - 1))) << radius;
        EXPECT_NEAR(area(mesh), (side - 1) * (side - 1), 1e-9) << radius;
        EXPECT_EQ(boundary_edges(mesh), static_cast<size_t>(4 * (side - 1))) << radius;
        EXPECT_TRUE(is_vertex_manifold(mesh)) << radius;
    }
}

TEST(BallPivoting, RadiusTooSmallGivesNoTriangles) {
    const PointCloud cloud = sphere_cloud(500, 1.0, 3);
    const TriangleMesh mesh = create_from_point_cloud_ball_pivoting(cloud, {1e-4, 2e-4});
    EXPECT_TRUE(mesh.triangles.empty());
    EXPECT_EQ(mesh.vertices, cloud.points);
}

TEST(BallPivoting, HugeRadiusGivesTheConvexHull) {
    // A ball far larger than the cloud is nearly a half-space: its empty triangles are the hull's.
    const size_t n = 400;
    const PointCloud cloud = sphere_cloud(n, 1.0, 4);
    const TriangleMesh mesh = create_from_point_cloud_ball_pivoting(cloud, {1000.0});
    expect_consistent_with_cloud(mesh, cloud);
    EXPECT_EQ(mesh.triangles.size(), 2 * n - 4);
    EXPECT_TRUE(is_watertight(mesh));
}

TEST(BallPivoting, CoincidentPointsAreUsedOnce) {
    const size_t n = 1500;
    const double r = 1.5 * std::sqrt(4.0 * M_PI / n);
    PointCloud cloud = sphere_cloud(n, 1.0, 5);
    const PointCloud once = cloud;
    cloud.points.insert(cloud.points.end(), once.points.begin(), once.points.end());
    cloud.normals.insert(cloud.normals.end(), once.normals.begin(), once.normals.end());
    TriangleMesh mesh = create_from_point_cloud_ball_pivoting(cloud, {r, 2.0 * r});
    expect_consistent_with_cloud(mesh, cloud);
    EXPECT_EQ(used_vertices(mesh), n);  // one copy of each point
    EXPECT_EQ(mesh.triangles.size(), 2 * n - 4);
    EXPECT_TRUE(is_watertight(mesh));
    EXPECT_GT(area(mesh), 0.97 * 4.0 * M_PI);

    // Copies a rounding error apart count as the same point too (else each copy takes part of the fan).
    SplitMix64 rng{9};
    for (size_t i = n; i < 2 * n; ++i)
        cloud.points[i] += 1e-12 * Eigen::Vector3d(rng.uniform() - 0.5, rng.uniform() - 0.5, rng.uniform() - 0.5);
    mesh = create_from_point_cloud_ball_pivoting(cloud, {r, 2.0 * r});
    expect_consistent_with_cloud(mesh, cloud);
    EXPECT_EQ(used_vertices(mesh), n);
    EXPECT_TRUE(is_watertight(mesh));

    PointCloud same;
    same.points.assign(50, Eigen::Vector3d(1.0, 2.0, 3.0));
    same.normals.assign(50, Eigen::Vector3d(0.0, 0.0, 1.0));
    EXPECT_TRUE(create_from_point_cloud_ball_pivoting(same, {0.5, 1.0}).triangles.empty());
}

TEST(BallPivoting, CollinearPointsGiveNoTriangles) {
    PointCloud line;
    for (int i = 0; i < 100; ++i) {
        line.points.emplace_back(0.1 * i, 0.2 * i, -0.05 * i);
        line.normals.emplace_back(0.0, 0.0, 1.0);
    }
    EXPECT_TRUE(create_from_point_cloud_ball_pivoting(line, {0.1, 1.0, 100.0}).triangles.empty());
}

TEST(BallPivoting, ZeroNormalsTakeTheirNeighboursOrientation) {
    const size_t n = 2000;
    const double r = 1.5 * std::sqrt(4.0 * M_PI / n);
    PointCloud cloud = sphere_cloud(n, 1.0, 6);
    for (size_t i = 0; i < n; i += 4) cloud.normals[i].setZero();
    const TriangleMesh mesh = create_from_point_cloud_ball_pivoting(cloud, {r, 2.0 * r});
    expect_consistent_with_cloud(mesh, cloud);
    EXPECT_GT(area(mesh), 0.97 * 4.0 * M_PI);
    for (size_t t = 0; t < mesh.triangles.size(); ++t)  // outward, zero-normal vertices included
        EXPECT_GT(triangle_cross(mesh, t).dot(centroid(mesh, t)), 0.0);

    for (auto& normal : cloud.normals) normal.setZero();  // nothing can orient a seed
    EXPECT_TRUE(create_from_point_cloud_ball_pivoting(cloud, {r, 2.0 * r}).triangles.empty());
}

TEST(BallPivoting, ColorsAreCarried) {
    PointCloud cloud = sphere_cloud(300, 2.0, 7);
    for (size_t i = 0; i < cloud.size(); ++i) cloud.colors.emplace_back(i / 300.0, 0.5, 1.0 - i / 300.0);
    const TriangleMesh mesh = create_from_point_cloud_ball_pivoting(cloud, {0.5});
    expect_consistent_with_cloud(mesh, cloud);
    EXPECT_FALSE(mesh.triangles.empty());
}

TEST(BallPivoting, ProgressAndCancel) {
    const size_t n = 3000;
    const double r = 1.5 * std::sqrt(4.0 * M_PI / n);
    const PointCloud cloud = sphere_cloud(n, 1.0, 1);
    std::vector<double> seen;
    const TriangleMesh mesh = create_from_point_cloud_ball_pivoting(cloud, {r, 2.0 * r}, [&](double f) {
        seen.push_back(f);
        return true;
    });
    EXPECT_EQ(mesh.triangles.size(), 2 * n - 4);
    ASSERT_GE(seen.size(), 3u);
    EXPECT_GE(seen.front(), 0.0);
    EXPECT_EQ(seen.back(), 1.0);
    for (size_t i = 1; i < seen.size(); ++i) EXPECT_GE(seen[i], seen[i - 1]);

    int calls = 0;
    EXPECT_THROW(create_from_point_cloud_ball_pivoting(cloud, {r, 2.0 * r},
                                                       [&](double) { return ++calls < 2; }),
                 o3d::Cancelled);
    EXPECT_EQ(calls, 2);
}

TEST(BallPivoting, Errors) {
    using o3d::InvalidArgument;
    const PointCloud good = sphere_cloud(50, 1.0, 8);
    EXPECT_THROW(create_from_point_cloud_ball_pivoting(PointCloud{}, {1.0}), InvalidArgument);
    PointCloud no_normals = good;
    no_normals.normals.clear();
    EXPECT_THROW(create_from_point_cloud_ball_pivoting(no_normals, {1.0}), InvalidArgument);
    no_normals.normals.resize(10);  // the wrong count is no normals either
    EXPECT_THROW(create_from_point_cloud_ball_pivoting(no_normals, {1.0}), InvalidArgument);
    PointCloud bad = good;
    bad.points[7].y() = NAN;
    EXPECT_THROW(create_from_point_cloud_ball_pivoting(bad, {1.0}), InvalidArgument);
    bad = good;
    bad.normals[3].z() = INFINITY;
    EXPECT_THROW(create_from_point_cloud_ball_pivoting(bad, {1.0}), InvalidArgument);
    EXPECT_THROW(create_from_point_cloud_ball_pivoting(good, {}), InvalidArgument);
    for (const double r : {0.0, -1.0, double(NAN), double(INFINITY)})
        EXPECT_THROW(create_from_point_cloud_ball_pivoting(good, {0.1, r}), InvalidArgument) << r;
    EXPECT_THROW(create_from_point_cloud_ball_pivoting(good, {0.2, 0.1}), InvalidArgument);
    EXPECT_THROW(create_from_point_cloud_ball_pivoting(good, {0.2, 0.2}), InvalidArgument);
    EXPECT_NO_THROW(create_from_point_cloud_ball_pivoting(good, {0.1, 0.2}));
}
