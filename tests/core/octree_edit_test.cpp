// SPDX-License-Identifier: MIT
// Octrees with given bounds: inserting points, traversal order and early stop, and the conversions to and
// from voxel grids; Open3D 0.20's numbers recorded by tools/reference/record_voxel_edit_octree.py.
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <utility>
#include <vector>

#include "o3d/geometry/octree_edit.h"
#include "o3d/geometry/octree_ops.h"
#include "o3d/geometry/octree_voxel_conversion.h"
#include "o3d/geometry/voxel_grid_edit.h"
#include "o3d/utility/error.h"

using namespace o3d::geometry;

namespace {

struct Visit {
    int node;
    OctreeNodeInfo info;
};

std::vector<Visit> visits(const Octree& tree, const std::function<bool(const OctreeNodeInfo&)>& skip = nullptr) {
    std::vector<Visit> out;
    octree_traverse(tree, [&](int node, const OctreeNodeInfo& info) {
        out.push_back({node, info});
        return skip ? skip(info) : false;
    });
    return out;
}

/// Open3D 0.20's example: Octree(2, (0, 0, 0), 4), points i = 0..4 with color (i / 10, 0, 0); (5, 5, 5) is
/// outside the root cube.
Octree five_point_tree() {
    Octree tree = make_octree_with_bounds(2, Eigen::Vector3d::Zero(), 4.0);
    const Eigen::Vector3d pts[5] = {{0.5, 0.5, 0.5}, {3.5, 0.5, 0.5}, {0.6, 0.6, 0.6}, {1.5, 2.5, 3.5}, {5, 5, 5}};
    for (int i = 0; i < 5; ++i)
        EXPECT_EQ(octree_insert_point(tree, pts[i], i, Eigen::Vector3d(i / 10.0, 0, 0)), i < 4) << i;
    return tree;
}

}  // namespace

TEST(OctreeEdit, PointInBoundIsHalfOpen) {
    // Open3D 0.20: is_point_in_bound([1, 0, 0], 0, 1) is False, ([0, 0, 0], 0, 1) True.
    const Eigen::Vector3d o = Eigen::Vector3d::Zero();
    EXPECT_TRUE(is_point_in_bound({0, 0, 0}, o, 1.0));
    EXPECT_FALSE(is_point_in_bound({1, 0, 0}, o, 1.0));
    EXPECT_FALSE(is_point_in_bound({0.5, 1, 0.5}, o, 1.0));
    EXPECT_TRUE(is_point_in_bound({0.999, 0.5, 0.2}, o, 1.0));
    EXPECT_FALSE(is_point_in_bound({-1e-12, 0.5, 0.2}, o, 1.0));
    EXPECT_FALSE(is_point_in_bound({NAN, 0.5, 0.2}, o, 1.0));
    EXPECT_TRUE(is_point_in_bound({-2.5, 0, 3}, {-3, -1, 2}, 1.5));
}

TEST(OctreeEdit, InsertAndTraverseLikeOpen3D) {
    const Octree tree = five_point_tree();
    EXPECT_EQ(count_leaves(tree), 3u);
    // Open3D 0.20's traversal: (depth, child index, origin, size, leaf indices).
    struct Expect {
        int depth, child;
        Eigen::Vector3d origin;
        double size;
        std::vector<int> indices;
    };
    const std::vector<Expect> open3d = {
        {0, 0, {0, 0, 0}, 4.0, {}},     {1, 0, {0, 0, 0}, 2.0, {}}, {2, 0, {0, 0, 0}, 1.0, {0, 2}},
        {1, 1, {2, 0, 0}, 2.0, {}},     {2, 1, {3, 0, 0}, 1.0, {1}}, {1, 6, {0, 2, 2}, 2.0, {}},
        {2, 5, {1, 2, 3}, 1.0, {3}}};
    const std::vector<Visit> seen = visits(tree);
    ASSERT_EQ(seen.size(), open3d.size());
    EXPECT_EQ(seen.size(), tree.nodes.size());
    for (size_t i = 0; i < seen.size(); ++i) {
        const OctreeNode& n = tree.nodes[seen[i].node];
        EXPECT_EQ(seen[i].info.depth, open3d[i].depth) << i;
        EXPECT_EQ(seen[i].info.child_index, open3d[i].child) << i;
        EXPECT_EQ(seen[i].info.origin, open3d[i].origin) << i;
        EXPECT_EQ(seen[i].info.size, open3d[i].size) << i;
        EXPECT_EQ(n.is_leaf, !open3d[i].indices.empty()) << i;
        EXPECT_EQ(n.indices, open3d[i].indices) << i;
    }
    // The leaf's color is the mean of its points' (Open3D 0.20 keeps the last one, 0.2).
    EXPECT_TRUE(tree.nodes[seen[2].node].color.isApprox(Eigen::Vector3d(0.1, 0, 0)));
    EXPECT_TRUE(tree.nodes[seen[6].node].color.isApprox(Eigen::Vector3d(0.3, 0, 0)));
    // Returning true at (depth 1, child 0) skips its leaf only (Open3D 0.20: (0,0) (1,0) (1,1) (2,1) (1,6) (2,5)).
    const std::vector<Visit> stopped =
        visits(tree, [](const OctreeNodeInfo& info) { return info.depth == 1 && info.child_index == 0; });
    const int expect_stop[6][2] = {{0, 0}, {1, 0}, {1, 1}, {2, 1}, {1, 6}, {2, 5}};
    ASSERT_EQ(stopped.size(), 6u);
    for (int i = 0; i < 6; ++i) {
        EXPECT_EQ(stopped[i].info.depth, expect_stop[i][0]);
        EXPECT_EQ(stopped[i].info.child_index, expect_stop[i][1]);
    }
    // Returning true at the root visits the root alone.
    EXPECT_EQ(visits(tree, [](const OctreeNodeInfo&) { return true; }).size(), 1u);
    // Nothing to visit without nodes.
    EXPECT_TRUE(visits(make_octree(3)).empty());
}

TEST(OctreeEdit, InsertMatchesTheCloudConversion) {
    std::mt19937 rng(7);
    std::uniform_real_distribution<double> coord(-1.0, 2.0), unit(0.0, 1.0);
    PointCloud pc;
    for (int i = 0; i < 400; ++i) {
        pc.points.emplace_back(coord(rng), coord(rng) * 0.5, coord(rng));
        pc.colors.emplace_back(unit(rng), unit(rng), unit(rng));
    }
    Octree ref = make_octree(4);
    octree_from_point_cloud(ref, pc, 0.01);
    // The same cube, the points inserted in reverse order.
    Octree tree = make_octree_with_bounds(4, ref.origin, ref.size);
    for (int i = static_cast<int>(pc.points.size()) - 1; i >= 0; --i)
        EXPECT_TRUE(octree_insert_point(tree, pc.points[i], i, pc.colors[i]));
    EXPECT_EQ(count_leaves(tree), count_leaves(ref));
    EXPECT_EQ(tree.nodes.size(), ref.nodes.size());
    for (size_t i = 0; i < pc.points.size(); ++i) {
        OctreeNodeInfo a, b;
        const int la = locate_leaf(tree, pc.points[i], &a), lb = locate_leaf(ref, pc.points[i], &b);
        ASSERT_GE(la, 0);
        ASSERT_GE(lb, 0);
        EXPECT_EQ(a.origin, b.origin);
        EXPECT_EQ(a.depth, 4);
        EXPECT_EQ(a.child_index, b.child_index);
        EXPECT_EQ(tree.nodes[la].indices, ref.nodes[lb].indices);
        EXPECT_TRUE(tree.nodes[la].color.isApprox(ref.nodes[lb].color, 1e-12));
    }
    // Inserting an index again changes nothing.
    const std::vector<OctreeNode> before = tree.nodes;
    EXPECT_TRUE(octree_insert_point(tree, pc.points[5], 5, Eigen::Vector3d(9, 9, 9)));
    ASSERT_EQ(tree.nodes.size(), before.size());
    for (size_t i = 0; i < before.size(); ++i) {
        EXPECT_EQ(tree.nodes[i].indices, before[i].indices);
        EXPECT_EQ(tree.nodes[i].color, before[i].color);
    }
    // The traversal visits every node once, parents before children, leaves with locate_leaf's info.
    const std::vector<Visit> seen = visits(tree);
    ASSERT_EQ(seen.size(), tree.nodes.size());
    size_t leaves = 0;
    for (const Visit& v : seen) {
        if (!tree.nodes[v.node].is_leaf) continue;
        ++leaves;
        const Eigen::Vector3d centre = v.info.origin + Eigen::Vector3d::Constant(v.info.size / 2);
        OctreeNodeInfo info;
        EXPECT_EQ(locate_leaf(tree, centre, &info), v.node);
        EXPECT_EQ(info.origin, v.info.origin);
        EXPECT_EQ(info.size, v.info.size);
    }
    EXPECT_EQ(leaves, count_leaves(tree));
    // Outside the root: false and no change (Open3D 0.20 would still create the root of an empty tree).
    Octree empty = make_octree_with_bounds(2, Eigen::Vector3d::Zero(), 1.0);
    EXPECT_FALSE(octree_insert_point(empty, {1, 0.5, 0.5}, 0, Eigen::Vector3d::Zero()));
    EXPECT_TRUE(empty.nodes.empty());
    // make_octree(int) has no cube yet: nothing fits.
    Octree no_cube = make_octree(2);
    EXPECT_FALSE(octree_insert_point(no_cube, {0, 0, 0}, 0, Eigen::Vector3d::Zero()));
}

TEST(OctreeEdit, ToVoxelGridUsesTheDeepestCells) {
    // Open3D 0.20's to_voxel_grid leaves voxel_size at 0 and puts every leaf at INT_MIN; o3d implements its
    // intent: origin = the root's, voxel_size = size / 2^max_depth, one voxel per leaf with its color.
    const Octree tree = five_point_tree();
    const VoxelGrid g = octree_to_voxel_grid(tree);
    EXPECT_EQ(g.origin, Eigen::Vector3d::Zero());
    EXPECT_EQ(g.voxel_size, 1.0);
    ASSERT_EQ(g.voxels.size(), 3u);
    EXPECT_EQ(g.voxels[0].grid_index, Eigen::Vector3i(0, 0, 0));
    EXPECT_EQ(g.voxels[1].grid_index, Eigen::Vector3i(1, 2, 3));
    EXPECT_EQ(g.voxels[2].grid_index, Eigen::Vector3i(3, 0, 0));
    EXPECT_TRUE(g.voxels[0].color.isApprox(Eigen::Vector3d(0.1, 0, 0)));
    EXPECT_TRUE(g.voxels[1].color.isApprox(Eigen::Vector3d(0.3, 0, 0)));
    EXPECT_TRUE(g.voxels[2].color.isApprox(Eigen::Vector3d(0.1, 0, 0)));
    // Each voxel holds the points of its leaf.
    const Eigen::Vector3d pts[4] = {{0.5, 0.5, 0.5}, {3.5, 0.5, 0.5}, {0.6, 0.6, 0.6}, {1.5, 2.5, 3.5}};
    for (const Eigen::Vector3d& p : pts)
        EXPECT_NE(find_voxel(g, ((p - g.origin) / g.voxel_size).array().floor().cast<int>()), nullptr);
    // A tree without nodes: an empty grid.
    const VoxelGrid e = octree_to_voxel_grid(make_octree_with_bounds(3, {1, 2, 3}, 8.0));
    EXPECT_TRUE(e.voxels.empty());
    EXPECT_EQ(e.voxel_size, 1.0);
}

TEST(OctreeEdit, FromVoxelGridLikeOpen3D) {
    // record_voxel_edit_octree.py: voxel 0.3 at origin (0.1, -0.2, 0.05), four voxels, Octree(2). Open3D 0.20:
    // root origin = the grid's, size 1.5 (the largest extent from the origin to the max bound (1.6, 1.0,
    // 0.95)), the leaves below in traversal order.
    VoxelGrid grid;
    grid.voxel_size = 0.3;
    grid.origin = {0.1, -0.2, 0.05};
    for (const Eigen::Vector3i& idx : {Eigen::Vector3i(0, 0, 0), Eigen::Vector3i(4, 1, 2), Eigen::Vector3i(2, 2, 2),
                                       Eigen::Vector3i(1, 3, 0)})
        add_voxel(grid, {idx, Eigen::Vector3d(idx.x() / 10.0, 0.5, idx.z() / 4.0)});
    Octree tree = make_octree(2);
    octree_from_voxel_grid(tree, grid);
    EXPECT_EQ(tree.max_depth, 2);
    EXPECT_EQ(tree.origin, grid.origin);
    EXPECT_NEAR(tree.size, 1.5, 1e-12);
    std::vector<Visit> leaves;
    for (const Visit& v : visits(tree))
        if (tree.nodes[v.node].is_leaf) leaves.push_back(v);
    ASSERT_EQ(leaves.size(), 4u);
    const int child[4] = {0, 1, 2, 3};
    const Eigen::Vector3d origin[4] = {{0.1, -0.2, 0.05}, {0.475, 0.55, 0.05}, {0.85, 0.175, 0.8}, {1.225, 0.175, 0.8}};
    const Eigen::Vector3d color[4] = {{0, 0.5, 0}, {0.1, 0.5, 0}, {0.2, 0.5, 0.5}, {0.4, 0.5, 0.5}};
    // Point indices are the voxels' ranks in grid.voxels: (0,0,0), (1,3,0), (2,2,2), (4,1,2).
    const int rank[4] = {0, 1, 2, 3};
    for (int i = 0; i < 4; ++i) {
        EXPECT_EQ(leaves[i].info.child_index, child[i]) << i;
        EXPECT_TRUE(leaves[i].info.origin.isApprox(origin[i], 1e-12)) << i;
        EXPECT_NEAR(leaves[i].info.size, 0.375, 1e-12);
        EXPECT_TRUE(tree.nodes[leaves[i].node].color.isApprox(color[i], 1e-12)) << i;
        EXPECT_EQ(tree.nodes[leaves[i].node].indices, std::vector<int>{rank[i]}) << i;
    }
}

TEST(OctreeEdit, VoxelGridRoundTrip) {
    // Indices in [0, 8)^3 with (7, 7, 7) present: the root cube is exactly the 8^3 cells, and at depth 3 each
    // leaf is one voxel, so the grid comes back unchanged.
    std::mt19937 rng(11);
    std::uniform_int_distribution<int> cell(0, 7);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    VoxelGrid grid;
    grid.voxel_size = 0.25;
    grid.origin = {1.0, -2.0, 0.5};
    add_voxel(grid, {{7, 7, 7}, {1, 0, 0}});
    for (int i = 0; i < 120; ++i)
        add_voxel(grid, {{cell(rng), cell(rng), cell(rng)}, {unit(rng), unit(rng), unit(rng)}});
    Octree tree = make_octree(3);
    octree_from_voxel_grid(tree, grid);
    EXPECT_EQ(tree.origin, grid.origin);
    EXPECT_EQ(tree.size, 2.0);
    EXPECT_EQ(count_leaves(tree), grid.voxels.size());
    const VoxelGrid back = octree_to_voxel_grid(tree);
    EXPECT_EQ(back.origin, grid.origin);
    EXPECT_EQ(back.voxel_size, grid.voxel_size);
    ASSERT_EQ(back.voxels.size(), grid.voxels.size());
    for (size_t i = 0; i < grid.voxels.size(); ++i) {
        EXPECT_EQ(back.voxels[i].grid_index, grid.voxels[i].grid_index) << i;
        EXPECT_EQ(back.voxels[i].color, grid.voxels[i].color) << i;
    }
    // A coarser tree merges voxels: each leaf lists its voxels and their mean color.
    Octree coarse = make_octree(1);
    octree_from_voxel_grid(coarse, grid);
    size_t listed = 0;
    for (const OctreeNode& n : coarse.nodes) {
        if (!n.is_leaf) continue;
        listed += n.indices.size();
        Eigen::Vector3d mean = Eigen::Vector3d::Zero();
        for (int r : n.indices) mean += grid.voxels[r].color;
        EXPECT_TRUE(n.color.isApprox(mean / n.indices.size(), 1e-12));
    }
    EXPECT_EQ(listed, grid.voxels.size());
}

TEST(OctreeEdit, FromVoxelGridKeepsNegativeIndicesAndEmptyGrids) {
    // Open3D 0.20 puts the root at the grid origin and drops voxels at negative indices; o3d moves the root
    // down to the lowest index.
    VoxelGrid grid;
    grid.voxel_size = 0.5;
    grid.origin = {1, 1, 1};
    add_voxel(grid, {{-2, 0, 0}, {0.1, 0.2, 0.3}});
    add_voxel(grid, {{1, 1, 1}, {0.4, 0.5, 0.6}});
    Octree tree = make_octree(2);
    octree_from_voxel_grid(tree, grid);
    EXPECT_TRUE(tree.origin.isApprox(Eigen::Vector3d(0, 1, 1)));
    EXPECT_DOUBLE_EQ(tree.size, 2.0);  // from x = 0 to the max bound x = 2
    EXPECT_EQ(count_leaves(tree), 2u);
    for (const Voxel& v : grid.voxels) EXPECT_GE(locate_leaf(tree, voxel_center_coordinate(grid, v.grid_index), nullptr), 0);
    // An empty grid: the old nodes go, no root, size 0 at the grid's origin (as Open3D).
    octree_from_voxel_grid(tree, VoxelGrid{0.5, {3, 4, 5}, {}});
    EXPECT_TRUE(tree.nodes.empty());
    EXPECT_EQ(tree.size, 0.0);
    EXPECT_EQ(tree.origin, Eigen::Vector3d(3, 4, 5));
}

TEST(OctreeEdit, BadInputsAreErrors) {
    const Eigen::Vector3d o = Eigen::Vector3d::Zero();
    EXPECT_THROW(make_octree_with_bounds(0, o, 1.0), o3d::InvalidArgument);
    EXPECT_THROW(make_octree_with_bounds(kMaxOctreeDepth + 1, o, 1.0), o3d::InvalidArgument);
    EXPECT_THROW(make_octree_with_bounds(2, {NAN, 0, 0}, 1.0), o3d::InvalidArgument);
    EXPECT_THROW(make_octree_with_bounds(2, o, 0.0), o3d::InvalidArgument);
    EXPECT_THROW(make_octree_with_bounds(2, o, -1.0), o3d::InvalidArgument);
    EXPECT_THROW(make_octree_with_bounds(2, o, INFINITY), o3d::InvalidArgument);

    Octree tree = make_octree_with_bounds(2, o, 1.0);
    EXPECT_THROW(octree_insert_point(tree, {0.5, 0.5, 0.5}, -1, o), o3d::InvalidArgument);
    EXPECT_THROW(octree_insert_point(tree, {NAN, 0.5, 0.5}, 0, o), o3d::InvalidArgument);
    EXPECT_THROW(octree_insert_point(tree, {0.5, 0.5, 0.5}, 0, {0, INFINITY, 0}), o3d::InvalidArgument);
    EXPECT_TRUE(tree.nodes.empty());
    Octree shallow;  // max_depth 0
    shallow.size = 1.0;
    EXPECT_THROW(octree_insert_point(shallow, {0.5, 0.5, 0.5}, 0, o), o3d::InvalidArgument);
    EXPECT_THROW(octree_to_voxel_grid(shallow), o3d::InvalidArgument);

    VoxelGrid grid = voxel_grid_create_dense(o, o, 0.5, 1, 1, 1);
    EXPECT_THROW(octree_from_voxel_grid(shallow, grid), o3d::InvalidArgument);
    VoxelGrid bad = grid;
    bad.voxel_size = 0.0;
    EXPECT_THROW(octree_from_voxel_grid(tree, bad), o3d::InvalidArgument);
    bad = grid;
    bad.origin.y() = NAN;
    EXPECT_THROW(octree_from_voxel_grid(tree, bad), o3d::InvalidArgument);
    bad = grid;
    bad.voxels[3].color.x() = NAN;
    EXPECT_THROW(octree_from_voxel_grid(tree, bad), o3d::InvalidArgument);
    bad = grid;
    std::swap(bad.voxels[0], bad.voxels[1]);
    EXPECT_THROW(octree_from_voxel_grid(tree, bad), o3d::InvalidArgument);
    bad = grid;
    bad.voxels.push_back(bad.voxels.back());
    EXPECT_THROW(octree_from_voxel_grid(tree, bad), o3d::InvalidArgument);

    // A hand-made tree whose child points back at its parent, or with a leaf above max depth.
    Octree cyclic = make_octree_with_bounds(2, o, 1.0);
    cyclic.nodes.resize(2);
    cyclic.nodes[0].children[3] = 1;
    cyclic.nodes[1].children[0] = 0;
    EXPECT_THROW(octree_traverse(cyclic, [](int, const OctreeNodeInfo&) { return false; }), o3d::InvalidArgument);
    EXPECT_THROW(octree_to_voxel_grid(cyclic), o3d::InvalidArgument);
    Octree early = make_octree_with_bounds(2, o, 1.0);
    early.nodes.resize(2);
    early.nodes[0].children[3] = 1;
    early.nodes[1].is_leaf = true;
    early.nodes[1].indices = {0};
    EXPECT_THROW(octree_to_voxel_grid(early), o3d::InvalidArgument);
    // An exception from the visitor propagates.
    const Octree five = five_point_tree();
    EXPECT_THROW(octree_traverse(five, [](int, const OctreeNodeInfo& info) -> bool {
                     if (info.depth == 2) throw o3d::InvalidArgument("stop");
                     return false;
                 }),
                 o3d::InvalidArgument);
}
