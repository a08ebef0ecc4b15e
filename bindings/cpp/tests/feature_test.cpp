// SPDX-License-Identifier: MIT
// Feature through the wrapper: views, resize, selection, files (the shared FPFH file), FPFH on
// cloud_bin_0, matching quality across the two scans, KD-trees over features, bad arguments.
#include <cmath>
#include <fstream>
#include <iterator>
#include <random>

#include "test_util.hpp"

using o3dpp::Feature;

TEST(Feature, ConstructViewResizeAndClone) {
    Feature zeros(4, 3);
    EXPECT_EQ(zeros.dimension(), 4u);
    EXPECT_EQ(zeros.num(), 3u);
    for (double v : zeros.data()) EXPECT_EQ(v, 0.0);

    std::vector<double> values(12);
    for (int i = 0; i < 12; ++i) values[i] = i;
    Feature f = Feature::from_data(values, 3);
    EXPECT_EQ(f.num(), 4u);
    EXPECT_EQ(f.get_data(), values);
    EXPECT_EQ(f.descriptor(1)[0], 3.0);
    EXPECT_O3D_ERROR(f.descriptor(4), O3D_ERROR_INVALID_ARGUMENT);

    Feature copy = f.clone();
    f.data()[0] = 42.0;
    EXPECT_EQ(f.get_data()[0], 42.0);
    EXPECT_EQ(copy.data()[0], 0.0);

    f.resize(3, 6);
    ASSERT_EQ(f.num(), 6u);
    const auto kept = f.get_data();
    EXPECT_EQ(kept[0], 42.0);
    EXPECT_EQ(kept[11], 11.0);
    for (int i = 12; i < 18; ++i) EXPECT_EQ(kept[i], 0.0);

    Feature moved = std::move(f);
    EXPECT_FALSE(static_cast<bool>(f));  // NOLINT(bugprone-use-after-move): moved-from is empty
    EXPECT_EQ(moved.num(), 6u);
}

TEST(Feature, SelectByIndex) {
    Feature f = Feature::from_data({0, 0.5, 1, 1.5, 2, 2.5, 3, 3.5}, 2);
    EXPECT_EQ(f.select_by_index({3, 1}).get_data(), (std::vector<double>{3, 3.5, 1, 1.5}));
    EXPECT_EQ(f.select_by_index({3, 1}, true).get_data(), (std::vector<double>{0, 0.5, 2, 2.5}));
    EXPECT_O3D_ERROR(f.select_by_index({0, 4}), O3D_ERROR_INVALID_ARGUMENT);
    EXPECT_O3D_ERROR(f.select_by_index({-1}), O3D_ERROR_INVALID_ARGUMENT);
}

TEST(Feature, BadConstructionArguments) {
    EXPECT_O3D_ERROR(Feature::from_data({1, 2, 3}, 2), O3D_ERROR_INVALID_ARGUMENT);
    EXPECT_O3D_ERROR(Feature::from_data({1, NAN}, 2), O3D_ERROR_INVALID_ARGUMENT);
    EXPECT_O3D_ERROR(Feature::from_data(nullptr, 2, 3), O3D_ERROR_INVALID_ARGUMENT);
    EXPECT_O3D_ERROR(Feature(static_cast<o3d_feature_t*>(nullptr)), O3D_ERROR_INVALID_ARGUMENT);
}

TEST(Feature, FileRoundTripAndErrors) {
    Feature f = Feature::from_data({0.25, -1, 3.5, 1e-300, 7, 8}, 3);
    const std::string path = o3dpp_test::tmp_path("feature_roundtrip.bin");
    o3dpp::write_feature(path, f);
    std::ifstream in(path, std::ios::binary);
    std::vector<char> bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    ASSERT_EQ(bytes.size(), 8u + 6 * 8);
    EXPECT_EQ(bytes[0], 3);  // int32 dimension, then int32 num
    EXPECT_EQ(bytes[4], 2);
    Feature back = o3dpp::read_feature(path);
    EXPECT_EQ(back.dimension(), 3u);
    EXPECT_EQ(back.get_data(), f.get_data());

    const std::string short_path = o3dpp_test::tmp_path("feature_short.bin");
    std::ofstream(short_path, std::ios::binary).write(bytes.data(), static_cast<std::streamsize>(bytes.size() - 1));
    EXPECT_O3D_ERROR(o3dpp::read_feature(short_path), O3D_ERROR_PARSE);
    EXPECT_O3D_ERROR(o3dpp::read_feature(o3dpp_test::tmp_path("no_such_feature.bin")), O3D_ERROR_IO);
}

TEST(Feature, ReadsTheSharedFpfhFile) {
    O3DPP_DATA_OR_SKIP(path, "open3d/Feature/cloud_bin_0.fpfh.bin");
    Feature f = o3dpp::read_feature(path);
    EXPECT_EQ(f.dimension(), 33u);
    EXPECT_EQ(f.num(), 3903u);
    // Three 11-bin histograms per point, each normalised to 100.
    const auto d = f.data();
    for (std::size_t i = 0; i < f.num(); ++i)
        for (int part = 0; part < 3; ++part) {
            double sum = 0;
            for (int b = 0; b < 11; ++b) sum += d[i * 33 + part * 11 + b];
            ASSERT_NEAR(sum, 100.0, 1e-3) << "descriptor " << i;
        }
    EXPECT_NEAR(d[0], 6.71196556, 1e-6);
}

namespace {
o3dpp::PointCloud read_cloud(const std::string& path) { return o3dpp::read_point_cloud(path); }

// Share of `source` points whose nearest `target` feature is within 0.075 m of them.
double matching_share(const o3dpp::PointCloud& source, const o3dpp::PointCloud& target, const Feature& fs,
                      const Feature& ft) {
    const auto pairs = o3dpp::correspondences_from_features(fs, ft);
    EXPECT_EQ(pairs.size(), fs.num());
    const auto ps = source.points();
    const auto pt = target.points();
    std::size_t good = 0;
    for (const auto& p : pairs) {
        double d2 = 0;
        for (int k = 0; k < 3; ++k) d2 += std::pow(ps[p[0]][k] - pt[p[1]][k], 2);
        good += d2 < 0.075 * 0.075;
    }
    return static_cast<double>(good) / static_cast<double>(pairs.size());
}
}  // namespace

TEST(Feature, StoredFeaturesMatchAcrossTheScans) {
    O3DPP_DATA_OR_SKIP(p0, "open3d/Feature/cloud_bin_0.pcd");
    O3DPP_DATA_OR_SKIP(p1, "open3d/Feature/cloud_bin_1.pcd");
    O3DPP_DATA_OR_SKIP(f0p, "open3d/Feature/cloud_bin_0.fpfh.bin");
    O3DPP_DATA_OR_SKIP(f1p, "open3d/Feature/cloud_bin_1.fpfh.bin");
    auto c0 = read_cloud(p0), c1 = read_cloud(p1);
    auto f0 = o3dpp::read_feature(f0p), f1 = o3dpp::read_feature(f1p);
    // Chance would put well under 1% this close; the stored features reach about 11%.
    const double share = matching_share(c1, c0, f1, f0);
    EXPECT_GT(share, 0.09);
    EXPECT_LT(share, 0.14);
    const auto mutual = o3dpp::correspondences_from_features(f1, f0, true);
    EXPECT_GT(mutual.size(), 0u);
    EXPECT_LT(mutual.size(), f1.num());
}

TEST(Feature, FpfhOnCloudBinIsAHistogramThatMatchesAcrossScans) {
    O3DPP_DATA_OR_SKIP(p0, "open3d/Feature/cloud_bin_0.pcd");
    O3DPP_DATA_OR_SKIP(p1, "open3d/Feature/cloud_bin_1.pcd");
    const auto param = o3dpp::SearchParam::Hybrid(0.25, 100);
    auto d0 = read_cloud(p0).voxel_down_sample(0.05);
    auto d1 = read_cloud(p1).voxel_down_sample(0.05);
    d0.estimate_normals(o3dpp::SearchParam::Hybrid(0.1, 30));
    d1.estimate_normals(o3dpp::SearchParam::Hybrid(0.1, 30));
    auto f0 = o3dpp::compute_fpfh_feature(d0, param);
    auto f1 = o3dpp::compute_fpfh_feature(d1, param);
    ASSERT_EQ(f0.dimension(), 33u);
    ASSERT_EQ(f0.num(), d0.size());
    const auto v = f0.data();
    for (std::size_t i = 0; i < f0.num(); ++i) {
        double sum = 0;
        for (int b = 0; b < 33; ++b) {
            ASSERT_GE(v[i * 33 + b], 0.0);
            sum += v[i * 33 + b];
        }
        ASSERT_NEAR(sum, 600.0, 1e-9);  // Open3D 0.20: own SPFH + neighbours' mean, each 11-bin part 200
    }
    EXPECT_GT(matching_share(d1, d0, f1, f0), 0.10);  // Open3D's FPFH: 14% on this setting
    // One thread gives the same values; a subset of indices gives those descriptors, in ascending
    // point order (Open3D's mask semantics).
    EXPECT_EQ(o3dpp::compute_fpfh_feature(d0, param, {}, 1).get_data(), f0.get_data());
    EXPECT_EQ(o3dpp::compute_fpfh_feature(d0, param, {17, 0, 5}, 2).get_data(),
              f0.select_by_index({0, 5, 17}).get_data());
}

TEST(Feature, FpfhAndMatchingRejectBadInput) {
    o3dpp::PointCloud bare(o3dpp_test::random_points(50));
    EXPECT_O3D_ERROR(o3dpp::compute_fpfh_feature(bare, o3dpp::SearchParam::Knn(10)), O3D_ERROR_INVALID_ARGUMENT);
    auto with_normals = bare.clone();
    with_normals.estimate_normals(o3dpp::SearchParam::Knn(10));
    EXPECT_O3D_ERROR(o3dpp::compute_fpfh_feature(with_normals, o3dpp::SearchParam::Radius(-1.0)),
                     O3D_ERROR_INVALID_ARGUMENT);
    EXPECT_O3D_ERROR(o3dpp::compute_fpfh_feature(with_normals, o3dpp::SearchParam::Knn(10), {50}),
                     O3D_ERROR_INVALID_ARGUMENT);
    EXPECT_O3D_ERROR(o3dpp::correspondences_from_features(Feature(3, 4), Feature(2, 4)), O3D_ERROR_INVALID_ARGUMENT);
}

TEST(Feature, MatchingAFeatureWithItself) {
    std::mt19937 rng(5);
    std::uniform_real_distribution<double> u(0, 1);
    std::vector<double> values(200 * 5);
    for (double& v : values) v = u(rng);
    Feature f = Feature::from_data(values, 5);
    for (bool mutual : {false, true}) {
        const auto pairs = o3dpp::correspondences_from_features(f, f, mutual, 0.1, 2);
        ASSERT_EQ(pairs.size(), 200u);
        for (int i = 0; i < 200; ++i) EXPECT_EQ(pairs[i], (std::array<int32_t, 2>{i, i}));
    }
}

TEST(Feature, KDTreeOverAFeatureAndXdPoints) {
    std::mt19937 rng(7);
    std::uniform_real_distribution<double> u(-1, 1);
    std::vector<double> values(300 * 6);
    for (double& v : values) v = u(rng);
    Feature f = Feature::from_data(values, 6);
    o3dpp::KDTreeFlann tree(f);
    EXPECT_EQ(tree.dimension(), 6u);
    EXPECT_EQ(tree.size(), 300u);
    const std::vector<double> q(values.begin() + 17 * 6, values.begin() + 18 * 6);
    auto r = tree.search_knn_vector_xd(q, 2);
    ASSERT_EQ(r.total(), 2u);
    EXPECT_EQ(r.indices()[0], 17);
    EXPECT_EQ(r.distances2()[0], 0.0);
    auto all = tree.search_xd(f, o3dpp::SearchParam::Knn(1));
    for (int i = 0; i < 300; ++i) EXPECT_EQ(all.indices()[i], i);
    EXPECT_EQ(tree.search_radius_vector_xd(q, 1e-9).total(), 1u);
    EXPECT_EQ(tree.search_hybrid_vector_xd(q, 10.0, 5).total(), 5u);

    auto tree2 = o3dpp::KDTreeFlann::from_points_xd({0, 0, 1, 1, 5, 5}, 2);
    EXPECT_EQ(tree2.dimension(), 2u);
    auto r2 = tree2.search_xd({0.9, 0.8, 4, 4}, 2, o3dpp::SearchParam::Knn(1));
    EXPECT_EQ(r2.get_indices(), (std::vector<int32_t>{1, 2}));
    EXPECT_EQ(o3dpp::KDTreeFlann(std::vector<o3dpp::Vec3>{{0, 0, 0}, {1, 1, 1}}).dimension(), 3u);

    EXPECT_O3D_ERROR(tree.search_knn_vector_xd(std::vector<double>(5, 0.0), 1), O3D_ERROR_INVALID_ARGUMENT);
    EXPECT_O3D_ERROR(tree2.search_xd({0, 0, 0}, 2, o3dpp::SearchParam::Knn(1)), O3D_ERROR_INVALID_ARGUMENT);
    EXPECT_O3D_ERROR(o3dpp::KDTreeFlann::from_points_xd({0, 0, 1, 1, 5, 5}, 4), O3D_ERROR_INVALID_ARGUMENT);
    EXPECT_O3D_ERROR(o3dpp::KDTreeFlann::from_points_xd({NAN, 0}, 2), O3D_ERROR_INVALID_ARGUMENT);
    EXPECT_O3D_ERROR(o3dpp::KDTreeFlann::from_points_xd(nullptr, 2, 3), O3D_ERROR_INVALID_ARGUMENT);
}
