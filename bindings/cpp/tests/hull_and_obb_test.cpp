// SPDX-License-Identifier: MIT
// OrientedBoundingBox, cropping by it, convex hulls and hidden-point removal through the wrapper:
// analytic boxes and hulls, Open3D 0.20's corner order (tools/reference/record_bindings_round2.py),
// errors as exceptions.
#include <algorithm>
#include <cmath>
#include <limits>

#include "test_util.hpp"

using o3dpp::OrientedBoundingBox;
using o3dpp::PointCloud;
using o3dpp::TriangleMesh;
using o3dpp::Vec3;

namespace {
/// Corners of [0,2] x [0,1] x [0,0.5], then two interior points.
std::vector<Vec3> box_points() {
    std::vector<Vec3> pts;
    for (double x : {0.0, 2.0})
        for (double y : {0.0, 1.0})
            for (double z : {0.0, 0.5}) pts.push_back({x, y, z});
    pts.push_back({1.0, 0.5, 0.25});
    pts.push_back({0.5, 0.2, 0.1});
    return pts;
}

Vec3 sub(const Vec3& a, const Vec3& b) { return {a[0] - b[0], a[1] - b[1], a[2] - b[2]}; }
Vec3 cross(const Vec3& a, const Vec3& b) {
    return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}
double dot(const Vec3& a, const Vec3& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }

/// Every triangle's normal points away from `inside`.
void expect_outward(const TriangleMesh& mesh, const Vec3& inside) {
    const auto v = mesh.get_vertices();
    for (const auto& t : mesh.get_triangles()) {
        const Vec3 n = cross(sub(v[t[1]], v[t[0]]), sub(v[t[2]], v[t[0]]));
        EXPECT_GT(dot(n, sub(v[t[0]], inside)), 0.0) << t[0] << " " << t[1] << " " << t[2];
    }
}
}  // namespace

TEST(OrientedBoundingBox, AxisAlignedPointSetGivesItsExtentsAndVolume) {
    const auto pts = box_points();
    const auto obb = OrientedBoundingBox::create_from_points(pts);
    EXPECT_NEAR(obb.volume(), 1.0, 1e-9);
    for (int i = 0; i < 3; ++i) EXPECT_NEAR(obb.center[i], (Vec3{1.0, 0.5, 0.25})[i], 1e-9);
    Vec3 extent = obb.extent;
    std::sort(extent.begin(), extent.end());
    EXPECT_NEAR(extent[0], 0.5, 1e-9);
    EXPECT_NEAR(extent[1], 1.0, 1e-9);
    EXPECT_NEAR(extent[2], 2.0, 1e-9);
    // Whatever the axis order, the corners are the box's corners.
    auto corners = obb.get_box_points();
    std::vector<Vec3> got(corners.begin(), corners.end()), want(pts.begin(), pts.begin() + 8);
    for (auto& p : got)
        for (auto& x : p) x = std::round(x * 1e9) / 1e9 + 0.0;
    std::sort(got.begin(), got.end());
    std::sort(want.begin(), want.end());
    EXPECT_EQ(got, want);

    EXPECT_NEAR(PointCloud(pts).get_oriented_bounding_box().volume(), 1.0, 1e-9);
    EXPECT_NEAR(TriangleMesh::create_box(2, 1, 0.5).get_oriented_bounding_box().volume(), 1.0, 1e-9);
}

TEST(OrientedBoundingBox, AxisAlignedBoxFollowsOpen3DCornerOrder) {
    const auto obb = OrientedBoundingBox::create_from_axis_aligned_bounding_box({0, 0, 0}, {2, 1, 0.5});
    EXPECT_EQ(obb.center, (Vec3{1, 0.5, 0.25}));
    EXPECT_EQ(obb.R, (o3dpp::Mat3{1, 0, 0, 0, 1, 0, 0, 0, 1}));
    EXPECT_EQ(obb.extent, (Vec3{2, 1, 0.5}));
    // Open3D 0.20 get_box_points() (record_bindings_round2.py).
    const std::array<Vec3, 8> open3d{{{0, 0, 0}, {2, 0, 0}, {0, 1, 0}, {0, 0, 0.5},
                                      {2, 1, 0.5}, {0, 1, 0.5}, {2, 0, 0.5}, {2, 1, 0}}};
    EXPECT_EQ(obb.get_box_points(), open3d);
}

TEST(OrientedBoundingBox, IndicesWithinAndCrop) {
    // 2 x 1 x 1 box turned 45 degrees about z, centred at the origin.
    const double s = std::sqrt(0.5);
    OrientedBoundingBox obb;
    obb.R = {s, -s, 0, s, s, 0, 0, 0, 1};
    obb.extent = {2, 1, 1};
    const std::vector<Vec3> pts{{0, 0, 0}, {0.9 * s, 0.9 * s, 0}, {0.9, 0, 0}, {-0.3 * s, 0.3 * s, 0.4}, {0, 0, 0.6}};
    EXPECT_EQ(obb.get_point_indices_within_bounding_box(pts), (std::vector<int32_t>{0, 1, 3}));
    const PointCloud cloud(pts);
    EXPECT_EQ(cloud.crop(obb).size(), 3u);
    EXPECT_EQ(cloud.crop(obb, true).get_points(), (std::vector<Vec3>{pts[2], pts[4]}));
    const TriangleMesh mesh(pts, {{0, 1, 3}, {0, 1, 2}, {1, 3, 4}});
    const auto cropped = mesh.crop(obb);
    EXPECT_EQ(cropped.num_triangles(), 1u);
    EXPECT_EQ(cropped.num_vertices(), 3u);
}

TEST(OrientedBoundingBox, BadInputThrows) {
    EXPECT_O3D_ERROR(OrientedBoundingBox::create_from_points(std::vector<Vec3>{{0, 0, 0}, {1, 0, 0}}),
                     O3D_ERROR_INVALID_ARGUMENT);
    auto bad = box_points();
    bad[2][0] = std::numeric_limits<double>::quiet_NaN();
    EXPECT_O3D_ERROR(OrientedBoundingBox::create_from_points(bad), O3D_ERROR_INVALID_ARGUMENT);
    EXPECT_O3D_ERROR(OrientedBoundingBox::create_from_axis_aligned_bounding_box({1, 1, 1}, {0, 0, 0}),
                     O3D_ERROR_INVALID_ARGUMENT);
    const std::vector<Vec3> planar{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {1, 1, 0}, {0.5, 0.2, 0}};
    EXPECT_THROW(OrientedBoundingBox::create_from_points(planar), o3dpp::Error);
    EXPECT_NO_THROW(OrientedBoundingBox::create_from_points(planar, true));
    OrientedBoundingBox nan_box;
    nan_box.center[0] = std::numeric_limits<double>::quiet_NaN();
    EXPECT_O3D_ERROR(nan_box.get_box_points(), O3D_ERROR_INVALID_ARGUMENT);
    EXPECT_O3D_ERROR(PointCloud(box_points()).crop(nan_box), O3D_ERROR_INVALID_ARGUMENT);
}

TEST(ConvexHull, CubeCornersAndInteriorPointsGiveTheCube) {
    auto pts = o3dpp_test::random_points(20, 0.1, 0.9);
    for (double x : {0.0, 1.0})
        for (double y : {0.0, 1.0})
            for (double z : {0.0, 1.0}) pts.push_back({x, y, z});
    const auto [hull, indices] = o3dpp::compute_convex_hull(PointCloud(pts));
    EXPECT_EQ(hull.num_vertices(), 8u);
    EXPECT_EQ(hull.num_triangles(), 12u);
    EXPECT_NEAR(hull.get_volume(), 1.0, 1e-12);
    EXPECT_TRUE(hull.is_watertight());
    expect_outward(hull, {0.5, 0.5, 0.5});
    ASSERT_EQ(indices.size(), 8u);
    const auto v = hull.get_vertices();
    for (std::size_t i = 0; i < indices.size(); ++i) {
        EXPECT_GE(indices[i], 20);
        EXPECT_EQ(v[i], pts[indices[i]]);
    }

    const auto sphere = TriangleMesh::create_sphere(1.0, 10);
    const auto [mesh_hull, mesh_indices] = sphere.compute_convex_hull();
    EXPECT_EQ(mesh_indices.size(), mesh_hull.num_vertices());
    EXPECT_EQ(mesh_hull.num_vertices(), sphere.num_vertices());
    EXPECT_NEAR(mesh_hull.get_volume(), sphere.get_volume(), 1e-9);
    expect_outward(mesh_hull, {0, 0, 0});
    EXPECT_EQ(o3dpp::compute_convex_hull(sphere).second.size(), mesh_indices.size());
}

TEST(ConvexHull, DegenerateInputThrowsUnlessJoggled) {
    const PointCloud planar(std::vector<Vec3>{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {1, 1, 0}});
    EXPECT_THROW(o3dpp::compute_convex_hull(planar), o3dpp::Error);
    const auto joggled = o3dpp::compute_convex_hull(planar, true);
    EXPECT_EQ(joggled.second.size(), joggled.first.num_vertices());
    EXPECT_O3D_ERROR(o3dpp::compute_convex_hull(PointCloud()), O3D_ERROR_INVALID_ARGUMENT);
}

TEST(HiddenPointRemoval, KeepsTheSideFacingTheCamera) {
    const auto sphere = TriangleMesh::create_sphere(1.0, 20);
    const auto pts = sphere.get_vertices();
    const PointCloud cloud(pts);
    const auto [mesh, visible] = o3dpp::hidden_point_removal(cloud, {0, 0, 10}, 1000.0);
    ASSERT_FALSE(visible.empty());
    EXPECT_EQ(visible.size(), mesh.num_vertices());
    for (int32_t i : visible) EXPECT_GT(pts[i][2], 0.0) << i;
    const auto north = std::find_if(pts.begin(), pts.end(), [](const Vec3& p) { return p[2] > 1 - 1e-12; });
    const auto south = std::find_if(pts.begin(), pts.end(), [](const Vec3& p) { return p[2] < -1 + 1e-12; });
    EXPECT_NE(std::find(visible.begin(), visible.end(), int32_t(north - pts.begin())), visible.end());
    EXPECT_EQ(std::find(visible.begin(), visible.end(), int32_t(south - pts.begin())), visible.end());
    EXPECT_O3D_ERROR(o3dpp::hidden_point_removal(cloud, {0, 0, 10}, -1.0), O3D_ERROR_INVALID_ARGUMENT);
}
