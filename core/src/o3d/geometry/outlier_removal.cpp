// SPDX-License-Identifier: MIT
#include "o3d/geometry/outlier_removal.h"

#include <cmath>
#include <limits>
#include <string>

#include "o3d/geometry/self_knn_distances.h"
#include "o3d/kdtree/kd_tree.h"
#include "o3d/utility/error.h"

namespace o3d::geometry {

std::vector<int64_t> statistical_outlier_indices(const PointCloud& cloud, int nb_neighbors, double std_ratio,
                                                 int num_threads) {
    if (nb_neighbors < 1) throw InvalidArgument("nb_neighbors must be >= 1, got " + std::to_string(nb_neighbors));
    if (!std::isfinite(std_ratio) || std_ratio <= 0.0)
        throw InvalidArgument("std_ratio must be finite and > 0, got " + std::to_string(std_ratio));
    if (cloud.points.empty()) throw InvalidArgument("point cloud is empty");
    const size_t n = cloud.points.size();
    const std::vector<double> avg = mean_self_knn_distances(cloud.points, nb_neighbors, num_threads);
    size_t valid = 0;
    for (double a : avg)
        if (a >= 0.0) ++valid;
    std::vector<int64_t> kept;
    if (valid == 0) return kept;
    double mean = 0.0;
    for (double a : avg)
        if (a > 0.0) mean += a;
    mean /= static_cast<double>(valid);
    double sq = 0.0;
    for (double a : avg)
        if (a > 0.0) sq += (a - mean) * (a - mean);
    // Bessel's correction as Open3D; with one point its avg is 0 and nothing is kept anyway.
    const double std_dev = valid > 1 ? std::sqrt(sq / static_cast<double>(valid - 1)) : 0.0;
    const double threshold = mean + std_ratio * std_dev;
    for (size_t i = 0; i < n; ++i)
        if (avg[i] > 0.0 && avg[i] < threshold) kept.push_back(static_cast<int64_t>(i));
    return kept;
}

std::vector<int64_t> radius_outlier_indices(const PointCloud& cloud, int nb_points, double radius, int num_threads) {
    if (nb_points < 1) throw InvalidArgument("nb_points must be >= 1, got " + std::to_string(nb_points));
    if (!std::isfinite(radius) || radius <= 0.0)
        throw InvalidArgument("radius must be finite and > 0, got " + std::to_string(radius));
    if (cloud.points.empty()) throw InvalidArgument("point cloud is empty");
    const kdtree::KDTree tree(cloud.points);
    const int cap = nb_points < std::numeric_limits<int>::max() ? nb_points + 1 : nb_points;
    // Hybrid search capped at nb_points + 1: enough to decide "> nb_points", without listing dense neighbourhoods.
    const kdtree::SearchResult res =
        tree.search_batch(cloud.points, kdtree::SearchParam::make_hybrid(radius, cap), num_threads);
    std::vector<int64_t> kept;
    for (size_t i = 0; i < cloud.points.size(); ++i)
        if (res.offsets[i + 1] - res.offsets[i] > nb_points) kept.push_back(static_cast<int64_t>(i));
    return kept;
}

}  // namespace o3d::geometry
