// SPDX-License-Identifier: MIT
#pragma once
/// @file correspondence_pass.h
/// @brief Internal: one parallel sweep over the source that moves each point, finds its nearest
/// target point and feeds the pair to an accumulator, with a thread-count-independent sum order.
#include <Eigen/Core>
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <exception>
#include <type_traits>
#include <vector>

#include "o3d/kdtree/kd_tree.h"
#include "o3d/registration/registration_result.h"

namespace o3d::registration::detail {

/// Points per reduction block. Fixed (never derived from the thread count) so that the order of
/// every floating-point addition, and hence every bit of the result, is the same for any thread count.
inline constexpr int64_t kBlockSize = 256;

/// @brief Accumulator for passes that only need the inlier statistics.
struct NoSums {
    void add(const NoSums&) {}
};

/// @brief Partial sums of one block. Cache-line aligned so that threads writing neighbouring
/// blocks do not share lines.
template <typename Sums>
struct alignas(64) BlockSums {
    int64_t count = 0;
    double error2 = 0.0;
    Sums sums{};
};

/// @brief Reusable buffers, so that ICP iterations do not allocate.
template <typename Sums>
struct PassWorkspace {
    std::vector<int32_t> nearest;  ///< per source point: target index, or -1 when none in range
    std::vector<BlockSums<Sums>> blocks;
    bool warm = false;  ///< `nearest` holds the previous pass's pairs for this same source
};

/// @brief Totals of one pass.
template <typename Sums>
struct PassTotals {
    int64_t count = 0;
    double error2 = 0.0;
    Sums sums{};

    double fitness(size_t num_source) const { return static_cast<double>(count) / static_cast<double>(num_source); }
    double inlier_rmse() const { return count ? std::sqrt(error2 / static_cast<double>(count)) : 0.0; }
};

/// @brief Move every source point by `transform`, pair it with its nearest target point within
/// `max_distance`, and call `visit(sums, moved_point, target_index)` for each pair found, or
/// `visit(sums, moved_point, target_index, source_index)` when the visitor takes the source index too.
/// Non-finite source points never pair (they still count in the fitness denominator, as in Open3D).
/// Each block is summed serially; blocks are combined in index order on the calling thread.
template <typename Sums, typename Visit>
PassTotals<Sums> correspondence_pass(const std::vector<Eigen::Vector3d>& source, const Eigen::Matrix4d& transform,
                                     const kdtree::KDTree& tree, double max_distance, int num_threads,
                                     PassWorkspace<Sums>& ws, const Visit& visit) {
    const int64_t n = static_cast<int64_t>(source.size());
    const int64_t num_blocks = (n + kBlockSize - 1) / kBlockSize;
    ws.blocks.resize(static_cast<size_t>(num_blocks));
    if (!ws.warm) ws.nearest.assign(source.size(), -1);
    const auto& targets = tree.points();
    const Eigen::Matrix3d rotation = transform.topLeftCorner<3, 3>();
    const Eigen::Vector3d translation = transform.topRightCorner<3, 1>();
    const int threads = static_cast<int>(std::max<int64_t>(1, std::min<int64_t>(num_threads, num_blocks)));

    // An exception must not escape an OpenMP region (that would terminate the process).
    std::exception_ptr error;
#pragma omp parallel for schedule(dynamic, 1) num_threads(threads) if (threads > 1)
    for (int64_t b = 0; b < num_blocks; ++b) {
        BlockSums<Sums> block;
        try {
            const int64_t end = std::min(n, (b + 1) * kBlockSize);
            for (int64_t i = b * kBlockSize; i < end; ++i) {
                const Eigen::Vector3d moved = rotation * source[static_cast<size_t>(i)] + translation;
                int index = -1;
                double distance2 = 0.0;
                if (moved.allFinite()) {
                    // Between ICP iterations points move little: the previous partner bounds the nearest
                    // distance, and a tight search radius prunes most of the tree. The bound is inflated
                    // so that the previous partner itself (at exactly that distance) stays inside it.
                    double radius = max_distance;
                    const int32_t previous = ws.warm ? ws.nearest[static_cast<size_t>(i)] : -1;
                    if (previous >= 0)
                        radius = std::min(radius, (moved - targets[previous]).norm() * (1.0 + 1e-9) + 1e-150);
                    index = tree.search_nearest(moved, radius, distance2);
                }
                ws.nearest[static_cast<size_t>(i)] = index;
                if (index < 0) continue;
                ++block.count;
                block.error2 += distance2;
                if constexpr (std::is_invocable_v<const Visit&, Sums&, const Eigen::Vector3d&, int, int64_t>)
                    visit(block.sums, moved, index, i);
                else
                    visit(block.sums, moved, index);
            }
        } catch (...) {
#pragma omp critical(o3d_registration_pass_error)
            if (!error) error = std::current_exception();
        }
        ws.blocks[static_cast<size_t>(b)] = block;
    }
    if (error) std::rethrow_exception(error);
    ws.warm = true;

    PassTotals<Sums> totals;
    for (const auto& block : ws.blocks) {
        totals.count += block.count;
        totals.error2 += block.error2;
        totals.sums.add(block.sums);
    }
    return totals;
}

/// @brief The correspondence set recorded by the last pass, in ascending source index.
inline CorrespondenceSet collect_correspondences(const std::vector<int32_t>& nearest, int64_t count) {
    CorrespondenceSet set;
    set.reserve(static_cast<size_t>(count));
    for (size_t i = 0; i < nearest.size(); ++i)
        if (nearest[i] >= 0) set.emplace_back(static_cast<int>(i), nearest[i]);
    return set;
}

}  // namespace o3d::registration::detail
