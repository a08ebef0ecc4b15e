// SPDX-License-Identifier: MIT
// Per-point covariances: planar neighbourhoods, the identity fallback, thread-count independence,
// carried through the point-cloud operations, Open3D 0.20 reference numbers, errors.
#include "o3d/geometry/point_cloud_covariances.h"

#include <Eigen/Eigenvalues>
#include <Eigen/Geometry>
#include <gtest/gtest.h>

#include <random>

#include "o3d/geometry/point_cloud_ops.h"
#include "o3d/io/point_cloud_io.h"
#include "o3d/utility/error.h"
#include "test_data.h"

using namespace o3d::geometry;
using o3d::kdtree::SearchParam;

namespace {

PointCloud tilted_plane(size_t n, uint64_t seed, Eigen::Vector3d* normal) {
    const Eigen::Vector3d u = Eigen::Vector3d(1, 1, 0).normalized(), v = Eigen::Vector3d(-1, 1, 1).normalized();
    *normal = u.cross(v).normalized();
    std::mt19937_64 rng(seed);
    std::uniform_real_distribution<double> d(-1.0, 1.0);
    PointCloud c;
    for (size_t i = 0; i < n; ++i) c.points.push_back(Eigen::Vector3d(5, -3, 2) + d(rng) * u + d(rng) * v);
    return c;
}

}  // namespace

TEST(PointCloudCovariances, PlanarNeighbourhoodHasZeroEigenvalueAlongTheNormal) {
    Eigen::Vector3d normal;
    PointCloud cloud = tilted_plane(2000, 4, &normal);
    estimate_covariances(cloud, SearchParam::make_knn(30));
    ASSERT_TRUE(cloud.has_covariances());
    for (size_t i = 0; i < cloud.size(); i += 97) {
        const Eigen::Matrix3d& C = cloud.covariances[i];
        EXPECT_TRUE(C.isApprox(C.transpose(), 1e-15));
        EXPECT_NEAR((C * normal).norm(), 0.0, 1e-12);  // zero eigenvalue along the normal
        const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> es(C);
        EXPECT_GT(es.eigenvalues()(1), 1e-5);  // in-plane spread
    }
}

TEST(PointCloudCovariances, KnownNeighbourhood) {
    // Four points, KNN 4: the covariance of the whole set (divided by N) at every point.
    PointCloud cloud;
    cloud.points = {{0, 0, 0}, {2, 0, 0}, {0, 2, 0}, {2, 2, 0}};
    estimate_covariances(cloud, SearchParam::make_knn(4));
    for (const auto& C : cloud.covariances) EXPECT_TRUE(C.isApprox(Eigen::Vector3d(1, 1, 0).asDiagonal().toDenseMatrix()));
}

TEST(PointCloudCovariances, FewerThanThreeNeighboursGiveIdentity) {
    PointCloud cloud;
    cloud.points = {{0, 0, 0}, {0.1, 0, 0}, {10, 0, 0}, {10, 0.1, 0}, {10, 0, 0.1}};
    estimate_covariances(cloud, SearchParam::make_radius(0.5));
    EXPECT_EQ(cloud.covariances[0], Eigen::Matrix3d::Identity());
    EXPECT_EQ(cloud.covariances[1], Eigen::Matrix3d::Identity());
    EXPECT_NE(cloud.covariances[2], Eigen::Matrix3d::Identity());
}

TEST(PointCloudCovariances, IdenticalForAnyThreadCount) {
    Eigen::Vector3d normal;
    PointCloud a = tilted_plane(5000, 8, &normal), b = a;
    estimate_covariances(a, SearchParam::make_hybrid(0.2, 20), 1);
    estimate_covariances(b, SearchParam::make_hybrid(0.2, 20), 4);
    ASSERT_EQ(a.covariances.size(), b.covariances.size());
    for (size_t i = 0; i < a.size(); ++i) ASSERT_EQ(a.covariances[i], b.covariances[i]) << i;
}

TEST(PointCloudCovariances, FollowThePointsThroughOperations) {
    PointCloud cloud;
    for (int i = 0; i < 6; ++i) {
        cloud.points.emplace_back(i, 0, 0);
        cloud.covariances.push_back(Eigen::Vector3d(1 + i, 2, 3).asDiagonal());
    }
    const PointCloud picked = select_by_index(cloud, {1, 4});
    ASSERT_TRUE(picked.has_covariances());
    EXPECT_EQ(picked.covariances[1], cloud.covariances[4]);

    PointCloud sum = cloud;
    append(sum, picked);
    EXPECT_EQ(sum.covariances.size(), 8u);
    PointCloud bare;
    bare.points = {{0, 0, 0}};
    append(sum, bare);  // one side lacks them: dropped, as normals/colors
    EXPECT_FALSE(sum.has_covariances());

    PointCloud with_nan = cloud;
    with_nan.points[2].x() = NAN;
    remove_non_finite_points(with_nan, true, true);
    ASSERT_TRUE(with_nan.has_covariances());
    EXPECT_EQ(with_nan.covariances[2], cloud.covariances[3]);

    const Eigen::Matrix3d R = Eigen::AngleAxisd(0.4, Eigen::Vector3d(1, 1, 1).normalized()).toRotationMatrix();
    PointCloud rotated = cloud;
    rotate(rotated, R, Eigen::Vector3d::Zero());
    EXPECT_TRUE(rotated.covariances[5].isApprox(R * cloud.covariances[5] * R.transpose()));
    PointCloud moved = cloud;
    Eigen::Matrix4d T = Eigen::Matrix4d::Identity();
    T.topLeftCorner<3, 3>() = R;
    T(0, 3) = 7.0;
    transform(moved, T);
    EXPECT_TRUE(moved.covariances[5].isApprox(R * cloud.covariances[5] * R.transpose()));
    moved.clear();
    EXPECT_TRUE(moved.covariances.empty());
}

// Numbers from tools/reference/record_hull_obb.py (Open3D 0.20).
TEST(PointCloudCovariances, MatchesOpen3DOnCloudBin0) {
    O3D_TEST_DATA_OR_SKIP(path, "open3d/Feature/cloud_bin_0.pcd");
    PointCloud cloud = o3d::io::read_point_cloud(path);
    estimate_covariances(cloud, SearchParam::make_knn(30));
    const double knn0[9] = {0.00107995231629,  0.000934985542567, -0.000514799600145,
                            0.000934985542567, 0.00424541377841,  -0.00091369316711,
                            -0.000514799600145, -0.00091369316711, 0.00301379055436};
    const double knn2000[9] = {0.00439165961966, 0.00220893547486,  0.000199356334699,
                               0.00220893547486, 0.00202713579797,  0.000824454290129,
                               0.000199356334699, 0.000824454290129, 0.00364644853797};
    for (int k = 0; k < 9; ++k) {
        EXPECT_NEAR(cloud.covariances[0](k / 3, k % 3), knn0[k], 1e-12);
        EXPECT_NEAR(cloud.covariances[2000](k / 3, k % 3), knn2000[k], 1e-12);
    }
    estimate_covariances(cloud, SearchParam::make_hybrid(0.05, 20));
    size_t identity = 0;
    for (const auto& C : cloud.covariances) identity += C == Eigen::Matrix3d::Identity();
    EXPECT_EQ(identity, 200u);
    const double hybrid500[9] = {0.000632800228838, 0.000282284337932, 8.07770176152e-05,
                                 0.000282284337932, 0.000599811406474, 5.31186601336e-05,
                                 8.07770176152e-05, 5.31186601336e-05, 1.10363709114e-05};
    for (int k = 0; k < 9; ++k) EXPECT_NEAR(cloud.covariances[500](k / 3, k % 3), hybrid500[k], 1e-12);
}

TEST(PointCloudCovariances, Errors) {
    PointCloud cloud;
    cloud.points = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
    EXPECT_THROW(estimate_covariances(cloud, SearchParam::make_radius(0.0)), o3d::InvalidArgument);
    EXPECT_THROW(estimate_covariances(cloud, SearchParam::make_radius(-1.0)), o3d::InvalidArgument);
    EXPECT_THROW(estimate_covariances(cloud, SearchParam::make_knn(0)), o3d::InvalidArgument);
    cloud.points[1].y() = NAN;
    EXPECT_THROW(estimate_covariances(cloud, SearchParam::make_knn(3)), o3d::InvalidArgument);
    PointCloud empty;
    estimate_covariances(empty, SearchParam::make_knn(30));
    EXPECT_TRUE(empty.covariances.empty());
}
