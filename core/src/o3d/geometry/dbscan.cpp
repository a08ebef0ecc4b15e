// SPDX-License-Identifier: MIT
#include "o3d/geometry/dbscan.h"

#include <cmath>
#include <limits>
#include <string>

#include "o3d/kdtree/kd_tree.h"
#include "o3d/utility/error.h"

namespace o3d::geometry {

std::vector<int32_t> cluster_dbscan(const PointCloud& cloud, double eps, int min_points, int num_threads) {
    if (!std::isfinite(eps) || eps <= 0.0) throw InvalidArgument("eps must be finite and > 0, got " + std::to_string(eps));
    if (min_points < 0) throw InvalidArgument("min_points must be >= 0, got " + std::to_string(min_points));
    if (cloud.points.empty()) throw InvalidArgument("point cloud is empty");
    const kdtree::KDTree tree(cloud.points);
    const kdtree::SearchResult nbs = tree.search_batch(cloud.points, kdtree::SearchParam::make_radius(eps), num_threads);
    const size_t n = cloud.points.size();
    auto is_core = [&](size_t i) { return nbs.offsets[i + 1] - nbs.offsets[i] >= static_cast<int64_t>(min_points); };

    constexpr int32_t kUndefined = -2, kNoise = -1;
    std::vector<int32_t> labels(n, kUndefined);
    int32_t cluster = 0;
    std::vector<int32_t> stack;
    for (size_t idx = 0; idx < n; ++idx) {
        if (labels[idx] != kUndefined) continue;
        if (!is_core(idx)) {
            labels[idx] = kNoise;
            continue;
        }
        // Grow through core points. A border point (noise so far, or undefined and not core) is labelled
        // but not expanded; a point labelled by an earlier cluster is left alone, as in Open3D.
        labels[idx] = cluster;
        stack.assign(1, static_cast<int32_t>(idx));
        while (!stack.empty()) {
            const int32_t p = stack.back();
            stack.pop_back();
            for (int64_t k = nbs.offsets[p]; k < nbs.offsets[p + 1]; ++k) {
                const int32_t q = nbs.indices[k];
                if (labels[q] == kNoise) {
                    labels[q] = cluster;
                } else if (labels[q] == kUndefined) {
                    labels[q] = cluster;
                    if (is_core(q)) stack.push_back(q);
                }
            }
        }
        ++cluster;
    }
    // Renumber clusters by their lowest point index (the contract of the C API).
    std::vector<int32_t> renumber(static_cast<size_t>(cluster), -1);
    int32_t next = 0;
    for (size_t i = 0; i < n; ++i) {
        const int32_t l = labels[i];
        if (l < 0) continue;
        if (renumber[l] < 0) renumber[l] = next++;
        labels[i] = renumber[l];
    }
    return labels;
}

}  // namespace o3d::geometry
