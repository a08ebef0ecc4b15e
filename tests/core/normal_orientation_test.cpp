// SPDX-License-Identifier: MIT
// Consistent normal orientation (Hoppe et al. 1992): analytic surfaces with scrambled normal signs must
// come back consistent, with Open3D 0.20's sign rule (lowest point's normal faces -z), checked on the
// open3d 0.20.0 wheel: a unit sphere comes out outward, a height field downward.
#include "o3d/geometry/normal_orientation.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>

#include "o3d/geometry/normals.h"
#include "o3d/utility/error.h"

using namespace o3d::geometry;

namespace {

constexpr double kPi = 3.14159265358979323846;

// Fibonacci lattice on a sphere: quasi-uniform, so k = 10 neighbourhoods are well shaped.
PointCloud sphere(size_t n, const Eigen::Vector3d& center, double radius) {
    PointCloud pc;
    const double golden = kPi * (3.0 - std::sqrt(5.0));
    for (size_t i = 0; i < n; ++i) {
        const double z = 1.0 - 2.0 * (static_cast<double>(i) + 0.5) / static_cast<double>(n);
        const double r = std::sqrt(1.0 - z * z), t = golden * static_cast<double>(i);
        const Eigen::Vector3d u(r * std::cos(t), r * std::sin(t), z);
        pc.points.push_back(center + radius * u);
        pc.normals.push_back(u);
    }
    return pc;
}

// Random points of a torus around the z axis with their outward unit normals.
PointCloud torus(size_t n, double big_r, double small_r, uint64_t seed) {
    std::mt19937_64 rng(seed);
    std::uniform_real_distribution<double> ang(0.0, 2.0 * kPi), acc(0.0, 1.0);
    PointCloud pc;
    while (pc.size() < n) {
        const double u = ang(rng), v = ang(rng);
        // Rejection keeps the density uniform in area (the outer rim is larger than the inner one).
        if (acc(rng) * (big_r + small_r) > big_r + small_r * std::cos(v)) continue;
        const Eigen::Vector3d nrm(std::cos(v) * std::cos(u), std::cos(v) * std::sin(u), std::sin(v));
        pc.points.emplace_back((big_r + small_r * std::cos(v)) * std::cos(u),
                               (big_r + small_r * std::cos(v)) * std::sin(u), small_r * std::sin(v));
        pc.normals.push_back(nrm);
    }
    return pc;
}

void scramble(PointCloud& pc, uint64_t seed) {
    std::mt19937_64 rng(seed);
    for (auto& n : pc.normals)
        if (rng() & 1) n = -n;
}

}  // namespace

TEST(NormalOrientation, SphereComesOutOutward) {
    PointCloud pc = sphere(1500, Eigen::Vector3d(0.3, -0.2, 2.0), 1.5);
    const std::vector<Eigen::Vector3d> truth = pc.normals;
    scramble(pc, 1);
    orient_normals_consistent_tangent_plane(pc, 10);
    for (size_t i = 0; i < pc.size(); ++i) ASSERT_GT(pc.normals[i].dot(truth[i]), 0.999) << "point " << i;
}

TEST(NormalOrientation, TorusComesOutOutward) {
    // The lowest points lie on the bottom circle, where the outward normal is -z: all outward.
    PointCloud pc = torus(4000, 1.0, 0.4, 7);
    const std::vector<Eigen::Vector3d> truth = pc.normals;
    scramble(pc, 2);
    orient_normals_consistent_tangent_plane(pc, 10);
    size_t wrong = 0;
    for (size_t i = 0; i < pc.size(); ++i) wrong += pc.normals[i].dot(truth[i]) < 0.0;
    EXPECT_EQ(wrong, 0u);
}

TEST(NormalOrientation, NoisyEstimatedNormalsOnTorus) {
    // Estimated (PCA) normals of a noisy sampling: only their sign can be judged against the truth.
    PointCloud pc = torus(5000, 1.0, 0.4, 11);
    const std::vector<Eigen::Vector3d> truth = pc.normals;
    std::mt19937_64 rng(3);
    std::normal_distribution<double> g(0.0, 0.004);
    for (auto& p : pc.points) p += Eigen::Vector3d(g(rng), g(rng), g(rng));
    pc.normals.clear();
    estimate_normals(pc, o3d::kdtree::SearchParam::make_knn(20));
    scramble(pc, 4);
    orient_normals_consistent_tangent_plane(pc, 12);
    size_t wrong = 0;
    for (size_t i = 0; i < pc.size(); ++i) wrong += pc.normals[i].dot(truth[i]) < 0.0;
    EXPECT_EQ(wrong, 0u);
}

TEST(NormalOrientation, HeightFieldFacesDown) {
    // Open3D 0.20 gives 400 of 400 normals with z < 0 on this surface (random initial signs).
    PointCloud pc;
    for (int i = 0; i < 20; ++i)
        for (int j = 0; j < 20; ++j) {
            const double x = -1.0 + 2.0 * i / 19.0, y = -1.0 + 2.0 * j / 19.0;
            pc.points.emplace_back(x, y, 0.3 * std::sin(3 * x) * std::cos(3 * y));
            pc.normals.push_back(
                Eigen::Vector3d(-0.9 * std::cos(3 * x) * std::cos(3 * y), 0.9 * std::sin(3 * x) * std::sin(3 * y), 1.0)
                    .normalized());
        }
    scramble(pc, 5);
    orient_normals_consistent_tangent_plane(pc, 10);
    for (const auto& n : pc.normals) ASSERT_LT(n.z(), 0.0);
}

TEST(NormalOrientation, SeparatedSpheresAreEachConsistent) {
    // The Euclidean tree bridges the two spheres; across the bridge the sign of the second one follows
    // the first (Open3D 0.20 on the same layout: first all outward, second all inward), but each sphere
    // must be consistent and the one holding the lowest point outward.
    PointCloud a = sphere(600, Eigen::Vector3d::Zero(), 1.0);
    const PointCloud b = sphere(600, Eigen::Vector3d(10.0, 0.0, 5.0), 1.0);
    a.points.insert(a.points.end(), b.points.begin(), b.points.end());
    a.normals.insert(a.normals.end(), b.normals.begin(), b.normals.end());
    const std::vector<Eigen::Vector3d> truth = a.normals;
    scramble(a, 6);
    orient_normals_consistent_tangent_plane(a, 10);
    size_t outward_a = 0, outward_b = 0;
    for (size_t i = 0; i < 600; ++i) outward_a += a.normals[i].dot(truth[i]) > 0.0;
    for (size_t i = 600; i < 1200; ++i) outward_b += a.normals[i].dot(truth[i]) > 0.0;
    EXPECT_EQ(outward_a, 600u);
    EXPECT_TRUE(outward_b == 0u || outward_b == 600u) << outward_b;
}

TEST(NormalOrientation, DisconnectedGraphOrientsEachComponentFromItsOwnRoot) {
    // A vertical plane x = 0 and a sphere beside it: every edge between them runs along x, inside the
    // cone of both end normals, so cos_alpha_tol = 0.5 leaves two components. The sphere is oriented from
    // its own lowest point (outward); the plane only needs to be consistent.
    PointCloud pc = sphere(800, Eigen::Vector3d(3.0, 0.0, 0.0), 1.0);
    const std::vector<Eigen::Vector3d> truth = pc.normals;
    for (int i = 0; i < 30; ++i)
        for (int j = 0; j < 30; ++j) {
            pc.points.emplace_back(0.0, -1.5 + 3.0 * i / 29.0, -2.0 + 3.0 * j / 29.0);
            pc.normals.emplace_back(1.0, 0.0, 0.0);
        }
    scramble(pc, 8);
    orient_normals_consistent_tangent_plane(pc, 10, 0.0, 0.5);
    for (size_t i = 0; i < 800; ++i) ASSERT_GT(pc.normals[i].dot(truth[i]), 0.0) << "sphere point " << i;
    const double sign = pc.normals[800].x();
    for (size_t i = 800; i < pc.size(); ++i) ASSERT_EQ(pc.normals[i].x(), sign) << "plane point " << i;
}

TEST(NormalOrientation, PenaltyAndConeKeepACleanSurfaceConsistent) {
    PointCloud pc = sphere(1200, Eigen::Vector3d::Zero(), 1.0);
    const std::vector<Eigen::Vector3d> truth = pc.normals;
    scramble(pc, 9);
    orient_normals_consistent_tangent_plane(pc, 10, 1.0, 0.6);
    for (size_t i = 0; i < pc.size(); ++i) ASSERT_GT(pc.normals[i].dot(truth[i]), 0.0) << "point " << i;
}

TEST(NormalOrientation, DuplicatePointsAndTinyClouds) {
    PointCloud pc = sphere(500, Eigen::Vector3d::Zero(), 1.0);
    const size_t n = pc.size();
    for (size_t i = 0; i < n; ++i) {  // every point twice, the copy with the opposite sign
        pc.points.push_back(pc.points[i]);
        pc.normals.push_back(-pc.normals[i]);
    }
    orient_normals_consistent_tangent_plane(pc, 10);
    for (size_t i = 0; i < pc.size(); ++i) ASSERT_GT(pc.normals[i].dot(pc.points[i]), 0.0) << "point " << i;

    PointCloud one;
    one.points = {Eigen::Vector3d(1, 2, 3)};
    one.normals = {Eigen::Vector3d(0, 0.6, 0.8)};
    orient_normals_consistent_tangent_plane(one, 10);  // k > n is fine
    EXPECT_EQ(one.normals[0], Eigen::Vector3d(0, -0.6, -0.8));

    PointCloud two;
    two.points = {Eigen::Vector3d(0, 0, 1), Eigen::Vector3d(1, 0, 0)};
    two.normals = {Eigen::Vector3d(0, 0, 1), Eigen::Vector3d(0, 0, 1)};
    orient_normals_consistent_tangent_plane(two, 1);  // only the Euclidean tree joins them
    EXPECT_EQ(two.normals[1], Eigen::Vector3d(0, 0, -1));
    EXPECT_EQ(two.normals[0], Eigen::Vector3d(0, 0, -1));
}

TEST(NormalOrientation, DeterministicAcrossThreadCounts) {
    PointCloud pc = torus(6000, 1.0, 0.3, 21);
    std::mt19937_64 rng(12);
    std::normal_distribution<double> g(0.0, 0.01);
    for (auto& n : pc.normals) n = (n + Eigen::Vector3d(g(rng), g(rng), g(rng))).normalized();
    scramble(pc, 13);
    PointCloud a = pc, b = pc;
    orient_normals_consistent_tangent_plane(a, 8, 0.5, 0.9, 1);
    orient_normals_consistent_tangent_plane(b, 8, 0.5, 0.9, 2);
    ASSERT_EQ(a.normals.size(), b.normals.size());
    for (size_t i = 0; i < a.size(); ++i) ASSERT_EQ(a.normals[i], b.normals[i]) << "point " << i;
}

TEST(NormalOrientation, Errors) {
    PointCloud pc = sphere(100, Eigen::Vector3d::Zero(), 1.0);
    PointCloud bare;
    bare.points = pc.points;
    EXPECT_THROW(orient_normals_consistent_tangent_plane(bare, 10), o3d::InvalidArgument);
    PointCloud empty;
    EXPECT_THROW(orient_normals_consistent_tangent_plane(empty, 10), o3d::InvalidArgument);
    EXPECT_THROW(orient_normals_consistent_tangent_plane(pc, 0), o3d::InvalidArgument);
    EXPECT_THROW(orient_normals_consistent_tangent_plane(pc, 10, std::nan("")), o3d::InvalidArgument);
    EXPECT_THROW(orient_normals_consistent_tangent_plane(pc, 10, -1.0), o3d::InvalidArgument);
    EXPECT_THROW(orient_normals_consistent_tangent_plane(pc, 10, 0.0, std::numeric_limits<double>::infinity()),
                 o3d::InvalidArgument);
    PointCloud bad = pc;
    bad.points[3].y() = std::numeric_limits<double>::quiet_NaN();
    EXPECT_THROW(orient_normals_consistent_tangent_plane(bad, 10), o3d::InvalidArgument);
}
