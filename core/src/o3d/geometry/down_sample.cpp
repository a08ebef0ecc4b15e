// SPDX-License-Identifier: MIT
#include "o3d/geometry/down_sample.h"

#include <algorithm>
#include <array>
#include <climits>
#include <cmath>
#include <limits>
#include <numeric>
#include <random>
#include <string>
#include <tuple>

#include "o3d/geometry/point_cloud_ops.h"
#include "o3d/geometry/radix_sort.h"
#include "o3d/utility/error.h"
#include "o3d/utility/parallel.h"

namespace o3d::geometry {
namespace {

using VoxelIndex = std::array<int64_t, 3>;

/// @brief Bits needed to hold values up to v.
int bit_width(uint64_t v) {
    int bits = 0;
    while (v) {
        ++bits;
        v >>= 1;
    }
    return bits;
}

/// @brief Point indices grouped by voxel: voxels ordered by (z, y, x), points within a voxel by index.
std::vector<size_t> group_by_voxel(const std::vector<VoxelIndex>& voxel, const VoxelIndex& dims,
                                   std::vector<size_t>& run_starts) {
    const size_t n = voxel.size();
    std::vector<size_t> order(n);
    run_starts.clear();
    const unsigned __int128 cells = static_cast<unsigned __int128>(dims[0]) * static_cast<unsigned __int128>(dims[1]) *
                                    static_cast<unsigned __int128>(dims[2]);
    auto same = [&](size_t a, size_t b) { return voxel[a] == voxel[b]; };
    if (cells <= std::numeric_limits<uint64_t>::max()) {
        // Common case: one 64-bit linear key, radix-sorted (stable, so ties stay in index order).
        std::vector<std::pair<uint64_t, size_t>> keyed(n);
        for (size_t i = 0; i < n; ++i) {
            const auto& v = voxel[i];
            const uint64_t key = static_cast<uint64_t>(v[0]) +
                                 static_cast<uint64_t>(dims[0]) *
                                     (static_cast<uint64_t>(v[1]) + static_cast<uint64_t>(dims[1]) * static_cast<uint64_t>(v[2]));
            keyed[i] = {key, i};
        }
        radix_sort_by_key(keyed, bit_width(static_cast<uint64_t>(cells - 1)));
        for (size_t i = 0; i < n; ++i) order[i] = keyed[i].second;
    } else {
        std::iota(order.begin(), order.end(), size_t{0});
        std::stable_sort(order.begin(), order.end(), [&](size_t a, size_t b) {
            const auto& va = voxel[a];
            const auto& vb = voxel[b];
            return std::tie(va[2], va[1], va[0]) < std::tie(vb[2], vb[1], vb[0]);
        });
    }
    for (size_t i = 0; i < n; ++i)
        if (i == 0 || !same(order[i], order[i - 1])) run_starts.push_back(i);
    run_starts.push_back(n);
    return order;
}

/// @brief Uniform integer in [0, range) from `rng` without modulo bias (Lemire's multiply-shift).
uint64_t bounded(std::mt19937_64& rng, uint64_t range) {
    unsigned __int128 m = static_cast<unsigned __int128>(rng()) * range;
    uint64_t low = static_cast<uint64_t>(m);
    if (low < range) {
        const uint64_t threshold = (0 - range) % range;
        while (low < threshold) {
            m = static_cast<unsigned __int128>(rng()) * range;
            low = static_cast<uint64_t>(m);
        }
    }
    return static_cast<uint64_t>(m >> 64);
}

PointCloud select_sorted(const PointCloud& cloud, const std::vector<size_t>& indices) {
    std::vector<uint8_t> keep(cloud.points.size(), 0);
    for (size_t i : indices) keep[i] = 1;
    return select_by_mask(cloud, keep);
}

}  // namespace

PointCloud voxel_down_sample(const PointCloud& cloud, double voxel_size, int num_threads) {
    if (!std::isfinite(voxel_size) || voxel_size <= 0.0)
        throw InvalidArgument("voxel_size must be finite and > 0, got " + std::to_string(voxel_size));
    const size_t n = cloud.points.size();
    if (n == 0) return {};
    for (size_t i = 0; i < n; ++i)
        if (!cloud.points[i].allFinite())
            throw InvalidArgument("point " + std::to_string(i) +
                                  " is not finite (call remove_non_finite_points first)");
    const Eigen::Vector3d half(0.5 * voxel_size, 0.5 * voxel_size, 0.5 * voxel_size);
    const Eigen::Vector3d origin = min_bound(cloud) - half;
    const Eigen::Vector3d extent = max_bound(cloud) + half - origin;
    // Open3D's own limit: the voxel index must fit an int.
    if (voxel_size * static_cast<double>(INT_MAX) < extent.maxCoeff())
        throw InvalidArgument("voxel_size " + std::to_string(voxel_size) + " is too small for a cloud of extent " +
                              std::to_string(extent.maxCoeff()));

    std::vector<VoxelIndex> voxel(n);
    VoxelIndex dims{1, 1, 1};
    const int threads = utility::resolve_num_threads(num_threads);
#pragma omp parallel for schedule(static) num_threads(threads)
    for (int64_t i = 0; i < static_cast<int64_t>(n); ++i) {
        const Eigen::Vector3d r = (cloud.points[static_cast<size_t>(i)] - origin) / voxel_size;
        for (int a = 0; a < 3; ++a) voxel[static_cast<size_t>(i)][a] = static_cast<int64_t>(std::floor(r(a)));
    }
    for (const auto& v : voxel)
        for (int a = 0; a < 3; ++a) dims[a] = std::max(dims[a], v[a] + 1);

    std::vector<size_t> runs;
    const std::vector<size_t> order = group_by_voxel(voxel, dims, runs);
    const size_t num_voxels = runs.size() - 1;
    const bool normals = cloud.has_normals(), colors = cloud.has_colors();
    PointCloud out;
    out.points.resize(num_voxels);
    if (normals) out.normals.resize(num_voxels);
    if (colors) out.colors.resize(num_voxels);
#pragma omp parallel for schedule(static) num_threads(threads)
    for (int64_t v = 0; v < static_cast<int64_t>(num_voxels); ++v) {
        const size_t begin = runs[static_cast<size_t>(v)], end = runs[static_cast<size_t>(v) + 1];
        Eigen::Vector3d p = Eigen::Vector3d::Zero(), nrm = Eigen::Vector3d::Zero(), col = Eigen::Vector3d::Zero();
        for (size_t j = begin; j < end; ++j) {
            const size_t i = order[j];
            p += cloud.points[i];
            if (normals) nrm += cloud.normals[i];
            if (colors) col += cloud.colors[i];
        }
        const double count = static_cast<double>(end - begin);
        out.points[static_cast<size_t>(v)] = p / count;
        if (normals) out.normals[static_cast<size_t>(v)] = nrm / count;
        if (colors) out.colors[static_cast<size_t>(v)] = col / count;
    }
    return out;
}

PointCloud uniform_down_sample(const PointCloud& cloud, size_t every_k_points) {
    if (every_k_points == 0) throw InvalidArgument("every_k_points must be >= 1");
    std::vector<uint8_t> keep(cloud.points.size(), 0);
    for (size_t i = 0; i < keep.size(); i += every_k_points) keep[i] = 1;
    return select_by_mask(cloud, keep);
}

PointCloud random_down_sample(const PointCloud& cloud, double sampling_ratio, uint64_t seed) {
    if (!(sampling_ratio >= 0.0 && sampling_ratio <= 1.0))
        throw InvalidArgument("sampling_ratio must be in [0, 1], got " + std::to_string(sampling_ratio));
    const size_t n = cloud.points.size();
    const size_t count = static_cast<size_t>(sampling_ratio * static_cast<double>(n));
    std::vector<size_t> pool(n);
    std::iota(pool.begin(), pool.end(), size_t{0});
    // Partial Fisher-Yates: the first `count` slots become a uniform sample without replacement.
    std::mt19937_64 rng(seed);
    for (size_t i = 0; i < count; ++i) std::swap(pool[i], pool[i + bounded(rng, n - i)]);
    pool.resize(count);
    return select_sorted(cloud, pool);
}

PointCloud farthest_point_down_sample(const PointCloud& cloud, size_t num_samples, size_t start_index,
                                      int num_threads) {
    const size_t n = cloud.points.size();
    if (num_samples == 0) return {};
    if (num_samples > n)
        throw InvalidArgument("num_samples " + std::to_string(num_samples) + " exceeds the " + std::to_string(n) +
                              " points");
    if (start_index >= n)
        throw InvalidArgument("start_index " + std::to_string(start_index) + " is out of range for " +
                              std::to_string(n) + " points");
    const auto& pts = cloud.points;
    std::vector<double> dist(n, std::numeric_limits<double>::infinity());
    std::vector<size_t> picked;
    picked.reserve(num_samples);
    // Small clouds are not worth a parallel region per sample.
    const int threads = n >= 20000 ? utility::resolve_num_threads(num_threads) : 1;
    size_t farthest = start_index;
    for (size_t s = 0; s < num_samples; ++s) {
        picked.push_back(farthest);
        const Eigen::Vector3d chosen = pts[farthest];
        // Keep Open3D's rule: the first point with the strictly largest distance; when all are 0 the
        // previous pick repeats (and collapses in the selection mask).
        double best = 0.0;
        size_t best_index = farthest;
#pragma omp parallel num_threads(threads)
        {
            double local_best = 0.0;
            size_t local_index = farthest;
#pragma omp for schedule(static) nowait
            for (int64_t j = 0; j < static_cast<int64_t>(n); ++j) {
                const size_t k = static_cast<size_t>(j);
                dist[k] = std::min(dist[k], (pts[k] - chosen).squaredNorm());
                if (dist[k] > local_best) {
                    local_best = dist[k];
                    local_index = k;
                }
            }
#pragma omp critical
            if (local_best > best || (local_best == best && local_best > 0.0 && local_index < best_index)) {
                best = local_best;
                best_index = local_index;
            }
        }
        farthest = best_index;
    }
    return select_sorted(cloud, picked);
}

}  // namespace o3d::geometry
