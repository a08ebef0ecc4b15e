// SPDX-License-Identifier: MIT
// KD-tree of any dimension: knn / radius / hybrid against brute force in 33-D, batch == single,
// thread-count independence, bad input; and nearest-descriptor search on the stored FPFH features.
#include "o3d/kdtree/kd_tree_xd.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>

#include "o3d/io/feature_io.h"
#include "o3d/utility/error.h"
#include "test_data.h"

using o3d::kdtree::KDTreeXd;
using o3d::kdtree::SearchParam;
using o3d::kdtree::SearchResult;

namespace {

constexpr int kDim = 33;

Eigen::MatrixXd random_points(int dim, int n, uint64_t seed) {
    std::mt19937_64 rng(seed);
    std::uniform_real_distribution<double> u(-1.0, 1.0);
    Eigen::MatrixXd pts(dim, n);
    for (int i = 0; i < n; ++i)
        for (int d = 0; d < dim; ++d) pts(d, i) = u(rng);
    return pts;
}

/// Brute force: (distance2, index) of every column, ascending.
std::vector<std::pair<double, int>> brute(const Eigen::MatrixXd& pts, const double* q) {
    const Eigen::Map<const Eigen::VectorXd> query(q, pts.rows());
    std::vector<std::pair<double, int>> all;
    for (int i = 0; i < pts.cols(); ++i) all.emplace_back((pts.col(i) - query).squaredNorm(), i);
    std::sort(all.begin(), all.end());
    return all;
}

void expect_matches(const std::vector<std::pair<double, int>>& expected, const int* idx, const double* d2,
                    size_t count) {
    ASSERT_EQ(count, expected.size());
    for (size_t i = 0; i < count; ++i) {
        EXPECT_EQ(idx[i], expected[i].second) << "rank " << i;
        EXPECT_NEAR(d2[i], expected[i].first, 1e-12 * (1.0 + expected[i].first)) << "rank " << i;
    }
}

}  // namespace

TEST(KDTreeXd, KnnMatchesBruteForceIn33D) {
    const Eigen::MatrixXd pts = random_points(kDim, 1500, 1);
    const Eigen::MatrixXd queries = random_points(kDim, 40, 2);
    const KDTreeXd tree(pts);
    EXPECT_EQ(tree.dimension(), 33u);
    EXPECT_EQ(tree.size(), 1500u);
    std::vector<int> idx;
    std::vector<double> d2;
    for (int q = 0; q < queries.cols(); ++q) {
        const double* query = queries.col(q).data();
        auto all = brute(pts, query);
        all.resize(10);
        ASSERT_EQ(tree.search_knn(query, 10, idx, d2), 10);
        expect_matches(all, idx.data(), d2.data(), idx.size());
        double nearest_d2 = -1.0;
        EXPECT_EQ(tree.search_nearest(query, nearest_d2), all[0].second);
        EXPECT_NEAR(nearest_d2, all[0].first, 1e-12);
    }
}

TEST(KDTreeXd, RadiusAndHybridMatchBruteForceIn33D) {
    const Eigen::MatrixXd pts = random_points(kDim, 1500, 3);
    const KDTreeXd tree(pts);
    std::vector<int> idx;
    std::vector<double> d2;
    // Queries on data points, radius chosen so that a few dozen neighbours fall inside
    // (squared distances of uniform points in [-1, 1]^33 average 22 with a spread of 4.5).
    const double radius = 3.5;
    size_t found = 0;
    for (int q = 0; q < 30; ++q) {
        const double* query = pts.col(q * 37).data();
        auto all = brute(pts, query);
        std::vector<std::pair<double, int>> inside;
        for (const auto& e : all)
            if (e.first < radius * radius) inside.push_back(e);
        found += inside.size();
        tree.search_radius(query, radius, idx, d2);
        expect_matches(inside, idx.data(), d2.data(), idx.size());
        if (inside.size() > 5) inside.resize(5);
        tree.search_hybrid(query, radius, 5, idx, d2);
        expect_matches(inside, idx.data(), d2.data(), idx.size());
    }
    EXPECT_GT(found, 90u);  // not only the query points themselves
}

TEST(KDTreeXd, BatchEqualsSingleForAnyThreadCount) {
    const Eigen::MatrixXd pts = random_points(kDim, 800, 4);
    const Eigen::MatrixXd queries = random_points(kDim, 700, 5);  // more than one chunk
    const KDTreeXd tree(pts);
    for (const SearchParam& param :
         {SearchParam::make_knn(7), SearchParam::make_radius(3.5), SearchParam::make_hybrid(3.5, 4)}) {
        const SearchResult one = tree.search_batch(queries.data(), queries.cols(), param, 1);
        const SearchResult two = tree.search_batch(queries.data(), queries.cols(), param, 2);
        EXPECT_EQ(one.offsets, two.offsets);
        EXPECT_EQ(one.indices, two.indices);
        EXPECT_EQ(one.distances2, two.distances2);
        ASSERT_EQ(one.offsets.size(), 701u);
        std::vector<int> idx;
        std::vector<double> d2;
        size_t total = 0;
        for (int q = 0; q < queries.cols(); ++q) {
            tree.search(queries.col(q).data(), param, idx, d2);
            const int64_t b = one.offsets[q], e = one.offsets[q + 1];
            ASSERT_EQ(static_cast<size_t>(e - b), idx.size()) << "query " << q;
            for (size_t k = 0; k < idx.size(); ++k) {
                EXPECT_EQ(one.indices[b + k], idx[k]);
                EXPECT_EQ(one.distances2[b + k], d2[k]);
            }
            total += idx.size();
        }
        EXPECT_EQ(total, one.indices.size());
        if (param.kind == SearchParam::Kind::Radius) EXPECT_GT(total, 700u);  // the radius finds something
    }
}

TEST(KDTreeXd, OtherDimensionsAndEmptyTrees) {
    // 1-D: the nearest of 0, 1, ..., 9 to 3.4 is 3.
    Eigen::MatrixXd line(1, 10);
    for (int i = 0; i < 10; ++i) line(0, i) = i;
    const KDTreeXd tree1(line);
    const double q = 3.4;
    double d2 = 0.0;
    EXPECT_EQ(tree1.search_nearest(&q, d2), 3);
    EXPECT_NEAR(d2, 0.16, 1e-12);

    const KDTreeXd empty(Eigen::MatrixXd(33, 0));
    EXPECT_EQ(empty.size(), 0u);
    std::vector<int> idx;
    std::vector<double> dist;
    const Eigen::VectorXd query = Eigen::VectorXd::Zero(33);
    EXPECT_EQ(empty.search_knn(query.data(), 3, idx, dist), 0);
    EXPECT_EQ(empty.search_nearest(query.data(), d2), -1);
    const SearchResult r = empty.search_batch(query.data(), 1, SearchParam::make_knn(3));
    EXPECT_EQ(r.offsets, (std::vector<int64_t>{0, 0}));
}

TEST(KDTreeXd, RejectsBadInput) {
    Eigen::MatrixXd pts = random_points(5, 20, 6);
    pts(2, 7) = std::numeric_limits<double>::quiet_NaN();
    EXPECT_THROW(KDTreeXd{pts}, o3d::InvalidArgument);
    EXPECT_THROW(KDTreeXd{Eigen::MatrixXd(0, 4)}, o3d::InvalidArgument);

    const KDTreeXd tree(random_points(5, 20, 7));
    Eigen::VectorXd query = Eigen::VectorXd::Zero(5);
    EXPECT_THROW(tree.search_batch(query.data(), 1, SearchParam::make_knn(0)), o3d::InvalidArgument);
    EXPECT_THROW(tree.search_batch(query.data(), 1, SearchParam::make_radius(-1.0)), o3d::InvalidArgument);
    EXPECT_THROW(tree.search_batch(nullptr, 1, SearchParam::make_knn(1)), o3d::InvalidArgument);
    query[4] = std::numeric_limits<double>::infinity();
    EXPECT_THROW(tree.search_batch(query.data(), 1, SearchParam::make_knn(1)), o3d::InvalidArgument);
    std::vector<int> idx;
    std::vector<double> d2;
    EXPECT_EQ(tree.search_knn(query.data(), 1, idx, d2), 0);  // single searches find nothing
}

// KDTreeFlann(feature).search_knn_vector_xd on the stored FPFH of cloud_bin_0: every descriptor is
// its own nearest neighbour (distance 0), and the 5-NN agree with brute force.
TEST(KDTreeXd, KnnOnStoredFeature) {
    O3D_TEST_DATA_OR_SKIP(path, "open3d/Feature/cloud_bin_0.fpfh.bin");
    const auto feature = o3d::io::read_feature(path);
    ASSERT_EQ(feature.dimension(), 33u);
    const KDTreeXd tree(feature.data);
    const SearchResult self = tree.search_batch(feature.data.data(), feature.num(), SearchParam::make_knn(1), 2);
    size_t at_zero = 0;
    for (size_t i = 0; i < feature.num(); ++i) at_zero += self.distances2[i] == 0.0;
    EXPECT_EQ(at_zero, feature.num());
    std::vector<int> idx;
    std::vector<double> d2;
    for (int i : {0, 500, 3902}) {
        auto all = brute(feature.data, feature.data.col(i).data());
        all.resize(5);
        tree.search_knn(feature.data.col(i).data(), 5, idx, d2);
        ASSERT_EQ(idx.size(), 5u);
        for (size_t k = 0; k < 5; ++k) EXPECT_NEAR(d2[k], all[k].first, 1e-9 * (1.0 + all[k].first));
        EXPECT_EQ(d2[0], 0.0);
    }
}
