// SPDX-License-Identifier: MIT
// smooth_laplacian and smooth_taubin: explicit uniform Laplacian steps on a k-nearest-neighbour graph.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "o3d/geometry/point_cloud_smoothing.h"
#include "o3d/utility/error.h"
#include "o3d/utility/parallel.h"

namespace o3d::geometry {
namespace {

/// Largest fixed graph (indices) built: 2^31 entries, 8 GiB.
constexpr size_t kMaxGraphEntries = size_t{1} << 31;

/// @brief Writes the `k` nearest other points of `p[i]` to `row` (k <= N - 1, so every slot is filled: the
/// search asks for k + 1 and drops the point's own index wherever it lands among equal distances).
void nearest_others(const kdtree::KDTree& tree, const std::vector<Eigen::Vector3d>& p, size_t i, int k,
                    std::vector<int>& idx, std::vector<double>& d2, int* row) {
    tree.search_knn(p[i], k + 1, idx, d2);
    size_t filled = 0;
    for (size_t r = 0; r < idx.size() && filled < static_cast<size_t>(k); ++r)
        if (static_cast<size_t>(idx[r]) != i) row[filled++] = idx[r];
}

/// @brief The fixed graph: `k` slots per point, from the input positions.
std::vector<int> knn_graph(const std::vector<Eigen::Vector3d>& p, int k, int threads) {
    const size_t width = static_cast<size_t>(k);
    if (p.size() > kMaxGraphEntries / width)
        throw InvalidArgument("a fixed neighbourhood graph of " + std::to_string(p.size()) + " points x " +
                              std::to_string(k) + " neighbours is too large; use fewer neighbours or "
                              "use_fixed_neighborhoods = false");
    std::vector<int> graph(p.size() * width);
    const kdtree::KDTree tree(p);
#pragma omp parallel num_threads(threads)
    {
        std::vector<int> idx;
        std::vector<double> d2;
#pragma omp for schedule(dynamic, 256)
        for (int64_t ii = 0; ii < static_cast<int64_t>(p.size()); ++ii) {
            const size_t i = static_cast<size_t>(ii);
            nearest_others(tree, p, i, k, idx, d2, graph.data() + i * width);
        }
    }
    return graph;
}

/// @brief One step next_i = p_i + factor * (mean of the k nearest other points of i - p_i), every point from
/// `p`; the neighbours come from `graph` when given, else from a tree over `p` (searched point by point, so
/// a large k costs no N x k table).
void laplacian_step(const std::vector<Eigen::Vector3d>& p, const std::vector<int>* graph, int k, double factor,
                    std::vector<Eigen::Vector3d>& next, int threads) {
    const size_t width = static_cast<size_t>(k);
    std::unique_ptr<kdtree::KDTree> tree;
    if (!graph) tree = std::make_unique<kdtree::KDTree>(p);
#pragma omp parallel num_threads(threads)
    {
        std::vector<int> idx, own_row(graph ? 0 : width);
        std::vector<double> d2;
#pragma omp for schedule(dynamic, 256)
        for (int64_t ii = 0; ii < static_cast<int64_t>(p.size()); ++ii) {
            const size_t i = static_cast<size_t>(ii);
            const int* row = graph ? graph->data() + i * width : own_row.data();
            if (!graph) nearest_others(*tree, p, i, k, idx, d2, own_row.data());
            Eigen::Vector3d sum = Eigen::Vector3d::Zero();
            for (size_t r = 0; r < width; ++r) sum += p[static_cast<size_t>(row[r])];
            next[i] = p[i] + factor * (sum / static_cast<double>(k) - p[i]);
        }
    }
}

void check_finite(double x, const char* name) {
    if (!std::isfinite(x)) throw InvalidArgument(std::string(name) + " must be finite, got " + std::to_string(x));
}

void check_common(const PointCloud& cloud, int iterations, double lambda, int knn) {
    if (iterations < 0) throw InvalidArgument("iterations must be >= 0, got " + std::to_string(iterations));
    if (knn < 1) throw InvalidArgument("knn must be >= 1, got " + std::to_string(knn));
    check_finite(lambda, "lambda");
    for (size_t i = 0; i < cloud.points.size(); ++i)
        if (!cloud.points[i].allFinite())
            throw InvalidArgument("point " + std::to_string(i) + " has a non-finite coordinate");
}

/// @brief `iterations` rounds of one Laplacian step per factor, on a graph rebuilt before every step or
/// built once from the input.
PointCloud smooth(const PointCloud& cloud, int iterations, const std::vector<double>& factors, int knn,
                  bool fixed, int num_threads) {
    PointCloud out = cloud;
    const size_t n = cloud.points.size();
    if (iterations == 0 || n < 2) return out;  // a single point has no neighbour to move towards
    // Never more neighbours than other points (and no overflow in the k + 1 search).
    const int k = static_cast<int>(std::min<size_t>(static_cast<size_t>(knn), n - 1));
    const int threads = utility::resolve_num_threads(num_threads);
    std::vector<int> graph;
    if (fixed) graph = knn_graph(out.points, k, threads);
    std::vector<Eigen::Vector3d> next(n);
    for (int it = 0; it < iterations; ++it) {
        for (const double factor : factors) {
            laplacian_step(out.points, fixed ? &graph : nullptr, k, factor, next, threads);
            std::swap(out.points, next);
        }
    }
    return out;
}

}  // namespace

PointCloud smooth_laplacian(const PointCloud& cloud, int iterations, double lambda, int knn,
                            bool use_fixed_neighborhoods, int num_threads) {
    check_common(cloud, iterations, lambda, knn);
    return smooth(cloud, iterations, {lambda}, knn, use_fixed_neighborhoods, num_threads);
}

PointCloud smooth_taubin(const PointCloud& cloud, int iterations, double lambda, double mu, int knn,
                         bool use_fixed_neighborhoods, int num_threads) {
    check_common(cloud, iterations, lambda, knn);
    check_finite(mu, "mu");
    return smooth(cloud, iterations, {lambda, mu}, knn, use_fixed_neighborhoods, num_threads);
}

}  // namespace o3d::geometry
