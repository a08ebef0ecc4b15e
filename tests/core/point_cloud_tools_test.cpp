// SPDX-License-Identifier: MIT
// Point-cloud tools: outlier filters, AABB crop, RANSAC plane, DBSCAN, mean/covariance, Mahalanobis.
#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <random>
#include <set>

#include "o3d/geometry/crop.h"
#include "o3d/geometry/dbscan.h"
#include "o3d/geometry/down_sample.h"
#include "o3d/geometry/outlier_removal.h"
#include "o3d/geometry/segment_plane.h"
#include "o3d/geometry/statistics.h"
#include "o3d/io/point_cloud_io.h"
#include "o3d/utility/error.h"
#include "test_data.h"

using namespace o3d::geometry;
using Eigen::Vector3d;

namespace {

/// 10 x 10 grid of spacing 0.1 on z = 0 (indices 0..99), then 3 far outliers (100, 101, 102).
PointCloud plane_with_outliers() {
    PointCloud c;
    for (int i = 0; i < 10; ++i)
        for (int j = 0; j < 10; ++j) c.points.emplace_back(0.1 * i, 0.1 * j, 0.0);
    c.points.emplace_back(5, 5, 5);
    c.points.emplace_back(-4, 3, 2);
    c.points.emplace_back(3, -6, -1);
    return c;
}

std::vector<int64_t> iota(int64_t n) {
    std::vector<int64_t> v(n);
    for (int64_t i = 0; i < n; ++i) v[i] = i;
    return v;
}

}  // namespace

TEST(StatisticalOutlier, DropsFarPoints) {
    const PointCloud c = plane_with_outliers();
    EXPECT_EQ(statistical_outlier_indices(c, 8, 2.0), iota(100));
    EXPECT_EQ(statistical_outlier_indices(c, 8, 2.0, 1), statistical_outlier_indices(c, 8, 2.0, 2));
}

TEST(StatisticalOutlier, DuplicatesWithZeroMeanDistanceAreDroppedAsOpen3D) {
    // Open3D keeps only 0 < avg < threshold: with nb_neighbors = 2 the two coincident points have avg 0.
    PointCloud c;
    c.points = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {5, 5, 5}, {0, 0, 0}};
    EXPECT_EQ(statistical_outlier_indices(c, 2, 1.0), (std::vector<int64_t>{1, 2}));  // Open3D 0.20: [1, 2]
    EXPECT_TRUE(statistical_outlier_indices(c, 1, 2.0).empty());                       // Open3D 0.20: []
}

TEST(StatisticalOutlier, RejectsBadArguments) {
    const PointCloud c = plane_with_outliers();
    EXPECT_THROW(statistical_outlier_indices(c, 0, 2.0), o3d::InvalidArgument);
    EXPECT_THROW(statistical_outlier_indices(c, 5, 0.0), o3d::InvalidArgument);
    EXPECT_THROW(statistical_outlier_indices(c, 5, -1.0), o3d::InvalidArgument);
    EXPECT_THROW(statistical_outlier_indices(c, 5, NAN), o3d::InvalidArgument);
    EXPECT_THROW(statistical_outlier_indices(PointCloud{}, 5, 1.0), o3d::InvalidArgument);
}

TEST(RadiusOutlier, DropsIsolatedPoints) {
    const PointCloud c = plane_with_outliers();
    EXPECT_EQ(radius_outlier_indices(c, 3, 0.15), iota(100));
    // Every grid point has >= 2 others within 0.11 (corners have exactly 2): nb_points 2 keeps all, 3 drops corners.
    EXPECT_EQ(radius_outlier_indices(c, 2, 0.11), iota(100));
    const auto no_corners = radius_outlier_indices(c, 3, 0.11);
    EXPECT_EQ(no_corners.size(), 96u);
    for (int64_t corner : {0, 9, 90, 99}) EXPECT_EQ(std::count(no_corners.begin(), no_corners.end(), corner), 0);
}

TEST(RadiusOutlier, CountsOthersStrictlyInsideRadiusAsOpen3D) {
    PointCloud c;
    c.points = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {5, 5, 5}, {0, 0, 0}};
    // Open3D 0.20: remove_radius_outlier(1, 1.5) -> [0, 1, 2, 4]; (1, 1.0) -> [0, 4] (distance 1 is outside).
    EXPECT_EQ(radius_outlier_indices(c, 1, 1.5), (std::vector<int64_t>{0, 1, 2, 4}));
    EXPECT_EQ(radius_outlier_indices(c, 1, 1.0), (std::vector<int64_t>{0, 4}));
    EXPECT_TRUE(radius_outlier_indices(c, 2, 1.0).empty());
    EXPECT_THROW(radius_outlier_indices(c, 0, 1.0), o3d::InvalidArgument);
    EXPECT_THROW(radius_outlier_indices(c, 1, 0.0), o3d::InvalidArgument);
    EXPECT_THROW(radius_outlier_indices(c, 1, INFINITY), o3d::InvalidArgument);
}

TEST(CropAabb, InclusiveBoundsInvertAndAttributes) {
    PointCloud c;
    c.points = {{0, 0, 0}, {1, 1, 1}, {0.5, 0.5, 0.5}, {1.0000001, 0.5, 0.5}, {-1, 0, 0}};
    c.normals = {{0, 0, 1}, {0, 1, 0}, {1, 0, 0}, {0, 0, -1}, {0, -1, 0}};
    c.colors = {{0.1, 0, 0}, {0.2, 0, 0}, {0.3, 0, 0}, {0.4, 0, 0}, {0.5, 0, 0}};
    EXPECT_EQ(indices_in_aabb(c, Vector3d(0, 0, 0), Vector3d(1, 1, 1)), (std::vector<int64_t>{0, 1, 2}));
    const PointCloud in = crop_aabb(c, Vector3d(0, 0, 0), Vector3d(1, 1, 1));
    ASSERT_EQ(in.size(), 3u);
    EXPECT_EQ(in.points[1], Vector3d(1, 1, 1));
    EXPECT_EQ(in.normals[2], Vector3d(1, 0, 0));
    EXPECT_EQ(in.colors[2], Vector3d(0.3, 0, 0));
    const PointCloud out = crop_aabb(c, Vector3d(0, 0, 0), Vector3d(1, 1, 1), true);
    ASSERT_EQ(out.size(), 2u);
    EXPECT_EQ(out.points[0], Vector3d(1.0000001, 0.5, 0.5));
    EXPECT_EQ(out.normals[1], Vector3d(0, -1, 0));
    EXPECT_EQ(out.colors[1], Vector3d(0.5, 0, 0));
}

TEST(CropAabb, RejectsInvertedFlatAndNonFiniteBoxes) {
    PointCloud c;
    c.points = {{0, 0, 0}};
    EXPECT_THROW(crop_aabb(c, Vector3d(1, 0, 0), Vector3d(0, 1, 1)), o3d::InvalidArgument);
    EXPECT_THROW(crop_aabb(c, Vector3d(0, 0, 0), Vector3d(1, 1, 0)), o3d::InvalidArgument);  // Open3D: zero size
    EXPECT_THROW(crop_aabb(c, Vector3d(0, 0, NAN), Vector3d(1, 1, 1)), o3d::InvalidArgument);
}

namespace {

/// 400 points on 0.6 x + 0.8 z - 2 = 0 ... i.e. plane n = (0, 0.6, 0.8), d = -2, noise +-0.005, then 100 outliers.
PointCloud noisy_plane(std::vector<int64_t>* inlier_ids) {
    std::mt19937 rng(7);
    std::uniform_real_distribution<double> u(-1.0, 1.0);
    const Vector3d n(0.0, 0.6, 0.8), e1(1, 0, 0), e2(0, 0.8, -0.6);
    PointCloud c;
    for (int i = 0; i < 400; ++i) {
        c.points.push_back(2.0 * n + 3.0 * u(rng) * e1 + 3.0 * u(rng) * e2 + 0.005 * u(rng) * n);
        if (inlier_ids) inlier_ids->push_back(i);
    }
    for (int i = 0; i < 100; ++i) c.points.emplace_back(3 * u(rng), 3 * u(rng), 5 + 2 * u(rng));
    return c;
}

}  // namespace

TEST(SegmentPlane, RecoversKnownPlane) {
    std::vector<int64_t> truth;
    const PointCloud c = noisy_plane(&truth);
    const PlaneSegmentation seg = segment_plane(c, 0.02, 3, 200, 0.99999999, 42);
    Eigen::Vector4d plane = seg.plane;
    if (plane[3] > 0) plane = -plane;
    EXPECT_NEAR(plane.head<3>().norm(), 1.0, 1e-12);
    EXPECT_NEAR(plane[0], 0.0, 5e-3);
    EXPECT_NEAR(plane[1], 0.6, 5e-3);
    EXPECT_NEAR(plane[2], 0.8, 5e-3);
    EXPECT_NEAR(plane[3], -2.0, 5e-3);
    // All plane points are inliers; the box of outliers (z in [3, 7]) lies far from it except by chance.
    ASSERT_GE(seg.inliers.size(), 400u);
    EXPECT_TRUE(std::is_sorted(seg.inliers.begin(), seg.inliers.end()));
    EXPECT_EQ(std::vector<int64_t>(seg.inliers.begin(), seg.inliers.begin() + 400), truth);
}

TEST(SegmentPlane, SameSeedSameResultOnAnyThreadCount) {
    const PointCloud c = noisy_plane(nullptr);
    const auto a = segment_plane(c, 0.01, 3, 500, 1.0, 123, 1);
    const auto b = segment_plane(c, 0.01, 3, 500, 1.0, 123, 2);
    const auto d = segment_plane(c, 0.01, 3, 500, 1.0, 123, 2);
    EXPECT_EQ(a.plane, b.plane);
    EXPECT_EQ(a.inliers, b.inliers);
    EXPECT_EQ(b.plane, d.plane);
    const auto e = segment_plane(c, 0.01, 5, 100, 0.99, 9, 1);  // ransac_n > 3: least-squares samples
    const auto f = segment_plane(c, 0.01, 5, 100, 0.99, 9, 2);
    EXPECT_EQ(e.plane, f.plane);
    EXPECT_EQ(e.inliers, f.inliers);
}

TEST(SegmentPlane, RejectsBadArguments) {
    const PointCloud c = noisy_plane(nullptr);
    EXPECT_THROW(segment_plane(c, -0.1, 3, 10, 0.9, 0), o3d::InvalidArgument);
    EXPECT_THROW(segment_plane(c, NAN, 3, 10, 0.9, 0), o3d::InvalidArgument);
    EXPECT_THROW(segment_plane(c, 0.1, 2, 10, 0.9, 0), o3d::InvalidArgument);
    EXPECT_THROW(segment_plane(c, 0.1, 3, 0, 0.9, 0), o3d::InvalidArgument);
    EXPECT_THROW(segment_plane(c, 0.1, 3, 10, 0.0, 0), o3d::InvalidArgument);
    EXPECT_THROW(segment_plane(c, 0.1, 3, 10, 1.5, 0), o3d::InvalidArgument);
    PointCloud two;
    two.points = {{0, 0, 0}, {1, 0, 0}};
    EXPECT_THROW(segment_plane(two, 0.1, 3, 10, 0.9, 0), o3d::InvalidArgument);
    PointCloud line;
    for (int i = 0; i < 10; ++i) line.points.emplace_back(i, 0, 0);
    EXPECT_THROW(segment_plane(line, 0.1, 3, 10, 0.9, 0), o3d::NotConverged);
}

TEST(ClusterDbscan, ThreeBlobsAndNoise) {
    std::mt19937 rng(3);
    std::uniform_real_distribution<double> u(-0.2, 0.2);
    PointCloud c;
    c.points.emplace_back(50, 50, 50);  // index 0: noise
    const Vector3d centres[3] = {{10, 0, 0}, {0, 0, 0}, {0, 10, 0}};
    for (const auto& centre : centres)
        for (int i = 0; i < 60; ++i) c.points.push_back(centre + Vector3d(u(rng), u(rng), u(rng)));
    c.points.emplace_back(-50, 0, 0);  // last: noise
    const auto labels = cluster_dbscan(c, 0.3, 5);
    ASSERT_EQ(labels.size(), c.size());
    EXPECT_EQ(labels.front(), -1);
    EXPECT_EQ(labels.back(), -1);
    for (int b = 0; b < 3; ++b)
        for (int i = 0; i < 60; ++i) EXPECT_EQ(labels[1 + 60 * b + i], b);
    EXPECT_EQ(cluster_dbscan(c, 0.3, 5, 1), cluster_dbscan(c, 0.3, 5, 2));
}

TEST(ClusterDbscan, Open3DSmallCaseAndErrors) {
    PointCloud q;
    q.points = {{0, 0, 0}, {0.1, 0, 0}, {5, 0, 0}, {0.2, 0, 0}, {5.1, 0, 0}, {10, 0, 0}};
    EXPECT_EQ(cluster_dbscan(q, 0.15, 2), (std::vector<int32_t>{0, 0, 1, 0, 1, -1}));  // Open3D 0.20 output
    // Border point 0 of the left blob precedes that blob's only core point (2), and the right blob's core
    // point 1 comes before it. Open3D 0.20 numbers clusters by first core point: [1, 0, 1, 1, 0, 0]; the
    // contract here (pointcloud.h) numbers them by lowest point index: same partition, labels swapped.
    PointCloud b;
    b.points = {{0, 0, 0}, {9.05, 0, 0}, {0.1, 0, 0}, {0.2, 0, 0}, {9, 0, 0}, {9.1, 0, 0}};
    EXPECT_EQ(cluster_dbscan(b, 0.15, 3), (std::vector<int32_t>{0, 1, 0, 0, 1, 1}));
    EXPECT_THROW(cluster_dbscan(q, 0.0, 2), o3d::InvalidArgument);
    EXPECT_THROW(cluster_dbscan(q, NAN, 2), o3d::InvalidArgument);
    EXPECT_THROW(cluster_dbscan(q, 0.1, -1), o3d::InvalidArgument);
    EXPECT_THROW(cluster_dbscan(PointCloud{}, 0.1, 2), o3d::InvalidArgument);
}

TEST(Statistics, MeanAndCovarianceAnalytic) {
    PointCloud c;
    c.points = {{1, 0, 0}, {-1, 0, 0}, {0, 2, 0}, {0, -2, 0}, {0, 0, 3}, {0, 0, -3}};
    for (auto& p : c.points) p += Vector3d(100, -50, 7);
    const auto [mean, cov] = compute_mean_and_covariance(c);
    EXPECT_NEAR((mean - Vector3d(100, -50, 7)).norm(), 0.0, 1e-12);
    Eigen::Matrix3d expected = Eigen::Vector3d(2.0 / 6, 8.0 / 6, 18.0 / 6).asDiagonal();
    EXPECT_NEAR((cov - expected).norm(), 0.0, 1e-12);
    EXPECT_THROW(compute_mean_and_covariance(PointCloud{}), o3d::InvalidArgument);
}

TEST(Statistics, MahalanobisMatchesDirectComputation) {
    std::mt19937 rng(11);
    std::normal_distribution<double> g(0.0, 1.0);
    PointCloud c;
    for (int i = 0; i < 500; ++i) c.points.emplace_back(g(rng) + 0.5 * g(rng), 2 * g(rng), 0.3 * g(rng) + 1);
    const auto [mean, cov] = compute_mean_and_covariance(c);
    const Eigen::Matrix3d inv = cov.inverse();
    const auto d = compute_mahalanobis_distance(c);
    ASSERT_EQ(d.size(), c.size());
    for (size_t i = 0; i < c.size(); ++i) {
        const Vector3d r = c.points[i] - mean;
        EXPECT_NEAR(d[i], std::sqrt(r.dot(inv * r)), 1e-9);
    }
    EXPECT_EQ(d, compute_mahalanobis_distance(c, 1));
}

TEST(Statistics, MahalanobisOfDegenerateCloudsUsesPseudoInverse) {
    // Open3D returns NaN here (inverse of a singular matrix); the pseudo-inverse measures inside the plane.
    PointCloud sq;
    sq.points = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {1, 1, 0}};  // cov = diag(0.25, 0.25, 0)
    for (double v : compute_mahalanobis_distance(sq)) EXPECT_NEAR(v, std::sqrt(2.0), 1e-12);
    PointCloud one;
    one.points = {{3, 4, 5}};
    EXPECT_EQ(compute_mahalanobis_distance(one), std::vector<double>{0.0});
}

// Reference numbers: Open3D 0.20.0 on open3d/fragment.pcd (113662 points), recorded by
// tools/reference/record_tools.py.
TEST(PointCloudToolsReference, Fragment) {
    O3D_TEST_DATA_OR_SKIP(path, "open3d/fragment.pcd");
    const PointCloud c = o3d::io::read_point_cloud(path);
    ASSERT_EQ(c.size(), 113662u);
    EXPECT_EQ(statistical_outlier_indices(c, 20, 2.0).size(), 112356u);
    EXPECT_EQ(statistical_outlier_indices(c, 20, 0.5).size(), 70327u);
    EXPECT_EQ(radius_outlier_indices(c, 16, 0.05).size(), 113660u);
    EXPECT_EQ(radius_outlier_indices(c, 16, 0.02).size(), 112129u);
    EXPECT_EQ(crop_aabb(c, Vector3d(0.5, 1.0, 0.6), Vector3d(2.0, 2.0, 1.2)).size(), 6291u);
    EXPECT_EQ(crop_aabb(c, Vector3d(0.5, 1.0, 0.6), Vector3d(2.0, 2.0, 1.2), true).size(), 107371u);

    const auto [mean, cov] = compute_mean_and_covariance(c);
    EXPECT_NEAR(mean.x(), 2.2721989223271186, 1e-9);
    EXPECT_NEAR(mean.y(), 1.7389421708490782, 1e-9);
    EXPECT_NEAR(mean.z(), 1.3153000239180128, 1e-9);
    Eigen::Matrix3d ref;
    ref << 0.49565162387600203, -0.03803476116944848, 0.04354744998688487, -0.03803476116944848,
        0.3353354223900227, 0.019382744680746633, 0.04354744998688487, 0.019382744680746633, 0.018709066930092;
    EXPECT_NEAR((cov - ref).cwiseAbs().maxCoeff(), 0.0, 1e-9);
    const auto md = compute_mahalanobis_distance(c);
    EXPECT_NEAR(md[0], 2.713776350053593, 1e-6);
    EXPECT_NEAR(md[2], 2.71194108005951, 1e-6);
    EXPECT_NEAR(*std::max_element(md.begin(), md.end()), 4.671135788869934, 1e-6);

    const PointCloud down = voxel_down_sample(c, 0.02);
    ASSERT_EQ(down.size(), 15678u);
    const auto labels = cluster_dbscan(down, 0.05, 10);
    EXPECT_EQ(*std::max_element(labels.begin(), labels.end()) + 1, 4);
    EXPECT_EQ(std::count(labels.begin(), labels.end(), -1), 9);

    // Open3D's RANSAC is unseeded: its runs gave planes ~(-0.06, -0.10, 0.993, -1.05) with 57124-57518 inliers.
    const auto seg = segment_plane(c, 0.01, 3, 1000, 0.99999999, 1);
    Eigen::Vector4d p = seg.plane;
    if (p[2] < 0) p = -p;
    EXPECT_NEAR(p[0], -0.06, 0.02);
    EXPECT_NEAR(p[1], -0.10, 0.02);
    EXPECT_NEAR(p[2], 0.993, 0.005);
    EXPECT_NEAR(p[3], -1.06, 0.03);
    EXPECT_GT(seg.inliers.size(), 55000u);
    EXPECT_LT(seg.inliers.size(), 60000u);
}
