// SPDX-License-Identifier: MIT
// Voxel grids from point clouds and meshes: analytic cases, and Open3D 0.20's numbers on the shared data
// recorded by tools/reference/record_lineset_voxel_octree.py.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <limits>

#include "o3d/geometry/voxel_grid_ops.h"
#include "o3d/io/point_cloud_io.h"
#include "o3d/io/triangle_mesh_io.h"
#include "o3d/utility/error.h"
#include "test_data.h"

using namespace o3d::geometry;

namespace {

/// The recording script's checksum: sum over rank r of (r + 1) * (i + 1009 j + 1009^2 k).
int64_t index_checksum(const VoxelGrid& g) {
    int64_t sum = 0;
    for (size_t r = 0; r < g.voxels.size(); ++r) {
        const Eigen::Vector3i& v = g.voxels[r].grid_index;
        sum += static_cast<int64_t>(r + 1) * (v(0) + 1009LL * v(1) + 1009LL * 1009LL * v(2));
    }
    return sum;
}

bool sorted_unique(const VoxelGrid& g) {
    for (size_t i = 1; i < g.voxels.size(); ++i) {
        const Eigen::Vector3i &a = g.voxels[i - 1].grid_index, &b = g.voxels[i].grid_index;
        if (!std::lexicographical_compare(a.data(), a.data() + 3, b.data(), b.data() + 3)) return false;
    }
    return true;
}

}  // namespace

TEST(VoxelGrid, UnitCubeCornersAtHalfVoxels) {
    // The 8 corners of the unit cube plus the centre; voxel 0.5, origin = (-0.25)^3.
    PointCloud pc;
    for (int i = 0; i < 8; ++i) {
        pc.points.emplace_back(i & 1, (i >> 1) & 1, (i >> 2) & 1);
        pc.colors.emplace_back(i & 1, 0.0, 1.0);
    }
    pc.points.emplace_back(0.5, 0.5, 0.5);
    pc.colors.emplace_back(0.2, 0.4, 0.6);
    pc.points.emplace_back(0.6, 0.6, 0.6);  // same cell as the centre: (0.85 / 0.5) floors to 1
    pc.colors.emplace_back(0.4, 0.0, 0.0);
    const VoxelGrid g = voxel_grid_from_point_cloud(pc, 0.5);
    EXPECT_TRUE(g.origin.isApprox(Eigen::Vector3d::Constant(-0.25)));
    EXPECT_DOUBLE_EQ(g.voxel_size, 0.5);
    ASSERT_EQ(g.voxels.size(), 9u);
    ASSERT_TRUE(sorted_unique(g));
    EXPECT_EQ(g.voxels.front().grid_index, Eigen::Vector3i(0, 0, 0));
    EXPECT_EQ(g.voxels.back().grid_index, Eigen::Vector3i(2, 2, 2));
    // Corners land on even indices, the centre cell is (1,1,1) with the mean of its two colors.
    for (const Voxel& v : g.voxels) {
        if (v.grid_index == Eigen::Vector3i(1, 1, 1)) {
            EXPECT_TRUE(v.color.isApprox(Eigen::Vector3d(0.3, 0.2, 0.3)));
        } else {
            EXPECT_EQ(v.grid_index.array().unaryExpr([](int x) { return x % 2; }).sum(), 0);
            EXPECT_DOUBLE_EQ(v.color(0), v.grid_index(0) / 2.0);
            EXPECT_DOUBLE_EQ(v.color(2), 1.0);
        }
    }
    EXPECT_EQ(voxel_index_of(g, {1.0, 0.0, 0.4}), Eigen::Vector3i(2, 0, 1));
    const std::vector<bool> inc = voxels_include(g, {{0, 0, 0}, {0.5, 0, 0}, {0.55, 0.55, 0.55}, {9, 9, 9}});
    EXPECT_EQ(inc, (std::vector<bool>{true, false, true, false}));
}

TEST(VoxelGrid, WithinBoundsDropsOutsidePoints) {
    PointCloud pc;
    pc.points = {{0, 0, 0}, {0.9, 0.9, 0.9}, {1.5, 0.2, 0.2}, {-0.1, 0.5, 0.5}};
    const VoxelGrid g = voxel_grid_from_point_cloud_within_bounds(pc, 0.5, {0, 0, 0}, {1, 1, 1});
    EXPECT_TRUE(g.origin.isZero());
    ASSERT_EQ(g.voxels.size(), 2u);
    EXPECT_EQ(g.voxels[0].grid_index, Eigen::Vector3i(0, 0, 0));
    EXPECT_EQ(g.voxels[1].grid_index, Eigen::Vector3i(1, 1, 1));
    EXPECT_TRUE(g.voxels[0].color.isZero());  // no colors
    EXPECT_THROW(voxel_grid_from_point_cloud_within_bounds(pc, 0.5, {1, 1, 1}, {0, 0, 0}), o3d::InvalidArgument);
}

TEST(VoxelGrid, BadInputsAreErrors) {
    PointCloud pc;
    EXPECT_THROW(voxel_grid_from_point_cloud(pc, 0.5), o3d::InvalidArgument);
    pc.points = {{0, 0, 0}, {1, 1, 1}};
    EXPECT_THROW(voxel_grid_from_point_cloud(pc, 0.0), o3d::InvalidArgument);
    EXPECT_THROW(voxel_grid_from_point_cloud(pc, -1.0), o3d::InvalidArgument);
    EXPECT_THROW(voxel_grid_from_point_cloud(pc, std::nan("")), o3d::InvalidArgument);
    EXPECT_THROW(voxel_grid_from_point_cloud(pc, 1e-300), o3d::InvalidArgument);  // indices overflow int32
    pc.points.emplace_back(std::numeric_limits<double>::infinity(), 0, 0);
    EXPECT_THROW(voxel_grid_from_point_cloud(pc, 0.5), o3d::InvalidArgument);
    TriangleMesh mesh;
    EXPECT_THROW(voxel_grid_from_triangle_mesh(mesh, 0.5), o3d::InvalidArgument);
    mesh.vertices = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
    mesh.triangles = {{0, 1, 3}};
    EXPECT_THROW(voxel_grid_from_triangle_mesh(mesh, 0.5), o3d::InvalidArgument);
    PointCloud one;
    one.points = {{0, 0, 0}};
    const VoxelGrid g = voxel_grid_from_point_cloud_within_bounds(one, 1.0, {0, 0, 0}, {1, 1, 1});
    EXPECT_THROW(voxel_index_of(g, {NAN, 0, 0}), o3d::InvalidArgument);
    EXPECT_THROW(voxel_index_of(g, {1e300, 0, 0}), o3d::InvalidArgument);
}

TEST(VoxelGrid, TriangleBoxOverlapSeparatingAxes) {
    const Eigen::Vector3d c(0, 0, 0), h(0.5, 0.5, 0.5);
    EXPECT_TRUE(triangle_box_overlap(c, h, {-2, -2, 0}, {2, -2, 0}, {0, 2, 0}));  // cuts through the middle
    EXPECT_TRUE(triangle_box_overlap(c, h, {0.5, 0, 0}, {2, 0, 0}, {2, 1, 0}));   // touches a face
    EXPECT_FALSE(triangle_box_overlap(c, h, {0.6, 0, 0}, {2, 0, 0}, {2, 1, 0}));  // box-axis separation
    EXPECT_FALSE(triangle_box_overlap(c, h, {-2, -2, 0.7}, {2, -2, 0.7}, {0, 2, 0.7}));
    // A tilted triangle whose bounding box covers the box's corner: its plane passes beyond or through it.
    EXPECT_FALSE(triangle_box_overlap(c, h, {1.6, 0, 0}, {0, 1.6, 0}, {0, 0, 1.6}));
    EXPECT_TRUE(triangle_box_overlap(c, h, {1.4, 0, 0}, {0, 1.4, 0}, {0, 0, 1.4}));
    // A tall sliver passing beside a box edge.
    EXPECT_FALSE(triangle_box_overlap(c, h, {1.2, 0, -5}, {0, 1.2, -5}, {0, 1.2, 5}));
}

TEST(VoxelGrid, FlatTriangleVoxelsLieOnItsPlane) {
    // A triangle in the plane z = 0.3 (inside a voxel layer), then one on the tilted plane x + y + z = 1.
    TriangleMesh mesh;
    mesh.vertices = {{0, 0, 0.3}, {2, 0, 0.3}, {0, 2, 0.3}};
    mesh.triangles = {{0, 1, 2}};
    const double s = 0.25;
    VoxelGrid g = voxel_grid_from_triangle_mesh(mesh, s);
    EXPECT_TRUE(g.origin.isApprox(Eigen::Vector3d(-s / 2, -s / 2, 0.3 - s / 2)));
    ASSERT_TRUE(sorted_unique(g));
    // Cells whose centre is within the triangle, and a few along the hypotenuse: all in layer k = 0.
    for (const Voxel& v : g.voxels) EXPECT_EQ(v.grid_index(2), 0);
    // Cell (i, j) overlaps iff its lower-left corner (i s - s/2, j s - s/2) has x + y <= 2 -> i + j <= 9.
    size_t expected = 0;
    for (int i = 0; i <= 8; ++i)
        for (int j = 0; j <= 8; ++j) expected += (i + j <= 9) ? 1 : 0;
    EXPECT_EQ(g.voxels.size(), expected);

    mesh.vertices = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
    g = voxel_grid_from_triangle_mesh(mesh, 0.1);
    ASSERT_FALSE(g.voxels.empty());
    const double half_diagonal = 0.1 * std::sqrt(3.0) / 2.0;
    for (const Voxel& v : g.voxels) {
        const Eigen::Vector3d centre = g.origin + (v.grid_index.cast<double>().array() + 0.5).matrix() * 0.1;
        // Distance from the cell centre to the plane is at most the cell's half diagonal.
        EXPECT_LE(std::abs(centre.sum() - 1.0) / std::sqrt(3.0), half_diagonal + 1e-12);
    }
}

TEST(VoxelGrid, CloudBin0MatchesOpen3D) {
    O3D_TEST_DATA_OR_SKIP(path, "open3d/Feature/cloud_bin_0.pcd");
    const PointCloud pc = o3d::io::read_point_cloud(path);
    ASSERT_EQ(pc.points.size(), 3903u);
    const VoxelGrid g = voxel_grid_from_point_cloud(pc, 0.05);
    // record_lineset_voxel_octree.py: origin, count 2655, checksum 44848341670868.
    EXPECT_NEAR(g.origin.x(), 1.2066981554031373, 1e-12);
    EXPECT_NEAR(g.origin.y(), -0.02985198013484478, 1e-12);
    EXPECT_NEAR(g.origin.z(), -2.315013790130615, 1e-12);
    EXPECT_EQ(g.voxels.size(), 2655u);
    EXPECT_EQ(index_checksum(g), 44848341670868LL);
    ASSERT_FALSE(g.voxels.empty());
    EXPECT_EQ(g.voxels[0].grid_index, Eigen::Vector3i(0, 19, 2));
    EXPECT_NEAR(g.voxels[0].color(0), 0.5254901960784314, 1e-12);
    EXPECT_NEAR(g.voxels[0].color(1), 0.6078431372549019, 1e-12);
    EXPECT_NEAR(g.voxels[0].color(2), 0.7490196078431373, 1e-12);
    Eigen::Vector3d color_sum = Eigen::Vector3d::Zero();
    for (const Voxel& v : g.voxels) color_sum += v.color;
    EXPECT_NEAR(color_sum(0), 291.64222222222276, 1e-9);
    EXPECT_NEAR(color_sum(1), 276.8083006535957, 1e-9);
    EXPECT_NEAR(color_sum(2), 258.6162091503271, 1e-9);
}

TEST(VoxelGrid, KnotMeshMatchesOpen3D) {
    O3D_TEST_DATA_OR_SKIP(path, "open3d/knot.ply");
    const TriangleMesh mesh = o3d::io::read_triangle_mesh(path);
    const VoxelGrid g = voxel_grid_from_triangle_mesh(mesh, 3.0);
    // record_lineset_voxel_octree.py: origin, count 18920, checksum 5515302917987842.
    EXPECT_NEAR(g.origin.x(), -150.79086303710938, 1e-9);
    EXPECT_NEAR(g.origin.y(), -68.3590087890625, 1e-9);
    EXPECT_NEAR(g.origin.z(), -168.72898864746094, 1e-9);
    EXPECT_EQ(g.voxels.size(), 18920u);
    EXPECT_EQ(index_checksum(g), 5515302917987842LL);
}
