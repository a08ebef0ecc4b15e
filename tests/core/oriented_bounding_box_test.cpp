// SPDX-License-Identifier: MIT
// Oriented bounding boxes: rotated boxes recovered, Open3D's corner order, containment, crops,
// Open3D 0.20 reference numbers, errors.
#include "o3d/geometry/oriented_bounding_box.h"

#include <Eigen/Geometry>
#include <gtest/gtest.h>

#include <algorithm>
#include <random>

#include "o3d/io/point_cloud_io.h"
#include "o3d/utility/error.h"
#include "test_data.h"

using namespace o3d::geometry;

namespace {

Eigen::Matrix3d some_rotation() {
    return (Eigen::AngleAxisd(0.7, Eigen::Vector3d(1, 2, 3).normalized()) *
            Eigen::AngleAxisd(0.3, Eigen::Vector3d::UnitX()))
        .toRotationMatrix();
}

/// Points filling a box of the given full extents, rotated by R and centred at c, with its 8 corners.
std::vector<Eigen::Vector3d> rotated_box_points(const Eigen::Vector3d& extent, const Eigen::Matrix3d& R,
                                                const Eigen::Vector3d& c, size_t n, uint64_t seed) {
    std::mt19937_64 rng(seed);
    std::uniform_real_distribution<double> u(-0.5, 0.5);
    std::vector<Eigen::Vector3d> pts;
    for (int i = 0; i < 8; ++i)
        pts.push_back(R * Eigen::Vector3d((i & 1) - 0.5, ((i >> 1) & 1) - 0.5, ((i >> 2) & 1) - 0.5)
                                  .cwiseProduct(extent) +
                      c);
    for (size_t i = 0; i < n; ++i) pts.push_back(R * Eigen::Vector3d(u(rng), u(rng), u(rng)).cwiseProduct(extent) + c);
    return pts;
}

bool same_point_set(std::array<Eigen::Vector3d, 8> a, std::vector<Eigen::Vector3d> b, double tol) {
    for (const auto& p : a) {
        const auto it = std::find_if(b.begin(), b.end(), [&](const Eigen::Vector3d& q) { return (p - q).norm() < tol; });
        if (it == b.end()) return false;
        b.erase(it);
    }
    return b.empty();
}

}  // namespace

TEST(OrientedBoundingBox, RecoversARotatedBox) {
    const Eigen::Vector3d extent(4.0, 2.0, 1.0), c(1.0, -2.0, 3.0);
    const Eigen::Matrix3d R = some_rotation();
    const auto pts = rotated_box_points(extent, R, c, 500, 2);
    const OrientedBoundingBox box = obb_from_points(pts);
    EXPECT_NEAR(box.volume(), 8.0, 1e-9);
    EXPECT_TRUE(box.extent.isApprox(extent, 1e-9)) << box.extent.transpose();  // decreasing variance order
    EXPECT_TRUE(box.center.isApprox(c, 1e-9)) << box.center.transpose();
    EXPECT_NEAR(box.R.determinant(), 1.0, 1e-12);
    for (int k = 0; k < 3; ++k) EXPECT_NEAR(std::abs(box.R.col(k).dot(R.col(k))), 1.0, 1e-9);
    const auto corners = box_points(box);
    EXPECT_TRUE(same_point_set(corners, std::vector<Eigen::Vector3d>(pts.begin(), pts.begin() + 8), 1e-9));
    EXPECT_EQ(indices_in_obb(pts, box).size(), pts.size());
}

TEST(OrientedBoundingBox, BoxPointsInOpen3DOrder) {
    // Open3D 0.20: OrientedBoundingBox(0, I, [2,4,6]).get_box_points() (tools/reference/record_hull_obb.py probe).
    const OrientedBoundingBox box = obb_from_aabb(Eigen::Vector3d(-1, -2, -3), Eigen::Vector3d(1, 2, 3));
    const double expected[8][3] = {{-1, -2, -3}, {1, -2, -3}, {-1, 2, -3}, {-1, -2, 3},
                                   {1, 2, 3},    {-1, 2, 3},  {1, -2, 3},  {1, 2, -3}};
    const auto corners = box_points(box);
    for (int i = 0; i < 8; ++i)
        EXPECT_EQ(corners[static_cast<size_t>(i)], Eigen::Vector3d(expected[i][0], expected[i][1], expected[i][2]));
    EXPECT_EQ(box.R, Eigen::Matrix3d::Identity());
    EXPECT_DOUBLE_EQ(box.volume(), 48.0);
}

TEST(OrientedBoundingBox, ContainmentAndCrops) {
    OrientedBoundingBox box;
    box.R = some_rotation();
    box.center = Eigen::Vector3d(1, 1, 1);
    box.extent = Eigen::Vector3d(2, 2, 2);
    PointCloud cloud;
    cloud.points = {box.center, box.center + box.R.col(0) * 0.99, box.center + box.R.col(1) * 1.01,
                    Eigen::Vector3d(NAN, 0, 0), box.center - box.R.col(2) * 0.5};
    cloud.colors.assign(cloud.points.size(), Eigen::Vector3d(0.5, 0.5, 0.5));
    cloud.covariances.assign(cloud.points.size(), Eigen::Matrix3d::Identity() * 2.0);
    const std::vector<int64_t> inside = indices_in_obb(cloud.points, box);
    EXPECT_EQ(inside, (std::vector<int64_t>{0, 1, 4}));
    const PointCloud in = crop_obb(cloud, box);
    ASSERT_EQ(in.size(), 3u);
    EXPECT_TRUE(in.has_colors());
    EXPECT_TRUE(in.has_covariances());
    EXPECT_EQ(crop_obb(cloud, box, true).size(), 2u);

    TriangleMesh mesh;
    mesh.vertices = {box.center, box.center + box.R.col(0) * 0.5, box.center + box.R.col(1) * 0.5,
                     box.center + box.R.col(2) * 3.0};
    mesh.triangles = {{0, 1, 2}, {0, 1, 3}};
    const TriangleMesh cropped = crop_obb(mesh, box);
    ASSERT_EQ(cropped.triangles.size(), 1u);
    EXPECT_EQ(cropped.vertices.size(), 3u);
    EXPECT_EQ(cropped.triangles[0], Eigen::Vector3i(0, 1, 2));
}

// Numbers from tools/reference/record_hull_obb.py (Open3D 0.20).
TEST(OrientedBoundingBox, MatchesOpen3DOnCloudBin0) {
    O3D_TEST_DATA_OR_SKIP(path, "open3d/Feature/cloud_bin_0.pcd");
    const PointCloud cloud = o3d::io::read_point_cloud(path);
    const OrientedBoundingBox box = obb_from_points(cloud.points);
    EXPECT_NEAR(box.volume(), 6.74249408362, 1e-8);
    EXPECT_TRUE(box.center.isApprox(Eigen::Vector3d(2.15397555865, 0.979776182279, -1.73828953775), 1e-9));
    EXPECT_TRUE(box.extent.isApprox(Eigen::Vector3d(2.16487489043, 2.0313580173, 1.53320878242), 1e-9));
    Eigen::Matrix3d R_open3d;
    R_open3d << -0.104056401588, 0.865994749907, 0.489106694314, 0.962834110719, 0.210954427097, -0.168667438836,
        -0.249244339001, 0.453377682316, -0.855760443497;
    for (int k = 0; k < 3; ++k)  // the same axes up to sign (Open3D's eigenvector signs are arbitrary)
        EXPECT_NEAR(std::abs(box.R.col(k).dot(R_open3d.col(k))), 1.0, 1e-9);
    // Open3D counts 3902 of 3903 inside: the extreme hull points sit on the boundary, where rounding decides.
    EXPECT_GE(indices_in_obb(cloud.points, box).size(), 3902u);
}

TEST(OrientedBoundingBox, FlatSetsNeedRobust) {
    std::vector<Eigen::Vector3d> square = {{0, 0, 0}, {2, 0, 0}, {0, 1, 0}, {2, 1, 0}, {1, 0.5, 0}};
    EXPECT_THROW(obb_from_points(square, false), o3d::InvalidArgument);
    const OrientedBoundingBox box = obb_from_points(square, true);
    EXPECT_NEAR(box.extent(0), 2.0, 1e-6);
    EXPECT_NEAR(box.extent(1), 1.0, 1e-6);
    EXPECT_NEAR(box.extent(2), 0.0, 1e-6);
}

TEST(OrientedBoundingBox, Errors) {
    EXPECT_THROW(obb_from_points({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}), o3d::InvalidArgument);
    EXPECT_THROW(obb_from_points({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, NAN}}), o3d::InvalidArgument);
    EXPECT_THROW(obb_from_aabb(Eigen::Vector3d(1, 0, 0), Eigen::Vector3d(0, 1, 1)), o3d::InvalidArgument);
    OrientedBoundingBox bad;
    bad.extent = Eigen::Vector3d(1, 1, 1);
    bad.R(0, 0) = 2.0;  // not a rotation
    EXPECT_THROW(indices_in_obb({{0, 0, 0}}, bad), o3d::InvalidArgument);
    OrientedBoundingBox flat;
    flat.extent = Eigen::Vector3d(1, 1, 0);
    PointCloud cloud;
    cloud.points = {{0, 0, 0}};
    EXPECT_THROW(crop_obb(cloud, flat), o3d::InvalidArgument);
    flat.extent(2) = -1.0;
    EXPECT_THROW(indices_in_obb(cloud.points, flat), o3d::InvalidArgument);
}
