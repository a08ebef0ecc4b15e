// SPDX-License-Identifier: MIT
// Point-cloud tools through the wrapper: outlier removal, crop, RANSAC plane, DBSCAN, statistics.
#include <cmath>
#include <limits>

#include "test_util.hpp"

using o3dpp::Vec3;

namespace {

/// 10 x 10 grid (spacing 0.1) on z = 0 with three far outliers at indices 3, 47 and 102.
std::vector<Vec3> plane_with_outliers(std::vector<int32_t>* kept) {
    const std::vector<Vec3> outliers = {{50, 50, 50}, {-40, 30, 20}, {10, -60, 5}};
    std::vector<Vec3> pts;
    size_t g = 0, o = 0;
    for (int32_t idx = 0; idx < 103; ++idx) {
        if (idx == 3 || idx == 47 || idx == 102) {
            pts.push_back(outliers[o++]);
        } else {
            kept->push_back(idx);
            pts.push_back({0.1 * double(g / 10), 0.1 * double(g % 10), 0.0});
            ++g;
        }
    }
    return pts;
}

/// Axis points about c = (1, 2, 3): mean c, covariance diag(1/3, 4/3, 3).
std::vector<Vec3> axis_points() {
    return {{2, 2, 3}, {0, 2, 3}, {1, 4, 3}, {1, 0, 3}, {1, 2, 6}, {1, 2, 0}};
}

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

}  // namespace

TEST(Tools, StatisticalOutlierRemovalKeepsThePlane) {
    std::vector<int32_t> expected;
    const auto pts = plane_with_outliers(&expected);
    o3dpp::PointCloud pc(pts);
    auto [kept_cloud, kept] = pc.remove_statistical_outlier(10, 1.0);
    EXPECT_EQ(kept, expected);
    std::vector<Vec3> want;
    for (int32_t i : expected) want.push_back(pts[static_cast<size_t>(i)]);
    EXPECT_EQ(kept_cloud.get_points(), want);
    EXPECT_EQ(pc.size(), 103u);
}

TEST(Tools, RadiusOutlierRemovalKeepsThePlane) {
    std::vector<int32_t> expected;
    const auto pts = plane_with_outliers(&expected);
    o3dpp::PointCloud pc(pts);
    pc.paint_uniform_color({0.25, 0.5, 1.0});
    auto [kept_cloud, kept] = pc.remove_radius_outlier(3, 0.25);
    EXPECT_EQ(kept, expected);
    ASSERT_EQ(kept_cloud.size(), 100u);
    EXPECT_EQ(kept_cloud.get_points()[3], pts[4]);
    EXPECT_EQ(kept_cloud.get_colors().size(), 100u);
}

TEST(Tools, OutlierRemovalRejectsBadArguments) {
    std::vector<int32_t> expected;
    o3dpp::PointCloud pc(plane_with_outliers(&expected));
    EXPECT_O3D_ERROR(pc.remove_statistical_outlier(0, 1.0), O3D_ERROR_INVALID_ARGUMENT);
    EXPECT_O3D_ERROR(pc.remove_statistical_outlier(-3, 1.0), O3D_ERROR_INVALID_ARGUMENT);
    EXPECT_O3D_ERROR(pc.remove_statistical_outlier(10, 0.0), O3D_ERROR_INVALID_ARGUMENT);
    EXPECT_O3D_ERROR(pc.remove_statistical_outlier(10, kNaN), O3D_ERROR_INVALID_ARGUMENT);
    EXPECT_O3D_ERROR(pc.remove_radius_outlier(0, 0.25), O3D_ERROR_INVALID_ARGUMENT);
    EXPECT_O3D_ERROR(pc.remove_radius_outlier(3, 0.0), O3D_ERROR_INVALID_ARGUMENT);
    EXPECT_O3D_ERROR(pc.remove_radius_outlier(3, -1.0), O3D_ERROR_INVALID_ARGUMENT);
    o3dpp::PointCloud empty;
    EXPECT_O3D_ERROR(empty.remove_statistical_outlier(10, 1.0), O3D_ERROR_INVALID_ARGUMENT);
    EXPECT_O3D_ERROR(empty.remove_radius_outlier(3, 0.25), O3D_ERROR_INVALID_ARGUMENT);
}

TEST(Tools, CropAabbIsInclusiveAndInverts) {
    std::vector<Vec3> pts;
    for (int i = 0; i <= 10; ++i) pts.push_back({double(i), 0, 0});
    o3dpp::PointCloud pc(pts);
    EXPECT_EQ(pc.crop_aabb({2, -1, -1}, {5, 1, 1}).get_points(),
              (std::vector<Vec3>{{2, 0, 0}, {3, 0, 0}, {4, 0, 0}, {5, 0, 0}}));
    std::vector<double> xs;
    for (const auto& p : pc.crop_aabb({2, -1, -1}, {5, 1, 1}, true).get_points()) xs.push_back(p[0]);
    EXPECT_EQ(xs, (std::vector<double>{0, 1, 6, 7, 8, 9, 10}));
    EXPECT_EQ(pc.crop_aabb({0, 0, 0}, {10, 1, 1}).size(), 11u);  // points on the faces stay
    EXPECT_TRUE(pc.crop_aabb({20, 0, 0}, {21, 1, 1}).empty());
}

TEST(Tools, CropAabbRejectsBadBoxes) {
    o3dpp::PointCloud pc(std::vector<Vec3>{{0, 0, 0}, {1, 1, 1}});
    EXPECT_O3D_ERROR(pc.crop_aabb({1, 0, 0}, {0, 1, 1}), O3D_ERROR_INVALID_ARGUMENT);
    EXPECT_O3D_ERROR(pc.crop_aabb({0, 0, 0}, {0, 1, 1}), O3D_ERROR_INVALID_ARGUMENT);
    EXPECT_O3D_ERROR(pc.crop_aabb({kNaN, 0, 0}, {1, 1, 1}), O3D_ERROR_INVALID_ARGUMENT);
}

namespace {
/// 400 points on 0.5 x - 0.25 y - z + 1 = 0 and 20 points 0.8..1.5 above it, interleaved.
std::vector<Vec3> tilted_plane(std::vector<int32_t>* inliers) {
    auto z = [](double x, double y) { return 0.5 * x - 0.25 * y + 1.0; };
    std::mt19937 rng(7);
    std::uniform_real_distribution<double> u(0.0, 2.0), up(0.8, 1.5);
    std::vector<Vec3> pts;
    for (int i = 0; i < 20; ++i) {
        for (int j = 0; j < 20; ++j) {
            if (j == 7) {
                const double ox = u(rng), oy = u(rng);
                pts.push_back({ox, oy, z(ox, oy) + up(rng)});
            }
            const double x = 0.1 * i, y = 0.1 * j;
            inliers->push_back(static_cast<int32_t>(pts.size()));
            pts.push_back({x, y, z(x, y)});
        }
    }
    return pts;
}
}  // namespace

TEST(Tools, SegmentPlaneRecoversAKnownPlane) {
    std::vector<int32_t> expected;
    o3dpp::PointCloud pc(tilted_plane(&expected));
    ASSERT_EQ(pc.size(), 420u);
    auto [plane, inliers] = pc.segment_plane(0.01, 3, 1000, 0.9999, 42);
    EXPECT_EQ(inliers, expected);
    EXPECT_NEAR(std::sqrt(plane[0] * plane[0] + plane[1] * plane[1] + plane[2] * plane[2]), 1.0, 1e-9);
    const double k = std::sqrt(1.3125);
    const std::array<double, 4> want = {0.5 / k, -0.25 / k, -1.0 / k, 1.0 / k};
    const double sign = plane[2] < 0 ? 1.0 : -1.0;  // the normal is defined up to sign
    for (int i = 0; i < 4; ++i) EXPECT_NEAR(sign * plane[i], want[i], 1e-6) << i;
    auto again = pc.segment_plane(0.01, 3, 1000, 0.9999, 42);  // same seed, same answer
    EXPECT_EQ(again.first, plane);
    EXPECT_EQ(again.second, inliers);
}

TEST(Tools, SegmentPlaneRejectsBadArguments) {
    std::vector<int32_t> expected;
    o3dpp::PointCloud pc(tilted_plane(&expected));
    EXPECT_O3D_ERROR(pc.segment_plane(-0.01), O3D_ERROR_INVALID_ARGUMENT);
    EXPECT_O3D_ERROR(pc.segment_plane(kNaN), O3D_ERROR_INVALID_ARGUMENT);
    EXPECT_O3D_ERROR(pc.segment_plane(0.01, 2), O3D_ERROR_INVALID_ARGUMENT);
    EXPECT_O3D_ERROR(pc.segment_plane(0.01, 3, 0), O3D_ERROR_INVALID_ARGUMENT);
    EXPECT_O3D_ERROR(pc.segment_plane(0.01, 3, 100, 0.0), O3D_ERROR_INVALID_ARGUMENT);
    EXPECT_O3D_ERROR(pc.segment_plane(0.01, 3, 100, 1.5), O3D_ERROR_INVALID_ARGUMENT);
    o3dpp::PointCloud two(std::vector<Vec3>{{0, 0, 0}, {1, 1, 1}});
    EXPECT_O3D_ERROR(two.segment_plane(0.01), O3D_ERROR_INVALID_ARGUMENT);
    EXPECT_O3D_ERROR(o3dpp::PointCloud().segment_plane(0.01), O3D_ERROR_INVALID_ARGUMENT);
}

TEST(Tools, DbscanLabelsBlobsInIndexOrderAndNoise) {
    auto blob = [](std::vector<Vec3>* pts, Vec3 c) {
        for (int k = 0; k < 20; ++k) pts->push_back({c[0] + 0.05 * (k % 4), c[1] + 0.05 * (k / 4 % 5), c[2]});
    };
    std::vector<Vec3> pts = {{100, 100, 100}};  // 0: noise
    blob(&pts, {10, 0, 0});                     // 1..20: cluster 0 (lowest index)
    blob(&pts, {0, 0, 0});                      // 21..40: cluster 1
    pts.push_back({-100, 0, 0});                // 41: noise
    pts.push_back({5, 5, 5});                   // 42: noise
    std::vector<int32_t> want = {-1};
    want.insert(want.end(), 20, 0);
    want.insert(want.end(), 20, 1);
    want.insert(want.end(), {-1, -1});
    EXPECT_EQ(o3dpp::PointCloud(pts).cluster_dbscan(0.5, 5), want);
}

TEST(Tools, DbscanRejectsBadArguments) {
    o3dpp::PointCloud pc(std::vector<Vec3>{{0, 0, 0}, {1, 1, 1}});
    EXPECT_O3D_ERROR(pc.cluster_dbscan(0.0, 5), O3D_ERROR_INVALID_ARGUMENT);
    EXPECT_O3D_ERROR(pc.cluster_dbscan(-1.0, 5), O3D_ERROR_INVALID_ARGUMENT);
    EXPECT_O3D_ERROR(pc.cluster_dbscan(std::numeric_limits<double>::infinity(), 5), O3D_ERROR_INVALID_ARGUMENT);
    EXPECT_O3D_ERROR(pc.cluster_dbscan(0.5, -1), O3D_ERROR_INVALID_ARGUMENT);
    EXPECT_O3D_ERROR(o3dpp::PointCloud().cluster_dbscan(0.5, 5), O3D_ERROR_INVALID_ARGUMENT);
}

TEST(Tools, MeanAndCovarianceAreAnalytic) {
    // x = t, y = 2t, z = 0, t = 0..3: mean (1.5, 3, 0); var x = 1.25, cov xy = 2.5, var y = 5 (row-major).
    std::vector<Vec3> line;
    for (int t = 0; t < 4; ++t) line.push_back({double(t), 2.0 * t, 0});
    auto [mean, cov] = o3dpp::PointCloud(line).compute_mean_and_covariance();
    const Vec3 want_mean = {1.5, 3, 0};
    const o3dpp::Mat3 want_cov = {1.25, 2.5, 0, 2.5, 5, 0, 0, 0, 0};
    for (int i = 0; i < 3; ++i) EXPECT_NEAR(mean[i], want_mean[i], 1e-12);
    for (int i = 0; i < 9; ++i) EXPECT_NEAR(cov[i], want_cov[i], 1e-12) << i;

    auto [mean2, cov2] = o3dpp::PointCloud(axis_points()).compute_mean_and_covariance();
    const Vec3 want_mean2 = {1, 2, 3};
    const o3dpp::Mat3 want_cov2 = {1.0 / 3, 0, 0, 0, 4.0 / 3, 0, 0, 0, 3};
    for (int i = 0; i < 3; ++i) EXPECT_NEAR(mean2[i], want_mean2[i], 1e-12);
    for (int i = 0; i < 9; ++i) EXPECT_NEAR(cov2[i], want_cov2[i], 1e-12) << i;

    EXPECT_O3D_ERROR(o3dpp::PointCloud().compute_mean_and_covariance(), O3D_ERROR_INVALID_ARGUMENT);
}

TEST(Tools, MahalanobisDistanceIsAnalytic) {
    // Each axis point lies sqrt(3) standard deviations out along its axis.
    const auto d = o3dpp::PointCloud(axis_points()).compute_mahalanobis_distance();
    ASSERT_EQ(d.size(), 6u);
    for (double v : d) EXPECT_NEAR(v, std::sqrt(3.0), 1e-9);
    EXPECT_O3D_ERROR(o3dpp::PointCloud().compute_mahalanobis_distance(), O3D_ERROR_INVALID_ARGUMENT);
}
