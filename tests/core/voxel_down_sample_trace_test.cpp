// SPDX-License-Identifier: MIT
// Voxel down-sampling with its trace: Open3D 0.20 reference on a small cloud (points, normals, colors,
// cubic ids, index lists; approximate classes and their ties), points outside the bounds, order, errors.
#include "o3d/geometry/voxel_down_sample_trace.h"

#include <gtest/gtest.h>

#include <limits>

#include "o3d/utility/error.h"

using namespace o3d::geometry;

namespace {

/// The cloud of the Open3D reference (voxel_size 1, min_bound 0, max_bound 2): points 6 and 7 lie outside
/// the bounds, point 4 sits exactly on a voxel's mid-plane (x fraction 0.5 counts as the upper half).
PointCloud reference_cloud() {
    PointCloud c;
    c.points = {{0.1, 0.1, 0.1}, {0.9, 0.2, 0.1}, {0.6, 0.6, 0.6}, {0.2, 0.7, 0.3}, {1.5, 0.1, 0.1},
                {1.6, 0.2, 0.9}, {-0.5, 0.1, 0.1}, {5, 5, 5}, {0.4, 0.4, 0.4}};
    c.normals = {{0, 0, 1}, {0, 1, 0}, {1, 0, 0}, {0, 0, 1}, {0, 0, 2}, {1, 1, 1}, {0, 1, 0}, {1, 0, 0}, {0, 0, 1}};
    c.colors = {{1, 0, 0}, {2, 0, 0}, {2, 0.5, 0}, {3, 0, 0}, {0.5, 0, 0}, {1.7, 0, 0}, {0.2, 0, 0}, {0, 0, 0}, {2.9, 1, 1}};
    return c;
}

std::vector<int> indices_of(const VoxelTrace& t, size_t i) {
    return {t.indices.begin() + t.offsets[i], t.indices.begin() + t.offsets[i + 1]};
}

}  // namespace

TEST(VoxelDownSampleTrace, MatchesOpen3D) {
    // Open3D 0.20: pc.voxel_down_sample_and_trace(1.0, [0,0,0], [2,2,2], False) on reference_cloud(); its rows
    // come in hash order, here in (z, y, x) voxel order: voxels (-1,0,0), (0,0,0), (1,0,0), (5,5,5).
    const VoxelTrace t = voxel_down_sample_and_trace(reference_cloud(), 1.0, {0, 0, 0}, {2, 2, 2});
    ASSERT_EQ(t.cloud.size(), 4u);
    ASSERT_EQ(t.offsets.size(), 5u);
    ASSERT_EQ(t.cubic_ids.size(), 4u);
    const std::vector<Eigen::Vector3d> points = {{-0.5, 0.1, 0.1}, {0.44, 0.4, 0.3}, {1.55, 0.15, 0.5}, {5, 5, 5}};
    const std::vector<Eigen::Vector3d> normals = {{0, 1, 0}, {0.2, 0.2, 0.6}, {0.5, 0.5, 1.5}, {1, 0, 0}};
    const std::vector<Eigen::Vector3d> colors = {{0.2, 0, 0}, {2.18, 0.3, 0.2}, {1.1, 0, 0}, {0, 0, 0}};
    const std::vector<std::array<int, 8>> cubic = {{-1, 6, -1, -1, -1, -1, -1, -1},
                                                   {8, 1, 3, -1, -1, -1, -1, 2},
                                                   {-1, 4, -1, -1, -1, 5, -1, -1},
                                                   {7, -1, -1, -1, -1, -1, -1, -1}};
    const std::vector<std::vector<int>> members = {{6}, {0, 1, 2, 3, 8}, {4, 5}, {7}};
    for (size_t i = 0; i < 4; ++i) {
        EXPECT_LT((t.cloud.points[i] - points[i]).norm(), 1e-12) << i;
        EXPECT_LT((t.cloud.normals[i] - normals[i]).norm(), 1e-12) << i;
        EXPECT_LT((t.cloud.colors[i] - colors[i]).norm(), 1e-12) << i;
        EXPECT_EQ(t.cubic_ids[i], cubic[i]) << i;
        EXPECT_EQ(indices_of(t, i), members[i]) << i;
    }
    EXPECT_TRUE(t.cloud.covariances.empty());
}

TEST(VoxelDownSampleTrace, ApproximateClassMatchesOpen3D) {
    // Open3D 0.20, approximate_class=True: colors (k, k, k) for the most frequent int(red).
    const VoxelTrace t = voxel_down_sample_and_trace(reference_cloud(), 1.0, {0, 0, 0}, {2, 2, 2}, true);
    const std::vector<double> classes = {0, 2, 1, 0};  // voxel (1,0,0): int(0.5) = 0 and int(1.7) = 1 tie
    for (size_t i = 0; i < 4; ++i) EXPECT_EQ(t.cloud.colors[i], Eigen::Vector3d::Constant(classes[i])) << i;
    EXPECT_TRUE(t.cloud.points[1].isApprox(Eigen::Vector3d(0.44, 0.4, 0.3), 1e-12));
}

TEST(VoxelDownSampleTrace, ApproximateClassTiesAsOpen3D) {
    // Open3D 0.20 on one voxel with these reds: ties go to the class first seen last; int() truncates.
    struct Case {
        std::vector<double> reds;
        double expected;
    };
    const std::vector<Case> cases = {{{0, 1}, 1},       {{1, 0}, 0},          {{3, 1, 2}, 2},     {{2, 1, 3}, 3},
                                     {{1, 2, 3, 3, 1}, 3}, {{3, 1, 1, 3}, 1}, {{10, 3, 10, 3}, 3}, {{4, 9, 2, 9, 4}, 9},
                                     {{-1.5, -0.5, 0.2}, 0}, {{0.5, 1.5}, 1}};
    for (const auto& c : cases) {
        PointCloud cloud;
        for (size_t i = 0; i < c.reds.size(); ++i) {
            cloud.points.emplace_back(0.1 + 0.01 * static_cast<double>(i), 0.1, 0.1);
            cloud.colors.emplace_back(c.reds[i], 0.5, 0.7);
        }
        const VoxelTrace t = voxel_down_sample_and_trace(cloud, 1.0, {0, 0, 0}, {2, 2, 2}, true);
        ASSERT_EQ(t.cloud.size(), 1u);
        EXPECT_EQ(t.cloud.colors[0], Eigen::Vector3d::Constant(c.expected)) << "first red " << c.reds[0];
    }
}

TEST(VoxelDownSampleTrace, GridAnchoredAtMinBound) {
    // The same points, the grid shifted by half a voxel: other groups and octants (as Open3D 0.20).
    PointCloud cloud;
    cloud.points = {{0.1, 0, 0}, {0.4, 0, 0}, {0.6, 0, 0}, {0.9, 0, 0}};
    const VoxelTrace a = voxel_down_sample_and_trace(cloud, 1.0, {0, 0, 0}, {1, 1, 1});
    ASSERT_EQ(a.cloud.size(), 1u);
    EXPECT_EQ(a.cubic_ids[0], (std::array<int, 8>{1, 3, -1, -1, -1, -1, -1, -1}));
    const VoxelTrace b = voxel_down_sample_and_trace(cloud, 1.0, {-0.5, 0, 0}, {1, 1, 1});
    ASSERT_EQ(b.cloud.size(), 2u);
    EXPECT_EQ(indices_of(b, 0), (std::vector<int>{0, 1}));
    EXPECT_EQ(indices_of(b, 1), (std::vector<int>{2, 3}));
    EXPECT_EQ(b.cubic_ids[0], (std::array<int, 8>{-1, 1, -1, -1, -1, -1, -1, -1}));
    EXPECT_EQ(b.cubic_ids[1], (std::array<int, 8>{3, -1, -1, -1, -1, -1, -1, -1}));
    EXPECT_TRUE(b.cloud.points[1].isApprox(Eigen::Vector3d(0.75, 0, 0), 1e-15));
    EXPECT_TRUE(b.cloud.normals.empty());
    EXPECT_TRUE(b.cloud.colors.empty());
}

TEST(VoxelDownSampleTrace, EmptyCloudGivesEmptyTrace) {
    const VoxelTrace t = voxel_down_sample_and_trace(PointCloud{}, 1.0, {0, 0, 0}, {1, 1, 1});
    EXPECT_EQ(t.cloud.size(), 0u);
    EXPECT_EQ(t.offsets, std::vector<int>{0});
    EXPECT_TRUE(t.indices.empty());
}

TEST(VoxelDownSampleTrace, BadInputThrows) {
    const PointCloud cloud = reference_cloud();
    const double nan = std::numeric_limits<double>::quiet_NaN();
    EXPECT_THROW(voxel_down_sample_and_trace(cloud, 0.0, {0, 0, 0}, {1, 1, 1}), o3d::InvalidArgument);
    EXPECT_THROW(voxel_down_sample_and_trace(cloud, -1.0, {0, 0, 0}, {1, 1, 1}), o3d::InvalidArgument);
    EXPECT_THROW(voxel_down_sample_and_trace(cloud, nan, {0, 0, 0}, {1, 1, 1}), o3d::InvalidArgument);
    EXPECT_THROW(voxel_down_sample_and_trace(cloud, 1.0, {1, 1, 1}, {0, 0, 0}), o3d::InvalidArgument);
    EXPECT_THROW(voxel_down_sample_and_trace(cloud, 1.0, {0, nan, 0}, {1, 1, 1}), o3d::InvalidArgument);
    EXPECT_THROW(voxel_down_sample_and_trace(cloud, 1e-12, {0, 0, 0}, {1e3, 1, 1}), o3d::InvalidArgument);
    PointCloud far = cloud;
    far.points[2] = {1e15, 0, 0};  // inside no int voxel index
    EXPECT_THROW(voxel_down_sample_and_trace(far, 1.0, {0, 0, 0}, {1, 1, 1}), o3d::InvalidArgument);
    PointCloud bad = cloud;
    bad.points[3].z() = nan;
    EXPECT_THROW(voxel_down_sample_and_trace(bad, 1.0, {0, 0, 0}, {1, 1, 1}), o3d::InvalidArgument);
    PointCloud bad_red = cloud;
    bad_red.colors[1].x() = nan;
    EXPECT_NO_THROW(voxel_down_sample_and_trace(bad_red, 1.0, {0, 0, 0}, {1, 1, 1}));
    EXPECT_THROW(voxel_down_sample_and_trace(bad_red, 1.0, {0, 0, 0}, {1, 1, 1}, true), o3d::InvalidArgument);
}
