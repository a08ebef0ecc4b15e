// SPDX-License-Identifier: MIT
#pragma once
/// @file odometry_reduce.h
/// @brief Sums over image rows split into fixed blocks: blocks run in parallel, each into its own partial sum,
/// and the partials are added in block order. The block size depends on nothing but this constant, so the
/// result is the same bits for any thread count.
#include <algorithm>
#include <vector>

#include "o3d/utility/parallel.h"

namespace o3d::odometry::detail {

constexpr int kBlockRows = 8;  ///< rows per partial sum: the unit of work and of rounding

/// @brief block(first_row, last_row, sum) for each block [first, last) of rows [0, height), each into a fresh
/// `Sum`; returns the partials added with `+=` in block order.
template <typename Sum, typename Block>
Sum reduce_row_blocks(int height, const Block& block) {
    const int blocks = (height + kBlockRows - 1) / kBlockRows;
    std::vector<Sum> partial(static_cast<size_t>(blocks));
    const int threads = std::max(1, std::min(utility::resolve_num_threads(), blocks));
#pragma omp parallel for schedule(static) num_threads(threads) if (threads > 1)
    for (int b = 0; b < blocks; ++b) {
        Sum local;  // on this thread's stack: no false sharing between neighbouring blocks
        block(b * kBlockRows, std::min(height, (b + 1) * kBlockRows), local);
        partial[size_t(b)] = local;
    }
    Sum total;
    for (const Sum& p : partial) total += p;
    return total;
}

}  // namespace o3d::odometry::detail
