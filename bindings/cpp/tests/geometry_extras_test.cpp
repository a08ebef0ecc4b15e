// SPDX-License-Identifier: MIT
// Bounding volumes, smoothing, covariances, planar patches, traced down-sampling, sharpening, ellipsoids and
// as-rigid-as-possible deformation through the wrapper, each against an analytic answer: a rotated box's minimal box,
// an ellipsoid recovered from its own vertices, two points smoothed by hand, a cube's corner covariance, a flat
// patch, a rigid ARAP motion reproduced; bad input throws.
#include <algorithm>
#include <array>
#include <cmath>
#include <vector>

#include "test_util.hpp"

using o3dpp::DeformAsRigidAsPossibleEnergy;
using o3dpp::Mat3;
using o3dpp::OrientedBoundingBox;
using o3dpp::OrientedBoundingEllipsoid;
using o3dpp::PointCloud;
using o3dpp::SearchParam;
using o3dpp::TriangleMesh;
using o3dpp::Vec3;

namespace {
/// Rotation about the axis (1, 2, 3) by 0.7 rad, row-major.
Mat3 some_rotation() {
    const double n = std::sqrt(14.0), x = 1 / n, y = 2 / n, z = 3 / n, c = std::cos(0.7), s = std::sin(0.7), t = 1 - c;
    return {t * x * x + c,     t * x * y - s * z, t * x * z + s * y, t * x * y + s * z, t * y * y + c,
            t * y * z - s * x, t * x * z - s * y, t * y * z + s * x, t * z * z + c};
}
Vec3 apply(const Mat3& R, const Vec3& v, const Vec3& t = {0, 0, 0}) {
    return {R[0] * v[0] + R[1] * v[1] + R[2] * v[2] + t[0], R[3] * v[0] + R[4] * v[1] + R[5] * v[2] + t[1],
            R[6] * v[0] + R[7] * v[1] + R[8] * v[2] + t[2]};
}
/// v expressed in the frame of column axes R about `c`: R^T (v - c).
Vec3 local(const Mat3& R, const Vec3& v, const Vec3& c) {
    const Vec3 d{v[0] - c[0], v[1] - c[1], v[2] - c[2]};
    return {R[0] * d[0] + R[3] * d[1] + R[6] * d[2], R[1] * d[0] + R[4] * d[1] + R[7] * d[2],
            R[2] * d[0] + R[5] * d[1] + R[8] * d[2]};
}
std::array<double, 3> sorted(std::array<double, 3> a) {
    std::sort(a.begin(), a.end());
    return a;
}
std::vector<Vec3> grid(int n, double step) {
    std::vector<Vec3> pts;
    for (int i = 0; i < n; ++i)
        for (int j = 0; j < n; ++j) pts.push_back({i * step, j * step, 0.0});
    return pts;
}
}  // namespace

TEST(BoundingVolumes, MinimalBoxOfARotatedBox) {
    TriangleMesh box = TriangleMesh::create_box(1, 2, 3);
    box.rotate(some_rotation(), {0, 0, 0});
    const OrientedBoundingBox obb = box.get_minimal_oriented_bounding_box();
    EXPECT_NEAR(obb.volume(), 6.0, 1e-6);
    const auto e = sorted(obb.extent);
    EXPECT_NEAR(e[0], 1.0, 1e-6);
    EXPECT_NEAR(e[1], 2.0, 1e-6);
    EXPECT_NEAR(e[2], 3.0, 1e-6);
    const OrientedBoundingBox from_points = OrientedBoundingBox::create_from_points_minimal(box.get_vertices());
    EXPECT_NEAR(from_points.volume(), 6.0, 1e-6);
    PointCloud cloud(box.get_vertices());
    EXPECT_NEAR(cloud.get_minimal_oriented_bounding_box().volume(), 6.0, 1e-6);
    // Fewer than 4 points, and a flat set without `robust`, are errors.
    EXPECT_THROW(OrientedBoundingBox::create_from_points_minimal({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}), o3dpp::Error);
    EXPECT_THROW(PointCloud(grid(3, 1.0)).get_minimal_oriented_bounding_box(), o3dpp::Error);
}

TEST(BoundingVolumes, EllipsoidRecoveredFromItsVertices) {
    const Mat3 R = some_rotation();
    const Vec3 t{1, -2, 0.5};
    TriangleMesh mesh = TriangleMesh::create_ellipsoid(1, 2, 3, 10);
    ASSERT_EQ(mesh.num_vertices(), 2 + 9 * 20);
    for (const Vec3& v : mesh.get_vertices()) EXPECT_NEAR(v[0] * v[0] + v[1] * v[1] / 4 + v[2] * v[2] / 9, 1.0, 1e-9);
    mesh.rotate(R, {0, 0, 0});
    mesh.translate(t);
    const OrientedBoundingEllipsoid obe = mesh.get_oriented_bounding_ellipsoid();
    for (int i = 0; i < 3; ++i) EXPECT_NEAR(obe.center[i], t[i], 1e-2);
    const auto r = sorted(obe.radii);
    EXPECT_NEAR(r[0], 1.0, 1e-2);
    EXPECT_NEAR(r[1], 2.0, 1e-2);
    EXPECT_NEAR(r[2], 3.0, 1e-2);
    const OrientedBoundingEllipsoid from_cloud = PointCloud(mesh.get_vertices()).get_oriented_bounding_ellipsoid();
    EXPECT_NEAR(from_cloud.volume(), obe.volume(), 1e-9);
    EXPECT_NEAR(OrientedBoundingEllipsoid::create_from_points(mesh.get_vertices()).volume(), obe.volume(), 1e-9);

    // Its mesh lies on it: every vertex at unit "radius" in the ellipsoid's frame.
    const TriangleMesh shell = TriangleMesh::create_from_oriented_bounding_ellipsoid(obe, {1, 1, 1}, 8);
    EXPECT_EQ(shell.num_vertices(), 2 + 7 * 16);
    for (const Vec3& v : shell.get_vertices()) {
        const Vec3 u = local(obe.R, v, obe.center);
        double q = 0;
        for (int i = 0; i < 3; ++i) q += u[i] * u[i] / (obe.radii[i] * obe.radii[i]);
        EXPECT_NEAR(q, 1.0, 1e-9);
    }
    EXPECT_THROW(OrientedBoundingEllipsoid::create_from_points(grid(3, 1.0)), o3dpp::Error);
    EXPECT_THROW(TriangleMesh::create_ellipsoid(1, 1, 1, 1), o3dpp::Error);
    EXPECT_THROW(TriangleMesh::create_ellipsoid(-1, 1, 1), o3dpp::Error);
    OrientedBoundingEllipsoid flat = obe;
    flat.radii = {1, 0, 1};
    EXPECT_THROW(TriangleMesh::create_from_oriented_bounding_ellipsoid(flat), o3dpp::Error);
}

TEST(BoundingVolumes, MeshOfABox) {
    OrientedBoundingBox obb;
    obb.center = {1, 2, 3};
    obb.R = some_rotation();
    obb.extent = {1, 2, 3};
    const TriangleMesh mesh = TriangleMesh::create_from_oriented_bounding_box(obb, {2, 1, 1});
    EXPECT_EQ(mesh.num_vertices(), 8);
    EXPECT_EQ(mesh.num_triangles(), 12);
    EXPECT_TRUE(mesh.is_watertight());
    EXPECT_NEAR(mesh.get_volume(), 12.0, 1e-9);
    obb.extent = {1, -2, 3};
    EXPECT_THROW(TriangleMesh::create_from_oriented_bounding_box(obb), o3dpp::Error);
}

TEST(PointCloudSmoothing, TwoPointsByHand) {
    const PointCloud two(std::vector<Vec3>{{0, 0, 0}, {1, 0, 0}});
    // One Laplacian step of 0.5 meets in the middle.
    auto pts = two.smooth_laplacian(1, 0.5, 1).get_points();
    EXPECT_NEAR(pts[0][0], 0.5, 1e-12);
    EXPECT_NEAR(pts[1][0], 0.5, 1e-12);
    // Taubin: 0.25 in (0.25, 0.75), then -0.5 back out to (0, 1).
    pts = two.smooth_taubin(1, 0.25, -0.5, 1).get_points();
    EXPECT_NEAR(pts[0][0], 0.0, 1e-12);
    EXPECT_NEAR(pts[1][0], 1.0, 1e-12);
    EXPECT_THROW(two.smooth_laplacian(1, 0.5, 0), o3dpp::Error);
    EXPECT_THROW(two.smooth_taubin(-1), o3dpp::Error);
}

TEST(PointCloudSmoothing, PlaneStaysFlat) {
    PointCloud plane(grid(10, 0.01));
    for (const Vec3& p : plane.smooth_mls().get_points()) EXPECT_NEAR(p[2], 0.0, 1e-12);
    plane.set_normals(std::vector<Vec3>(plane.size(), Vec3{0, 0, 1}));
    const PointCloud b = plane.smooth_bilateral(SearchParam::Hybrid(0.05, 30), 0.05, 0.05);
    ASSERT_EQ(b.size(), plane.size());
    for (const Vec3& p : b.get_points()) EXPECT_NEAR(p[2], 0.0, 1e-12);
    EXPECT_THROW(plane.smooth_bilateral(SearchParam::Hybrid(0.05, 30), 0.0), o3dpp::Error);
    EXPECT_THROW(plane.smooth_mls(SearchParam::Radius(-1.0)), o3dpp::Error);
}

TEST(PointCloudCovariances, CubeCornersStatic) {
    std::vector<Vec3> corners;
    for (double x : {0.0, 1.0})
        for (double y : {0.0, 1.0})
            for (double z : {0.0, 1.0}) corners.push_back({x, y, z});
    const PointCloud cube(corners);
    const std::vector<Mat3> cov = PointCloud::estimate_point_covariances(cube, SearchParam::Knn(8));
    ASSERT_EQ(cov.size(), 8u);
    for (const Mat3& c : cov)
        for (int i = 0; i < 9; ++i) EXPECT_NEAR(c[i], i % 4 == 0 ? 0.25 : 0.0, 1e-12);
    EXPECT_FALSE(cube.has_covariances());  // static: the cloud is unchanged
    EXPECT_THROW(PointCloud::estimate_point_covariances(cube, SearchParam::Knn(8), -1), o3dpp::Error);
}

TEST(PlanarPatches, OneFlatPatch) {
    PointCloud plane(grid(30, 1.0 / 29));
    o3dpp::PlanarPatchOptions options;
    EXPECT_DOUBLE_EQ(options.normal_variance_threshold_deg, 60.0);
    EXPECT_DOUBLE_EQ(options.coplanarity_deg, 75.0);
    EXPECT_EQ(SearchParam(options.search_param).kind, o3dpp::SearchKind::Knn);
    EXPECT_EQ(options.search_param.knn, 30);
    EXPECT_THROW(plane.detect_planar_patches(), o3dpp::Error);  // needs normals
    plane.set_normals(std::vector<Vec3>(plane.size(), Vec3{0, 0, 1}));
    options.search_param = SearchParam::Knn(20);
    const std::vector<OrientedBoundingBox> patches = plane.detect_planar_patches(options);
    ASSERT_EQ(patches.size(), 1u);
    const OrientedBoundingBox& p = patches[0];
    EXPECT_NEAR(std::fabs(p.R[8]), 1.0, 1e-6);  // column 2, the normal, along z
    EXPECT_NEAR(p.center[2], 0.0, 1e-6);
    EXPECT_NEAR(p.center[0], 0.5, 0.05);
    EXPECT_NEAR(p.center[1], 0.5, 0.05);
    options.outlier_ratio = 1.5;
    EXPECT_THROW(plane.detect_planar_patches(options), o3dpp::Error);
}

TEST(VoxelDownSampleAndTrace, TwoVoxels) {
    const PointCloud cloud(std::vector<Vec3>{{0.1, 0.1, 0.1}, {0.2, 0.2, 0.2}, {1.7, 0.1, 0.1}});
    const auto trace = cloud.voxel_down_sample_and_trace(1.0, {0, 0, 0}, {2, 2, 2});
    const auto pts = trace.cloud.get_points();
    ASSERT_EQ(pts.size(), 2u);
    EXPECT_NEAR(pts[0][0], 0.15, 1e-12);
    EXPECT_NEAR(pts[1][0], 1.7, 1e-12);
    EXPECT_EQ(trace.original_indices, (o3dpp::IndexLists{{0, 1}, {2}}));
    ASSERT_EQ(trace.cubic_ids.size(), 2u);
    EXPECT_EQ(trace.cubic_ids[0], (std::array<int, 8>{1, -1, -1, -1, -1, -1, -1, -1}));  // both in the lower octant
    EXPECT_EQ(trace.cubic_ids[1], (std::array<int, 8>{-1, 2, -1, -1, -1, -1, -1, -1}));  // upper half along x
    EXPECT_THROW(cloud.voxel_down_sample_and_trace(0.0, {0, 0, 0}, {2, 2, 2}), o3dpp::Error);
    EXPECT_THROW(cloud.voxel_down_sample_and_trace(1.0, {0, 0, 0}, {-1, 2, 2}), o3dpp::Error);
}

TEST(MeshFilters, SharpenOneTriangleByHand) {
    const TriangleMesh tri({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}, {{0, 1, 2}});
    // v += sum over neighbours (v - neighbour).
    const auto v = tri.filter_sharpen().get_vertices();
    EXPECT_EQ(v[0], (Vec3{-1, -1, 0}));
    EXPECT_EQ(v[1], (Vec3{3, -1, 0}));
    EXPECT_EQ(v[2], (Vec3{-1, 3, 0}));
    const auto half = tri.filter_sharpen(1, 0.5, o3dpp::FilterScope::Vertex).get_vertices();
    EXPECT_EQ(half[0], (Vec3{-0.5, -0.5, 0}));
    EXPECT_THROW(tri.filter_sharpen(-1), o3dpp::Error);
    EXPECT_THROW(tri.filter_sharpen(1, std::nan("")), o3dpp::Error);
}

TEST(MeshDeformation, RigidMotionReproduced) {
    const TriangleMesh sphere = TriangleMesh::create_sphere(1.0, 8);
    const auto verts = sphere.get_vertices();
    const Mat3 R = some_rotation();
    const Vec3 t{0.4, -1.0, 2.0};
    // Both caps (|z| > 0.5) moved rigidly: the whole sphere follows.
    std::vector<int32_t> ids;
    std::vector<Vec3> targets, shifted;
    for (std::size_t i = 0; i < verts.size(); ++i)
        if (std::fabs(verts[i][2]) > 0.5) {
            ids.push_back(static_cast<int32_t>(i));
            targets.push_back(apply(R, verts[i], t));
            shifted.push_back(apply({1, 0, 0, 0, 1, 0, 0, 0, 1}, verts[i], t));
        }
    const auto out = sphere.deform_as_rigid_as_possible(ids, targets, 60).get_vertices();
    ASSERT_EQ(out.size(), verts.size());
    for (std::size_t i = 0; i < verts.size(); ++i) {
        const Vec3 want = apply(R, verts[i], t);
        for (int k = 0; k < 3; ++k) EXPECT_NEAR(out[i][k], want[k], 1e-6);
    }
    // A translation is reproduced by either energy at once.
    for (auto energy : {DeformAsRigidAsPossibleEnergy::Spokes, DeformAsRigidAsPossibleEnergy::Smoothed}) {
        const auto moved = sphere.deform_as_rigid_as_possible(ids, shifted, 2, energy).get_vertices();
        for (std::size_t i = 0; i < verts.size(); ++i)
            for (int k = 0; k < 3; ++k) EXPECT_NEAR(moved[i][k], verts[i][k] + t[k], 1e-9);
    }
    // max_iter 0 returns the input positions.
    EXPECT_EQ(sphere.deform_as_rigid_as_possible(ids, targets, 0).get_vertices(), verts);
    EXPECT_THROW(sphere.deform_as_rigid_as_possible({0, 1}, {targets[0]}, 5), o3dpp::Error);
    EXPECT_THROW(sphere.deform_as_rigid_as_possible({}, {}, 5), o3dpp::Error);
    EXPECT_THROW(sphere.deform_as_rigid_as_possible({100000}, {targets[0]}, 5), o3dpp::Error);
    EXPECT_THROW(sphere.deform_as_rigid_as_possible({0, 0}, {targets[0], targets[0]}, 5), o3dpp::Error);
    EXPECT_THROW(sphere.deform_as_rigid_as_possible({0}, {targets[0]}, -1), o3dpp::Error);
}
