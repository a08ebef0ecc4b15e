// SPDX-License-Identifier: MIT
// Normals of sampled analytic surfaces, orientation rules, thread-count independence, eigen solver.
#include "o3d/geometry/normals.h"

#include <Eigen/Eigenvalues>
#include <Eigen/Geometry>
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "o3d/geometry/symmetric_eigen3.h"
#include "o3d/utility/error.h"

using namespace o3d::geometry;
using o3d::kdtree::SearchParam;

namespace {

/// Points on the plane through `origin` spanned by u, v (random in [-1,1]^2).
PointCloud sample_plane(const Eigen::Vector3d& origin, const Eigen::Vector3d& u, const Eigen::Vector3d& v, size_t n,
                        uint64_t seed) {
    std::mt19937_64 rng(seed);
    std::uniform_real_distribution<double> d(-1.0, 1.0);
    PointCloud c;
    for (size_t i = 0; i < n; ++i) c.points.push_back(origin + d(rng) * u + d(rng) * v);
    return c;
}

PointCloud sample_sphere(double radius, size_t n, uint64_t seed) {
    std::mt19937_64 rng(seed);
    std::normal_distribution<double> g;
    PointCloud c;
    for (size_t i = 0; i < n; ++i) c.points.push_back(Eigen::Vector3d(g(rng), g(rng), g(rng)).normalized() * radius);
    return c;
}

}  // namespace

TEST(SymmetricEigen3, MatchesEigenSolverOnRandomCovariances) {
    std::mt19937_64 rng(1);
    std::uniform_real_distribution<double> u(-1.0, 1.0);
    for (int t = 0; t < 2000; ++t) {
        Eigen::Matrix3d m;
        for (int i = 0; i < 9; ++i) m(i) = u(rng);
        const Eigen::Matrix3d a = m * m.transpose() * std::pow(10.0, u(rng) * 8);  // PSD, varied scale
        const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> ref(a);
        const Eigen::Vector3d v = smallest_eigenvector(a);
        EXPECT_NEAR(v.norm(), 1.0, 1e-12);
        // Residual relative to the largest eigenvalue, the meaningful accuracy measure.
        EXPECT_LT((a * v - ref.eigenvalues()(0) * v).norm(), 1e-9 * ref.eigenvalues()(2)) << "case " << t;
    }
}

TEST(SymmetricEigen3, DegenerateCases) {
    EXPECT_EQ(smallest_eigenvector(Eigen::Matrix3d::Zero()), Eigen::Vector3d::Zero());
    EXPECT_EQ(smallest_eigenvector(Eigen::Matrix3d::Identity()), Eigen::Vector3d::UnitZ());
    EXPECT_EQ(smallest_eigenvector(Eigen::Vector3d(2, 1, 3).asDiagonal()), Eigen::Vector3d::UnitY());
    // A line along (1,1,0): the two small eigenvalues are equal (0); any normal orthogonal to the line.
    const Eigen::Vector3d dir = Eigen::Vector3d(1, 1, 0).normalized();
    const Eigen::Vector3d v = smallest_eigenvector(dir * dir.transpose());
    EXPECT_NEAR(v.norm(), 1.0, 1e-12);
    EXPECT_NEAR(v.dot(dir), 0.0, 1e-12);
}

TEST(EstimateNormals, TiltedPlaneGivesPlaneNormal) {
    const Eigen::Vector3d u = Eigen::Vector3d(1, 0.2, 0.3), v = Eigen::Vector3d(-0.1, 1, 0.4);
    const Eigen::Vector3d expected = u.cross(v).normalized();
    PointCloud c = sample_plane({5, -3, 100}, u, v, 3000, 2);  // far from the origin on purpose
    estimate_normals(c, SearchParam::make_knn(20));
    ASSERT_TRUE(c.has_normals());
    for (const auto& n : c.normals) EXPECT_NEAR(std::abs(n.dot(expected)), 1.0, 1e-9);
}

TEST(EstimateNormals, SphereNormalsAreRadial) {
    PointCloud c = sample_sphere(2.0, 20000, 3);
    estimate_normals(c, SearchParam::make_hybrid(0.2, 30));
    double worst = 1.0;
    for (size_t i = 0; i < c.size(); ++i) worst = std::min(worst, std::abs(c.normals[i].dot(c.points[i].normalized())));
    EXPECT_GT(worst, 0.99);  // neighbourhoods of ~0.1 rad: curvature tilts the PCA normal slightly
}

TEST(EstimateNormals, FlipsToAgreeWithExistingNormals) {
    PointCloud c = sample_plane({0, 0, 0}, Eigen::Vector3d::UnitX(), Eigen::Vector3d::UnitY(), 500, 4);
    c.normals.assign(c.size(), Eigen::Vector3d(0, 0.1, -1));  // all hint "down"
    c.normals[7] = Eigen::Vector3d(0, 0, 1);                  // one hints "up"
    estimate_normals(c, SearchParam::make_knn(10));
    for (size_t i = 0; i < c.size(); ++i) EXPECT_NEAR(c.normals[i].z(), i == 7 ? 1.0 : -1.0, 1e-12);
}

TEST(EstimateNormals, TooFewNeighboursGiveUnitZ) {
    PointCloud c;
    c.points = {{0, 0, 0}, {1, 0, 0}, {100, 0, 0}};
    estimate_normals(c, SearchParam::make_radius(2.0));  // 2, 2 and 1 neighbours
    for (const auto& n : c.normals) EXPECT_EQ(n, Eigen::Vector3d::UnitZ());
}

TEST(EstimateNormals, IdenticalForOneAndTwoThreads) {
    PointCloud a = sample_sphere(1.0, 30000, 5);
    PointCloud b = a;
    estimate_normals(a, SearchParam::make_knn(30), 1);
    estimate_normals(b, SearchParam::make_knn(30), 2);
    EXPECT_EQ(a.normals, b.normals);  // bitwise
}

TEST(EstimateNormals, RejectsBadInput) {
    PointCloud c = sample_sphere(1.0, 100, 6);
    EXPECT_THROW(estimate_normals(c, SearchParam::make_knn(0)), o3d::InvalidArgument);
    EXPECT_THROW(estimate_normals(c, SearchParam::make_hybrid(std::nan(""), 5)), o3d::InvalidArgument);
    c.points[3].x() = NAN;
    EXPECT_THROW(estimate_normals(c, SearchParam::make_knn(5)), o3d::InvalidArgument);
    PointCloud empty;
    estimate_normals(empty, SearchParam::make_knn(5));
    EXPECT_TRUE(empty.normals.empty());
}

TEST(OrientNormals, AlignWithDirection) {
    PointCloud c;
    c.points = {{0, 0, 0}, {1, 0, 0}, {2, 0, 0}};
    c.normals = {{0, 0, -1}, {0, 0, 0}, {1, 0, 0.5}};
    orient_normals_to_align_with_direction(c, {0, 0, 2});
    EXPECT_EQ(c.normals[0], Eigen::Vector3d(0, 0, 1));
    EXPECT_EQ(c.normals[1], Eigen::Vector3d(0, 0, 2));  // zero normal takes the reference as given (Open3D)
    EXPECT_EQ(c.normals[2], Eigen::Vector3d(1, 0, 0.5));
    PointCloud none;
    none.points = c.points;
    EXPECT_THROW(orient_normals_to_align_with_direction(none), o3d::InvalidArgument);
    EXPECT_THROW(orient_normals_to_align_with_direction(c, {NAN, 0, 0}), o3d::InvalidArgument);
}

TEST(OrientNormals, TowardsCameraLocation) {
    PointCloud c;
    c.points = {{0, 0, 0}, {0, 0, 5}, {1, 1, 1}};
    c.normals = {{0, 0, 1}, {0, 0, 1}, {0, 0, 0}};
    orient_normals_towards_camera_location(c, {0, 0, 3});
    EXPECT_EQ(c.normals[0], Eigen::Vector3d(0, 0, 1));
    EXPECT_EQ(c.normals[1], Eigen::Vector3d(0, 0, -1));
    EXPECT_TRUE(c.normals[2].isApprox(Eigen::Vector3d(-1, -1, 2).normalized(), 1e-15));
}
