// SPDX-License-Identifier: MIT
// Minimal oriented boxes and minimum-volume ellipsoids: analytic shapes recovered, never larger than Open3D
// 0.20's, its reference numbers, containment, the static covariance estimate, errors.
#include <Eigen/Geometry>
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>

#include "o3d/geometry/minimal_bounding_box.h"
#include "o3d/geometry/oriented_bounding_box.h"
#include "o3d/geometry/oriented_bounding_ellipsoid_fit.h"
#include "o3d/geometry/point_cloud_covariances.h"
#include "o3d/geometry/point_covariances_static.h"
#include "o3d/utility/error.h"

using namespace o3d::geometry;

namespace {

/// The clouds the Open3D references were taken on (same formulas in numpy):
/// kind 0: (3 sin(1.7 i + 0.3), cos(2.3 i), 0.5 sin(3.1 i + 1)), i < n;
/// kind 1: A (sin(0.9 i), sin(1.9 i + 0.5), cos(2.9 i + 0.2)) + (10, -20, 5), A below.
std::vector<Eigen::Vector3d> formula_cloud(int kind, int n) {
    std::vector<Eigen::Vector3d> pts;
    Eigen::Matrix3d A;
    A << 2, 0.5, 0.1, 0.3, 1, 0.4, 0, 0.2, 0.6;
    for (int k = 0; k < n; ++k) {
        const double i = k;
        if (kind == 0)
            pts.emplace_back(3 * std::sin(1.7 * i + 0.3), std::cos(2.3 * i), 0.5 * std::sin(3.1 * i + 1.0));
        else
            pts.push_back(A * Eigen::Vector3d(std::sin(0.9 * i), std::sin(1.9 * i + 0.5), std::cos(2.9 * i + 0.2)) +
                          Eigen::Vector3d(10, -20, 5));
    }
    return pts;
}

Eigen::Matrix3d some_rotation() {
    return (Eigen::AngleAxisd(0.7, Eigen::Vector3d(1, 2, 3).normalized()) *
            Eigen::AngleAxisd(0.3, Eigen::Vector3d::UnitX()))
        .toRotationMatrix();
}

/// A box of full extents `extent`, rotated by R about c: its 8 corners and n points inside.
std::vector<Eigen::Vector3d> rotated_box_points(const Eigen::Vector3d& extent, const Eigen::Matrix3d& R,
                                                const Eigen::Vector3d& c, size_t n, uint64_t seed) {
    std::mt19937_64 rng(seed);
    std::uniform_real_distribution<double> u(-0.5, 0.5);
    std::vector<Eigen::Vector3d> pts;
    for (int i = 0; i < 8; ++i)
        pts.push_back(R * Eigen::Vector3d((i & 1) - 0.5, ((i >> 1) & 1) - 0.5, ((i >> 2) & 1) - 0.5).cwiseProduct(extent) +
                      c);
    for (size_t i = 0; i < n; ++i) pts.push_back(R * Eigen::Vector3d(u(rng), u(rng), u(rng)).cwiseProduct(extent) + c);
    return pts;
}

void expect_rotation(const Eigen::Matrix3d& R) {
    EXPECT_TRUE((R.transpose() * R).isApprox(Eigen::Matrix3d::Identity(), 1e-12));
    EXPECT_NEAR(R.determinant(), 1.0, 1e-12);
}

/// Every column of `got` is ± a column of `want` carrying the same length.
void expect_same_axes(const Eigen::Matrix3d& got, const Eigen::Vector3d& got_len, const Eigen::Matrix3d& want,
                      const Eigen::Vector3d& want_len, double tol) {
    for (int k = 0; k < 3; ++k) {
        int match = -1;
        for (int j = 0; j < 3; ++j)
            if (std::abs(std::abs(got.col(k).dot(want.col(j))) - 1.0) < tol) match = j;
        ASSERT_GE(match, 0) << "axis " << k << " matches no expected axis";
        EXPECT_NEAR(got_len(k), want_len(match), tol);
    }
}

double max_normalised_distance(const std::vector<Eigen::Vector3d>& pts, const OrientedBoundingEllipsoid& e) {
    double worst = 0.0;
    for (const auto& p : pts)
        worst = std::max(worst, (e.R.transpose() * (p - e.center)).cwiseQuotient(e.radii).norm());
    return worst;
}

}  // namespace

// ---- minimal oriented box ----

TEST(MinimalBoundingBox, RecoversARotatedBox) {
    const Eigen::Matrix3d R = some_rotation();
    const Eigen::Vector3d extent(4, 1, 2), c(1, -2, 3);
    const OrientedBoundingBox box = minimal_obb_from_points(rotated_box_points(extent, R, c, 300, 5));
    expect_rotation(box.R);
    expect_same_axes(box.R, box.extent, R, extent, 1e-9);
    EXPECT_TRUE(box.center.isApprox(c, 1e-12));
    EXPECT_NEAR(box.volume(), 8.0, 1e-9);
    // The PCA box of the same points is larger: the minimal one is a real improvement.
    EXPECT_LT(box.volume(), obb_from_points(rotated_box_points(extent, R, c, 300, 5)).volume());
}

TEST(MinimalBoundingBox, AxisAlignedSetGivesTheIdentityFrame) {
    // The axes are listed closest to the identity: an axis-aligned box comes back with R = I.
    const OrientedBoundingBox box =
        minimal_obb_from_points(rotated_box_points({3, 1, 2}, Eigen::Matrix3d::Identity(), {0.5, 0, -1}, 100, 2));
    EXPECT_TRUE(box.R.isApprox(Eigen::Matrix3d::Identity(), 1e-12));
    EXPECT_TRUE(box.extent.isApprox(Eigen::Vector3d(3, 1, 2), 1e-12));
    EXPECT_TRUE(box.center.isApprox(Eigen::Vector3d(0.5, 0, -1), 1e-12));
}

TEST(MinimalBoundingBox, NeverLargerThanOpen3DAndHoldsEveryPoint) {
    // Open3D 0.20 create_from_points_minimal volumes on formula_cloud(0, 60) and formula_cloud(1, 80)
    // (its Jylanki search, in single precision: its R is orthonormal to ~5e-8 only); the PCA boxes are
    // 12.0517979659 and 20.0711683291.
    const double open3d_volume[2] = {11.7795027515, 14.356300591};
    const int sizes[2] = {60, 80};
    for (int kind = 0; kind < 2; ++kind) {
        const auto pts = formula_cloud(kind, sizes[kind]);
        const OrientedBoundingBox box = minimal_obb_from_points(pts);
        expect_rotation(box.R);
        EXPECT_LE(box.volume(), open3d_volume[kind] * (1 + 1e-6)) << "kind " << kind;
        EXPECT_GT(box.volume(), open3d_volume[kind] * (1 - 1e-3)) << "kind " << kind;
        EXPECT_EQ(indices_in_obb(pts, box).size(), pts.size());
    }
}

TEST(MinimalBoundingBox, RotatingTheInputRotatesTheBox) {
    const auto pts = formula_cloud(0, 60);
    const Eigen::Matrix3d Q = some_rotation();
    std::vector<Eigen::Vector3d> moved;
    for (const auto& p : pts) moved.push_back(Q * p + Eigen::Vector3d(-3, 7, 1));
    const OrientedBoundingBox a = minimal_obb_from_points(pts), b = minimal_obb_from_points(moved);
    EXPECT_NEAR(a.volume(), b.volume(), 1e-9 * a.volume());
    EXPECT_TRUE(b.center.isApprox(Q * a.center + Eigen::Vector3d(-3, 7, 1), 1e-9));
}

TEST(MinimalBoundingBox, RobustFlatSetGivesTheMinimumRectangle) {
    // A 3 x 1 rectangle tilted in space, with points inside: with robust, a flat box of that rectangle.
    const Eigen::Matrix3d R = some_rotation();
    std::vector<Eigen::Vector3d> pts = rotated_box_points({3, 1, 0}, R, {1, 1, 1}, 50, 9);
    EXPECT_THROW(minimal_obb_from_points(pts), o3d::InvalidArgument);
    const OrientedBoundingBox box = minimal_obb_from_points(pts, true);
    expect_rotation(box.R);
    expect_same_axes(box.R, box.extent, R, Eigen::Vector3d(3, 1, 0), 1e-9);
}

TEST(MinimalBoundingBox, BadInputThrows) {
    EXPECT_THROW(minimal_obb_from_points({}), o3d::InvalidArgument);
    EXPECT_THROW(minimal_obb_from_points({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}), o3d::InvalidArgument);
    auto pts = formula_cloud(0, 20);
    pts[4].y() = std::numeric_limits<double>::quiet_NaN();
    EXPECT_THROW(minimal_obb_from_points(pts), o3d::InvalidArgument);
}

// ---- minimum-volume ellipsoid ----

TEST(BoundingEllipsoid, RecoversASampledEllipsoid) {
    // Points on the surface of a known ellipsoid: it is its own minimum-volume enclosing ellipsoid.
    const Eigen::Matrix3d R = some_rotation();
    const Eigen::Vector3d radii(3, 2, 0.5), c(-1, 4, 2);
    std::vector<Eigen::Vector3d> pts;
    for (int i = 0; i < 12; ++i)
        for (int j = 0; j < 24; ++j) {
            const double th = M_PI * (i + 0.5) / 12, ph = 2 * M_PI * j / 24;
            const Eigen::Vector3d u(std::sin(th) * std::cos(ph), std::sin(th) * std::sin(ph), std::cos(th));
            pts.push_back(c + R * radii.cwiseProduct(u));
        }
    const OrientedBoundingEllipsoid e = ellipsoid_from_points(pts);
    expect_rotation(e.R);
    // Khachiyan stops at weights moving by 1e-6 (Open3D's tolerance): a few parts in a thousand.
    EXPECT_TRUE(e.center.isApprox(c, 2e-3)) << e.center.transpose();
    expect_same_axes(e.R, e.radii, R, radii, 1e-2);
    EXPECT_NEAR(max_normalised_distance(pts, e), 1.0, 5e-3);
}

TEST(BoundingEllipsoid, MatchesOpen3D) {
    // Open3D 0.20 OrientedBoundingEllipsoid.create_from_points on formula_cloud(kind, n).
    struct Reference {
        int kind, n;
        double volume;
        Eigen::Vector3d center, radii;
        Eigen::Matrix3d R;
    };
    Reference refs[2];
    refs[0] = {0, 60, 20.7391263702, {0.6255644775893168, -0.03647163013269328, -0.02357000960746461},
               {4.527424708629831, 1.412719380911818, 0.7740957956384046}, Eigen::Matrix3d::Zero()};
    refs[0].R << 0.9999287413099145, 0.01115197995856802, -0.00425977057757032, -0.01135471785987434,
        0.9986353068281009, -0.0509764096290378, 0.00368546939920648, 0.05102114560991847, 0.9986907729702715;
    refs[1] = {1, 80, 15.1969710453, {9.932731972822255, -20.027305620029345, 5.0077135810942},
               {3.5045081642453657, 1.503992323868876, 0.6883284670468262}, Eigen::Matrix3d::Zero()};
    refs[1].R << 0.941470939969865, -0.33051510061218187, 0.06627395762724668, 0.3190909497636147,
        0.8104052954762646, -0.4913493897859063, 0.10868962678753273, 0.48373859193922875, 0.8684374126541526;
    for (const auto& ref : refs) {
        const auto pts = formula_cloud(ref.kind, ref.n);
        const OrientedBoundingEllipsoid e = ellipsoid_from_points(pts);
        expect_rotation(e.R);
        EXPECT_NEAR(e.volume(), ref.volume, 1e-6 * ref.volume) << "kind " << ref.kind;
        EXPECT_TRUE(e.center.isApprox(ref.center, 1e-6)) << e.center.transpose();
        EXPECT_TRUE(e.radii.isApprox(ref.radii, 1e-6)) << e.radii.transpose();
        EXPECT_TRUE(e.R.isApprox(ref.R, 1e-6)) << e.R;
        EXPECT_LT(max_normalised_distance(pts, e), 1.01);  // inside, up to Khachiyan's tolerance
    }
}

TEST(BoundingEllipsoid, SmallerThanTheBoxAroundIt) {
    // A unit cube's corners: the minimum ellipsoid is the circumscribed sphere, radius sqrt(3)/2.
    std::vector<Eigen::Vector3d> corners;
    for (int i = 0; i < 8; ++i) corners.emplace_back(i & 1, (i >> 1) & 1, (i >> 2) & 1);
    const OrientedBoundingEllipsoid e = ellipsoid_from_points(corners);
    EXPECT_TRUE(e.center.isApprox(Eigen::Vector3d::Constant(0.5), 1e-9));
    EXPECT_TRUE(e.radii.isApprox(Eigen::Vector3d::Constant(std::sqrt(3.0) / 2), 1e-6)) << e.radii.transpose();
}

TEST(BoundingEllipsoid, BadInputThrows) {
    EXPECT_THROW(ellipsoid_from_points({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}), o3d::InvalidArgument);
    std::vector<Eigen::Vector3d> flat;
    for (int i = 0; i < 10; ++i) flat.emplace_back(std::sin(i), std::cos(2 * i), 0.0);
    EXPECT_THROW(ellipsoid_from_points(flat), o3d::InvalidArgument);
    EXPECT_THROW(ellipsoid_from_points(flat, true), o3d::InvalidArgument);  // no solid ellipsoid
    auto pts = formula_cloud(0, 20);
    pts[2].x() = std::numeric_limits<double>::infinity();
    EXPECT_THROW(ellipsoid_from_points(pts), o3d::InvalidArgument);
}

// ---- static covariances ----

TEST(PointCovariancesStatic, MatchesOpen3DAndLeavesTheCloudAlone) {
    // Open3D 0.20 PointCloud.estimate_point_covariances(cloud, KDTreeSearchParamKNN(4)) on formula_cloud(0, 12).
    PointCloud cloud;
    cloud.points = formula_cloud(0, 12);
    const auto covs = estimate_point_covariances(cloud, o3d::kdtree::SearchParam::make_knn(4));
    EXPECT_FALSE(cloud.has_covariances());
    ASSERT_EQ(covs.size(), 12u);
    Eigen::Matrix3d c0, c5;
    c0 << 0.3144026265267026, 0.05416255767835926, -0.0118248216055475, 0.05416255767835926, 0.2698441218335366,
        0.0853933827384512, -0.0118248216055475, 0.0853933827384512, 0.09924434939611457;
    c5 << 0.8873968886314745, -0.06414234923069739, 0.09007818107530344, -0.06414234923069739, 0.04445321735337793,
        0.04375932301960987, 0.09007818107530344, 0.04375932301960987, 0.11566932875695797;
    EXPECT_TRUE(covs[0].isApprox(c0, 1e-12));
    EXPECT_TRUE(covs[5].isApprox(c5, 1e-12));
    // The same as the in-place estimate.
    estimate_covariances(cloud, o3d::kdtree::SearchParam::make_knn(4));
    for (size_t i = 0; i < covs.size(); ++i) EXPECT_EQ(covs[i], cloud.covariances[i]);
    EXPECT_THROW(estimate_point_covariances(cloud, o3d::kdtree::SearchParam::make_knn(0)), o3d::InvalidArgument);
}
