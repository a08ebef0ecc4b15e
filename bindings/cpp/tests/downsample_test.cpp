// SPDX-License-Identifier: MIT
// Down-sampling through the wrapper: voxel averages, uniform, random (seeded), farthest point.
#include <algorithm>

#include "test_util.hpp"

using o3dpp::Vec3;

TEST(DownSample, VoxelAveragesEachCluster) {
    // Three tight clusters 5 apart; each lies well inside one voxel of edge 1 whatever the grid origin.
    std::vector<Vec3> pts, colors;
    const std::vector<Vec3> offsets = {{0.40, 0.40, 0.40}, {0.60, 0.45, 0.50}, {0.50, 0.60, 0.45}, {0.50, 0.55, 0.60}};
    for (int c = 0; c < 3; ++c) {
        for (const auto& o : offsets) {
            pts.push_back({5.0 * c + o[0], o[1], o[2]});
            colors.push_back({0.1 * (c + 1), 0.0, 1.0});
        }
    }
    o3dpp::PointCloud pc(pts);
    pc.set_colors(colors);
    auto down = pc.voxel_down_sample(1.0);
    auto out = down.get_points();
    ASSERT_EQ(out.size(), 3u);
    auto out_colors = down.get_colors();
    ASSERT_EQ(out_colors.size(), 3u);
    std::vector<size_t> order = {0, 1, 2};
    std::sort(order.begin(), order.end(), [&](size_t a, size_t b) { return out[a][0] < out[b][0]; });
    for (int c = 0; c < 3; ++c) {
        const auto& p = out[order[c]];
        EXPECT_NEAR(p[0], 5.0 * c + 0.5, 1e-12);
        EXPECT_NEAR(p[1], 0.5, 1e-12);
        EXPECT_NEAR(p[2], 0.4875, 1e-12);
        EXPECT_NEAR(out_colors[order[c]][0], 0.1 * (c + 1), 1e-12);
    }
}

TEST(DownSample, UniformKeepsEveryKth) {
    std::vector<Vec3> pts;
    for (int i = 0; i < 10; ++i) pts.push_back({double(i), 0, 0});
    auto down = o3dpp::PointCloud(pts).uniform_down_sample(3);
    EXPECT_EQ(down.get_points(), (std::vector<Vec3>{{0, 0, 0}, {3, 0, 0}, {6, 0, 0}, {9, 0, 0}}));
}

TEST(DownSample, RandomIsSeededOrderedAndSized) {
    std::vector<Vec3> pts;
    for (int i = 0; i < 1000; ++i) pts.push_back({double(i), 0, 0});
    o3dpp::PointCloud pc(pts);
    auto a = pc.random_down_sample(0.25, 7).get_points();
    auto b = pc.random_down_sample(0.25, 7).get_points();
    EXPECT_EQ(a.size(), 250u);
    EXPECT_EQ(a, b);
    EXPECT_TRUE(std::is_sorted(a.begin(), a.end()));
    EXPECT_TRUE(std::adjacent_find(a.begin(), a.end()) == a.end());
}

TEST(DownSample, FarthestPointPicksExtremes) {
    std::vector<Vec3> pts;
    for (int i = 0; i <= 10; ++i) pts.push_back({double(i), 0, 0});
    auto down = o3dpp::PointCloud(pts).farthest_point_down_sample(3, 0).get_points();
    EXPECT_EQ(down.size(), 3u);
    std::sort(down.begin(), down.end());
    EXPECT_EQ(down, (std::vector<Vec3>{{0, 0, 0}, {5, 0, 0}, {10, 0, 0}}));
}
