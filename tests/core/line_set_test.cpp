// SPDX-License-Identifier: MIT
// Line sets: box edges, correspondences and mesh edges, checked analytically and against the order
// Open3D 0.20 uses (tools/reference/record_lineset_voxel_octree.py prints the same layouts).
#include <gtest/gtest.h>

#include <algorithm>
#include <set>
#include <utility>

#include "o3d/geometry/line_set_ops.h"
#include "o3d/utility/error.h"

using namespace o3d::geometry;

namespace {

std::multiset<double> edge_lengths(const LineSet& ls) {
    std::multiset<double> out;
    for (const auto& l : ls.lines) out.insert((ls.points[l(0)] - ls.points[l(1)]).norm());
    return out;
}

}  // namespace

TEST(LineSet, AxisAlignedBoxHasTwelveEdgesOfTheRightLengths) {
    const LineSet ls = line_set_from_axis_aligned_box({0, 0, 0}, {1, 2, 3});
    ASSERT_EQ(ls.points.size(), 8u);
    ASSERT_EQ(ls.lines.size(), 12u);
    validate_lines(ls);
    // Four edges of each length 1, 2, 3.
    const std::multiset<double> lengths = edge_lengths(ls);
    for (double len : {1.0, 2.0, 3.0}) EXPECT_EQ(lengths.count(len), 4u) << len;
    // Every corner of the box appears once, and each corner touches 3 edges.
    std::set<std::tuple<double, double, double>> corners;
    for (const auto& p : ls.points) corners.insert({p.x(), p.y(), p.z()});
    EXPECT_EQ(corners.size(), 8u);
    std::vector<int> degree(8, 0);
    for (const auto& l : ls.lines) ++degree[l(0)], ++degree[l(1)];
    for (int d : degree) EXPECT_EQ(d, 3);
    // Open3D 0.20's point order (get_box_points) for this box.
    EXPECT_TRUE(ls.points[0].isApprox(Eigen::Vector3d(0, 0, 0)));
    EXPECT_TRUE(ls.points[1].isApprox(Eigen::Vector3d(1, 0, 0)));
    EXPECT_TRUE(ls.points[2].isApprox(Eigen::Vector3d(0, 2, 0)));
    EXPECT_TRUE(ls.points[3].isApprox(Eigen::Vector3d(0, 0, 3)));
    EXPECT_TRUE(ls.points[4].isApprox(Eigen::Vector3d(1, 2, 3)));
    EXPECT_TRUE(ls.points[7].isApprox(Eigen::Vector3d(1, 2, 0)));
    EXPECT_EQ(ls.lines[1], Eigen::Vector2i(1, 7));
    EXPECT_EQ(ls.lines[11], Eigen::Vector2i(2, 5));
}

TEST(LineSet, OrientedBoxCornersFollowItsAxes) {
    // Rotated 90 degrees about z: local x runs along world y.
    Eigen::Matrix3d R;
    R << 0, -1, 0, 1, 0, 0, 0, 0, 1;
    const Eigen::Vector3d center(1, 1, 1), extent(2, 4, 6);
    const LineSet ls = line_set_from_oriented_box(center, R, extent);
    ASSERT_EQ(ls.points.size(), 8u);
    // Corner 1 is (+x, -y, -z) in box axes: center + R * (1, -2, -3).
    EXPECT_TRUE(ls.points[1].isApprox(center + R * Eigen::Vector3d(1, -2, -3)));
    EXPECT_TRUE(ls.points[4].isApprox(center + R * Eigen::Vector3d(1, 2, 3)));
    const std::multiset<double> lengths = edge_lengths(ls);
    for (double len : {2.0, 4.0, 6.0}) EXPECT_EQ(lengths.count(len), 4u) << len;
}

TEST(LineSet, CorrespondencesJoinTheRightPoints) {
    PointCloud a, b;
    a.points = {{0, 0, 0}, {1, 0, 0}};
    b.points = {{0, 5, 0}, {1, 5, 0}, {2, 5, 0}};
    const LineSet ls = line_set_from_correspondences(a, b, {{0, 2}, {1, 0}});
    ASSERT_EQ(ls.points.size(), 5u);
    ASSERT_EQ(ls.lines.size(), 2u);
    EXPECT_EQ(ls.lines[0], Eigen::Vector2i(0, 4));
    EXPECT_EQ(ls.lines[1], Eigen::Vector2i(1, 2));
    EXPECT_TRUE(ls.points[ls.lines[0](1)].isApprox(Eigen::Vector3d(2, 5, 0)));
    EXPECT_THROW(line_set_from_correspondences(a, b, {{2, 0}}), o3d::InvalidArgument);
    EXPECT_THROW(line_set_from_correspondences(a, b, {{0, 3}}), o3d::InvalidArgument);
    EXPECT_THROW(line_set_from_correspondences(a, b, {{-1, 0}}), o3d::InvalidArgument);
}

TEST(LineSet, MeshEdgesAreUniqueInOpen3DOrder) {
    // Open3D 0.20's create_box triangles and its create_from_triangle_mesh lines for them.
    TriangleMesh box;
    for (int i = 0; i < 8; ++i) box.vertices.emplace_back(i & 1, (i >> 1) & 1, (i >> 2) & 1);
    box.triangles = {{4, 7, 5}, {4, 6, 7}, {0, 2, 4}, {2, 6, 4}, {0, 1, 2}, {1, 3, 2},
                     {1, 5, 7}, {1, 7, 3}, {2, 3, 7}, {2, 7, 6}, {0, 4, 1}, {1, 4, 5}};
    const std::vector<Eigen::Vector2i> expected = {{4, 7}, {7, 5}, {5, 4}, {4, 6}, {6, 7}, {0, 2},
                                                   {2, 4}, {4, 0}, {2, 6}, {0, 1}, {1, 2}, {1, 3},
                                                   {3, 2}, {1, 5}, {7, 1}, {7, 3}, {7, 2}, {4, 1}};
    const LineSet ls = line_set_from_triangle_mesh(box);
    EXPECT_EQ(ls.points.size(), 8u);
    ASSERT_EQ(ls.lines.size(), expected.size());  // V - F + E = 2 on a sphere: 8 - 12 + 18
    for (size_t i = 0; i < expected.size(); ++i) EXPECT_EQ(ls.lines[i], expected[i]) << i;

    box.triangles.push_back({0, 1, 8});
    EXPECT_THROW(line_set_from_triangle_mesh(box), o3d::InvalidArgument);
}

TEST(LineSet, TransformPaintAndValidate) {
    LineSet ls = line_set_from_axis_aligned_box({0, 0, 0}, {1, 1, 1});
    Eigen::Matrix4d t = Eigen::Matrix4d::Identity();
    t(0, 3) = 10;
    transform_line_set(ls, t);
    EXPECT_TRUE(ls.points[0].isApprox(Eigen::Vector3d(10, 0, 0)));
    paint_line_set(ls, {0.5, 2.0, -1.0});
    ASSERT_TRUE(ls.has_colors());
    EXPECT_TRUE(ls.colors[3].isApprox(Eigen::Vector3d(0.5, 1.0, 0.0)));
    t(1, 1) = NAN;
    EXPECT_THROW(transform_line_set(ls, t), o3d::InvalidArgument);
    ls.lines.push_back({0, 8});
    EXPECT_THROW(validate_lines(ls), o3d::InvalidArgument);
}
