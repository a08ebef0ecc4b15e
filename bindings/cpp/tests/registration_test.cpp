// SPDX-License-Identifier: MIT
// Registration through the wrapper: ICP recovers a known transform; evaluation; progress callback.
#include <cmath>
#include <stdexcept>

#include "test_util.hpp"

using o3dpp::Mat4;
using o3dpp::Vec3;

namespace {
// Rotation of `deg` degrees about z then a translation.
Mat4 known_transform(double deg, const Vec3& t) {
    const double a = deg * M_PI / 180.0, c = std::cos(a), s = std::sin(a);
    return {c, -s, 0, t[0], s, c, 0, t[1], 0, 0, 1, t[2], 0, 0, 0, 1};
}
void expect_mat_near(const Mat4& a, const Mat4& b, double tol) {
    for (int i = 0; i < 16; ++i) EXPECT_NEAR(a[i], b[i], tol) << "element " << i;
}
}  // namespace

TEST(Registration, PointToPointRecoversKnownTransform) {
    o3dpp::PointCloud source(o3dpp_test::random_points(800));
    o3dpp::PointCloud target = source.clone();
    const Mat4 truth = known_transform(4.0, {0.05, -0.03, 0.02});
    target.transform(truth);
    o3dpp::IcpOptions opts;
    opts.max_iteration = 100;
    auto res = o3dpp::registration_icp(source, target, 0.5, o3dpp::identity4(), opts);
    expect_mat_near(res.transformation(), truth, 1e-6);
    EXPECT_DOUBLE_EQ(res.fitness(), 1.0);
    EXPECT_LT(res.inlier_rmse(), 1e-6);
    const auto corr = res.correspondence_set();
    ASSERT_EQ(corr.size(), 800u);
    for (const auto& c : corr) EXPECT_EQ(c[0], c[1]);
}

TEST(Registration, PointToPlaneOnRealData) {
    O3DPP_DATA_OR_SKIP(path, "open3d/Feature/cloud_bin_0.pcd");
    auto source = o3dpp::read_point_cloud(path);
    auto target = source.clone();
    const Mat4 truth = known_transform(2.0, {0.02, 0.01, -0.01});
    target.transform(truth);
    target.estimate_normals(o3dpp::SearchParam::Hybrid(0.1, 30));
    o3dpp::IcpOptions opts;
    opts.estimation = o3dpp::Estimation::PointToPlane;
    opts.max_iteration = 50;
    auto res = o3dpp::registration_icp(source, target, 0.1, o3dpp::identity4(), opts);
    expect_mat_near(res.transformation(), truth, 1e-4);
    EXPECT_GT(res.fitness(), 0.99);
}

TEST(Registration, EvaluateAndInformationMatrix) {
    std::vector<Vec3> src = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {5, 5, 5}};
    std::vector<Vec3> tgt = {{0, 0, 0.1}, {1, 0, 0.1}, {0, 1, 0.1}, {20, 20, 20}};
    o3dpp::PointCloud source(src), target(tgt);
    auto ev = o3dpp::evaluate_registration(source, target, 0.2);
    EXPECT_DOUBLE_EQ(ev.fitness(), 0.75);
    EXPECT_NEAR(ev.inlier_rmse(), 0.1, 1e-12);
    EXPECT_EQ(ev.correspondence_set().size(), 3u);
    EXPECT_EQ(ev.transformation(), o3dpp::identity4());
    // Moving the source up by 0.1 makes the three pairs exact.
    auto ev2 = o3dpp::evaluate_registration(source, target, 0.2, known_transform(0, {0, 0, 0.1}));
    EXPECT_NEAR(ev2.inlier_rmse(), 0.0, 1e-12);
    const auto info = o3dpp::get_information_matrix_from_point_clouds(source, target, 0.2);
    // Symmetric, and the translation block (rows/cols 3..5) is count * identity.
    for (int r = 0; r < 6; ++r)
        for (int c = 0; c < 6; ++c) EXPECT_DOUBLE_EQ(info[r * 6 + c], info[c * 6 + r]);
    EXPECT_DOUBLE_EQ(info[3 * 6 + 3], 3.0);
    EXPECT_DOUBLE_EQ(info[4 * 6 + 4], 3.0);
    EXPECT_DOUBLE_EQ(info[5 * 6 + 5], 3.0);
    EXPECT_DOUBLE_EQ(info[3 * 6 + 4], 0.0);
}

TEST(Registration, ProgressCallbackSeesFractionsAndCancels) {
    o3dpp::PointCloud source(o3dpp_test::random_points(300));
    o3dpp::PointCloud target = source.clone();
    target.transform(known_transform(10.0, {0.1, 0, 0}));
    o3dpp::IcpOptions opts;
    opts.relative_fitness = 0;
    opts.relative_rmse = 0;
    opts.max_iteration = 10;
    std::vector<double> seen;
    opts.progress = [&](double f) {
        seen.push_back(f);
        return seen.size() < 3;  // cancel on the third report
    };
    EXPECT_O3D_ERROR(o3dpp::registration_icp(source, target, 0.5, o3dpp::identity4(), opts), O3D_ERROR_CANCELLED);
    ASSERT_EQ(seen.size(), 3u);
    for (double f : seen) {
        EXPECT_GE(f, 0.0);
        EXPECT_LE(f, 1.0);
    }
    EXPECT_LT(seen[0], seen[2]);
}

TEST(Registration, ExceptionInProgressCallbackIsRethrownNotLeakedThroughC) {
    o3dpp::PointCloud source(o3dpp_test::random_points(100));
    o3dpp::PointCloud target = source.clone();
    o3dpp::IcpOptions opts;
    opts.progress = [](double) -> bool { throw std::logic_error("from the callback"); };
    try {
        o3dpp::registration_icp(source, target, 0.5, o3dpp::identity4(), opts);
        FAIL() << "no exception";
    } catch (const std::logic_error& e) {
        EXPECT_STREQ(e.what(), "from the callback");
    }
}
