// SPDX-License-Identifier: MIT
// Correspondence checkers on hand-made triples whose verdicts follow from Open3D's definitions.
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cmath>
#include <limits>

#include "o3d/registration/correspondence_checker.h"
#include "o3d/utility/error.h"

namespace reg = o3d::registration;
using o3d::geometry::PointCloud;
using Checker = reg::CorrespondenceChecker;

namespace {

PointCloud cloud(std::initializer_list<Eigen::Vector3d> points) {
    PointCloud pc;
    pc.points.assign(points.begin(), points.end());
    return pc;
}

const reg::CorrespondenceSet kIdentityPairs = {{0, 0}, {1, 1}, {2, 2}};

Eigen::Matrix4d translation(const Eigen::Vector3d& t) {
    Eigen::Matrix4d m = Eigen::Matrix4d::Identity();
    m.topRightCorner<3, 1>() = t;
    return m;
}

double degrees(double d) { return d * M_PI / 180.0; }

}  // namespace

TEST(CorrespondenceChecker, EdgeLengthComparesEdgesBothWays) {
    const PointCloud source = cloud({{0, 0, 0}, {1, 0, 0}, {1, 1, 0}});
    // Target triangle scaled by 0.95: every edge ratio is 0.95, so 0.9 passes and 0.96 fails,
    // whichever cloud is the larger (the test is symmetric).
    PointCloud target = source;
    for (auto& p : target.points) p *= 0.95;
    EXPECT_TRUE(Checker::edge_length(0.9).check(source, target, kIdentityPairs));
    EXPECT_FALSE(Checker::edge_length(0.96).check(source, target, kIdentityPairs));
    EXPECT_TRUE(Checker::edge_length(0.9).check(target, source, kIdentityPairs));
    EXPECT_FALSE(Checker::edge_length(0.96).check(target, source, kIdentityPairs));
}

TEST(CorrespondenceChecker, EdgeLengthTestsEveryPairNotOnlyConsecutiveOnes) {
    // Edges 0-1 and 1-2 have length 1 in both clouds; only edge 0-2 differs: sqrt(2) vs 1.2 (ratio 0.85).
    const PointCloud source = cloud({{0, 0, 0}, {1, 0, 0}, {1, 1, 0}});
    const double cos_phi = -0.28;  // |a'c'|^2 = 2 + 2 cos(phi) = 1.44
    const PointCloud target = cloud({{0, 0, 0}, {1, 0, 0}, {1 + cos_phi, std::sqrt(1 - cos_phi * cos_phi), 0}});
    ASSERT_NEAR((target.points[2] - target.points[0]).norm(), 1.2, 1e-12);
    ASSERT_NEAR((target.points[2] - target.points[1]).norm(), 1.0, 1e-12);
    EXPECT_FALSE(Checker::edge_length(0.9).check(source, target, kIdentityPairs));
    EXPECT_TRUE(Checker::edge_length(0.84).check(source, target, kIdentityPairs));
    // Without the far pair the remaining edge agrees.
    EXPECT_TRUE(Checker::edge_length(0.9).check(source, target, {{0, 0}, {1, 1}}));
}

TEST(CorrespondenceChecker, EdgeLengthIgnoresTheTransformation) {
    const PointCloud source = cloud({{0, 0, 0}, {1, 0, 0}, {1, 1, 0}});
    const Checker checker = Checker::edge_length(0.9);
    EXPECT_FALSE(checker.requires_alignment());
    EXPECT_TRUE(checker.check(source, source, kIdentityPairs, translation({100, -50, 3})));
}

TEST(CorrespondenceChecker, DistanceMovesTheSourceByTheTransformation) {
    const PointCloud source = cloud({{0, 0, 0}, {1, 0, 0}, {1, 1, 0}});
    PointCloud target = source;
    for (auto& p : target.points) p += Eigen::Vector3d(0.5, 0, 0);
    target.points[2] += Eigen::Vector3d(0, 0, 0.05);  // one pair is 0.05 off after the right move
    const Checker checker = Checker::distance(0.075);
    EXPECT_TRUE(checker.requires_alignment());
    EXPECT_FALSE(checker.check(source, target, kIdentityPairs));  // identity leaves them 0.5 apart
    EXPECT_TRUE(checker.check(source, target, kIdentityPairs, translation({0.5, 0, 0})));
    EXPECT_FALSE(Checker::distance(0.04).check(source, target, kIdentityPairs, translation({0.5, 0, 0})));
    EXPECT_TRUE(Checker::distance(0.04).check(source, target, {{0, 0}, {1, 1}}, translation({0.5, 0, 0})));
}

TEST(CorrespondenceChecker, NormalComparesRotatedSourceNormals) {
    PointCloud source = cloud({{0, 0, 0}, {1, 0, 0}, {1, 1, 0}});
    source.normals.assign(3, Eigen::Vector3d(0, 0, 1));
    PointCloud target = source;
    // Target normals tilted by 20 degrees about x.
    const Eigen::Matrix3d tilt = Eigen::AngleAxisd(degrees(20), Eigen::Vector3d::UnitX()).toRotationMatrix();
    for (auto& n : target.normals) n = tilt * n;
    EXPECT_TRUE(Checker::normal(degrees(30)).check(source, target, kIdentityPairs));
    EXPECT_FALSE(Checker::normal(degrees(10)).check(source, target, kIdentityPairs));
    // The same tilt applied to the source turns its normals onto the target's; a translation does nothing.
    Eigen::Matrix4d t = translation({3, 4, 5});
    t.topLeftCorner<3, 3>() = tilt;
    EXPECT_TRUE(Checker::normal(degrees(1)).check(source, target, kIdentityPairs, t));
    EXPECT_TRUE(Checker::normal(degrees(1)).requires_alignment());
}

TEST(CorrespondenceChecker, NormalNeedsNormalsOnBothClouds) {
    PointCloud with = cloud({{0, 0, 0}, {1, 0, 0}, {1, 1, 0}});
    with.normals.assign(3, Eigen::Vector3d(0, 0, 1));
    const PointCloud without = cloud({{0, 0, 0}, {1, 0, 0}, {1, 1, 0}});
    const Checker checker = Checker::normal(degrees(30));
    EXPECT_THROW(checker.check(with, without, kIdentityPairs), o3d::InvalidArgument);
    EXPECT_THROW(checker.check(without, with, kIdentityPairs), o3d::InvalidArgument);
    // The other kinds do not look at normals.
    EXPECT_TRUE(Checker::distance(0.1).check(without, without, kIdentityPairs));
}

TEST(CorrespondenceChecker, RejectsBadThresholdsIndicesAndTransformations) {
    const double nan = std::numeric_limits<double>::quiet_NaN();
    const double inf = std::numeric_limits<double>::infinity();
    EXPECT_THROW(Checker::edge_length(0.0), o3d::InvalidArgument);
    EXPECT_THROW(Checker::edge_length(1.01), o3d::InvalidArgument);
    EXPECT_THROW(Checker::edge_length(nan), o3d::InvalidArgument);
    EXPECT_NO_THROW(Checker::edge_length(1.0));
    EXPECT_THROW(Checker::distance(0.0), o3d::InvalidArgument);
    EXPECT_THROW(Checker::distance(-1.0), o3d::InvalidArgument);
    EXPECT_THROW(Checker::distance(inf), o3d::InvalidArgument);
    EXPECT_THROW(Checker::distance(nan), o3d::InvalidArgument);
    EXPECT_THROW(Checker::normal(0.0), o3d::InvalidArgument);
    EXPECT_THROW(Checker::normal(nan), o3d::InvalidArgument);

    const PointCloud pc = cloud({{0, 0, 0}, {1, 0, 0}, {1, 1, 0}});
    const Checker checker = Checker::distance(0.1);
    EXPECT_THROW(checker.check(pc, pc, {{0, 0}, {3, 1}}), o3d::InvalidArgument);
    EXPECT_THROW(checker.check(pc, pc, {{0, -1}}), o3d::InvalidArgument);
    Eigen::Matrix4d bad = Eigen::Matrix4d::Identity();
    bad(0, 3) = nan;
    EXPECT_THROW(checker.check(pc, pc, kIdentityPairs, bad), o3d::InvalidArgument);
    // No pairs: nothing to contradict the hypothesis.
    EXPECT_TRUE(checker.check(pc, pc, {}));
}
