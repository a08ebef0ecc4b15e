// SPDX-License-Identifier: MIT
// ICP, evaluation and information matrix on synthetic clouds whose right answers are known exactly.
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cmath>
#include <cstring>
#include <limits>
#include <vector>

#include "o3d/registration/estimation_point_to_plane.h"
#include "o3d/registration/estimation_point_to_point.h"
#include "o3d/registration/evaluation.h"
#include "o3d/registration/icp.h"
#include "o3d/registration/information_matrix.h"
#include "o3d/utility/error.h"

namespace reg = o3d::registration;
using o3d::geometry::PointCloud;

namespace {

/// A smooth, deliberately asymmetric height field z = f(x, y) with exact normals. No symmetry means
/// ICP has a single right answer; the samples follow the R2 low-discrepancy sequence rather than a
/// grid, because a grid gives point-to-point ICP false minima one grid step away.
PointCloud height_field(int n) {
    PointCloud pc;
    for (int k = 0; k < n; ++k) {
        const double u = std::fmod(0.5 + k * 0.7548776662466927, 1.0);
        const double v = std::fmod(0.5 + k * 0.5698402909980532, 1.0);
        const double x = -1.0 + 2.0 * u;
        const double y = -0.7 + 1.9 * v;
        const double z = 0.3 * std::sin(2.0 * x) + 0.2 * std::cos(3.0 * y) + 0.15 * x * y + 0.1 * x * x;
        const double fx = 0.6 * std::cos(2.0 * x) + 0.15 * y + 0.2 * x;
        const double fy = -0.6 * std::sin(3.0 * y) + 0.15 * x;
        pc.points.emplace_back(x, y, z);
        pc.normals.push_back(Eigen::Vector3d(-fx, -fy, 1.0).normalized());
    }
    return pc;
}

Eigen::Matrix4d rigid(double degrees, const Eigen::Vector3d& axis, const Eigen::Vector3d& t, double scale = 1.0) {
    Eigen::Matrix4d m = Eigen::Matrix4d::Identity();
    m.topLeftCorner<3, 3>() = scale * Eigen::AngleAxisd(degrees * M_PI / 180.0, axis.normalized()).toRotationMatrix();
    m.topRightCorner<3, 1>() = t;
    return m;
}

PointCloud transformed(const PointCloud& pc, const Eigen::Matrix4d& m) {
    PointCloud out = pc;
    for (auto& p : out.points) p = m.topLeftCorner<3, 3>() * p + m.topRightCorner<3, 1>();
    return out;
}

/// The known motion: source = motion^-1 * target, so ICP must return exactly `motion`.
const Eigen::Matrix4d kMotion = rigid(6.0, {0.3, -0.5, 1.0}, {0.04, -0.03, 0.02});

reg::IcpOptions tight(reg::Estimation e, int max_iteration = 100) {
    reg::IcpOptions o;
    o.estimation = e;
    o.criteria.relative_fitness = 1e-12;
    o.criteria.relative_rmse = 1e-12;
    o.criteria.max_iteration = max_iteration;
    return o;
}

bool bitwise_equal(const reg::RegistrationResult& a, const reg::RegistrationResult& b) {
    return std::memcmp(a.transformation.data(), b.transformation.data(), sizeof(double) * 16) == 0 &&
           std::memcmp(&a.fitness, &b.fitness, sizeof(double)) == 0 &&
           std::memcmp(&a.inlier_rmse, &b.inlier_rmse, sizeof(double)) == 0 &&
           a.correspondence_set == b.correspondence_set;
}

}  // namespace

TEST(RegistrationIcp, PointToPointRecoversKnownMotionExactly) {
    const PointCloud target = height_field(3000);
    const PointCloud source = transformed(target, kMotion.inverse());
    const auto r = reg::registration_icp(source, target, 0.2, Eigen::Matrix4d::Identity(),
                                         tight(reg::Estimation::PointToPoint));
    EXPECT_LT((r.transformation - kMotion).cwiseAbs().maxCoeff(), 1e-9);
    EXPECT_DOUBLE_EQ(r.fitness, 1.0);
    EXPECT_LT(r.inlier_rmse, 1e-9);
    ASSERT_EQ(r.correspondence_set.size(), source.size());
    for (size_t i = 0; i < source.size(); ++i) EXPECT_EQ(r.correspondence_set[i], Eigen::Vector2i(i, i));
}

TEST(RegistrationIcp, PointToPlaneRecoversKnownMotionExactly) {
    const PointCloud target = height_field(3000);
    const PointCloud source = transformed(target, kMotion.inverse());
    const auto r = reg::registration_icp(source, target, 0.2, Eigen::Matrix4d::Identity(),
                                         tight(reg::Estimation::PointToPlane));
    EXPECT_LT((r.transformation - kMotion).cwiseAbs().maxCoeff(), 1e-9);
    EXPECT_DOUBLE_EQ(r.fitness, 1.0);
    EXPECT_LT(r.inlier_rmse, 1e-9);
}

TEST(RegistrationIcp, StartsFromInit) {
    // Started at the answer, one iteration must keep it (and report zero error).
    const PointCloud target = height_field(1200);
    const PointCloud source = transformed(target, kMotion.inverse());
    const auto r = reg::registration_icp(source, target, 0.05, kMotion, tight(reg::Estimation::PointToPoint, 1));
    EXPECT_LT((r.transformation - kMotion).cwiseAbs().maxCoeff(), 1e-12);
    EXPECT_LT(r.inlier_rmse, 1e-12);
}

TEST(RegistrationIcp, ZeroIterationsOnlyScoresInit) {
    const PointCloud target = height_field(1200);
    const PointCloud source = transformed(target, kMotion.inverse());
    const auto r = reg::registration_icp(source, target, 0.2, Eigen::Matrix4d::Identity(),
                                         tight(reg::Estimation::PointToPoint, 0));
    const auto e = reg::evaluate_registration(source, target, 0.2);
    EXPECT_TRUE(bitwise_equal(r, e));
}

TEST(RegistrationIcp, WithScalingRecoversKnownScale) {
    const double scale = 1.07;
    const Eigen::Matrix4d motion = rigid(4.0, {1.0, 0.2, -0.4}, {0.02, 0.01, -0.03}, scale);
    const PointCloud target = height_field(3000);
    const PointCloud source = transformed(target, motion.inverse());
    auto options = tight(reg::Estimation::PointToPoint, 200);
    options.with_scaling = true;
    const auto r = reg::registration_icp(source, target, 0.2, Eigen::Matrix4d::Identity(), options);
    EXPECT_LT((r.transformation - motion).cwiseAbs().maxCoeff(), 1e-9);
    EXPECT_NEAR(std::cbrt(r.transformation.topLeftCorner<3, 3>().determinant()), scale, 1e-12);
    // Without scaling the same pair cannot be fitted exactly.
    const auto rigid_only =
        reg::registration_icp(source, target, 0.2, Eigen::Matrix4d::Identity(), tight(reg::Estimation::PointToPoint, 30));
    EXPECT_GT(rigid_only.inlier_rmse, 1e-3);
}

TEST(RegistrationIcp, ProgressReportsEachIterationAndCancels) {
    const PointCloud target = height_field(1200);
    const PointCloud source = transformed(target, kMotion.inverse());
    auto options = tight(reg::Estimation::PointToPoint, 50);
    std::vector<double> seen;
    options.progress = [&](double f) {
        seen.push_back(f);
        return seen.size() < 3;
    };
    EXPECT_THROW(reg::registration_icp(source, target, 0.2, Eigen::Matrix4d::Identity(), options), o3d::Cancelled);
    ASSERT_EQ(seen.size(), 3u);
    EXPECT_DOUBLE_EQ(seen[0], 1.0 / 50);
    EXPECT_DOUBLE_EQ(seen[2], 3.0 / 50);
}

TEST(RegistrationIcp, ProgressReachesOneWhenAllIterationsRun) {
    const PointCloud target = height_field(1200);
    const PointCloud source = transformed(target, kMotion.inverse());
    auto options = tight(reg::Estimation::PointToPlane, 4);
    std::vector<double> seen;
    options.progress = [&](double f) {
        seen.push_back(f);
        return true;
    };
    reg::registration_icp(source, target, 0.2, Eigen::Matrix4d::Identity(), options);
    EXPECT_EQ(seen, (std::vector<double>{0.25, 0.5, 0.75, 1.0}));
}

TEST(RegistrationIcp, BitwiseIdenticalForOneAndTwoThreads) {
    // Noisy, partial overlap, several reduction blocks: the sums are long and their order matters.
    PointCloud target = height_field(6000);
    PointCloud source = transformed(height_field(5000), kMotion.inverse());
    for (size_t i = 0; i < source.size(); ++i) source.points[i].z() += 1e-3 * std::sin(12.9898 * i);
    for (auto estimation : {reg::Estimation::PointToPoint, reg::Estimation::PointToPlane}) {
        auto options = tight(estimation, 30);
        options.num_threads = 1;
        const auto one = reg::registration_icp(source, target, 0.1, Eigen::Matrix4d::Identity(), options);
        options.num_threads = 2;
        const auto two = reg::registration_icp(source, target, 0.1, Eigen::Matrix4d::Identity(), options);
        EXPECT_GT(one.fitness, 0.5);
        EXPECT_TRUE(bitwise_equal(one, two)) << "estimation " << static_cast<int>(estimation);
    }
    const auto e1 = reg::evaluate_registration(source, target, 0.1, kMotion, 1);
    const auto e2 = reg::evaluate_registration(source, target, 0.1, kMotion, 2);
    EXPECT_TRUE(bitwise_equal(e1, e2));
    const auto i1 = reg::get_information_matrix_from_point_clouds(source, target, 0.1, kMotion, 1);
    const auto i2 = reg::get_information_matrix_from_point_clouds(source, target, 0.1, kMotion, 2);
    EXPECT_EQ(std::memcmp(i1.data(), i2.data(), sizeof(double) * 36), 0);
}

TEST(RegistrationIcp, SkipsNonFiniteSourcePoints) {
    const PointCloud target = height_field(1200);
    PointCloud source = transformed(target, kMotion.inverse());
    source.points[7] = Eigen::Vector3d(std::nan(""), 0.0, 0.0);
    source.points[9] = Eigen::Vector3d(0.0, std::numeric_limits<double>::infinity(), 0.0);
    const auto r = reg::registration_icp(source, target, 0.2, Eigen::Matrix4d::Identity(),
                                         tight(reg::Estimation::PointToPoint));
    EXPECT_LT((r.transformation - kMotion).cwiseAbs().maxCoeff(), 1e-9);
    EXPECT_DOUBLE_EQ(r.fitness, (source.size() - 2.0) / source.size());
}

TEST(RegistrationIcp, RejectsInvalidArguments) {
    const PointCloud target = height_field(100);
    const PointCloud source = target;
    const Eigen::Matrix4d id = Eigen::Matrix4d::Identity();
    const double nan = std::nan("");
    EXPECT_THROW(reg::registration_icp(PointCloud{}, target, 0.1), o3d::InvalidArgument);
    EXPECT_THROW(reg::registration_icp(source, PointCloud{}, 0.1), o3d::InvalidArgument);
    EXPECT_THROW(reg::registration_icp(source, target, 0.0), o3d::InvalidArgument);
    EXPECT_THROW(reg::registration_icp(source, target, -1.0), o3d::InvalidArgument);
    EXPECT_THROW(reg::registration_icp(source, target, nan), o3d::InvalidArgument);
    Eigen::Matrix4d bad = id;
    bad(1, 3) = std::numeric_limits<double>::infinity();
    EXPECT_THROW(reg::registration_icp(source, target, 0.1, bad), o3d::InvalidArgument);
    reg::IcpOptions o;
    o.criteria.max_iteration = -1;
    EXPECT_THROW(reg::registration_icp(source, target, 0.1, id, o), o3d::InvalidArgument);
    o = {};
    o.criteria.relative_rmse = nan;
    EXPECT_THROW(reg::registration_icp(source, target, 0.1, id, o), o3d::InvalidArgument);
    o = {};
    o.num_threads = -2;
    EXPECT_THROW(reg::registration_icp(source, target, 0.1, id, o), o3d::InvalidArgument);
    o = {};
    o.estimation = reg::Estimation::PointToPlane;
    PointCloud no_normals = target;
    no_normals.normals.clear();
    EXPECT_THROW(reg::registration_icp(source, no_normals, 0.1, id, o), o3d::InvalidArgument);
    EXPECT_THROW(reg::evaluate_registration(source, target, nan), o3d::InvalidArgument);
    EXPECT_THROW(reg::evaluate_registration(PointCloud{}, target, 0.1), o3d::InvalidArgument);
    EXPECT_THROW(reg::get_information_matrix_from_point_clouds(source, target, -0.1), o3d::InvalidArgument);
    EXPECT_THROW(reg::get_information_matrix_from_point_clouds(source, PointCloud{}, 0.1), o3d::InvalidArgument);
}

TEST(RegistrationEstimation, ClosedFormFitsGivenCorrespondences) {
    const PointCloud target = height_field(300);
    const PointCloud source = transformed(target, kMotion.inverse());
    reg::CorrespondenceSet corres;
    for (int i = 0; i < static_cast<int>(source.size()); i += 3) corres.emplace_back(i, i);
    EXPECT_LT((reg::estimate_point_to_point(source, target, corres) - kMotion).cwiseAbs().maxCoeff(), 1e-12);
    EXPECT_TRUE(reg::estimate_point_to_point(source, target, {}).isIdentity());
    EXPECT_TRUE(reg::estimate_point_to_plane(source, target, {}).isIdentity());
    // One linearised step from 6 degrees away lands within the second-order error of the answer.
    const Eigen::Matrix4d step = reg::estimate_point_to_plane(source, target, corres);
    EXPECT_LT((step - kMotion).cwiseAbs().maxCoeff(), 1e-2);
    EXPECT_GT((step - kMotion).cwiseAbs().maxCoeff(), 1e-9);
    EXPECT_THROW(reg::estimate_point_to_point(source, target, {Eigen::Vector2i(0, 100000)}), o3d::InvalidArgument);
    EXPECT_THROW(reg::estimate_point_to_plane(source, target, {Eigen::Vector2i(-1, 0)}), o3d::InvalidArgument);
}

TEST(RegistrationEvaluate, HandBuiltPairs) {
    PointCloud target;
    target.points = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
    PointCloud source;
    source.points = {{0, 0, 0.1}, {1, 0, 0.2}, {5, 5, 5}, {0, 1, 0.6}};
    const auto r = reg::evaluate_registration(source, target, 0.5);
    EXPECT_DOUBLE_EQ(r.fitness, 2.0 / 4.0);
    EXPECT_DOUBLE_EQ(r.inlier_rmse, std::sqrt((0.01 + 0.04) / 2.0));
    EXPECT_EQ(r.correspondence_set, (reg::CorrespondenceSet{{0, 0}, {1, 1}}));
    EXPECT_TRUE(r.transformation.isIdentity());

    // Moving the source down by 0.3 brings the fourth point in and the first two to 0.2 and 0.1.
    Eigen::Matrix4d down = Eigen::Matrix4d::Identity();
    down(2, 3) = -0.3;
    const auto moved = reg::evaluate_registration(source, target, 0.5, down);
    EXPECT_DOUBLE_EQ(moved.fitness, 3.0 / 4.0);
    EXPECT_NEAR(moved.inlier_rmse, std::sqrt((0.04 + 0.01 + 0.09) / 3.0), 1e-15);
    EXPECT_EQ(moved.correspondence_set, (reg::CorrespondenceSet{{0, 0}, {1, 1}, {3, 2}}));
    EXPECT_EQ(moved.transformation, down);

    const auto none = reg::evaluate_registration(source, target, 0.05);
    EXPECT_EQ(none.fitness, 0.0);
    EXPECT_EQ(none.inlier_rmse, 0.0);
    EXPECT_TRUE(none.correspondence_set.empty());
}

TEST(RegistrationInformationMatrix, MatchesDirectSumOverPairs) {
    PointCloud target;
    target.points = {{0.5, -1.0, 2.0}, {1.5, 0.25, -0.75}, {-2.0, 3.0, 1.0}};
    PointCloud source;
    // Pairs 0->0 and 2->2; source 1 is out of range and must not contribute.
    source.points = {{0.5, -1.0, 2.05}, {9.0, 9.0, 9.0}, {-2.0, 3.02, 1.0}};
    const auto info = reg::get_information_matrix_from_point_clouds(source, target, 0.1);

    Eigen::Matrix<double, 6, 6> expected = Eigen::Matrix<double, 6, 6>::Zero();
    for (int t : {0, 2}) {
        const Eigen::Vector3d q = target.points[t];
        // Jacobian of q under (small rotation w, translation u): q + w x q + u = q - [q]x w + u.
        Eigen::Matrix<double, 3, 6> g;
        Eigen::Matrix3d skew;
        skew << 0, -q.z(), q.y(), q.z(), 0, -q.x(), -q.y(), q.x(), 0;
        g << -skew, Eigen::Matrix3d::Identity();
        expected += g.transpose() * g;
    }
    EXPECT_LT((info - expected).cwiseAbs().maxCoeff(), 1e-12);
    EXPECT_EQ(info(3, 3), 2.0);

    // With a transformation, pairs follow the moved source (here nothing lands in range).
    Eigen::Matrix4d far = Eigen::Matrix4d::Identity();
    far(0, 3) = 10.0;
    EXPECT_TRUE(reg::get_information_matrix_from_point_clouds(source, target, 0.1, far).isZero());
}
