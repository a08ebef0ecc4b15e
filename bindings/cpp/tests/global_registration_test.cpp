// SPDX-License-Identifier: MIT
// Global registration through the wrapper: RANSAC and FGR recover a large known rotation of
// cloud_bin_0 onto cloud_bin_1 (reproducibly with a seed, on 1 or 2 threads), checkers, the
// global seed, progress with cancellation, bad arguments.
#include <algorithm>
#include <cmath>
#include <optional>
#include <random>
#include <stdexcept>

#include "test_util.hpp"

using o3dpp::CorrespondenceChecker;
using o3dpp::Correspondences;
using o3dpp::Mat4;
using o3dpp::Vec3;

namespace {
constexpr double kVoxel = 0.05;

Mat4 mul(const Mat4& a, const Mat4& b) {
    Mat4 m{};
    for (int i = 0; i < 4; ++i)
        for (int j = 0; j < 4; ++j)
            for (int k = 0; k < 4; ++k) m[i * 4 + j] += a[i * 4 + k] * b[k * 4 + j];
    return m;
}
// Rotation of `rad` about unit(axis), then translation t (Rodrigues).
Mat4 rigid(Vec3 axis, double rad, const Vec3& t) {
    const double n = std::sqrt(axis[0] * axis[0] + axis[1] * axis[1] + axis[2] * axis[2]);
    const double x = axis[0] / n, y = axis[1] / n, z = axis[2] / n, s = std::sin(rad), c = std::cos(rad),
                 v = 1 - c;
    return {v * x * x + c,     v * x * y - s * z, v * x * z + s * y, t[0], v * x * y + s * z, v * y * y + c,
            v * y * z - s * x, t[1],              v * x * z - s * y, v * y * z + s * x,    v * z * z + c, t[2],
            0,                 0,                 0,                 1};
}
Mat4 rigid_inverse(const Mat4& m) {
    Mat4 r{};
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) r[i * 4 + j] = m[j * 4 + i];
    for (int i = 0; i < 3; ++i) r[i * 4 + 3] = -(r[i * 4] * m[3] + r[i * 4 + 1] * m[7] + r[i * 4 + 2] * m[11]);
    r[15] = 1;
    return r;
}
double rotation_error_deg(const Mat4& a, const Mat4& b) {
    const Mat4 d = mul(a, rigid_inverse(b));
    return std::acos(std::clamp((d[0] + d[5] + d[10] - 1) / 2, -1.0, 1.0)) * 180.0 / M_PI;
}
double mean_displacement(const o3dpp::PointCloud& cloud, const Mat4& a, const Mat4& b) {
    const auto pts = cloud.points();
    double sum = 0;
    for (std::size_t i = 0; i < pts.size(); ++i) {
        double d2 = 0;
        for (int r = 0; r < 3; ++r) {
            double pa = a[r * 4 + 3], pb = b[r * 4 + 3];
            for (int k = 0; k < 3; ++k) {
                pa += a[r * 4 + k] * pts[i][k];
                pb += b[r * 4 + k] * pts[i][k];
            }
            d2 += (pa - pb) * (pa - pb);
        }
        sum += std::sqrt(d2);
    }
    return sum / static_cast<double>(pts.size());
}

struct Scene {
    o3dpp::PointCloud source, target;
    o3dpp::Feature source_feature, target_feature;
    Mat4 truth;  // moves the source back onto the target
};

void prepare(o3dpp::PointCloud& down, o3dpp::Feature& feature) {
    down.estimate_normals(o3dpp::SearchParam::Hybrid(2 * kVoxel, 30));
    feature = o3dpp::compute_fpfh_feature(down, o3dpp::SearchParam::Hybrid(5 * kVoxel, 100));
}

// cloud_bin_0 moved 60 degrees about (1, 2, 3) as the source, cloud_bin_1 as the target.
std::optional<Scene> scene(const std::string& p0, const std::string& p1) {
    const Mat4 motion = rigid({1, 2, 3}, 60 * M_PI / 180, {0.5, -0.3, 0.2});
    auto c0 = o3dpp::read_point_cloud(p0);
    c0.transform(motion);
    Scene s{c0.voxel_down_sample(kVoxel), o3dpp::read_point_cloud(p1).voxel_down_sample(kVoxel), o3dpp::Feature(),
            o3dpp::Feature(), rigid_inverse(motion)};
    prepare(s.source, s.source_feature);
    prepare(s.target, s.target_feature);
    return s;
}

void expect_near_truth(const Scene& s, const Mat4& t, double deg, double dist) {
    EXPECT_LT(rotation_error_deg(t, s.truth), deg);
    EXPECT_LT(mean_displacement(s.source, t, s.truth), dist);
}

std::vector<CorrespondenceChecker> tutorial_checkers() {
    return {CorrespondenceChecker::EdgeLength(0.9), CorrespondenceChecker::Distance(1.5 * kVoxel)};
}

o3dpp::RansacOptions seeded(uint64_t seed, int threads) {
    o3dpp::RansacOptions o;
    o.mutual_filter = true;
    o.seed = seed;
    o.num_threads = threads;
    return o;
}

o3dpp::RegistrationResult ransac(const Scene& s, const o3dpp::RansacOptions& o) {
    return o3dpp::registration_ransac_based_on_feature_matching(s.source, s.target, s.source_feature,
                                                                s.target_feature, 1.5 * kVoxel, tutorial_checkers(), o);
}

void expect_same(const o3dpp::RegistrationResult& a, const o3dpp::RegistrationResult& b) {
    EXPECT_EQ(a.transformation(), b.transformation());
    EXPECT_EQ(a.fitness(), b.fitness());
    EXPECT_EQ(a.inlier_rmse(), b.inlier_rmse());
    EXPECT_EQ(a.correspondence_set(), b.correspondence_set());
}

// `target` is `source` moved by `truth`; pairs i <-> i.
struct ExactPair {
    o3dpp::PointCloud source, target;
    Mat4 truth;
    Correspondences corres;
};
ExactPair exact_pair(int n) {
    const auto pts = o3dpp_test::random_points(static_cast<std::size_t>(n), 0.0, 1.0, 21);
    ExactPair p{o3dpp::PointCloud(pts), o3dpp::PointCloud(pts), rigid({0, 1, 1}, 0.7, {0.2, 0.1, -0.3}), {}};
    p.target.transform(p.truth);
    for (int i = 0; i < n; ++i) p.corres.push_back({i, i});
    return p;
}
}  // namespace

TEST(GlobalRegistration, DefaultsMatchTheLibrary) {
    const o3d_ransac_options_t r = o3dpp::RansacOptions().to_c();
    o3d_ransac_options_t lib;
    o3dpp::check(o3d_ransac_options_init(&lib, sizeof lib));
    EXPECT_EQ(r.ransac_n, lib.ransac_n);
    EXPECT_EQ(r.max_iteration, lib.max_iteration);
    EXPECT_EQ(r.confidence, lib.confidence);
    EXPECT_EQ(r.use_seed, lib.use_seed);
    const o3dpp::FgrOptions f;
    o3d_fgr_options_t flib;
    o3dpp::check(o3d_fgr_options_init(&flib, sizeof flib));
    EXPECT_EQ(f.division_factor, flib.division_factor);
    EXPECT_EQ(f.maximum_correspondence_distance, flib.maximum_correspondence_distance);
    EXPECT_EQ(f.iteration_number, flib.iteration_number);
    EXPECT_EQ(f.tuple_scale, flib.tuple_scale);
    EXPECT_EQ(f.maximum_tuple_count, flib.maximum_tuple_count);
    EXPECT_EQ(CorrespondenceChecker::library_default(CorrespondenceChecker::Kind::EdgeLength).threshold, 0.9);
    EXPECT_EQ(CorrespondenceChecker::library_default(CorrespondenceChecker::Kind::Distance).threshold, 0.075);
    EXPECT_NEAR(CorrespondenceChecker::library_default(CorrespondenceChecker::Kind::Normal).threshold, M_PI / 6, 1e-4);
}

TEST(GlobalRegistration, RansacRecoversALargeRotationReproducibly) {
    O3DPP_DATA_OR_SKIP(p0, "open3d/Feature/cloud_bin_0.pcd");
    O3DPP_DATA_OR_SKIP(p1, "open3d/Feature/cloud_bin_1.pcd");
    auto s = scene(p0, p1);
    const auto first = ransac(*s, seeded(42, 2));
    expect_near_truth(*s, first.transformation(), 5.0, 0.15);
    EXPECT_GT(first.fitness(), 0.5);
    expect_same(ransac(*s, seeded(42, 2)), first);
    expect_same(ransac(*s, seeded(42, 1)), first);

    o3dpp::IcpOptions icp;
    icp.estimation = o3dpp::Estimation::PointToPlane;
    const auto refined = o3dpp::registration_icp(s->source, s->target, 0.4 * kVoxel, first.transformation(), icp);
    expect_near_truth(*s, refined.transformation(), 1.5, 0.04);

    // Unseeded runs repeat after the same global seed.
    o3dpp::RansacOptions unseeded;
    unseeded.mutual_filter = true;
    unseeded.max_iteration = 20000;
    o3dpp::random_seed(7);
    const auto a = ransac(*s, unseeded);
    o3dpp::random_seed(7);
    expect_same(ransac(*s, unseeded), a);
}

TEST(GlobalRegistration, FgrRecoversTheSameRotation) {
    O3DPP_DATA_OR_SKIP(p0, "open3d/Feature/cloud_bin_0.pcd");
    O3DPP_DATA_OR_SKIP(p1, "open3d/Feature/cloud_bin_1.pcd");
    auto s = scene(p0, p1);
    o3dpp::FgrOptions opts;
    opts.maximum_correspondence_distance = 0.5 * kVoxel;
    opts.seed = 1;
    const auto r = o3dpp::registration_fgr_based_on_feature_matching(s->source, s->target, s->source_feature,
                                                                     s->target_feature, opts);
    expect_near_truth(*s, r.transformation(), 5.0, 0.15);
    const auto corres = o3dpp::correspondences_from_features(s->source_feature, s->target_feature, true);
    const auto r2 = o3dpp::registration_fgr_based_on_correspondence(s->source, s->target, corres, opts);
    expect_near_truth(*s, r2.transformation(), 5.0, 0.15);
    const auto r3 = o3dpp::registration_ransac_based_on_correspondence(s->source, s->target, corres, 1.5 * kVoxel,
                                                                       tutorial_checkers(), seeded(3, 0));
    expect_near_truth(*s, r3.transformation(), 5.0, 0.15);
}

TEST(GlobalRegistration, ExactOnExactCorrespondences) {
    auto p = exact_pair(200);
    for (std::size_t i = 0; i < p.corres.size(); i += 3) p.corres[i][1] = static_cast<int32_t>((i * 7 + 5) % 200);
    o3dpp::RansacOptions o;
    o.seed = 5;
    const auto r = o3dpp::registration_ransac_based_on_correspondence(p.source, p.target, p.corres, 0.01, {}, o);
    const Mat4 t = r.transformation();
    for (int i = 0; i < 16; ++i) EXPECT_NEAR(t[i], p.truth[i], 1e-9);
    EXPECT_NEAR(r.fitness(), 1.0, 1e-12);
    o3dpp::FgrOptions f;
    f.seed = 5;
    const Mat4 g = o3dpp::registration_fgr_based_on_correspondence(p.source, p.target, p.corres, f).transformation();
    for (int i = 0; i < 16; ++i) EXPECT_NEAR(g[i], p.truth[i], 1e-3);
}

TEST(GlobalRegistration, Checkers) {
    auto p = exact_pair(30);
    const Correspondences few(p.corres.begin(), p.corres.begin() + 3);
    EXPECT_TRUE(CorrespondenceChecker::EdgeLength(0.9).check(p.source, p.target, few, p.truth));
    EXPECT_TRUE(CorrespondenceChecker::Distance(0.01).check(p.source, p.target, few, p.truth));
    EXPECT_FALSE(CorrespondenceChecker::Distance(0.01).check(p.source, p.target, few));
    EXPECT_FALSE(CorrespondenceChecker::EdgeLength(0.99).check(p.source, p.target, {{0, 0}, {1, 1}, {2, 17}}, p.truth));
    std::vector<Vec3> grid;
    for (int i = 0; i < 25; ++i) grid.push_back({double(i % 5), double(i / 5), 0.0});
    o3dpp::PointCloud plane(grid);
    plane.set_normals(std::vector<Vec3>(25, Vec3{0, 0, 1}));
    auto moved = plane.clone();
    moved.transform(p.truth);
    const auto normal = CorrespondenceChecker::Normal(5 * M_PI / 180);
    EXPECT_TRUE(normal.check(plane, moved, few, p.truth));
    EXPECT_FALSE(normal.check(plane, moved, few));
    EXPECT_O3D_ERROR(normal.check(p.source, p.target, few, p.truth), O3D_ERROR_INVALID_ARGUMENT);
    EXPECT_O3D_ERROR(CorrespondenceChecker::Distance(NAN).check(p.source, p.target, few), O3D_ERROR_INVALID_ARGUMENT);
    EXPECT_O3D_ERROR(CorrespondenceChecker::EdgeLength(0).check(p.source, p.target, few), O3D_ERROR_INVALID_ARGUMENT);
    EXPECT_O3D_ERROR(CorrespondenceChecker::Distance(0.1).check(p.source, p.target, {{0, 0}, {1, 1}, {2, 30}}),
                     O3D_ERROR_INVALID_ARGUMENT);
}

namespace {
// Random pairs between unrelated clouds: never confident, so RANSAC runs every iteration.
struct Hopeless {
    o3dpp::PointCloud source{o3dpp_test::random_points(300, 0, 1, 8)};
    o3dpp::PointCloud target{o3dpp_test::random_points(300, 0, 1, 9)};
    Correspondences corres;
    Hopeless() {
        for (int i = 0; i < 300; ++i) corres.push_back({i, (i * 97 + 13) % 300});
    }
};
o3dpp::RansacOptions endless() {
    o3dpp::RansacOptions o;
    o.max_iteration = 1000000;
    o.confidence = 1.0;
    o.seed = 1;
    return o;
}
}  // namespace

TEST(GlobalRegistration, ProgressCanCancelAndRethrows) {
    Hopeless h;
    auto o = endless();
    std::vector<double> seen;
    o.progress = [&](double f) {
        seen.push_back(f);
        return seen.size() < 2;
    };
    EXPECT_O3D_ERROR(o3dpp::registration_ransac_based_on_correspondence(h.source, h.target, h.corres, 0.001, {}, o),
                     O3D_ERROR_CANCELLED);
    ASSERT_EQ(seen.size(), 2u);
    for (double f : seen) EXPECT_TRUE(f >= 0.0 && f < 1.0) << f;

    o.progress = [](double) -> bool { throw std::logic_error("from RANSAC progress"); };
    EXPECT_THROW(o3dpp::registration_ransac_based_on_correspondence(h.source, h.target, h.corres, 0.001, {}, o),
                 std::logic_error);

    // Feature matching: identical random descriptors pair the unrelated points i <-> i.
    std::vector<double> values(300 * 4);
    std::mt19937 rng(4);
    std::uniform_real_distribution<double> u(0, 1);
    for (double& v : values) v = u(rng);
    const auto f = o3dpp::Feature::from_data(values, 4);
    o.progress = [](double) { return false; };
    EXPECT_O3D_ERROR(o3dpp::registration_ransac_based_on_feature_matching(h.source, h.target, f, f, 0.001, {}, o),
                     O3D_ERROR_CANCELLED);

    auto p = exact_pair(300);
    o3dpp::FgrOptions fgr;
    int calls = 0;
    fgr.progress = [&](double) {
        ++calls;
        return false;
    };
    EXPECT_O3D_ERROR(o3dpp::registration_fgr_based_on_correspondence(p.source, p.target, p.corres, fgr),
                     O3D_ERROR_CANCELLED);
    EXPECT_EQ(calls, 1);
    EXPECT_O3D_ERROR(o3dpp::registration_fgr_based_on_feature_matching(p.source, p.target, f, f, fgr),
                     O3D_ERROR_CANCELLED);
}

TEST(GlobalRegistration, BadArguments) {
    Hopeless h;
    auto ok = endless();
    ok.max_iteration = 10;
    auto with = [&](auto change) {
        auto o = ok;
        change(o);
        return o;
    };
    auto ransac_corres = [&](const o3dpp::RansacOptions& o, const Correspondences& c, double dist,
                             const std::vector<CorrespondenceChecker>& checkers) {
        o3dpp::registration_ransac_based_on_correspondence(h.source, h.target, c, dist, checkers, o);
    };
    EXPECT_O3D_ERROR(ransac_corres(with([](auto& o) { o.ransac_n = 2; }), h.corres, 0.1, {}),
                     O3D_ERROR_INVALID_ARGUMENT);
    EXPECT_O3D_ERROR(ransac_corres(with([](auto& o) { o.confidence = 1.5; }), h.corres, 0.1, {}),
                     O3D_ERROR_INVALID_ARGUMENT);
    EXPECT_O3D_ERROR(ransac_corres(ok, h.corres, NAN, {}), O3D_ERROR_INVALID_ARGUMENT);
    EXPECT_O3D_ERROR(ransac_corres(ok, {{0, 0}, {1, 1}, {2, 300}}, 0.1, {}), O3D_ERROR_INVALID_ARGUMENT);
    EXPECT_O3D_ERROR(ransac_corres(ok, h.corres, 0.1, {CorrespondenceChecker::Distance(-1)}),
                     O3D_ERROR_INVALID_ARGUMENT);
    EXPECT_O3D_ERROR(ransac_corres(with([](auto& o) { o.estimation = o3dpp::Estimation::Generalized; }), h.corres,
                                   0.1, {}),
                     O3D_ERROR_INVALID_ARGUMENT);
    EXPECT_O3D_ERROR(ransac_corres(with([](auto& o) { o.estimation = o3dpp::Estimation::PointToPlane; }), h.corres,
                                   0.1, {}),
                     O3D_ERROR_INVALID_ARGUMENT);
    const o3dpp::Feature f4(4, 300), f3(3, 300), long4(4, 400);
    EXPECT_O3D_ERROR(o3dpp::registration_ransac_based_on_feature_matching(h.source, h.target, f4, f3, 0.1, {}, ok),
                     O3D_ERROR_INVALID_ARGUMENT);
    EXPECT_O3D_ERROR(o3dpp::registration_ransac_based_on_feature_matching(h.source, h.target, long4, f4, 0.1, {}, ok),
                     O3D_ERROR_INVALID_ARGUMENT);
    o3dpp::FgrOptions fgr;
    fgr.division_factor = 1.0;
    EXPECT_O3D_ERROR(o3dpp::registration_fgr_based_on_correspondence(h.source, h.target, h.corres, fgr),
                     O3D_ERROR_INVALID_ARGUMENT);
    EXPECT_O3D_ERROR(o3dpp::registration_fgr_based_on_feature_matching(h.source, h.target, f4, f3),
                     O3D_ERROR_INVALID_ARGUMENT);
    EXPECT_O3D_ERROR(o3dpp::registration_fgr_based_on_feature_matching(h.source, h.target, f4, long4),
                     O3D_ERROR_INVALID_ARGUMENT);
}
