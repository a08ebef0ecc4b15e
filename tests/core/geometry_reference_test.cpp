// SPDX-License-Identifier: MIT
// Voxel down-sampling and normal estimation on the shared data, against numbers recorded from
// Open3D 0.20.0 (pip wheel) by tools/reference/record_geometry.py.
#include <gtest/gtest.h>

#include <cmath>

#include "o3d/geometry/down_sample.h"
#include "o3d/geometry/normals.h"
#include "o3d/io/point_cloud_io.h"
#include "test_data.h"

using namespace o3d::geometry;

namespace {

Eigen::Vector3d mean_of(const std::vector<Eigen::Vector3d>& v) {
    Eigen::Vector3d s = Eigen::Vector3d::Zero();
    for (const auto& x : v) s += x;
    return s / static_cast<double>(v.size());
}

void expect_near(const Eigen::Vector3d& actual, const Eigen::Vector3d& expected, double tol) {
    for (int i = 0; i < 3; ++i) EXPECT_NEAR(actual(i), expected(i), tol) << "component " << i;
}

}  // namespace

TEST(GeometryReference, VoxelDownSampleFragmentMatchesOpen3D) {
    O3D_TEST_DATA_OR_SKIP(path, "open3d/fragment.pcd");
    const PointCloud cloud = o3d::io::read_point_cloud(path);
    ASSERT_EQ(cloud.size(), 113662u);
    const PointCloud down = voxel_down_sample(cloud, 0.05);
    // Open3D 0.20.0: len(fragment.voxel_down_sample(0.05).points) and the means of its arrays.
    // Means do not depend on output order (Open3D's is hash-map order, ours is sorted).
    EXPECT_EQ(down.size(), 2756u);
    ASSERT_TRUE(down.has_normals());
    ASSERT_TRUE(down.has_colors());
    expect_near(mean_of(down.points), {2.2330805689811837, 1.7559124261122498, 1.303686159111936}, 1e-12);
    expect_near(mean_of(down.normals), {0.11391560209302212, 0.08577494749340589, -0.7093144526518116}, 1e-12);
    expect_near(mean_of(down.colors), {0.46194491396255916, 0.44421926948720003, 0.42404109508188803}, 1e-12);
}

TEST(GeometryReference, EstimateNormalsCloudBin0MatchesOpen3D) {
    O3D_TEST_DATA_OR_SKIP(path, "open3d/Feature/cloud_bin_0.pcd");
    PointCloud cloud = o3d::io::read_point_cloud(path);
    ASSERT_EQ(cloud.size(), 3903u);
    cloud.normals.clear();
    estimate_normals(cloud, o3d::kdtree::SearchParam::make_hybrid(0.1, 30));
    // Open3D 0.20.0: estimate_normals(KDTreeSearchParamHybrid(0.1, 30)) after clearing the normals.
    // Without prior normals the sign is arbitrary, so compare |dot|.
    const std::pair<size_t, Eigen::Vector3d> expected[] = {
        {0, {0.9955899583897233, -0.08914477146011432, 0.029220617291100506}},
        {500, {-0.10582461088093655, -0.028286946829250474, 0.9939823943968915}},
        {1000, {0.9930933769302994, 0.08125003589320465, -0.08464027625502585}},
        {2000, {-0.07521121037708016, 0.9951586157603558, -0.06326613084065594}},
        {3902, {0.9631053075369859, -0.10644051175140758, -0.24718127771371798}},
    };
    for (const auto& [index, normal] : expected) {
        EXPECT_NEAR(cloud.normals[index].norm(), 1.0, 1e-12);
        EXPECT_NEAR(std::abs(cloud.normals[index].dot(normal)), 1.0, 1e-9) << "point " << index;
    }
}
