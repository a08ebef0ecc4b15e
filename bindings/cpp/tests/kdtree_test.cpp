// SPDX-License-Identifier: MIT
// KDTreeFlann / SearchResult: knn, radius and hybrid results against brute force.
#include <algorithm>
#include <cmath>

#include "test_util.hpp"

using o3dpp::Vec3;

namespace {
double d2(const Vec3& a, const Vec3& b) {
    return (a[0] - b[0]) * (a[0] - b[0]) + (a[1] - b[1]) * (a[1] - b[1]) + (a[2] - b[2]) * (a[2] - b[2]);
}
// Indices of `pts` sorted by distance to q.
std::vector<int32_t> brute_order(const std::vector<Vec3>& pts, const Vec3& q) {
    std::vector<int32_t> idx(pts.size());
    for (size_t i = 0; i < idx.size(); ++i) idx[i] = int32_t(i);
    std::sort(idx.begin(), idx.end(), [&](int32_t a, int32_t b) { return d2(pts[a], q) < d2(pts[b], q); });
    return idx;
}
}  // namespace

TEST(KDTree, KnnMatchesBruteForce) {
    const auto pts = o3dpp_test::random_points(500);
    const auto queries = o3dpp_test::random_points(20, -1.0, 1.0, 7);
    o3dpp::KDTreeFlann tree{o3dpp::PointCloud(pts)};
    EXPECT_EQ(tree.size(), 500u);
    auto res = tree.search_knn(queries, 7);
    ASSERT_EQ(res.num_queries(), 20u);
    ASSERT_EQ(res.total(), 140u);
    for (size_t q = 0; q < queries.size(); ++q) {
        const auto expected = brute_order(pts, queries[q]);
        const auto idx = res.indices(q);
        const auto dist = res.distances2(q);
        ASSERT_EQ(idx.size(), 7u);
        for (size_t k = 0; k < 7; ++k) {
            EXPECT_EQ(idx[k], expected[k]) << "query " << q << " rank " << k;
            EXPECT_NEAR(dist[k], d2(pts[expected[k]], queries[q]), 1e-12);
        }
    }
}

TEST(KDTree, RadiusAndHybridMatchBruteForce) {
    const auto pts = o3dpp_test::random_points(400);
    const auto queries = o3dpp_test::random_points(10, -1.0, 1.0, 3);
    o3dpp::KDTreeFlann tree(pts);
    const double r = 0.3;
    auto radius = tree.search_radius(queries, r);
    auto hybrid = tree.search_hybrid(queries, r, 5);
    for (size_t q = 0; q < queries.size(); ++q) {
        std::vector<int32_t> inside;
        for (int32_t i : brute_order(pts, queries[q]))
            if (d2(pts[i], queries[q]) <= r * r) inside.push_back(i);
        const auto got = radius.indices(q);
        EXPECT_EQ(std::vector<int32_t>(got.begin(), got.end()), inside) << "query " << q;
        const auto h = hybrid.indices(q);
        const size_t expect_n = std::min<size_t>(5, inside.size());
        ASSERT_EQ(h.size(), expect_n);
        for (size_t k = 0; k < expect_n; ++k) EXPECT_EQ(h[k], inside[k]);
    }
}

TEST(KDTree, CopiesEqualViewsAndOffsetsAreConsistent) {
    const auto pts = o3dpp_test::random_points(100);
    o3dpp::KDTreeFlann tree(pts.front().data(), pts.size());
    auto res = tree.search(pts, o3dpp::SearchParam::Knn(3), 2);
    const auto off = res.get_offsets();
    ASSERT_EQ(off.size(), 101u);
    EXPECT_EQ(off.front(), 0);
    EXPECT_EQ(off.back(), 300);
    EXPECT_TRUE(std::equal(off.begin(), off.end(), res.offsets().begin()));
    const auto idx = res.get_indices();
    EXPECT_TRUE(std::equal(idx.begin(), idx.end(), res.indices().begin()));
    const auto dist = res.get_distances2();
    EXPECT_TRUE(std::equal(dist.begin(), dist.end(), res.distances2().begin()));
    // Each point is its own nearest neighbour.
    for (size_t i = 0; i < pts.size(); ++i) {
        EXPECT_EQ(res.indices(i)[0], int32_t(i));
        EXPECT_EQ(res.distances2(i)[0], 0.0);
    }
    EXPECT_THROW(res.indices(100), o3dpp::Error);
}

TEST(KDTree, FloatQueriesMatchDouble) {
    std::vector<Vec3> pts;
    for (int i = 0; i < 50; ++i) pts.push_back({double(i), 0.5 * i, 0});
    o3dpp::KDTreeFlann tree(pts);
    const float q[] = {10.2f, 5.0f, 0.0f, 30.9f, 15.5f, 0.0f};
    auto res = tree.search(q, 2, o3dpp::SearchParam::Knn(1));
    EXPECT_EQ(res.get_indices(), (std::vector<int32_t>{10, 31}));
}

TEST(KDTree, EmptyAndNonFinite) {
    o3dpp::KDTreeFlann empty{o3dpp::PointCloud()};
    EXPECT_EQ(empty.size(), 0u);
    std::vector<Vec3> bad = {{0, 0, 0}, {std::nan(""), 0, 0}};
    EXPECT_O3D_ERROR(o3dpp::KDTreeFlann{bad}, O3D_ERROR_INVALID_ARGUMENT);
}
