// SPDX-License-Identifier: MIT
#include "o3d/geometry/distances.h"

#include <cmath>

#include "o3d/kdtree/kd_tree.h"
#include "o3d/utility/error.h"

namespace o3d::geometry {

std::vector<double> compute_nearest_neighbor_distance(const PointCloud& cloud, int num_threads) {
    const size_t n = cloud.points.size();
    std::vector<double> out(n, 0.0);
    if (n < 2) {
        if (n == 1 && !cloud.points[0].allFinite()) throw InvalidArgument("point 0 has a non-finite coordinate");
        return out;
    }
    const kdtree::KDTree tree(cloud.points);
    // Two nearest: the point itself (or a duplicate at distance 0) and its nearest other point.
    const kdtree::SearchResult r = tree.search_batch(cloud.points, kdtree::SearchParam::make_knn(2), num_threads);
    for (size_t i = 0; i < n; ++i) out[i] = std::sqrt(r.distances2[static_cast<size_t>(r.offsets[i]) + 1]);
    return out;
}

std::vector<double> compute_point_cloud_distance(const PointCloud& source, const PointCloud& target,
                                                 int num_threads) {
    if (source.points.empty()) return {};
    if (target.points.empty()) throw InvalidArgument("the target cloud is empty");
    const kdtree::KDTree tree(target.points);
    const kdtree::SearchResult r = tree.search_batch(source.points, kdtree::SearchParam::make_knn(1), num_threads);
    std::vector<double> out(source.points.size());
    for (size_t i = 0; i < out.size(); ++i) out[i] = std::sqrt(r.distances2[static_cast<size_t>(r.offsets[i])]);
    return out;
}

}  // namespace o3d::geometry
