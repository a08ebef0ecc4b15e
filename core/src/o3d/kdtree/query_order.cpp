// SPDX-License-Identifier: MIT
#include "o3d/kdtree/query_order.h"

#include <algorithm>
#include <array>
#include <limits>
#include <numeric>

namespace o3d::kdtree {
namespace {

// Below this, queries fit in cache anyway and ordering only costs time.
constexpr size_t kMinPointsToReorder = 8192;
constexpr int kBitsPerAxis = 10;  // 2^30 cells: far finer than the tree's leaves
constexpr int kRadixBits = 10;

/// @brief Spread the low 10 bits of v so that bit i lands on bit 3i.
uint64_t spread_bits(uint64_t v) {
    v &= 0x3ff;
    v = (v | (v << 16)) & 0x30000ff;
    v = (v | (v << 8)) & 0x300f00f;
    v = (v | (v << 4)) & 0x30c30c3;
    v = (v | (v << 2)) & 0x9249249;
    return v;
}

}  // namespace

std::vector<uint32_t> spatial_order(const std::vector<Eigen::Vector3d>& points) {
    const size_t n = points.size();
    std::vector<uint32_t> order(n);
    if (n < kMinPointsToReorder || n > std::numeric_limits<uint32_t>::max()) {
        std::iota(order.begin(), order.end(), 0u);
        return order;
    }
    Eigen::Vector3d lo = points[0], hi = points[0];
    for (const auto& p : points) {
        lo = lo.cwiseMin(p);
        hi = hi.cwiseMax(p);
    }
    const double cells = static_cast<double>((1 << kBitsPerAxis) - 1);
    const double extent = (hi - lo).maxCoeff();
    const double scale = extent > 0.0 ? cells / extent : 0.0;

    // Key = Morton code (30 bits) << 32 | index; an LSD radix sort on the code keeps equal codes in
    // index order, so the permutation is fully determined by the input.
    std::vector<uint64_t> keys(n), tmp(n);
    for (size_t i = 0; i < n; ++i) {
        const Eigen::Vector3d c = (points[i] - lo) * scale;
        const uint64_t code = spread_bits(static_cast<uint64_t>(c.x())) |
                              (spread_bits(static_cast<uint64_t>(c.y())) << 1) |
                              (spread_bits(static_cast<uint64_t>(c.z())) << 2);
        keys[i] = (code << 32) | static_cast<uint64_t>(i);
    }
    constexpr size_t kBuckets = size_t{1} << kRadixBits;
    for (int shift = 32; shift < 32 + 3 * kBitsPerAxis; shift += kRadixBits) {
        std::array<size_t, kBuckets> count{};
        for (uint64_t k : keys) ++count[(k >> shift) & (kBuckets - 1)];
        size_t sum = 0;
        for (size_t& c : count) {
            const size_t here = c;
            c = sum;
            sum += here;
        }
        for (uint64_t k : keys) tmp[count[(k >> shift) & (kBuckets - 1)]++] = k;
        keys.swap(tmp);
    }
    for (size_t i = 0; i < n; ++i) order[i] = static_cast<uint32_t>(keys[i] & 0xffffffffu);
    return order;
}

}  // namespace o3d::kdtree
