// SPDX-License-Identifier: MIT
// LineSet, VoxelGrid and Octree through the wrapper: box edges, unique mesh edges, sorted voxel
// indices with mean colors, octree leaves where Open3D 0.20 puts them
// (tools/reference/record_bindings_round2.py), errors as exceptions.
#include <algorithm>
#include <cmath>
#include <limits>

#include "test_util.hpp"

using o3dpp::GridIndex;
using o3dpp::Line;
using o3dpp::LineSet;
using o3dpp::Octree;
using o3dpp::PointCloud;
using o3dpp::TriangleMesh;
using o3dpp::Vec3;
using o3dpp::VoxelGrid;

TEST(LineSet, ContainerViewsColorsAndTransform) {
    LineSet set({{0, 0, 0}, {1, 0, 0}, {1, 1, 0}}, {{0, 1}, {1, 2}});
    EXPECT_EQ(set.num_points(), 3u);
    EXPECT_EQ(set.num_lines(), 2u);
    EXPECT_EQ(set.get_lines(), (std::vector<Line>{{0, 1}, {1, 2}}));
    EXPECT_EQ(set.lines().size(), 4u);
    EXPECT_EQ(set.lines()[3], 2);
    EXPECT_EQ(set.points()[2][1], 1.0);
    set.paint_uniform_color({0.25, 0.5, 1});
    EXPECT_EQ(set.get_colors(), (std::vector<Vec3>{{0.25, 0.5, 1}, {0.25, 0.5, 1}}));
    set.set_colors({{1, 0, 0}, {0, 1, 0}});
    EXPECT_EQ(set.colors()[1][1], 1.0);
    const LineSet copy = set.clone();
    set.transform({1, 0, 0, 1, 0, 1, 0, 2, 0, 0, 1, 3, 0, 0, 0, 1});
    EXPECT_EQ(set.get_points()[1], (Vec3{2, 2, 3}));
    EXPECT_EQ(copy.get_points()[1], (Vec3{1, 0, 0}));
}

TEST(LineSet, BoxesMeshesAndCorrespondences) {
    const auto box = LineSet::create_from_axis_aligned_bounding_box({-1, 0, 2}, {1, 3, 2.5});
    EXPECT_EQ(box.num_points(), 8u);
    EXPECT_EQ(box.num_lines(), 12u);
    const auto p = box.get_points();
    double total = 0;
    for (const auto& l : box.get_lines()) {
        const Vec3 d{p[l[1]][0] - p[l[0]][0], p[l[1]][1] - p[l[0]][1], p[l[1]][2] - p[l[0]][2]};
        EXPECT_EQ(std::count(d.begin(), d.end(), 0.0), 2) << "edge not along one axis";
        total += std::sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
    }
    EXPECT_NEAR(total, 4 * (2 + 3 + 0.5), 1e-12);
    const auto obb = o3dpp::OrientedBoundingBox::create_from_axis_aligned_bounding_box({-1, 0, 2}, {1, 3, 2.5});
    const auto corners = obb.get_box_points();
    EXPECT_EQ(LineSet::create_from_oriented_bounding_box(obb).get_points(),
              std::vector<Vec3>(corners.begin(), corners.end()));

    // A box mesh has 18 unique edges (12 sides + 6 face diagonals).
    const auto edges = LineSet::create_from_triangle_mesh(TriangleMesh::create_box());
    EXPECT_EQ(edges.num_points(), 8u);
    auto lines = edges.get_lines();
    for (auto& l : lines)
        if (l[0] > l[1]) std::swap(l[0], l[1]);
    std::sort(lines.begin(), lines.end());
    EXPECT_EQ(std::unique(lines.begin(), lines.end()) - lines.begin(), 18);
    EXPECT_EQ(lines.size(), 18u);

    const PointCloud c0(std::vector<Vec3>{{0, 0, 0}, {1, 0, 0}});
    const PointCloud c1(std::vector<Vec3>{{0, 5, 0}, {1, 5, 0}, {2, 5, 0}});
    const auto joined = LineSet::create_from_point_cloud_correspondences(c0, c1, {{0, 2}, {1, 0}});
    EXPECT_EQ(joined.num_points(), 5u);
    EXPECT_EQ(joined.get_lines(), (std::vector<Line>{{0, 4}, {1, 2}}));
    EXPECT_O3D_ERROR(LineSet::create_from_point_cloud_correspondences(c0, c1, {{0, 3}}), O3D_ERROR_INVALID_ARGUMENT);
    EXPECT_O3D_ERROR(LineSet::create_from_axis_aligned_bounding_box({1, 1, 1}, {0, 0, 0}),
                     O3D_ERROR_INVALID_ARGUMENT);
}

TEST(VoxelGrid, PointsFallInSortedCellsWithMeanColors) {
    PointCloud cloud(std::vector<Vec3>{{2, 0, 0}, {0, 0, 0}, {0, 3, 1}, {0.2, 0.1, 0}});
    cloud.set_colors(std::vector<Vec3>{{1, 0, 0}, {0, 0, 1}, {0.5, 0.5, 0.5}, {0, 1, 0}});
    const auto grid = VoxelGrid::create_from_point_cloud(cloud, 1.0);
    EXPECT_EQ(grid.voxel_size(), 1.0);
    EXPECT_EQ(grid.origin(), (Vec3{-0.5, -0.5, -0.5}));
    EXPECT_EQ(grid.num_voxels(), 3u);
    const auto voxels = grid.get_voxels();
    ASSERT_EQ(voxels.size(), 3u);
    EXPECT_EQ(voxels[0].grid_index, (GridIndex{0, 0, 0}));
    EXPECT_EQ(voxels[1].grid_index, (GridIndex{0, 3, 1}));
    EXPECT_EQ(voxels[2].grid_index, (GridIndex{2, 0, 0}));
    for (int i = 0; i < 3; ++i) EXPECT_NEAR(voxels[0].color[i], (Vec3{0, 0.5, 0.5})[i], 1e-12);
    EXPECT_EQ(grid.get_voxel({5.0, -2.0, 0.7}), (GridIndex{5, -2, 1}));
    EXPECT_EQ(grid.check_if_included({{0.4, 0.4, 0.4}, {1, 0, 0}, {2.3, -0.2, 0.1}}),
              (std::vector<bool>{true, false, true}));

    const auto bounded = VoxelGrid::create_from_point_cloud_within_bounds(cloud, 1.0, {0, 0, 0}, {2.5, 2.5, 2.5});
    EXPECT_EQ(bounded.origin(), (Vec3{0, 0, 0}));
    EXPECT_EQ(bounded.num_voxels(), 2u);

    const TriangleMesh square({{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}}, {{0, 1, 2}, {0, 2, 3}});
    const auto surface = VoxelGrid::create_from_triangle_mesh(square, 0.5);
    const auto cells = surface.get_voxels();
    ASSERT_EQ(cells.size(), 9u);
    for (std::size_t k = 0; k < 9; ++k)
        EXPECT_EQ(cells[k].grid_index, (GridIndex{int32_t(k / 3), int32_t(k % 3), 0}));

    EXPECT_O3D_ERROR(VoxelGrid::create_from_point_cloud(cloud, 0.0), O3D_ERROR_INVALID_ARGUMENT);
    EXPECT_O3D_ERROR(VoxelGrid::create_from_point_cloud(cloud, std::numeric_limits<double>::quiet_NaN()),
                     O3D_ERROR_INVALID_ARGUMENT);
}

TEST(Octree, LeavesAreWhereOpen3DPutsThem) {
    PointCloud cloud(
        std::vector<Vec3>{{0, 0, 0}, {4, 4, 4}, {0.5, 0.5, 0.5}, {3.5, 0.5, 1.5}, {3.6, 0.6, 1.6}, {1, 3, 2}});
    cloud.set_colors(std::vector<Vec3>{{0, 0, 0}, {1, 1, 1}, {0.2, 0.4, 0.6}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}});
    Octree tree(2);
    EXPECT_EQ(tree.num_leaf_nodes(), 0u);
    EXPECT_FALSE(tree.locate_leaf_node({0, 0, 0}).has_value());
    tree.convert_from_point_cloud(cloud);
    EXPECT_EQ(tree.origin(), (Vec3{0, 0, 0}));
    EXPECT_NEAR(tree.size(), 4.04, 1e-12);
    EXPECT_EQ(tree.max_depth(), 2);
    EXPECT_EQ(tree.num_leaf_nodes(), 4u);

    const auto leaf = tree.locate_leaf_node({3.5, 0.5, 1.5});
    ASSERT_TRUE(leaf.has_value());
    EXPECT_NEAR(leaf->info.origin[0], 3.03, 1e-12);
    EXPECT_NEAR(leaf->info.origin[2], 1.01, 1e-12);
    EXPECT_NEAR(leaf->info.size, 1.01, 1e-12);
    EXPECT_EQ(leaf->info.depth, 2);
    EXPECT_EQ(leaf->info.child_index, 5);
    EXPECT_EQ(leaf->indices, (std::vector<int32_t>{3, 4}));
    // The header's mean color (Open3D keeps the last point's color instead).
    for (int i = 0; i < 3; ++i) EXPECT_NEAR(leaf->color[i], (Vec3{0.5, 0.5, 0})[i], 1e-12);
    EXPECT_FALSE(tree.locate_leaf_node({10, 10, 10}).has_value());
    EXPECT_FALSE(tree.locate_leaf_node({2.5, 2.5, 2.5}).has_value());

    EXPECT_O3D_ERROR(Octree(0), O3D_ERROR_INVALID_ARGUMENT);
    EXPECT_O3D_ERROR(tree.convert_from_point_cloud(cloud, -1.0), O3D_ERROR_INVALID_ARGUMENT);
}
