// SPDX-License-Identifier: MIT
// Point-cloud operations: append, transforms, bounds, selection, non-finite removal, normalisation.
#include <Eigen/Geometry>
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "o3d/geometry/point_cloud_ops.h"
#include "o3d/utility/error.h"

using namespace o3d::geometry;

namespace {

PointCloud make_cloud(size_t n, bool normals, bool colors) {
    PointCloud c;
    for (size_t i = 0; i < n; ++i) {
        const double t = static_cast<double>(i);
        c.points.emplace_back(t, 2 * t, -t);
        if (normals) c.normals.emplace_back(0, 0, 1);
        if (colors) c.colors.emplace_back(0.1 * t, 0.5, 0.2);
    }
    return c;
}

}  // namespace

TEST(PointCloudOps, AppendKeepsAttributesOnlyWhenBothHaveThem) {
    PointCloud a = make_cloud(3, true, true);
    append(a, make_cloud(2, true, false));
    EXPECT_EQ(a.size(), 5u);
    EXPECT_TRUE(a.has_normals());
    EXPECT_FALSE(a.has_colors());
    EXPECT_TRUE(a.colors.empty());

    PointCloud empty;
    append(empty, make_cloud(2, true, true));  // empty target takes the source's attributes
    EXPECT_TRUE(empty.has_normals());
    EXPECT_TRUE(empty.has_colors());

    PointCloud b = make_cloud(2, true, true);
    append(b, PointCloud{});  // appending nothing changes nothing
    EXPECT_EQ(b.size(), 2u);
    EXPECT_TRUE(b.has_normals());
}

TEST(PointCloudOps, BoundsAndCenter) {
    const PointCloud c = make_cloud(4, false, false);  // points (t, 2t, -t), t = 0..3
    EXPECT_EQ(min_bound(c), Eigen::Vector3d(0, 0, -3));
    EXPECT_EQ(max_bound(c), Eigen::Vector3d(3, 6, 0));
    EXPECT_EQ(center(c), Eigen::Vector3d(1.5, 3, -1.5));
    EXPECT_EQ(center(PointCloud{}), Eigen::Vector3d::Zero());
    EXPECT_EQ(min_bound(PointCloud{}), Eigen::Vector3d::Zero());
}

TEST(PointCloudOps, TransformMovesPointsAndRotatesNormals) {
    PointCloud c;
    c.points = {{1, 0, 0}, {0, 1, 0}};
    c.normals = {{1, 0, 0}, {0, 0, 1}};
    Eigen::Matrix4d t = Eigen::Matrix4d::Identity();
    t.topLeftCorner<3, 3>() = Eigen::AngleAxisd(M_PI / 2, Eigen::Vector3d::UnitZ()).toRotationMatrix();
    t.topRightCorner<3, 1>() = Eigen::Vector3d(10, 20, 30);
    transform(c, t);
    EXPECT_TRUE(c.points[0].isApprox(Eigen::Vector3d(10, 21, 30), 1e-12));
    EXPECT_TRUE(c.points[1].isApprox(Eigen::Vector3d(9, 20, 30), 1e-12));
    EXPECT_TRUE(c.normals[0].isApprox(Eigen::Vector3d(0, 1, 0), 1e-12));  // rotated, not translated
    EXPECT_TRUE(c.normals[1].isApprox(Eigen::Vector3d(0, 0, 1), 1e-12));
    t(0, 0) = NAN;
    EXPECT_THROW(transform(c, t), o3d::InvalidArgument);
}

TEST(PointCloudOps, TranslateRotateScaleAboutCenter) {
    PointCloud c;
    c.points = {{0, 0, 0}, {2, 0, 0}};
    translate(c, {1, 1, 1}, true);
    EXPECT_EQ(c.points[0], Eigen::Vector3d(1, 1, 1));
    translate(c, {0, 0, 0}, false);  // center (2,1,1) moves to the origin
    EXPECT_EQ(c.points[0], Eigen::Vector3d(-1, 0, 0));
    EXPECT_EQ(c.points[1], Eigen::Vector3d(1, 0, 0));
    scale(c, 3.0, Eigen::Vector3d(1, 0, 0));
    EXPECT_EQ(c.points[0], Eigen::Vector3d(-5, 0, 0));
    EXPECT_EQ(c.points[1], Eigen::Vector3d(1, 0, 0));
    const Eigen::Matrix3d r = Eigen::AngleAxisd(M_PI, Eigen::Vector3d::UnitZ()).toRotationMatrix();
    rotate(c, r, Eigen::Vector3d(1, 0, 0));
    EXPECT_TRUE(c.points[0].isApprox(Eigen::Vector3d(7, 0, 0), 1e-12));
    EXPECT_TRUE(c.points[1].isApprox(Eigen::Vector3d(1, 0, 0), 1e-12));
}

TEST(PointCloudOps, SelectByIndexKeepsOrderCollapsesDuplicatesAndInverts) {
    const PointCloud c = make_cloud(6, true, true);
    const PointCloud s = select_by_index(c, {4, 1, 4, 1});
    ASSERT_EQ(s.size(), 2u);
    EXPECT_EQ(s.points[0], c.points[1]);
    EXPECT_EQ(s.points[1], c.points[4]);
    EXPECT_EQ(s.colors[1], c.colors[4]);
    EXPECT_TRUE(s.has_normals());
    const PointCloud inv = select_by_index(c, {4, 1}, true);
    ASSERT_EQ(inv.size(), 4u);
    EXPECT_EQ(inv.points[0], c.points[0]);
    EXPECT_EQ(inv.points[1], c.points[2]);
    EXPECT_EQ(inv.points[3], c.points[5]);
    EXPECT_THROW(select_by_index(c, {6}), o3d::InvalidArgument);
    EXPECT_THROW(select_by_index(c, {-1}), o3d::InvalidArgument);
}

TEST(PointCloudOps, RemoveNonFiniteHonoursFlags) {
    PointCloud base = make_cloud(4, true, true);
    base.points[1].x() = std::numeric_limits<double>::quiet_NaN();
    base.points[2].z() = -std::numeric_limits<double>::infinity();

    PointCloud c = base;
    remove_non_finite_points(c, true, false);
    ASSERT_EQ(c.size(), 3u);
    EXPECT_TRUE(std::isinf(c.points[1].z()));
    EXPECT_EQ(c.colors[2], base.colors[3]);  // attributes follow their points

    c = base;
    remove_non_finite_points(c, false, true);
    ASSERT_EQ(c.size(), 3u);
    EXPECT_TRUE(std::isnan(c.points[1].x()));

    c = base;
    remove_non_finite_points(c, true, true);
    ASSERT_EQ(c.size(), 2u);
    EXPECT_EQ(c.points[1], base.points[3]);
    EXPECT_EQ(c.normals.size(), 2u);

    c = base;
    remove_non_finite_points(c, false, false);
    EXPECT_EQ(c.size(), 4u);
}

TEST(PointCloudOps, PaintAndNormalize) {
    PointCloud c = make_cloud(3, false, false);
    paint_uniform_color(c, {0.2, 1.5, -1});
    ASSERT_TRUE(c.has_colors());
    EXPECT_EQ(c.colors[2], Eigen::Vector3d(0.2, 1.0, 0.0));  // clipped like Open3D
    c.normals = {{3, 4, 0}, {0, 0, 0}, {0, 0, -2}};
    normalize_normals(c);
    EXPECT_TRUE(c.normals[0].isApprox(Eigen::Vector3d(0.6, 0.8, 0), 1e-15));
    EXPECT_EQ(c.normals[1], Eigen::Vector3d::Zero());
    EXPECT_EQ(c.normals[2], Eigen::Vector3d(0, 0, -1));
}
