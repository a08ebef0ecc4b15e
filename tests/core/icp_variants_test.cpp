// SPDX-License-Identifier: MIT
// Colored, generalized and symmetric ICP and robust kernels: known motions recovered on synthetic and real
// scans, outliers resisted, single steps against independent formulas, determinism and argument checks.
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <vector>

#include "o3d/geometry/down_sample.h"
#include "o3d/geometry/point_cloud_ops.h"
#include "o3d/io/point_cloud_io.h"
#include "o3d/kdtree/kd_tree.h"
#include "o3d/registration/estimation_colored.h"
#include "o3d/registration/estimation_generalized.h"
#include "o3d/registration/estimation_point_to_plane.h"
#include "o3d/registration/estimation_symmetric.h"
#include "o3d/registration/evaluation.h"
#include "o3d/registration/icp.h"
#include "o3d/utility/error.h"
#include "test_data.h"

namespace reg = o3d::registration;
using o3d::geometry::PointCloud;
using Kind = reg::RobustKernelType;

namespace {

/// splitmix64: a portable generator, so the outliers are the same with every standard library.
struct SplitMix {
    uint64_t state;
    uint64_t next() {
        uint64_t z = (state += 0x9E3779B97F4A7C15ull);
        z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
        z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
        return z ^ (z >> 31);
    }
    double uniform() { return static_cast<double>(next() >> 11) * 0x1.0p-53; }
};

Eigen::Matrix4d rigid(double degrees, const Eigen::Vector3d& axis, const Eigen::Vector3d& t,
                      const Eigen::Vector3d& pivot = Eigen::Vector3d::Zero()) {
    Eigen::Matrix4d m = Eigen::Matrix4d::Identity();
    const Eigen::Matrix3d r = Eigen::AngleAxisd(degrees * M_PI / 180.0, axis.normalized()).toRotationMatrix();
    m.topLeftCorner<3, 3>() = r;
    m.topRightCorner<3, 1>() = pivot - r * pivot + t;
    return m;
}

PointCloud moved(const PointCloud& pc, const Eigen::Matrix4d& m) {
    PointCloud out = pc;
    o3d::geometry::transform(out, m);
    return out;
}

double angle_degrees(const Eigen::Matrix4d& a, const Eigen::Matrix4d& b) {
    const Eigen::Matrix3d d = a.topLeftCorner<3, 3>().transpose() * b.topLeftCorner<3, 3>();
    return Eigen::AngleAxisd(d).angle() * 180.0 / M_PI;
}

double offset(const Eigen::Matrix4d& a, const Eigen::Matrix4d& b) {
    return (a.topRightCorner<3, 1>() - b.topRightCorner<3, 1>()).norm();
}

reg::IcpOptions options_for(reg::Estimation e, reg::RobustKernel kernel = {}, int max_iteration = 60) {
    reg::IcpOptions o;
    o.estimation = e;
    o.kernel = kernel;
    o.criteria.relative_fitness = 1e-10;
    o.criteria.relative_rmse = 1e-10;
    o.criteria.max_iteration = max_iteration;
    return o;
}

bool bitwise_equal(const reg::RegistrationResult& a, const reg::RegistrationResult& b) {
    return std::memcmp(a.transformation.data(), b.transformation.data(), sizeof(double) * 16) == 0 &&
           std::memcmp(&a.fitness, &b.fitness, sizeof(double)) == 0 &&
           std::memcmp(&a.inlier_rmse, &b.inlier_rmse, sizeof(double)) == 0 &&
           a.correspondence_set == b.correspondence_set;
}

/// A flat, textured square: z = 0, normals +z, intensity a smooth non-periodic pattern of (x, y).
/// Geometry alone cannot fix the in-plane motion; only the colors can.
PointCloud textured_plane(int n, const Eigen::Vector2d& shift = Eigen::Vector2d::Zero()) {
    PointCloud pc;
    for (int k = 0; k < n; ++k) {
        // `shift` moves the samples, not the pattern: a second scan of the same textured surface.
        const double x = -0.5 + std::fmod(0.5 + k * 0.7548776662466927, 1.0) + shift(0);
        const double y = -0.5 + std::fmod(0.5 + k * 0.5698402909980532, 1.0) + shift(1);
        pc.points.emplace_back(x, y, 0.0);
        pc.normals.emplace_back(0.0, 0.0, 1.0);
        const double i = 0.5 + 0.25 * std::sin(7.0 * x + 2.0) * std::cos(5.0 * y - 1.0) + 0.2 * x * y;
        pc.colors.emplace_back(i, 0.8 * i, 1.2 * i);
    }
    return pc;
}

/// A smooth asymmetric height field with exact normals and a color pattern.
PointCloud height_field(int n) {
    PointCloud pc;
    for (int k = 0; k < n; ++k) {
        const double x = -1.0 + 2.0 * std::fmod(0.5 + k * 0.7548776662466927, 1.0);
        const double y = -0.7 + 1.9 * std::fmod(0.5 + k * 0.5698402909980532, 1.0);
        const double z = 0.3 * std::sin(2.0 * x) + 0.2 * std::cos(3.0 * y) + 0.15 * x * y + 0.1 * x * x;
        const double fx = 0.6 * std::cos(2.0 * x) + 0.15 * y + 0.2 * x;
        const double fy = -0.6 * std::sin(3.0 * y) + 0.15 * x;
        pc.points.emplace_back(x, y, z);
        pc.normals.push_back(Eigen::Vector3d(-fx, -fy, 1.0).normalized());
        const double i = 0.5 + 0.3 * std::sin(4.0 * x) * std::cos(3.0 * y);
        pc.colors.emplace_back(i, i, i);
    }
    return pc;
}

}  // namespace

// ---------------------------------------------------------------------------------------------------
// Synthetic: exact answers.

TEST(IcpVariants, ColoredIcpFixesInPlaneMotionThatGeometryCannot) {
    const PointCloud target = textured_plane(6000);
    // 2 degrees about z and (2 cm, -1.5 cm) in the plane: invisible to the plane's geometry.
    const Eigen::Matrix4d motion = rigid(2.0, Eigen::Vector3d::UnitZ(), {0.02, -0.015, 0.0});
    const PointCloud source = moved(textured_plane(5000, {0.003, 0.001}), motion.inverse());

    reg::IcpOptions colored = options_for(reg::Estimation::Colored);
    const auto c = reg::registration_icp(source, target, 0.05, Eigen::Matrix4d::Identity(), colored);
    const auto p = reg::registration_icp(source, target, 0.05, Eigen::Matrix4d::Identity(),
                                         options_for(reg::Estimation::PointToPlane));
    // Measured: colored 0.001 deg / 0.04 mm; point-to-plane stays at the start (2 deg / 25 mm).
    EXPECT_LT(angle_degrees(c.transformation, motion), 0.1);
    EXPECT_LT(offset(c.transformation, motion), 0.002);
    // Point-to-plane has nothing to pull it along the plane and stays near the start.
    EXPECT_GT(offset(p.transformation, motion), 0.02);
}

// The source is the target's own points moved by motion^-1, so every estimation's minimum is exactly `motion`.
TEST(IcpVariants, EveryEstimationRecoversKnownMotionExactly) {
    const PointCloud target = height_field(4000);
    const Eigen::Matrix4d motion = rigid(5.0, {0.3, -0.5, 1.0}, {0.03, -0.02, 0.01});
    const PointCloud source = moved(target, motion.inverse());
    for (auto e : {reg::Estimation::Colored, reg::Estimation::Generalized, reg::Estimation::Symmetric}) {
        for (auto kernel : {reg::RobustKernel{}, reg::RobustKernel{Kind::Tukey, 0.05}}) {
            SCOPED_TRACE(static_cast<int>(e) * 10 + static_cast<int>(kernel.type));
            const auto r =
                reg::registration_icp(source, target, 0.2, Eigen::Matrix4d::Identity(), options_for(e, kernel));
            EXPECT_LT((r.transformation - motion).cwiseAbs().maxCoeff(), 1e-7);
            EXPECT_DOUBLE_EQ(r.fitness, 1.0);
            EXPECT_LT(r.inlier_rmse, 1e-7);
        }
    }
}

// The colored gradient of a linear intensity I = a x + b y + c on the plane z = 0 is exactly (a, b, 0).
TEST(IcpVariants, ColorGradientOfLinearIntensityIsExact) {
    PointCloud pc;
    for (int k = 0; k < 2000; ++k) {
        const double x = std::fmod(0.5 + k * 0.7548776662466927, 1.0), y = std::fmod(0.5 + k * 0.5698402909980532, 1.0);
        pc.points.emplace_back(x, y, 0.0);
        pc.normals.emplace_back(0.0, 0.0, 1.0);
        const double i = 0.2 + 0.3 * x - 0.1 * y;
        pc.colors.emplace_back(i - 0.05, i, i + 0.05);  // mean of R, G, B is i
    }
    // Tilt the whole plane: the gradient must turn with it and stay in the plane.
    const Eigen::Matrix4d tilt = rigid(30.0, {1.0, 1.0, 0.0}, {0.5, 0.0, -0.2});
    const PointCloud tilted = moved(pc, tilt);
    const o3d::kdtree::KDTree tree(tilted.points);
    const auto gradients = reg::compute_color_gradients(tilted, tree, 0.06, 30, 1);
    const Eigen::Vector3d expected = tilt.topLeftCorner<3, 3>() * Eigen::Vector3d(0.3, -0.1, 0.0);
    for (size_t i = 0; i < gradients.size(); ++i) ASSERT_LT((gradients[i] - expected).norm(), 1e-9) << i;
    // Fewer than four neighbours: no gradient.
    const auto sparse = reg::compute_color_gradients(tilted, tree, 1e-6, 30, 1);
    for (const auto& g : sparse) ASSERT_TRUE(g.isZero());
    EXPECT_EQ(reg::color_intensities({Eigen::Vector3d(0.3, 0.6, 0.9)})[0], 0.6);
    EXPECT_THROW(reg::compute_color_gradients(tilted, tree, 0.0, 30), o3d::InvalidArgument);
    EXPECT_THROW(reg::compute_color_gradients(tilted, tree, 0.1, 0), o3d::InvalidArgument);
    PointCloud no_colors = tilted;
    no_colors.colors.clear();
    EXPECT_THROW(reg::compute_color_gradients(no_colors, tree, 0.1, 30), o3d::InvalidArgument);
    const o3d::kdtree::KDTree other(height_field(10).points);
    EXPECT_THROW(reg::compute_color_gradients(tilted, other, 0.1, 30), o3d::InvalidArgument);
}

TEST(IcpVariants, GeneralizedCovariancesFromNormalsPointsOrCloud) {
    const PointCloud field = height_field(3000);
    const double eps = 1e-3;
    const auto from_normals = reg::generalized_icp_covariances(field, eps);
    ASSERT_EQ(from_normals.size(), field.size());
    for (size_t i = 0; i < field.size(); i += 97) {
        const Eigen::Vector3d& n = field.normals[i];
        // Variance epsilon along the normal, 1 across it, and a flipped normal changes nothing.
        EXPECT_NEAR(n.dot(from_normals[i] * n), eps, 1e-12);
        const Eigen::Vector3d t = n.cross(Eigen::Vector3d::UnitX()).normalized();
        EXPECT_NEAR(t.dot(from_normals[i] * t), 1.0, 1e-12);
        EXPECT_LT((from_normals[i] * n - eps * n).norm(), 1e-12);
    }
    // Bare points: normals from 20 neighbours, so on a smooth surface nearly the same matrices (the
    // one-sided neighbourhoods at the border tilt a few normals by up to ~8 degrees).
    PointCloud bare;
    bare.points = field.points;
    const auto from_points = reg::generalized_icp_covariances(bare, eps);
    double mean = 0.0;
    for (size_t i = 0; i < field.size(); ++i) {
        mean += (from_points[i] - from_normals[i]).norm();
        ASSERT_NEAR(from_points[i].trace(), 2.0 + eps, 1e-12);  // still plane-like: eigenvalues (eps, 1, 1)
    }
    mean /= static_cast<double>(field.size());
    EXPECT_LT(mean, 0.03);  // measured 0.0136; raw neighbourhood covariances would be ~1.4 away
    // A cloud's own covariances win.
    PointCloud with_cov = field;
    with_cov.covariances.assign(field.size(), 2.0 * Eigen::Matrix3d::Identity());
    EXPECT_EQ(reg::generalized_icp_covariances(with_cov, eps)[5], 2.0 * Eigen::Matrix3d::Identity());
    for (double bad : {0.0, -1e-3, std::nan(""), std::numeric_limits<double>::infinity()})
        EXPECT_THROW(reg::generalized_icp_covariances(field, bad), o3d::InvalidArgument) << bad;
}

// ---------------------------------------------------------------------------------------------------
// One step against independent formulas (the loop folds its sums into the correspondence pass).

namespace {

/// ICP with one iteration from `init` must equal init composed with `step` fitted to evaluate_registration's pairs.
reg::CorrespondenceSet pairs_at(const PointCloud& source, const PointCloud& target, double gate) {
    return reg::evaluate_registration(source, target, gate).correspondence_set;
}

reg::IcpOptions one_step(reg::Estimation e, reg::RobustKernel kernel = {}) {
    reg::IcpOptions o = options_for(e, kernel, 1);
    return o;
}

Eigen::Matrix4d euler(const Eigen::Matrix<double, 6, 1>& x) {
    Eigen::Matrix4d m = Eigen::Matrix4d::Identity();
    m.topLeftCorner<3, 3>() = (Eigen::AngleAxisd(x(2), Eigen::Vector3d::UnitZ()) *
                               Eigen::AngleAxisd(x(1), Eigen::Vector3d::UnitY()) *
                               Eigen::AngleAxisd(x(0), Eigen::Vector3d::UnitX()))
                                  .toRotationMatrix();
    m.topRightCorner<3, 1>() = x.tail<3>();
    return m;
}

}  // namespace

// Open3D's formulation, written out directly: centre the pairs, one row per pair, a dense 6x6 solve.
TEST(IcpVariants, SymmetricStepMatchesDirectCentredFormulation) {
    const PointCloud target = height_field(3000);
    const Eigen::Matrix4d motion = rigid(4.0, {1.0, 0.2, -0.4}, {0.02, 0.01, -0.03});
    const PointCloud source = moved(height_field(2500), motion.inverse());
    const auto corres = pairs_at(source, target, 0.1);
    ASSERT_GT(corres.size(), 2000u);
    for (auto kernel : {reg::RobustKernel{}, reg::RobustKernel{Kind::Cauchy, 0.01}}) {
        Eigen::Vector3d sm = Eigen::Vector3d::Zero(), tm = Eigen::Vector3d::Zero();
        for (const auto& c : corres) {
            sm += source.points[c(0)];
            tm += target.points[c(1)];
        }
        sm /= static_cast<double>(corres.size());
        tm /= static_cast<double>(corres.size());
        Eigen::Matrix<double, 6, 6> jtj = Eigen::Matrix<double, 6, 6>::Zero();
        Eigen::Matrix<double, 6, 1> jtr = Eigen::Matrix<double, 6, 1>::Zero();
        for (const auto& c : corres) {
            const Eigen::Vector3d &s = source.points[c(0)], &q = target.points[c(1)];
            const Eigen::Vector3d &ns = source.normals[c(0)], &nq = target.normals[c(1)];
            const Eigen::Vector3d n = ns.dot(nq) < 0 ? Eigen::Vector3d(nq - ns) : Eigen::Vector3d(nq + ns);
            Eigen::Matrix<double, 6, 1> j;
            j << ((s - sm) + (q - tm)).cross(n), n;
            const double w = kernel.weight((s - q).dot(n));
            jtj += w * j * j.transpose();
            jtr += w * j * ((s - sm) - (q - tm)).dot(n);
        }
        const Eigen::Matrix<double, 6, 1> x = jtj.ldlt().solve(-jtr);
        const double theta = std::atan(x.head<3>().norm());
        const Eigen::Matrix3d half = Eigen::AngleAxisd(theta, x.head<3>().normalized()).toRotationMatrix();
        Eigen::Matrix4d expected = Eigen::Matrix4d::Identity();
        expected.topLeftCorner<3, 3>() = half * half;
        expected.topRightCorner<3, 1>() = tm + half * (x.tail<3>() * std::cos(theta)) - half * half * sm;

        EXPECT_LT((reg::estimate_symmetric(source, target, corres, kernel) - expected).cwiseAbs().maxCoeff(), 1e-12);
        const auto r = reg::registration_icp(source, target, 0.1, Eigen::Matrix4d::Identity(),
                                             one_step(reg::Estimation::Symmetric, kernel));
        EXPECT_LT((r.transformation - expected).cwiseAbs().maxCoeff(), 1e-12);
    }
}

// J^T (C_q + C_s)^-1 J summed directly, with J = [-[s]x, I]; and the robust path (rows of C^-1/2, each
// weighted on its own) with a kernel whose weight is 1 everywhere.
TEST(IcpVariants, GeneralizedStepMatchesMahalanobisNormalEquations) {
    PointCloud target = height_field(3000);
    PointCloud source = moved(height_field(2500), rigid(3.0, {0.0, 1.0, 0.5}, {0.01, -0.02, 0.0}));
    target.covariances = reg::generalized_icp_covariances(target, 1e-3);
    source.covariances = reg::generalized_icp_covariances(source, 1e-3);
    const auto corres = pairs_at(source, target, 0.1);
    Eigen::Matrix<double, 6, 6> jtj = Eigen::Matrix<double, 6, 6>::Zero();
    Eigen::Matrix<double, 6, 1> jtr = Eigen::Matrix<double, 6, 1>::Zero();
    for (const auto& c : corres) {
        const Eigen::Vector3d& s = source.points[c(0)];
        const Eigen::Matrix3d a = (source.covariances[c(0)] + target.covariances[c(1)]).inverse();
        Eigen::Matrix<double, 3, 6> j;
        Eigen::Matrix3d skew;
        skew << 0, -s(2), s(1), s(2), 0, -s(0), -s(1), s(0), 0;
        j << -skew, Eigen::Matrix3d::Identity();
        jtj += j.transpose() * a * j;
        jtr += j.transpose() * a * (s - target.points[c(1)]);
    }
    const Eigen::Matrix4d expected = euler(jtj.ldlt().solve(-jtr));
    EXPECT_LT((reg::estimate_generalized(source, target, corres) - expected).cwiseAbs().maxCoeff(), 1e-11);
    const reg::RobustKernel flat{Kind::Huber, 1e300};  // weight 1 for every residual
    EXPECT_LT((reg::estimate_generalized(source, target, corres, flat) - expected).cwiseAbs().maxCoeff(), 1e-9);
    // The loop rotates the source covariances itself; from identity it takes the same first step.
    reg::IcpOptions o = one_step(reg::Estimation::Generalized);
    const auto r = reg::registration_icp(source, target, 0.1, Eigen::Matrix4d::Identity(), o);
    EXPECT_LT((r.transformation - expected).cwiseAbs().maxCoeff(), 1e-11);
}

// Colored ICP's step with lambda = 1 has no photometric rows: exactly point-to-plane.
TEST(IcpVariants, ColoredStepReducesToPointToPlane) {
    const PointCloud target = height_field(3000);
    const PointCloud source = moved(height_field(2500), rigid(3.0, {0.0, 1.0, 0.5}, {0.01, -0.02, 0.0}));
    const auto corres = pairs_at(source, target, 0.1);
    const o3d::kdtree::KDTree tree(target.points);
    const auto gradients = reg::compute_color_gradients(target, tree, 0.2, 30);
    const reg::RobustKernel tukey{Kind::Tukey, 0.02};
    EXPECT_EQ(reg::estimate_colored(source, target, gradients, corres, 1.0, tukey),
              reg::estimate_point_to_plane(source, target, corres, tukey));
    // With the photometric term the step differs, and the loop's first step is the same as the standalone one.
    const Eigen::Matrix4d step = reg::estimate_colored(source, target, gradients, corres, 0.5);
    EXPECT_GT((step - reg::estimate_point_to_plane(source, target, corres)).cwiseAbs().maxCoeff(), 1e-6);
    reg::IcpOptions o = one_step(reg::Estimation::Colored);
    o.lambda_geometric = 0.5;
    EXPECT_LT((reg::registration_icp(source, target, 0.1, Eigen::Matrix4d::Identity(), o).transformation - step)
                  .cwiseAbs()
                  .maxCoeff(),
              1e-12);
    // The residual Open3D calls ComputeRMSE: a plain sum of lambda r_G^2 + (1 - lambda) r_C^2.
    double geometric = 0.0;
    for (const auto& c : corres) {
        const double r = (source.points[c(0)] - target.points[c(1)]).dot(target.normals[c(1)]);
        geometric += r * r;
    }
    EXPECT_NEAR(reg::colored_residual(source, target, gradients, corres, 1.0), geometric, 1e-12 * geometric);
    EXPECT_GT(reg::colored_residual(source, target, gradients, corres, 0.5), 0.0);
}

// A robust kernel reweighs point-to-plane rows: the same pairs with one pushed far off get a different step
// under L2, nearly the clean one under Tukey.
TEST(IcpVariants, PointToPlaneKernelDownweightsOutlierPair) {
    const PointCloud target = height_field(3000);
    PointCloud source = moved(height_field(2500), rigid(1.0, {0.0, 1.0, 0.5}, {0.005, -0.002, 0.0}));
    const auto corres = pairs_at(source, target, 0.1);
    const reg::RobustKernel tukey{Kind::Tukey, 0.02};
    const Eigen::Matrix4d clean = reg::estimate_point_to_plane(source, target, corres, tukey);
    for (size_t k = 0; k < 100; ++k) source.points[static_cast<size_t>(corres[k](0))] += Eigen::Vector3d(0, 0, 0.5);
    EXPECT_GT((reg::estimate_point_to_plane(source, target, corres) - clean).cwiseAbs().maxCoeff(), 1e-3);
    EXPECT_LT((reg::estimate_point_to_plane(source, target, corres, tukey) - clean).cwiseAbs().maxCoeff(), 1e-4);
}

// ---------------------------------------------------------------------------------------------------
// Determinism, cancellation and argument checks.

TEST(IcpVariants, ResultsDoNotDependOnThreadCount) {
    const PointCloud target = height_field(6000);
    const PointCloud source = moved(height_field(5000), rigid(4.0, {0.3, -0.5, 1.0}, {0.02, -0.01, 0.02}));
    PointCloud bare_source, bare_target;  // generalized ICP estimates its covariances (in parallel)
    bare_source.points = source.points;
    bare_target.points = target.points;
    for (auto e : {reg::Estimation::PointToPlane, reg::Estimation::Colored, reg::Estimation::Generalized,
                   reg::Estimation::Symmetric}) {
        for (auto kernel : {reg::RobustKernel{}, reg::RobustKernel{Kind::Huber, 0.01}}) {
            SCOPED_TRACE(static_cast<int>(e) * 10 + static_cast<int>(kernel.type));
            const bool bare = e == reg::Estimation::Generalized;
            const PointCloud& s = bare ? bare_source : source;
            const PointCloud& t = bare ? bare_target : target;
            reg::IcpOptions o = options_for(e, kernel, 15);
            o.num_threads = 1;
            const auto one = reg::registration_icp(s, t, 0.1, Eigen::Matrix4d::Identity(), o);
            o.num_threads = 2;
            const auto two = reg::registration_icp(s, t, 0.1, Eigen::Matrix4d::Identity(), o);
            o.num_threads = 3;
            const auto three = reg::registration_icp(s, t, 0.1, Eigen::Matrix4d::Identity(), o);
            EXPECT_TRUE(bitwise_equal(one, two));
            EXPECT_TRUE(bitwise_equal(one, three));
        }
    }
}

TEST(IcpVariants, ProgressCanCancelEveryEstimation) {
    const PointCloud target = height_field(1000);
    const PointCloud source = moved(target, rigid(3.0, {0.0, 0.0, 1.0}, {0.01, 0.0, 0.0}));
    for (auto e : {reg::Estimation::Colored, reg::Estimation::Generalized, reg::Estimation::Symmetric}) {
        reg::IcpOptions o = options_for(e);
        int calls = 0;
        o.progress = [&](double) { return ++calls < 2; };
        EXPECT_THROW(reg::registration_icp(source, target, 0.1, Eigen::Matrix4d::Identity(), o), o3d::Cancelled);
        EXPECT_EQ(calls, 2);
    }
}

TEST(IcpVariants, RejectsMissingAttributesAndBadOptions) {
    const PointCloud full = height_field(500);
    PointCloud no_colors = full, no_normals = full;
    no_colors.colors.clear();
    no_normals.normals.clear();
    const auto icp = [](const PointCloud& s, const PointCloud& t, const reg::IcpOptions& o) {
        return reg::registration_icp(s, t, 0.1, Eigen::Matrix4d::Identity(), o);
    };
    const reg::IcpOptions colored = options_for(reg::Estimation::Colored);
    EXPECT_THROW(icp(no_colors, full, colored), o3d::InvalidArgument);
    EXPECT_THROW(icp(full, no_colors, colored), o3d::InvalidArgument);
    EXPECT_THROW(icp(full, no_normals, colored), o3d::InvalidArgument);
    EXPECT_NO_THROW(icp(no_normals, full, colored));  // only the target's normals are used
    const reg::IcpOptions symmetric = options_for(reg::Estimation::Symmetric);
    EXPECT_THROW(icp(no_normals, full, symmetric), o3d::InvalidArgument);
    EXPECT_THROW(icp(full, no_normals, symmetric), o3d::InvalidArgument);
    // Generalized ICP always has a way to its covariances.
    EXPECT_NO_THROW(icp(no_normals, no_normals, options_for(reg::Estimation::Generalized)));

    reg::IcpOptions o = options_for(reg::Estimation::Colored);
    for (double lambda : {-0.01, 1.01, std::nan("")}) {
        o.lambda_geometric = lambda;
        EXPECT_THROW(icp(full, full, o), o3d::InvalidArgument) << lambda;
    }
    for (double lambda : {0.0, 1.0}) {
        o.lambda_geometric = lambda;
        EXPECT_NO_THROW(icp(full, full, o)) << lambda;
    }
    o = options_for(reg::Estimation::Generalized);
    for (double eps : {0.0, -1.0, std::nan(""), std::numeric_limits<double>::infinity()}) {
        o.epsilon = eps;
        EXPECT_THROW(icp(full, full, o), o3d::InvalidArgument) << eps;
    }
    o = options_for(reg::Estimation::PointToPlane);
    for (double k : {0.0, -0.5, std::nan("")}) {
        o.kernel = {Kind::Tukey, k};
        EXPECT_THROW(icp(full, full, o), o3d::InvalidArgument) << k;
    }
    o.kernel = {static_cast<Kind>(17), 1.0};
    EXPECT_THROW(icp(full, full, o), o3d::InvalidArgument);
    o = options_for(static_cast<reg::Estimation>(9));
    EXPECT_THROW(icp(full, full, o), o3d::InvalidArgument);

    // The standalone steps check their inputs too.
    const o3d::kdtree::KDTree tree(full.points);
    const auto gradients = reg::compute_color_gradients(full, tree, 0.2, 30);
    const reg::CorrespondenceSet bad = {Eigen::Vector2i(0, 500)};
    EXPECT_THROW(reg::estimate_colored(full, full, gradients, bad), o3d::InvalidArgument);
    EXPECT_THROW(reg::estimate_colored(full, full, {}, {}), o3d::InvalidArgument);
    EXPECT_THROW(reg::estimate_colored(full, full, gradients, {}, 2.0), o3d::InvalidArgument);
    EXPECT_TRUE(reg::estimate_colored(full, full, gradients, {}).isIdentity());
    EXPECT_THROW(reg::estimate_generalized(full, full, {}), o3d::InvalidArgument);  // no covariances
    EXPECT_THROW(reg::estimate_symmetric(no_normals, full, {}), o3d::InvalidArgument);
    EXPECT_THROW(reg::estimate_symmetric(full, full, bad), o3d::InvalidArgument);
    EXPECT_TRUE(reg::estimate_symmetric(full, full, {}).isIdentity());
    EXPECT_THROW(reg::estimate_point_to_plane(full, full, {}, {Kind::GM, -1.0}), o3d::InvalidArgument);
}

// A covariance that is not positive definite (here zero) carries no information: the pair is left out
// rather than poisoning the step with an inverse of infinity.
TEST(IcpVariants, GeneralizedSkipsDegenerateCovariances) {
    PointCloud target = height_field(2000);
    PointCloud source = moved(target, rigid(2.0, {0.0, 0.0, 1.0}, {0.01, 0.0, 0.0}).inverse());
    target.covariances = reg::generalized_icp_covariances(target);
    source.covariances = reg::generalized_icp_covariances(source);
    const auto corres = pairs_at(source, target, 0.1);
    const Eigen::Matrix4d clean = reg::estimate_generalized(source, target, corres);
    PointCloud broken_source = source, broken_target = target;
    broken_source.covariances[static_cast<size_t>(corres[0](0))].setZero();
    broken_target.covariances[static_cast<size_t>(corres[0](1))].setZero();
    broken_source.covariances[static_cast<size_t>(corres[1](0))](0, 0) = std::nan("");
    for (auto kernel : {reg::RobustKernel{}, reg::RobustKernel{Kind::Cauchy, 1.0}}) {
        const Eigen::Matrix4d step = reg::estimate_generalized(broken_source, broken_target, corres, kernel);
        EXPECT_TRUE(step.allFinite());
        EXPECT_LT((step - clean).cwiseAbs().maxCoeff(), 1e-3);
        EXPECT_FALSE(step.isIdentity());
    }
}

// ---------------------------------------------------------------------------------------------------
// Real scans: a known motion between two different samplings of the same scan.

namespace {

struct RealPair {
    PointCloud source;  // fragment at voxel 0.025, moved by motion^-1
    PointCloud target;  // fragment at voxel 0.02
    Eigen::Matrix4d motion;
};

/// fragment.pcd (colors and normals) sampled twice on different voxel grids, so that no source point has
/// an exact partner; the source then moved by a known 5 degree / 3 cm motion about its centroid.
bool load_fragment_pair(RealPair& pair) {
    const std::string path = o3d::test::data_path("open3d/fragment.pcd");
    if (path.empty()) return false;
    const PointCloud fragment = o3d::io::read_point_cloud(path);
    pair.target = o3d::geometry::voxel_down_sample(fragment, 0.02);
    const PointCloud source = o3d::geometry::voxel_down_sample(fragment, 0.025);
    pair.motion = rigid(5.0, {0.2, 1.0, 0.3}, {0.02, -0.02, 0.01}, o3d::geometry::center(source));
    pair.source = moved(source, pair.motion.inverse());
    return true;
}

/// Coarse (10 cm gate) then fine (3 cm) from identity.
reg::RegistrationResult coarse_to_fine(const PointCloud& source, const PointCloud& target, reg::IcpOptions options) {
    const auto coarse = reg::registration_icp(source, target, 0.1, Eigen::Matrix4d::Identity(), options);
    return reg::registration_icp(source, target, 0.03, coarse.transformation, options);
}

}  // namespace

#define LOAD_FRAGMENT_OR_SKIP(pair)                                                            \
    RealPair pair;                                                                             \
    if (!load_fragment_pair(pair)) {                                                           \
        if (o3d::test::data_required()) FAIL() << "missing test data open3d/fragment.pcd";     \
        GTEST_SKIP() << "test data open3d/fragment.pcd not found (set O3D_TEST_DATA)";         \
    }

namespace {

/// `fraction` * source.size() points drawn uniformly in the source's bounding box (grown by 5 cm), with
/// normals and colors so that every estimation accepts them.
PointCloud with_outliers(const PointCloud& source, double fraction, uint64_t seed) {
    PointCloud out = source;
    const Eigen::Vector3d lo = o3d::geometry::min_bound(source).array() - 0.05;
    const Eigen::Vector3d hi = o3d::geometry::max_bound(source).array() + 0.05;
    SplitMix rng{seed};
    const size_t count = static_cast<size_t>(fraction * static_cast<double>(source.size()));
    for (size_t k = 0; k < count; ++k) {
        Eigen::Vector3d p, n;
        for (int a = 0; a < 3; ++a) p(a) = lo(a) + (hi(a) - lo(a)) * rng.uniform();
        for (int a = 0; a < 3; ++a) n(a) = rng.uniform() - 0.5;
        out.points.push_back(p);
        if (source.has_normals()) out.normals.push_back(n.normalized());
        if (source.has_colors()) out.colors.emplace_back(rng.uniform(), rng.uniform(), rng.uniform());
    }
    return out;
}

}  // namespace


// Measured (fragment at voxel 0.02 / 0.025, ~15.7k / 10.2k points): colored 0.0056 deg / 0.66 mm, generalized
// 0.0022 deg / 0.16 mm (0.0039 deg / 0.23 mm on bare points), symmetric 0.0061 deg / 0.38 mm, point-to-plane
// 0.0048 deg / 0.29 mm. The bounds leave a 3x margin and are far inside the 0.5 deg / 5 mm; a run that
// misses is off by degrees (the motion is 5 deg / 3 cm, up to 13 cm at the scan's ends).
TEST(IcpVariantsSharedData, RecoverKnownMotionOfRealScan) {
    LOAD_FRAGMENT_OR_SKIP(pair);
    ASSERT_TRUE(pair.source.has_colors() && pair.source.has_normals());
    for (auto e : {reg::Estimation::Colored, reg::Estimation::Generalized, reg::Estimation::Symmetric,
                   reg::Estimation::PointToPlane}) {
        SCOPED_TRACE(static_cast<int>(e));
        const auto r = coarse_to_fine(pair.source, pair.target, options_for(e));
        EXPECT_LT(angle_degrees(r.transformation, pair.motion), 0.02);
        EXPECT_LT(offset(r.transformation, pair.motion), 0.002);
        EXPECT_GT(r.fitness, 0.99);
    }
}

// Generalized ICP on bare points: covariances come from 20-neighbour normals.
TEST(IcpVariantsSharedData, GeneralizedIcpRecoversKnownMotionOfBarePoints) {
    LOAD_FRAGMENT_OR_SKIP(pair);
    PointCloud source, target;
    source.points = pair.source.points;
    target.points = pair.target.points;
    const auto r = coarse_to_fine(source, target, options_for(reg::Estimation::Generalized));
    EXPECT_LT(angle_degrees(r.transformation, pair.motion), 0.02);
    EXPECT_LT(offset(r.transformation, pair.motion), 0.002);
}

// 30% of the source's point count added as uniform random points (in the bounding box grown by 5 cm) and a
// wide 0.2 m gate that lets many of them pair. Measured: plain L2 ends 0.20 deg / 12.4 mm off with
// point-to-plane, 0.56 deg / 34 mm with colored, 0.16 deg / 10 mm with symmetric; the kernels stay within
// 0.03 deg / 2.1 mm (point-to-plane: L1 0.12 mm, Huber 0.93, Cauchy 0.09, GM 0.20, Tukey 0.23; colored:
// Cauchy 0.19, Tukey 0.22; symmetric: Cauchy 0.22, Tukey 0.24). The bounds sit between with a 2x margin.
TEST(IcpVariantsSharedData, RobustKernelsResistThirtyPercentOutliers) {
    LOAD_FRAGMENT_OR_SKIP(pair);
    const PointCloud noisy = with_outliers(pair.source, 0.3, 7);
    ASSERT_EQ(noisy.size() - pair.source.size(), pair.source.size() * 3 / 10);
    const double gate = 0.2;
    const auto icp = [&](reg::Estimation e, reg::RobustKernel kernel) {
        return reg::registration_icp(noisy, pair.target, gate, Eigen::Matrix4d::Identity(), options_for(e, kernel))
            .transformation;
    };
    const std::vector<reg::RobustKernel> all = {
        {Kind::L1, 1.0}, {Kind::Huber, 0.01}, {Kind::Cauchy, 0.01}, {Kind::GM, 1e-4}, {Kind::Tukey, 0.03}};
    const std::vector<reg::RobustKernel> two = {{Kind::Cauchy, 0.01}, {Kind::Tukey, 0.03}};
    for (auto e : {reg::Estimation::PointToPlane, reg::Estimation::Colored, reg::Estimation::Symmetric}) {
        SCOPED_TRACE(static_cast<int>(e));
        const Eigen::Matrix4d plain = icp(e, {});
        EXPECT_GT(offset(plain, pair.motion), 0.006);
        EXPECT_GT(angle_degrees(plain, pair.motion), 0.1);
        for (const auto& kernel : e == reg::Estimation::PointToPlane ? all : two) {
            SCOPED_TRACE(static_cast<int>(kernel.type));
            const Eigen::Matrix4d robust = icp(e, kernel);
            EXPECT_LT(angle_degrees(robust, pair.motion), 0.06);
            EXPECT_LT(offset(robust, pair.motion), 0.004);
        }
    }
    // Generalized ICP shrugs these outliers off even without a kernel (their random normals make thin,
    // randomly turned covariances); its kernels must not spoil that.
    for (const auto& kernel : two) {
        SCOPED_TRACE(static_cast<int>(kernel.type));
        const Eigen::Matrix4d r = icp(reg::Estimation::Generalized, kernel);
        EXPECT_LT(angle_degrees(r, pair.motion), 0.02);
        EXPECT_LT(offset(r, pair.motion), 0.002);
    }
}
