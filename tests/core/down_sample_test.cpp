// SPDX-License-Identifier: MIT
// Voxel averages on hand-built clouds, every-k, seeded random, farthest-point sampling.
#include "o3d/geometry/down_sample.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <set>

#include "o3d/utility/error.h"

using namespace o3d::geometry;

namespace {

PointCloud random_cloud(size_t n, uint64_t seed) {
    std::mt19937_64 rng(seed);
    std::uniform_real_distribution<double> u(0.0, 1.0);
    PointCloud c;
    for (size_t i = 0; i < n; ++i) {
        c.points.emplace_back(u(rng) * 10, u(rng) * 10, u(rng));
        c.normals.emplace_back(u(rng), u(rng), u(rng));
        c.colors.emplace_back(u(rng), u(rng), u(rng));
    }
    return c;
}

}  // namespace

TEST(VoxelDownSample, AveragesPointsNormalsColorsPerVoxel) {
    // voxel 1, min bound (0,0,0) -> grid origin (-0.5,-0.5,-0.5): cells centred on integers.
    PointCloud c;
    c.points = {{0, 0, 0}, {0.4, 0.2, 0}, {3, 0, 0}, {0.2, 0.4, 0.1}, {3.2, 0.1, 0}};
    c.normals = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {0, 0, 1}, {0, 0, -1}};
    c.colors = {{0.3, 0, 0}, {0.6, 0, 0}, {1, 1, 1}, {0, 0.9, 0}, {0, 0, 0}};
    const PointCloud d = voxel_down_sample(c, 1.0);
    ASSERT_EQ(d.size(), 2u);
    // Output sorted by voxel (z, y, x): x-cell 0 first, then x-cell 3.
    EXPECT_TRUE(d.points[0].isApprox(Eigen::Vector3d(0.2, 0.2, 0.1 / 3), 1e-15));
    EXPECT_TRUE(d.normals[0].isApprox(Eigen::Vector3d(1, 1, 1) / 3, 1e-15));  // averaged, not renormalised
    EXPECT_TRUE(d.colors[0].isApprox(Eigen::Vector3d(0.3, 0.3, 0), 1e-15));
    EXPECT_TRUE(d.points[1].isApprox(Eigen::Vector3d(3.1, 0.05, 0), 1e-15));
    EXPECT_TRUE(d.normals[1].isZero());
    EXPECT_TRUE(d.colors[1].isApprox(Eigen::Vector3d(0.5, 0.5, 0.5), 1e-15));
}

TEST(VoxelDownSample, UsesOpen3DGridOrigin) {
    // With origin min - v/2 = -0.25, points 0.2 and 0.3 fall in different cells (0.2 -> 0, 0.3 -> 1).
    PointCloud c;
    c.points = {{0, 0, 0}, {0.2, 0, 0}, {0.3, 0, 0}};
    const PointCloud d = voxel_down_sample(c, 0.5);
    ASSERT_EQ(d.size(), 2u);
    EXPECT_DOUBLE_EQ(d.points[0].x(), 0.1);
    EXPECT_DOUBLE_EQ(d.points[1].x(), 0.3);
    EXPECT_FALSE(d.has_normals());
}

TEST(VoxelDownSample, DeterministicAcrossThreadCounts) {
    const PointCloud c = random_cloud(50000, 3);
    const PointCloud a = voxel_down_sample(c, 0.37, 1);
    const PointCloud b = voxel_down_sample(c, 0.37, 2);
    ASSERT_EQ(a.size(), b.size());
    EXPECT_EQ(a.points, b.points);
    EXPECT_EQ(a.normals, b.normals);
    EXPECT_EQ(a.colors, b.colors);
    // Each point's cell appears exactly once.
    EXPECT_LE(a.size(), 28u * 28u * 4u);
}

TEST(VoxelDownSample, RejectsBadInput) {
    const PointCloud c = random_cloud(10, 4);
    EXPECT_THROW(voxel_down_sample(c, 0.0), o3d::InvalidArgument);
    EXPECT_THROW(voxel_down_sample(c, -1.0), o3d::InvalidArgument);
    EXPECT_THROW(voxel_down_sample(c, std::nan("")), o3d::InvalidArgument);
    EXPECT_THROW(voxel_down_sample(c, 1e-12), o3d::InvalidArgument);  // index would overflow an int
    PointCloud bad = c;
    bad.points[2].x() = INFINITY;
    EXPECT_THROW(voxel_down_sample(bad, 0.1), o3d::InvalidArgument);
    EXPECT_EQ(voxel_down_sample(PointCloud{}, 0.1).size(), 0u);
}

TEST(UniformDownSample, EveryKth) {
    const PointCloud c = random_cloud(10, 5);
    const PointCloud d = uniform_down_sample(c, 3);
    ASSERT_EQ(d.size(), 4u);
    EXPECT_EQ(d.points[0], c.points[0]);
    EXPECT_EQ(d.points[1], c.points[3]);
    EXPECT_EQ(d.points[3], c.points[9]);
    EXPECT_EQ(d.colors[2], c.colors[6]);
    EXPECT_EQ(uniform_down_sample(c, 1).size(), 10u);
    EXPECT_THROW(uniform_down_sample(c, 0), o3d::InvalidArgument);
}

TEST(RandomDownSample, SeededCountOrderAndReproducibility) {
    PointCloud c;
    for (int i = 0; i < 1000; ++i) c.points.emplace_back(i, 0, 0);  // x = original index
    const PointCloud a = random_down_sample(c, 0.25, 42);
    ASSERT_EQ(a.size(), 250u);
    for (size_t i = 1; i < a.size(); ++i) EXPECT_LT(a.points[i - 1].x(), a.points[i].x());  // original order
    EXPECT_EQ(random_down_sample(c, 0.25, 42).points, a.points);
    EXPECT_NE(random_down_sample(c, 0.25, 43).points, a.points);
    EXPECT_EQ(random_down_sample(c, 0.0999, 1).size(), 99u);  // floor, as Open3D's (size_t)(ratio * N)
    EXPECT_EQ(random_down_sample(c, 1.0, 1).size(), 1000u);
    EXPECT_THROW(random_down_sample(c, 1.5, 1), o3d::InvalidArgument);
    EXPECT_THROW(random_down_sample(c, std::nan(""), 1), o3d::InvalidArgument);
}

TEST(RandomDownSample, IsRoughlyUniform) {
    PointCloud c;
    for (int i = 0; i < 10000; ++i) c.points.emplace_back(i, 0, 0);
    const PointCloud a = random_down_sample(c, 0.5, 7);
    size_t low_half = 0;
    for (const auto& p : a.points) low_half += p.x() < 5000 ? 1 : 0;
    EXPECT_NEAR(static_cast<double>(low_half), 2500.0, 200.0);  // ~6 sigma
}

TEST(FarthestPointDownSample, HandMadeCloud) {
    PointCloud c;
    // A tight cluster near the origin plus three far corners.
    c.points = {{0, 0, 0}, {0.1, 0, 0}, {10, 0, 0}, {0, 0.1, 0}, {0, 10, 0}, {0.05, 0.05, 0}, {10, 10, 0}};
    // From index 0: farthest is (10,10) [6], then (10,0) [2] (tie with (0,10) [4]: first index wins).
    const PointCloud d = farthest_point_down_sample(c, 3, 0);
    ASSERT_EQ(d.size(), 3u);
    EXPECT_EQ(d.points[0], c.points[0]);  // original order
    EXPECT_EQ(d.points[1], c.points[2]);
    EXPECT_EQ(d.points[2], c.points[6]);
    const PointCloud e = farthest_point_down_sample(c, 4, 0);
    EXPECT_EQ(e.points[2], c.points[4]);
    EXPECT_EQ(farthest_point_down_sample(c, 7, 3).size(), 7u);
    EXPECT_EQ(farthest_point_down_sample(c, 0, 0).size(), 0u);
    EXPECT_THROW(farthest_point_down_sample(c, 8, 0), o3d::InvalidArgument);
    EXPECT_THROW(farthest_point_down_sample(c, 2, 7), o3d::InvalidArgument);
}

TEST(FarthestPointDownSample, ParallelMatchesSerial) {
    const PointCloud c = random_cloud(30000, 9);  // above the parallel threshold
    const PointCloud a = farthest_point_down_sample(c, 50, 17, 1);
    const PointCloud b = farthest_point_down_sample(c, 50, 17, 2);
    ASSERT_EQ(a.size(), 50u);
    EXPECT_EQ(a.points, b.points);
}
