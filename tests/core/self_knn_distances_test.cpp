// SPDX-License-Identifier: MIT
// The grid-based self-kNN must give bit-identical mean distances to the KD-tree's batch kNN.
#include "o3d/geometry/self_knn_distances.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "o3d/io/point_cloud_io.h"
#include "o3d/kdtree/kd_tree.h"
#include "o3d/utility/error.h"
#include "test_data.h"

namespace {

using o3d::geometry::mean_self_knn_distances;

std::vector<double> reference(const std::vector<Eigen::Vector3d>& pts, int k) {
    const o3d::kdtree::KDTree tree(pts);
    const auto res = tree.search_batch(pts, o3d::kdtree::SearchParam::make_knn(k), 1);
    std::vector<double> out(pts.size());
    for (size_t i = 0; i < pts.size(); ++i) {
        double sum = 0.0;
        for (int64_t j = res.offsets[i]; j < res.offsets[i + 1]; ++j) sum += std::sqrt(res.distances2[j]);
        out[i] = sum / static_cast<double>(res.offsets[i + 1] - res.offsets[i]);
    }
    return out;
}

void expect_identical(const std::vector<Eigen::Vector3d>& pts, int k) {
    const std::vector<double> want = reference(pts, k);
    for (int threads : {1, 3}) {
        const std::vector<double> got = mean_self_knn_distances(pts, k, threads);
        ASSERT_EQ(got.size(), want.size());
        for (size_t i = 0; i < want.size(); ++i) ASSERT_EQ(got[i], want[i]) << "point " << i << ", k " << k;
    }
}

TEST(SelfKnnDistances, UniformCubeMatchesKdTree) {
    std::mt19937_64 rng(1);
    std::uniform_real_distribution<double> u(-1.0, 1.0);
    std::vector<Eigen::Vector3d> pts(20000);
    for (auto& p : pts) p = {u(rng), u(rng), u(rng)};
    expect_identical(pts, 20);
    expect_identical(pts, 1);
}

TEST(SelfKnnDistances, SurfaceWithDuplicatesAndOutliersMatchesKdTree) {
    std::mt19937_64 rng(2);
    std::uniform_real_distribution<double> u(0.0, 5.0);
    std::vector<Eigen::Vector3d> pts;
    for (int i = 0; i < 15000; ++i) pts.emplace_back(u(rng), u(rng), 0.001 * u(rng));  // a thin slab
    for (int i = 0; i < 300; ++i) pts.push_back(pts[static_cast<size_t>(i) * 7]);   // exact duplicates
    for (int i = 0; i < 20; ++i) pts.emplace_back(u(rng) * 40.0, -30.0, 25.0 * u(rng));  // far outliers
    expect_identical(pts, 20);
}

TEST(SelfKnnDistances, LineAndTinyCloudsMatchKdTree) {
    std::vector<Eigen::Vector3d> line;
    for (int i = 0; i < 5000; ++i) line.emplace_back(0.01 * i, 0.0, 0.0);
    expect_identical(line, 20);
    std::vector<Eigen::Vector3d> tiny = {{0, 0, 0}, {1, 0, 0}, {0, 2, 0}};
    expect_identical(tiny, 20);  // k > n: all points
    std::vector<Eigen::Vector3d> same(50, Eigen::Vector3d(1, 2, 3));
    expect_identical(same, 20);
}

TEST(SelfKnnDistances, ScanFromSharedDataMatchesKdTree) {
    O3D_TEST_DATA_OR_SKIP(path, "open3d/fragment.pcd");
    const auto cloud = o3d::io::read_point_cloud(path);
    expect_identical(cloud.points, 20);
}

TEST(SelfKnnDistances, BadInputIsAnError) {
    std::vector<Eigen::Vector3d> pts = {{0, 0, 0}, {1, 1, 1}};
    EXPECT_THROW(mean_self_knn_distances(pts, 0), o3d::InvalidArgument);
    pts.emplace_back(NAN, 0, 0);
    EXPECT_THROW(mean_self_knn_distances(pts, 3), o3d::InvalidArgument);
    EXPECT_TRUE(mean_self_knn_distances({}, 3).empty());
}

}  // namespace
