// SPDX-License-Identifier: MIT
// remove_duplicated_points: Open3D 0.20's behaviour (first occurrence kept, order preserved, -0 == 0,
// NaN points never merged), checked against the open3d 0.20.0 wheel on the same small cloud.
#include "o3d/geometry/duplicate_points.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>

using namespace o3d::geometry;

TEST(DuplicatePoints, KeepsFirstOccurrenceInOrder) {
    // Open3D 0.20.0 on these points keeps [1,0,0], [0,1,0], [2,2,2], [3,3,3] with colors of rows 0, 1, 3, 6.
    PointCloud pc;
    pc.points = {{1, 0, 0}, {0, 1, 0}, {1, 0, 0}, {2, 2, 2}, {0, 1, 0}, {-0.0, 1, 0}, {3, 3, 3}};
    for (size_t i = 0; i < pc.size(); ++i) {
        pc.colors.emplace_back(i / 10.0, 0, 0);
        pc.normals.emplace_back(0, 0, static_cast<double>(i));
        pc.covariances.push_back(static_cast<double>(i) * Eigen::Matrix3d::Identity());
    }
    const std::vector<int64_t> kept = remove_duplicated_points(pc);
    EXPECT_EQ(kept, (std::vector<int64_t>{0, 1, 3, 6}));
    ASSERT_EQ(pc.size(), 4u);
    EXPECT_EQ(pc.points[2], Eigen::Vector3d(2, 2, 2));
    for (size_t s = 0; s < kept.size(); ++s) {
        EXPECT_EQ(pc.colors[s].x(), static_cast<double>(kept[s]) / 10.0);
        EXPECT_EQ(pc.normals[s].z(), static_cast<double>(kept[s]));
        EXPECT_EQ(pc.covariances[s](1, 1), static_cast<double>(kept[s]));
    }
}

TEST(DuplicatePoints, RandomCloudWithCopies) {
    std::mt19937_64 rng(5);
    std::uniform_int_distribution<int> coord(0, 6);  // a coarse lattice: many exact repeats
    PointCloud pc;
    for (int i = 0; i < 3000; ++i) pc.points.emplace_back(coord(rng), coord(rng), coord(rng) * 0.1);
    const PointCloud before = pc;
    const std::vector<int64_t> kept = remove_duplicated_points(pc);
    // Brute force: a point is kept iff no earlier point equals it.
    std::vector<int64_t> expected;
    for (size_t i = 0; i < before.size(); ++i) {
        bool seen = false;
        for (size_t j = 0; j < i && !seen; ++j) seen = before.points[j] == before.points[i];
        if (!seen) expected.push_back(static_cast<int64_t>(i));
    }
    EXPECT_EQ(kept, expected);
    EXPECT_EQ(pc.size(), expected.size());
    EXPECT_LE(pc.size(), 7u * 7u * 7u);
}

TEST(DuplicatePoints, NanPointsAndEdgeCases) {
    const double nan = std::numeric_limits<double>::quiet_NaN();
    PointCloud pc;
    pc.points = {{nan, 0, 0}, {nan, 0, 0}, {1, 1, 1}};
    pc.normals = {{1, 0, 0}};  // not one per point: ignored, left alone
    EXPECT_EQ(remove_duplicated_points(pc).size(), 3u);  // Open3D 0.20.0 also keeps both NaN points
    EXPECT_EQ(pc.size(), 3u);
    PointCloud empty;
    EXPECT_TRUE(remove_duplicated_points(empty).empty());
    PointCloud same;
    same.points.assign(5, Eigen::Vector3d(0.5, 0.5, 0.5));
    EXPECT_EQ(remove_duplicated_points(same), (std::vector<int64_t>{0}));
    EXPECT_EQ(same.size(), 1u);
}
