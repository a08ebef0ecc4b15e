// SPDX-License-Identifier: MIT
// ISS keypoints through the wrapper: on a sampled box surface they sit at the corners (the only places where the
// neighbourhood spreads in three directions), their indices name them in the input, the options come from the
// C header, and bad options throw.
#include <algorithm>
#include <cmath>
#include <vector>

#include "test_util.hpp"

using o3dpp::IssOptions;
using o3dpp::PointCloud;
using o3dpp::Vec3;

namespace {
/// The surface of the unit cube sampled on a grid of `n` + 1 points a side (each point once).
std::vector<Vec3> box_surface(int n) {
    std::vector<Vec3> pts;
    for (int i = 0; i <= n; ++i)
        for (int j = 0; j <= n; ++j)
            for (int k = 0; k <= n; ++k)
                if (i == 0 || i == n || j == 0 || j == n || k == 0 || k == n)
                    pts.push_back({double(i) / n, double(j) / n, double(k) / n});
    return pts;
}

double distance_to_nearest_corner(const Vec3& p) {
    double d2 = 0;
    for (double c : p) d2 += std::min(c, 1 - c) * std::min(c, 1 - c);
    return std::sqrt(d2);
}
}  // namespace

TEST(Iss, OptionsComeFromTheCHeader) {
    o3d_iss_options_t c;
    o3dpp::check(o3d_iss_options_init(&c, sizeof c));
    const IssOptions o;
    EXPECT_EQ(o.salient_radius, c.salient_radius);
    EXPECT_EQ(o.non_max_radius, c.non_max_radius);
    EXPECT_EQ(o.gamma_21, c.gamma_21);
    EXPECT_EQ(o.gamma_32, c.gamma_32);
    EXPECT_EQ(o.min_neighbors, c.min_neighbors);
    EXPECT_EQ(o.num_threads, c.num_threads);
}

TEST(Iss, BoxKeypointsAreNearItsCorners) {
    const auto pts = box_surface(20);
    const PointCloud cloud(pts);
    IssOptions options;
    // A non-maximum radius wider than half an edge: an edge's middle is never a local maximum. (With these radii
    // the result stays at the corners when the grid is jittered too.)
    options.salient_radius = 0.2;
    options.non_max_radius = 0.6;
    const auto [keypoints, indices] = cloud.compute_iss_keypoints(options);
    ASSERT_GT(keypoints.size(), 0u);
    ASSERT_EQ(indices.size(), keypoints.size());
    EXPECT_TRUE(std::is_sorted(indices.begin(), indices.end()));
    const auto kp = keypoints.get_points();
    std::vector<bool> corner_seen(8, false);
    for (std::size_t i = 0; i < kp.size(); ++i) {
        EXPECT_EQ(kp[i], pts[indices[i]]);
        EXPECT_LT(distance_to_nearest_corner(kp[i]), 0.2) << kp[i][0] << " " << kp[i][1] << " " << kp[i][2];
        corner_seen[(kp[i][0] > 0.5) + 2 * (kp[i][1] > 0.5) + 4 * (kp[i][2] > 0.5)] = true;
    }
    EXPECT_EQ(std::count(corner_seen.begin(), corner_seen.end(), true), 8);

    // The thread count does not change them (defaults: radii from the cloud's resolution).
    IssOptions one, four;
    one.num_threads = 1;
    four.num_threads = 4;
    const auto a = cloud.compute_iss_keypoints(one), b = cloud.compute_iss_keypoints(four);
    EXPECT_FALSE(a.second.empty());
    EXPECT_EQ(a.second, b.second);
}

TEST(Iss, FlatCloudHasNoKeypointsAndBadOptionsThrow) {
    // On a plane the scatter has a zero eigenvalue everywhere: nothing is salient.
    std::vector<Vec3> plane;
    for (int i = 0; i < 30; ++i)
        for (int j = 0; j < 30; ++j) plane.push_back({0.03 * i, 0.03 * j, 0});
    EXPECT_EQ(PointCloud(plane).compute_iss_keypoints().second.size(), 0u);

    const PointCloud cloud(box_surface(10));
    IssOptions bad;
    bad.salient_radius = -1;
    EXPECT_O3D_ERROR(cloud.compute_iss_keypoints(bad), O3D_ERROR_INVALID_ARGUMENT);
    bad = IssOptions();
    bad.gamma_21 = 0;
    EXPECT_O3D_ERROR(cloud.compute_iss_keypoints(bad), O3D_ERROR_INVALID_ARGUMENT);
    bad = IssOptions();
    bad.gamma_32 = 1.5;
    EXPECT_O3D_ERROR(cloud.compute_iss_keypoints(bad), O3D_ERROR_INVALID_ARGUMENT);
    std::vector<Vec3> with_nan = box_surface(4);
    with_nan[5][0] = std::nan("");
    EXPECT_O3D_ERROR(PointCloud(with_nan).compute_iss_keypoints(), O3D_ERROR_INVALID_ARGUMENT);
}
