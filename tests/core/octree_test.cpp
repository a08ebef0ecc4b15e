// SPDX-License-Identifier: MIT
// Octrees over point clouds: analytic cases, and Open3D 0.20's numbers on cloud_bin_0 recorded by
// tools/reference/record_lineset_voxel_octree.py.
#include <gtest/gtest.h>

#include <cmath>
#include <numeric>

#include "o3d/geometry/octree_ops.h"
#include "o3d/io/point_cloud_io.h"
#include "o3d/utility/error.h"
#include "test_data.h"

using namespace o3d::geometry;

TEST(Octree, EightCornersGiveEightLeavesAtDepthOne) {
    PointCloud pc;
    for (int i = 0; i < 8; ++i) {
        pc.points.emplace_back(i & 1, (i >> 1) & 1, (i >> 2) & 1);
        pc.colors.emplace_back(i / 8.0, 0.5, 1.0);
    }
    Octree tree = make_octree(1);
    octree_from_point_cloud(tree, pc, 0.01);
    EXPECT_TRUE(tree.origin.isZero());
    EXPECT_DOUBLE_EQ(tree.size, 1.01);
    EXPECT_EQ(count_leaves(tree), 8u);
    for (int i = 0; i < 8; ++i) {
        OctreeNodeInfo info;
        const int leaf = locate_leaf(tree, pc.points[i], &info);
        ASSERT_GE(leaf, 0) << i;
        EXPECT_EQ(tree.nodes[leaf].indices, std::vector<int>{i});
        EXPECT_TRUE(tree.nodes[leaf].color.isApprox(pc.colors[i]));
        EXPECT_EQ(info.depth, 1);
        EXPECT_EQ(info.child_index, i);  // corner i has bits (x, y, z) = child x + 2y + 4z
        EXPECT_DOUBLE_EQ(info.size, 0.505);
        // The leaf's cube holds its point.
        EXPECT_TRUE((pc.points[i].array() >= info.origin.array()).all());
        EXPECT_TRUE((pc.points[i].array() < info.origin.array() + info.size).all());
    }
    OctreeNodeInfo info;
    EXPECT_EQ(locate_leaf(tree, {2, 2, 2}, &info), -1);  // outside the root
}

TEST(Octree, RootCubeAndLeavesLikeOpen3D) {
    // Open3D 0.20 on these points with Octree(2), size_expand 0.1: origin (-1, -0.5, 0), size 3.3, and the
    // leaves (origin, child index) printed below.
    PointCloud pc;
    pc.points = {{0, 0, 0}, {1, 2, 3}, {0.2, 1.9, 0.1}, {0.9, 0.1, 2.9}, {0.21, 1.91, 0.11}};
    Octree tree = make_octree(2);
    octree_from_point_cloud(tree, pc, 0.1);
    EXPECT_TRUE(tree.origin.isApprox(Eigen::Vector3d(-1, -0.5, 0)));
    EXPECT_NEAR(tree.size, 3.3, 1e-12);
    EXPECT_EQ(count_leaves(tree), 4u);
    OctreeNodeInfo info;
    int leaf = locate_leaf(tree, pc.points[1], &info);
    ASSERT_GE(leaf, 0);
    EXPECT_TRUE(info.origin.isApprox(Eigen::Vector3d(0.65, 1.975, 2.475)));
    EXPECT_NEAR(info.size, 0.825, 1e-12);
    EXPECT_EQ(info.child_index, 6);
    leaf = locate_leaf(tree, pc.points[2], &info);
    ASSERT_GE(leaf, 0);
    EXPECT_EQ(tree.nodes[leaf].indices, (std::vector<int>{2, 4}));
    EXPECT_TRUE(info.origin.isApprox(Eigen::Vector3d(-0.175, 1.15, 0.0)));
    EXPECT_EQ(info.child_index, 1);
    EXPECT_EQ(locate_leaf(tree, {0.9, 1.9, 0.1}, &info), -1);  // inside the root, empty cell

    // size_expand 0: the max corner lies on the open side of the root cube and is dropped (as Open3D).
    octree_from_point_cloud(tree, pc, 0.0);
    EXPECT_EQ(locate_leaf(tree, pc.points[1], &info), -1);
    EXPECT_EQ(count_leaves(tree), 3u);  // Open3D 0.20: 3 leaves, and None for (1, 2, 3)
}

TEST(Octree, BadInputsAreErrors) {
    EXPECT_THROW(make_octree(0), o3d::InvalidArgument);
    EXPECT_THROW(make_octree(kMaxOctreeDepth + 1), o3d::InvalidArgument);
    Octree tree = make_octree(3);
    PointCloud pc;
    EXPECT_THROW(octree_from_point_cloud(tree, pc, 0.01), o3d::InvalidArgument);
    pc.points = {{0, 0, 0}, {1, 1, 1}};
    EXPECT_THROW(octree_from_point_cloud(tree, pc, -0.1), o3d::InvalidArgument);
    EXPECT_THROW(octree_from_point_cloud(tree, pc, std::nan("")), o3d::InvalidArgument);
    pc.points.emplace_back(NAN, 0, 0);
    EXPECT_THROW(octree_from_point_cloud(tree, pc, 0.01), o3d::InvalidArgument);
    EXPECT_EQ(locate_leaf(tree, {0, 0, 0}, nullptr), -1);  // empty tree
}

TEST(Octree, CloudBin0DepthFourMatchesOpen3D) {
    O3D_TEST_DATA_OR_SKIP(path, "open3d/Feature/cloud_bin_0.pcd");
    const PointCloud pc = o3d::io::read_point_cloud(path);
    Octree tree = make_octree(4);
    octree_from_point_cloud(tree, pc, 0.01);
    // record_lineset_voxel_octree.py
    EXPECT_NEAR(tree.origin.x(), 1.0449087405577302, 1e-12);
    EXPECT_NEAR(tree.origin.y(), -0.00485198013484478, 1e-12);
    EXPECT_NEAR(tree.origin.z(), -2.5949632441625, 1e-12);
    EXPECT_NEAR(tree.size, 2.1118266860209407, 1e-12);
    EXPECT_EQ(count_leaves(tree), 472u);
    OctreeNodeInfo info;
    const int leaf = locate_leaf(tree, pc.points[1000], &info);
    ASSERT_GE(leaf, 0);
    EXPECT_NEAR(info.origin.x(), 2.760767922949744, 1e-12);
    EXPECT_NEAR(info.origin.y(), 1.315039698628243, 1e-12);
    EXPECT_NEAR(info.origin.z(), -1.5390499011520296, 1e-12);
    EXPECT_NEAR(info.size, 0.1319891678763088, 1e-12);
    EXPECT_EQ(info.depth, 4);
    EXPECT_EQ(info.child_index, 1);
    const std::vector<int>& ind = tree.nodes[leaf].indices;
    ASSERT_EQ(ind.size(), 12u);
    EXPECT_EQ(std::accumulate(ind.begin(), ind.end(), 0), 19870);
    EXPECT_EQ(std::vector<int>(ind.begin(), ind.begin() + 5), (std::vector<int>{473, 596, 612, 875, 1000}));
    // The mean color of the leaf's points (o3d's header; Open3D 0.20 keeps the last point's color instead).
    EXPECT_NEAR(tree.nodes[leaf].color(0), 0.19084967320261437, 1e-12);
    EXPECT_NEAR(tree.nodes[leaf].color(1), 0.18529411764705883, 1e-12);
    EXPECT_NEAR(tree.nodes[leaf].color(2), 0.18169934640522875, 1e-12);
    // Every point inside the root is in exactly one leaf.
    size_t total = 0;
    for (const OctreeNode& n : tree.nodes) total += n.indices.size();
    EXPECT_EQ(total, pc.points.size());
}
