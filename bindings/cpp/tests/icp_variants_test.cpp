// SPDX-License-Identifier: MIT
// Colored, generalized and symmetric ICP and robust kernels through the wrapper.
#include <cmath>

#include "test_util.hpp"

using o3dpp::Mat4;
using o3dpp::RobustKernel;
using o3dpp::Vec3;

namespace {
Mat4 small_motion() {
    // 3 degrees about unit(0.3, -0.5, 0.8), then (0.02, -0.01, 0.015) (Rodrigues).
    const double n = std::sqrt(0.3 * 0.3 + 0.5 * 0.5 + 0.8 * 0.8);
    const double x = 0.3 / n, y = -0.5 / n, z = 0.8 / n, a = 3 * M_PI / 180, s = std::sin(a), c = std::cos(a),
                 v = 1 - c;
    return {v * x * x + c,     v * x * y - s * z, v * x * z + s * y, 0.02, v * x * y + s * z, v * y * y + c,
            v * y * z - s * x, -0.01,             v * x * z - s * y, v * y * z + s * x,    v * z * z + c, 0.015,
            0,                 0,                 0,                 1};
}
double max_abs_diff(const Mat4& a, const Mat4& b) {
    double d = 0;
    for (int i = 0; i < 16; ++i) d = std::max(d, std::abs(a[i] - b[i]));
    return d;
}
o3dpp::IcpOptions tight() {
    o3dpp::IcpOptions o;
    o.relative_fitness = 1e-12;
    o.relative_rmse = 1e-12;
    o.max_iteration = 100;
    return o;
}

// A flat 1 m square with a grey pattern, and its copy shifted within the plane.
struct PatternedPlane {
    o3dpp::PointCloud source, target;
    Mat4 truth = o3dpp::identity4();
    PatternedPlane() {
        std::vector<Vec3> pts, moved, colors;
        for (int i = 0; i < 10000; ++i) {
            const Vec3 p{(i % 100) * 0.01, (i / 100) * 0.01, 0.0};
            const double g = 0.5 + 0.5 * std::sin(p[0] * 12) * std::cos(p[1] * 9);
            pts.push_back(p);
            moved.push_back({p[0] + 0.03, p[1] - 0.02, 0.0});
            colors.push_back({g, g, g});
        }
        source.set_points(pts);
        source.set_colors(colors);
        source.set_normals(std::vector<Vec3>(pts.size(), Vec3{0, 0, 1}));
        target.set_points(moved);
        target.set_colors(colors);
        target.set_normals(std::vector<Vec3>(pts.size(), Vec3{0, 0, 1}));
        truth[3] = 0.03;
        truth[7] = -0.02;
    }
};
}  // namespace

TEST(IcpVariants, KernelWeights) {
    EXPECT_DOUBLE_EQ(RobustKernel::L2().weight(3.0), 1.0);
    EXPECT_DOUBLE_EQ(RobustKernel::L1().weight(4.0), 0.25);
    EXPECT_DOUBLE_EQ(RobustKernel::Huber(1.0).weight(0.5), 1.0);
    EXPECT_DOUBLE_EQ(RobustKernel::Huber(1.0).weight(2.0), 0.5);
    EXPECT_DOUBLE_EQ(RobustKernel::Cauchy(2.0).weight(2.0), 0.5);
    EXPECT_DOUBLE_EQ(RobustKernel::GM(1.0).weight(1.0), 0.25);
    EXPECT_DOUBLE_EQ(RobustKernel::Tukey(2.0).weight(1.0), 0.5625);
    EXPECT_DOUBLE_EQ(RobustKernel::Tukey(2.0).weight(-3.0), 0.0);
    EXPECT_O3D_ERROR(RobustKernel::Huber(0.0).weight(1.0), O3D_ERROR_INVALID_ARGUMENT);
    EXPECT_O3D_ERROR(RobustKernel::GM(NAN).weight(1.0), O3D_ERROR_INVALID_ARGUMENT);
    EXPECT_O3D_ERROR((RobustKernel{static_cast<RobustKernel::Type>(42), 1.0}.weight(1.0)),
                     O3D_ERROR_INVALID_ARGUMENT);
}

TEST(IcpVariants, DefaultsMatchTheLibrary) {
    const o3d_icp_options_t ours = o3dpp::IcpOptions().to_c();
    o3d_icp_options_t lib;
    o3dpp::check(o3d_icp_options_init(&lib, sizeof lib));
    EXPECT_EQ(ours.kernel, lib.kernel);
    EXPECT_EQ(ours.kernel_k, lib.kernel_k);
    EXPECT_EQ(ours.lambda_geometric, lib.lambda_geometric);
    EXPECT_EQ(ours.epsilon, lib.epsilon);
}

TEST(IcpVariants, ColoredIcpUsesTheColors) {
    PatternedPlane p;
    const auto r = o3dpp::registration_colored_icp(p.source, p.target, 0.05, o3dpp::identity4(), tight());
    EXPECT_LT(max_abs_diff(r.transformation(), p.truth), 1e-4);
    auto p2l = tight();
    p2l.estimation = o3dpp::Estimation::PointToPlane;
    const auto geometric = o3dpp::registration_icp(p.source, p.target, 0.05, o3dpp::identity4(), p2l);
    EXPECT_GT(max_abs_diff(geometric.transformation(), p.truth), 0.01) << "the plane alone cannot show the shift";
}

TEST(IcpVariants, ColoredGeneralizedSymmetricRecoverASmallMotion) {
    O3DPP_DATA_OR_SKIP(path, "open3d/fragment.pcd");
    auto source = o3dpp::read_point_cloud(path).voxel_down_sample(0.04);
    ASSERT_TRUE(source.has_colors() && source.has_normals());
    auto target = source.clone();
    const Mat4 truth = small_motion();
    target.transform(truth);
    const auto colored = o3dpp::registration_colored_icp(source, target, 0.08, o3dpp::identity4(), tight());
    const auto generalized = o3dpp::registration_generalized_icp(source, target, 0.08, o3dpp::identity4(), tight());
    const auto symmetric = o3dpp::registration_symmetric_icp(source, target, 0.08, o3dpp::identity4(), tight());
    for (const auto* r : {&colored, &generalized, &symmetric}) {
        EXPECT_LT(max_abs_diff(r->transformation(), truth), 1e-5);
        EXPECT_GT(r->fitness(), 0.99);
        EXPECT_LT(r->inlier_rmse(), 1e-4);
    }
    // Generalized ICP on bare points (covariances from neighbours) with a robust kernel.
    o3dpp::PointCloud bare_source(source.get_points()), bare_target(target.get_points());
    auto opts = tight();
    opts.kernel = RobustKernel::Cauchy(0.05);
    opts.epsilon = 1e-4;
    const auto r = o3dpp::registration_generalized_icp(bare_source, bare_target, 0.08, o3dpp::identity4(), opts);
    EXPECT_LT(max_abs_diff(r.transformation(), truth), 1e-5);
}

TEST(IcpVariants, MissingAttributesAndBadParameters) {
    PatternedPlane p;
    o3dpp::PointCloud bare(p.source.get_points());
    auto with = [](o3dpp::Estimation e) {
        o3dpp::IcpOptions o;
        o.estimation = e;
        return o;
    };
    using E = o3dpp::Estimation;
    EXPECT_O3D_ERROR(o3dpp::registration_icp(bare, p.target, 0.05, o3dpp::identity4(), with(E::Colored)),
                     O3D_ERROR_INVALID_ARGUMENT);
    EXPECT_O3D_ERROR(o3dpp::registration_icp(p.source, bare, 0.05, o3dpp::identity4(), with(E::Colored)),
                     O3D_ERROR_INVALID_ARGUMENT);
    EXPECT_O3D_ERROR(o3dpp::registration_icp(bare, p.target, 0.05, o3dpp::identity4(), with(E::Symmetric)),
                     O3D_ERROR_INVALID_ARGUMENT);
    auto bad = with(E::Colored);
    bad.lambda_geometric = 1.5;
    EXPECT_O3D_ERROR(o3dpp::registration_icp(p.source, p.target, 0.05, o3dpp::identity4(), bad),
                     O3D_ERROR_INVALID_ARGUMENT);
    bad = with(E::Generalized);
    bad.epsilon = 0;
    EXPECT_O3D_ERROR(o3dpp::registration_icp(p.source, p.target, 0.05, o3dpp::identity4(), bad),
                     O3D_ERROR_INVALID_ARGUMENT);
    bad = with(E::PointToPlane);
    bad.kernel = RobustKernel::Tukey(-1);
    EXPECT_O3D_ERROR(o3dpp::registration_icp(p.source, p.target, 0.05, o3dpp::identity4(), bad),
                     O3D_ERROR_INVALID_ARGUMENT);
    bad = with(static_cast<E>(99));
    EXPECT_O3D_ERROR(o3dpp::registration_icp(p.source, p.target, 0.05, o3dpp::identity4(), bad),
                     O3D_ERROR_INVALID_ARGUMENT);
}
