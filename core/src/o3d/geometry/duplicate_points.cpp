// SPDX-License-Identifier: MIT
#include "o3d/geometry/duplicate_points.h"

#include <algorithm>
#include <cmath>
#include <numeric>

namespace o3d::geometry {
namespace {

template <class T>
void keep_only(std::vector<T>& values, const std::vector<int64_t>& kept) {
    for (size_t s = 0; s < kept.size(); ++s) values[s] = values[static_cast<size_t>(kept[s])];
    values.resize(kept.size());
}

}  // namespace

std::vector<int64_t> remove_duplicated_points(PointCloud& cloud) {
    const auto& p = cloud.points;
    const size_t n = p.size();
    // Sorting (instead of hashing) groups equal points without a hash that would have to treat -0 and 0
    // alike; points with a NaN break the strict weak order and are never duplicates, so they stay out.
    std::vector<int64_t> order;
    order.reserve(n);
    for (size_t i = 0; i < n; ++i)
        if (!p[i].array().isNaN().any()) order.push_back(static_cast<int64_t>(i));
    std::sort(order.begin(), order.end(), [&](int64_t a, int64_t b) {
        const Eigen::Vector3d &u = p[static_cast<size_t>(a)], &v = p[static_cast<size_t>(b)];
        for (int k = 0; k < 3; ++k)
            if (u[k] != v[k]) return u[k] < v[k];
        return a < b;  // equal points: the first one leads its group
    });
    std::vector<uint8_t> keep(n, 1);
    for (size_t s = 1; s < order.size(); ++s)
        if (p[static_cast<size_t>(order[s])] == p[static_cast<size_t>(order[s - 1])])
            keep[static_cast<size_t>(order[s])] = 0;
    std::vector<int64_t> kept;
    for (size_t i = 0; i < n; ++i)
        if (keep[i]) kept.push_back(static_cast<int64_t>(i));
    if (kept.size() == n) return kept;
    const bool normals = cloud.has_normals(), colors = cloud.has_colors(), covariances = cloud.has_covariances();
    keep_only(cloud.points, kept);
    if (normals) keep_only(cloud.normals, kept);
    if (colors) keep_only(cloud.colors, kept);
    if (covariances) keep_only(cloud.covariances, kept);
    return kept;
}

}  // namespace o3d::geometry
