// SPDX-License-Identifier: MIT
// VoxelGrid editing, dense grids, cell centres and corners, meshes within bounds, space carving and the
// octree <-> voxel grid round trip through the wrapper: analytic answers (a dense grid's cells and centres,
// corners at centre +- half a voxel in Open3D 0.20's order, an all-ones mask keeping every voxel and an
// all-zeros one removing all), errors as exceptions.
#include <algorithm>
#include <vector>

#include "test_util.hpp"

using o3dpp::GridIndex;
using o3dpp::Image;
using o3dpp::Octree;
using o3dpp::PinholeCameraParameters;
using o3dpp::PinholeIntrinsic;
using o3dpp::TriangleMesh;
using o3dpp::Vec3;
using o3dpp::Voxel;
using o3dpp::VoxelGrid;

namespace {

void expect_near3(const Vec3& a, const Vec3& b) {
    for (int i = 0; i < 3; ++i) EXPECT_NEAR(a[i], b[i], 1e-12) << i;
}

// A 64 x 48 camera at the world origin looking down +z; a 1 m cube of 0.25 m voxels at z in [2, 3] in view.
PinholeCameraParameters camera() {
    PinholeCameraParameters p;
    p.intrinsic = PinholeIntrinsic(64, 48, 50.0, 50.0, 31.5, 23.5);
    return p;
}

VoxelGrid cube_in_view() { return VoxelGrid::create_dense({-0.5, -0.5, 2.0}, {1, 1, 1}, 0.25, 1.0, 1.0, 1.0); }

Image mask(float value, int ones_below_column = 64) {
    std::vector<float> v(64 * 48, 0.0f);
    for (int r = 0; r < 48; ++r)
        for (int c = 0; c < ones_below_column; ++c) v[r * 64 + c] = value;
    return Image::from_values(64, 48, v);
}

}  // namespace

TEST(VoxelGridEdit, DenseGridCellsCentresAndCorners) {
    const auto grid = VoxelGrid::create_dense({1, 2, 3}, {0.1, 0.2, 0.3}, 0.5, 1.0, 1.5, 0.5);
    EXPECT_EQ(grid.num_voxels(), 6u);
    EXPECT_EQ(grid.origin(), (Vec3{1, 2, 3}));
    EXPECT_EQ(grid.voxel_size(), 0.5);
    const auto voxels = grid.get_voxels();
    ASSERT_EQ(voxels.size(), 6u);
    std::vector<GridIndex> index;
    for (const auto& v : voxels) {
        index.push_back(v.grid_index);
        EXPECT_EQ(v.color, (Vec3{0.1, 0.2, 0.3}));
    }
    EXPECT_EQ(index, (std::vector<GridIndex>{{0, 0, 0}, {0, 1, 0}, {0, 2, 0}, {1, 0, 0}, {1, 1, 0}, {1, 2, 0}}));
    expect_near3(grid.get_voxel_center_coordinate({0, 0, 0}), {1.25, 2.25, 3.25});
    expect_near3(grid.get_voxel_center_coordinate({-2, 7, 1}), {0.25, 5.75, 3.75});  // empty cells too

    // Centre +- half a voxel, in Open3D 0.20's order (the wheel's get_voxel_bounding_points): y slowest, then x,
    // then z, each low then high.
    const auto corners = grid.get_voxel_bounding_points({1, 2, 0});
    const Vec3 c = grid.get_voxel_center_coordinate({1, 2, 0});
    std::size_t i = 0;
    for (double dy : {-0.25, 0.25})
        for (double dx : {-0.25, 0.25})
            for (double dz : {-0.25, 0.25}) expect_near3(corners[i++], {c[0] + dx, c[1] + dy, c[2] + dz});
    expect_near3(corners[0], {1.5, 3.0, 3.0});
    expect_near3(corners[7], {2.0, 3.5, 3.5});

    EXPECT_THROW(VoxelGrid::create_dense({0, 0, 0}, {1, 1, 1}, 0.0, 1, 1, 1), o3dpp::Error);
    EXPECT_THROW(VoxelGrid::create_dense({0, 0, 0}, {1, 1, 1}, 0.5, -1, 1, 1), o3dpp::Error);
}

TEST(VoxelGridEdit, AddReplacesAndRemoveDrops) {
    auto grid = VoxelGrid::create_dense({0, 0, 0}, {0, 0, 0}, 1.0, 2, 2, 2);
    ASSERT_EQ(grid.num_voxels(), 8u);
    grid.add_voxel(Voxel{{1, 0, 1}, {1, 0.5, 0}});  // replaces
    EXPECT_EQ(grid.num_voxels(), 8u);
    grid.add_voxel({{5, -1, 0}, {0, 0, 1}}).remove_voxel({0, 0, 0});
    EXPECT_EQ(grid.num_voxels(), 8u);
    grid.remove_voxel({9, 9, 9});  // nothing there
    EXPECT_EQ(grid.num_voxels(), 8u);
    const auto voxels = grid.get_voxels();
    const auto at = [&](const GridIndex& g) {
        return std::find_if(voxels.begin(), voxels.end(), [&](const Voxel& v) { return v.grid_index == g; });
    };
    ASSERT_NE(at({1, 0, 1}), voxels.end());
    EXPECT_EQ(at({1, 0, 1})->color, (Vec3{1, 0.5, 0}));
    ASSERT_NE(at({5, -1, 0}), voxels.end());
    EXPECT_EQ(at({5, -1, 0})->color, (Vec3{0, 0, 1}));
    EXPECT_EQ(at({0, 0, 0}), voxels.end());
    EXPECT_EQ(grid.check_if_included({{0.5, 0.5, 0.5}, {5.5, -0.5, 0.5}}), (std::vector<bool>{false, true}));
    const double nan = std::numeric_limits<double>::quiet_NaN();
    EXPECT_THROW(grid.add_voxel({{0, 0, 0}, {nan, 0, 0}}), o3dpp::Error);
}

TEST(VoxelGridEdit, MeshWithinBounds) {
    // The [0, 1]^3 box at 0.5: Open3D 0.20 (the wheel) tests the boxes of edge 0.5 centred on min_bound + 0.5 * index,
    // so of the 3 x 3 x 3 of them only the one centred inside the box, (1, 1, 1), touches no triangle: 26 voxels.
    const auto box = TriangleMesh::create_box();
    const auto all = VoxelGrid::create_from_triangle_mesh_within_bounds(box, 0.5, {0, 0, 0}, {1, 1, 1});
    EXPECT_EQ(all.num_voxels(), 26u);
    EXPECT_EQ(all.origin(), (Vec3{0, 0, 0}));
    EXPECT_EQ(all.voxel_size(), 0.5);
    for (const auto& v : all.get_voxels()) {
        EXPECT_NE(v.grid_index, (GridIndex{1, 1, 1}));
        for (int a = 0; a < 3; ++a) EXPECT_TRUE(v.grid_index[a] >= 0 && v.grid_index[a] <= 2);
    }
    // Bounds halved along x: the cells past them are never made (2 x 3 x 3 less the inner one).
    const auto half = VoxelGrid::create_from_triangle_mesh_within_bounds(box, 0.5, {0, 0, 0}, {0.5, 1, 1});
    EXPECT_EQ(half.num_voxels(), 17u);
    for (const auto& v : half.get_voxels()) EXPECT_LE(v.grid_index[0], 1);
    EXPECT_THROW(VoxelGrid::create_from_triangle_mesh_within_bounds(box, 0.0, {0, 0, 0}, {1, 1, 1}), o3dpp::Error);
    EXPECT_THROW(VoxelGrid::create_from_triangle_mesh_within_bounds(box, 0.5, {1, 1, 1}, {0, 0, 0}), o3dpp::Error);
}

TEST(VoxelGridEdit, CarveSilhouette) {
    const auto cam = camera();
    auto grid = cube_in_view();
    ASSERT_EQ(grid.num_voxels(), 64u);
    EXPECT_EQ(grid.carve_silhouette(mask(1.0f), cam).num_voxels(), 64u);  // all ones keeps every voxel
    EXPECT_EQ(cube_in_view().carve_silhouette(mask(0.0f), cam).num_voxels(), 0u);  // all zeros removes all
    // Ones on columns 0..33: the cells with x <= 0 (u <= 31.5) stay, those with x >= 0.25 (u >= 35.6) go.
    auto left = cube_in_view();
    left.carve_silhouette(mask(1.0f, 34), cam);
    EXPECT_EQ(left.num_voxels(), 48u);
    for (const auto& v : left.get_voxels()) EXPECT_LE(v.grid_index[0], 2);

    // A grid wider than the view: with keep_voxels_outside_image the cells seen outside the image stay.
    const auto wide = [] { return VoxelGrid::create_dense({-2, -0.5, 2}, {1, 1, 1}, 0.25, 4.0, 1.0, 1.0); };
    EXPECT_EQ(wide().carve_silhouette(mask(0.0f), cam).num_voxels(), 0u);
    auto kept = wide();
    kept.carve_silhouette(mask(0.0f), cam, true);
    EXPECT_GT(kept.num_voxels(), 0u);
    EXPECT_LT(kept.num_voxels(), 256u);
    for (const auto& v : kept.get_voxels()) EXPECT_TRUE(v.grid_index[0] <= 3 || v.grid_index[0] >= 12);

    auto scaled = cam;
    scaled.extrinsic[0] = 2.0;  // not rigid
    EXPECT_THROW(cube_in_view().carve_silhouette(mask(1.0f), scaled), o3dpp::Error);
    const Image bytes = Image::from_values(64, 48, std::vector<uint8_t>(64 * 48, 1));  // uint8, not float32
    EXPECT_THROW(cube_in_view().carve_silhouette(bytes, cam), o3dpp::Error);
    EXPECT_THROW(cube_in_view().carve_silhouette(Image::from_values(32, 48, std::vector<float>(32 * 48, 1.f)), cam),
                 o3dpp::Error);
}

TEST(VoxelGridEdit, CarveDepthMap) {
    const auto cam = camera();
    // Observed depth 2.4 everywhere: the layer z in [2, 2.25] is in front of it (free space) and goes.
    const Image depth = Image::from_values(64, 48, std::vector<float>(64 * 48, 2.4f));
    auto grid = cube_in_view();
    grid.carve_depth_map(depth, cam);
    EXPECT_EQ(grid.num_voxels(), 48u);
    for (const auto& v : grid.get_voxels()) EXPECT_GE(v.grid_index[2], 1);
    // A surface in front of the cube hides all of it (kept); one far behind it sees it all as free space (carved).
    EXPECT_EQ(cube_in_view().carve_depth_map(Image::from_values(64, 48, std::vector<float>(64 * 48, 1.f)), cam)
                  .num_voxels(),
              64u);
    EXPECT_EQ(cube_in_view().carve_depth_map(Image::from_values(64, 48, std::vector<float>(64 * 48, 10.f)), cam)
                  .num_voxels(),
              0u);
    auto sheared = cam;
    sheared.extrinsic[1] = 0.5;
    EXPECT_THROW(cube_in_view().carve_depth_map(depth, sheared), o3dpp::Error);
    EXPECT_THROW(cube_in_view().carve_depth_map(Image::from_values(64, 48, std::vector<uint16_t>(64 * 48, 2400)), cam),
                 o3dpp::Error);
}

TEST(OctreeEdit, BoundsInsertAndVoxelGridRoundTrip) {
    EXPECT_TRUE(Octree::is_point_in_bound({0, 0, 0}, {0, 0, 0}, 8));
    EXPECT_TRUE(Octree::is_point_in_bound({7.99, 3, 5}, {0, 0, 0}, 8));
    EXPECT_FALSE(Octree::is_point_in_bound({8, 0, 0}, {0, 0, 0}, 8));  // half-open
    EXPECT_FALSE(Octree::is_point_in_bound({1, -0.1, 1}, {0, 0, 0}, 8));

    Octree tree(3, {0, 0, 0}, 8.0);  // leaves of edge 1
    EXPECT_EQ(tree.max_depth(), 3);
    EXPECT_EQ(tree.size(), 8.0);
    EXPECT_EQ(tree.origin(), (Vec3{0, 0, 0}));
    EXPECT_EQ(tree.num_leaf_nodes(), 0u);
    EXPECT_TRUE(tree.insert_point({0.5, 0.5, 0.5}, 1, {1, 0, 0}));
    EXPECT_TRUE(tree.insert_point({0.6, 0.4, 0.2}, 0, {0, 0, 1}));  // same leaf
    EXPECT_TRUE(tree.insert_point({7.5, 7.5, 7.5}, 2, {0, 1, 0}));
    EXPECT_TRUE(tree.insert_point({2.5, 0.5, 6.5}, 3, {0.5, 0.5, 0.5}));
    EXPECT_FALSE(tree.insert_point({9, 0, 0}, 4, {1, 1, 1}));  // outside the root
    EXPECT_EQ(tree.num_leaf_nodes(), 3u);
    const auto leaf = tree.locate_leaf_node({0.1, 0.9, 0.1});
    ASSERT_TRUE(leaf.has_value());
    EXPECT_EQ(leaf->indices, (std::vector<int32_t>{0, 1}));
    expect_near3(leaf->color, {0.5, 0, 0.5});
    expect_near3(leaf->info.origin, {0, 0, 0});
    EXPECT_EQ(leaf->info.size, 1.0);
    EXPECT_EQ(leaf->info.depth, 3);

    const auto grid = tree.to_voxel_grid();
    EXPECT_EQ(grid.voxel_size(), 1.0);
    EXPECT_EQ(grid.origin(), (Vec3{0, 0, 0}));
    const auto voxels = grid.get_voxels();
    ASSERT_EQ(voxels.size(), 3u);
    EXPECT_EQ(voxels[0].grid_index, (GridIndex{0, 0, 0}));
    expect_near3(voxels[0].color, {0.5, 0, 0.5});
    EXPECT_EQ(voxels[1].grid_index, (GridIndex{2, 0, 6}));
    EXPECT_EQ(voxels[2].grid_index, (GridIndex{7, 7, 7}));
    expect_near3(voxels[2].color, {0, 1, 0});
    EXPECT_EQ(VoxelGrid::create_from_octree(tree).num_voxels(), 3u);

    Octree back(3);
    back.create_from_voxel_grid(grid);
    EXPECT_EQ(back.num_leaf_nodes(), 3u);
    EXPECT_EQ(back.max_depth(), 3);
    // One leaf per voxel centre, holding the voxel's color and its position in the grid's order.
    const auto far = back.locate_leaf_node(grid.get_voxel_center_coordinate({7, 7, 7}));
    ASSERT_TRUE(far.has_value());
    EXPECT_EQ(far->indices, (std::vector<int32_t>{2}));
    expect_near3(far->color, {0, 1, 0});
    EXPECT_EQ(back.to_voxel_grid().num_voxels(), 3u);

    EXPECT_THROW(Octree(0, {0, 0, 0}, 1.0), o3dpp::Error);
    EXPECT_THROW(Octree(3, {0, 0, 0}, 0.0), o3dpp::Error);
    EXPECT_THROW(tree.insert_point({1, 1, 1}, -1, {0, 0, 0}), o3dpp::Error);
}
