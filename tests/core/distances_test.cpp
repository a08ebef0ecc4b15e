// SPDX-License-Identifier: MIT
// Nearest-neighbour and cloud-to-cloud distances against brute force.
#include "o3d/geometry/distances.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>

#include "o3d/utility/error.h"

using namespace o3d::geometry;

namespace {

PointCloud random_cloud(size_t n, uint64_t seed) {
    std::mt19937_64 rng(seed);
    std::uniform_real_distribution<double> u(-1.0, 1.0);
    PointCloud c;
    for (size_t i = 0; i < n; ++i) c.points.emplace_back(u(rng), u(rng), u(rng));
    return c;
}

double brute_nearest(const PointCloud& c, const Eigen::Vector3d& q, size_t skip) {
    double best = std::numeric_limits<double>::infinity();
    for (size_t i = 0; i < c.size(); ++i)
        if (i != skip) best = std::min(best, (c.points[i] - q).norm());
    return best;
}

}  // namespace

TEST(Distances, NearestNeighborMatchesBruteForce) {
    const PointCloud c = random_cloud(3000, 1);
    const auto d = compute_nearest_neighbor_distance(c, 2);
    ASSERT_EQ(d.size(), c.size());
    for (size_t i = 0; i < c.size(); i += 7) EXPECT_NEAR(d[i], brute_nearest(c, c.points[i], i), 1e-15);
}

TEST(Distances, NearestNeighborSpecialCases) {
    PointCloud one;
    one.points = {{1, 2, 3}};
    EXPECT_EQ(compute_nearest_neighbor_distance(one), std::vector<double>{0.0});
    PointCloud dup;
    dup.points = {{0, 0, 0}, {0, 0, 0}, {3, 4, 0}};
    EXPECT_EQ(compute_nearest_neighbor_distance(dup), (std::vector<double>{0.0, 0.0, 5.0}));
    EXPECT_TRUE(compute_nearest_neighbor_distance(PointCloud{}).empty());
}

TEST(Distances, PointCloudDistanceMatchesBruteForce) {
    const PointCloud s = random_cloud(500, 2), t = random_cloud(2000, 3);
    const auto d = compute_point_cloud_distance(s, t, 2);
    ASSERT_EQ(d.size(), s.size());
    for (size_t i = 0; i < s.size(); ++i)
        EXPECT_NEAR(d[i], brute_nearest(t, s.points[i], std::numeric_limits<size_t>::max()), 1e-15);
    EXPECT_THROW(compute_point_cloud_distance(s, PointCloud{}), o3d::InvalidArgument);
    EXPECT_TRUE(compute_point_cloud_distance(PointCloud{}, t).empty());
}
