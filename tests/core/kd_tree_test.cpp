// SPDX-License-Identifier: MIT
// KD-tree searches against brute force on random clouds; batch == single; thread-count independence.
#include "o3d/kdtree/kd_tree.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>

#include "o3d/utility/error.h"

using o3d::kdtree::KDTree;
using o3d::kdtree::SearchParam;
using o3d::kdtree::SearchResult;

namespace {

std::vector<Eigen::Vector3d> random_points(size_t n, uint64_t seed) {
    std::mt19937_64 rng(seed);
    std::uniform_real_distribution<double> u(-1.0, 1.0);
    std::vector<Eigen::Vector3d> pts(n);
    for (auto& p : pts) p = Eigen::Vector3d(u(rng), u(rng), u(rng));
    return pts;
}

/// Brute force: (distance2, index) of every point, sorted ascending.
std::vector<std::pair<double, int>> brute(const std::vector<Eigen::Vector3d>& pts, const Eigen::Vector3d& q) {
    std::vector<std::pair<double, int>> all;
    for (size_t i = 0; i < pts.size(); ++i) all.emplace_back((pts[i] - q).squaredNorm(), static_cast<int>(i));
    std::sort(all.begin(), all.end());
    return all;
}

void expect_matches(const std::vector<std::pair<double, int>>& expected, const std::vector<int>& idx,
                    const std::vector<double>& d2) {
    ASSERT_EQ(idx.size(), expected.size());
    ASSERT_EQ(d2.size(), expected.size());
    for (size_t i = 0; i < idx.size(); ++i) {
        EXPECT_EQ(idx[i], expected[i].second) << "rank " << i;
        EXPECT_DOUBLE_EQ(d2[i], expected[i].first) << "rank " << i;
    }
}

}  // namespace

TEST(KDTree, KnnMatchesBruteForce) {
    const auto pts = random_points(2000, 1);
    const KDTree tree(pts);
    std::vector<int> idx;
    std::vector<double> d2;
    for (const auto& q : random_points(50, 2)) {
        auto all = brute(pts, q);
        ASSERT_EQ(tree.search_knn(q, 17, idx, d2), 17);
        all.resize(17);
        expect_matches(all, idx, d2);
    }
}

TEST(KDTree, RadiusMatchesBruteForce) {
    const auto pts = random_points(2000, 3);
    const KDTree tree(pts);
    std::vector<int> idx;
    std::vector<double> d2;
    const double r = 0.3;
    for (const auto& q : random_points(50, 4)) {
        auto all = brute(pts, q);
        all.erase(std::remove_if(all.begin(), all.end(), [&](const auto& e) { return !(e.first < r * r); }),
                  all.end());
        EXPECT_EQ(tree.search_radius(q, r, idx, d2), static_cast<int>(all.size()));
        expect_matches(all, idx, d2);
    }
}

TEST(KDTree, HybridMatchesBruteForce) {
    const auto pts = random_points(2000, 5);
    const KDTree tree(pts);
    std::vector<int> idx;
    std::vector<double> d2;
    const double r = 0.2;
    size_t capped = 0, uncapped = 0;
    for (const auto& q : random_points(100, 6)) {
        auto all = brute(pts, q);
        all.erase(std::remove_if(all.begin(), all.end(), [&](const auto& e) { return !(e.first < r * r); }),
                  all.end());
        (all.size() > 8 ? capped : uncapped)++;
        if (all.size() > 8) all.resize(8);
        tree.search_hybrid(q, r, 8, idx, d2);
        expect_matches(all, idx, d2);
    }
    EXPECT_GT(capped, 0u);  // both regimes were exercised
    EXPECT_GT(uncapped, 0u);
}

TEST(KDTree, KnnLargerThanTreeReturnsAll) {
    const auto pts = random_points(7, 7);
    const KDTree tree(pts);
    std::vector<int> idx;
    std::vector<double> d2;
    EXPECT_EQ(tree.search_knn(Eigen::Vector3d::Zero(), 100, idx, d2), 7);
    expect_matches(brute(pts, Eigen::Vector3d::Zero()), idx, d2);
    const SearchResult r = tree.search_batch(pts, SearchParam::make_knn(100), 1);
    EXPECT_EQ(r.offsets.back(), 49);
}

TEST(KDTree, NearestWithinDistance) {
    const std::vector<Eigen::Vector3d> pts = {{0, 0, 0}, {1, 0, 0}, {0, 2, 0}};
    const KDTree tree(pts);
    double d2 = -1;
    EXPECT_EQ(tree.search_nearest({0.9, 0.1, 0}, 1.0, d2), 1);
    EXPECT_NEAR(d2, 0.02, 1e-15);
    EXPECT_EQ(tree.search_nearest({0, 5, 0}, 1.0, d2), -1);
    EXPECT_EQ(tree.search_nearest({0, 5, 0}, std::numeric_limits<double>::infinity(), d2), 2);
    EXPECT_DOUBLE_EQ(d2, 9.0);
}

TEST(KDTree, BatchEqualsSingleQueries) {
    const auto pts = random_points(20000, 8);  // above the size where queries get reordered
    const KDTree tree(pts);
    const auto queries = random_points(12000, 9);
    const SearchParam params[] = {SearchParam::make_knn(10), SearchParam::make_radius(0.08),
                                  SearchParam::make_hybrid(0.08, 5)};
    std::vector<int> idx;
    std::vector<double> d2;
    for (const auto& p : params) {
        const SearchResult r = tree.search_batch(queries, p, 2);
        ASSERT_EQ(r.offsets.size(), queries.size() + 1);
        for (size_t q = 0; q < queries.size(); q += 37) {
            tree.search(queries[q], p, idx, d2);
            const auto b = static_cast<size_t>(r.offsets[q]), e = static_cast<size_t>(r.offsets[q + 1]);
            ASSERT_EQ(e - b, idx.size()) << "query " << q;
            for (size_t k = 0; k < idx.size(); ++k) {
                EXPECT_EQ(r.indices[b + k], idx[k]);
                EXPECT_EQ(r.distances2[b + k], d2[k]);
            }
        }
    }
}

TEST(KDTree, BatchIsIdenticalForOneAndTwoThreads) {
    const auto pts = random_points(30000, 10);
    const KDTree tree(pts);
    for (const auto& p : {SearchParam::make_knn(30), SearchParam::make_radius(0.1), SearchParam::make_hybrid(0.1, 30)}) {
        const SearchResult a = tree.search_batch(pts, p, 1);
        const SearchResult b = tree.search_batch(pts, p, 2);
        EXPECT_EQ(a.offsets, b.offsets);
        EXPECT_EQ(a.indices, b.indices);
        EXPECT_EQ(a.distances2, b.distances2);  // bitwise: same doubles
    }
}

TEST(KDTree, EmptyTreeFindsNothing) {
    const KDTree tree({});
    std::vector<int> idx;
    std::vector<double> d2;
    EXPECT_EQ(tree.size(), 0u);
    EXPECT_EQ(tree.search_knn(Eigen::Vector3d::Zero(), 3, idx, d2), 0);
    double dist2;
    EXPECT_EQ(tree.search_nearest(Eigen::Vector3d::Zero(), 1.0, dist2), -1);
    const SearchResult r = tree.search_batch({Eigen::Vector3d::Zero()}, SearchParam::make_knn(3));
    EXPECT_EQ(r.offsets, (std::vector<int64_t>{0, 0}));
}

TEST(KDTree, RejectsBadInput) {
    std::vector<Eigen::Vector3d> pts = random_points(10, 11);
    pts[3].y() = std::nan("");
    EXPECT_THROW(KDTree{pts}, o3d::InvalidArgument);
    const KDTree tree(random_points(10, 12));
    std::vector<int> idx;
    std::vector<double> d2;
    EXPECT_THROW(tree.search(Eigen::Vector3d::Zero(), SearchParam::make_knn(0), idx, d2), o3d::InvalidArgument);
    EXPECT_THROW(tree.search(Eigen::Vector3d::Zero(), SearchParam::make_radius(-1), idx, d2), o3d::InvalidArgument);
    EXPECT_THROW(tree.search_batch({Eigen::Vector3d(0, INFINITY, 0)}, SearchParam::make_knn(1)), o3d::InvalidArgument);
    // A single non-finite query finds nothing rather than failing (hot path of ICP).
    EXPECT_EQ(tree.search_knn(Eigen::Vector3d(NAN, 0, 0), 3, idx, d2), 0);
}
