// SPDX-License-Identifier: MIT
#pragma once
/// @file triangle_box_grid.h
/// @brief Internal: the broad phase of the triangle-intersection queries (is_self_intersecting,
/// get_self_intersecting_triangles, is_intersecting): triangle boxes in a uniform grid, each overlapping pair
/// visited once.
#include <Eigen/Core>
#include <atomic>
#include <cstdint>
#include <utility>
#include <vector>

#include "o3d/geometry/triangle_mesh.h"
#include "o3d/utility/parallel.h"

namespace o3d::geometry::detail {

/// @brief A triangle's axis-aligned box; `mesh` 0 or 1 and `index` its triangle there.
struct TriangleBox {
    Eigen::Vector3d lo, hi;
    int mesh;
    int index;
};

inline bool boxes_overlap(const TriangleBox& a, const TriangleBox& b) {
    return !((a.hi.array() < b.lo.array()).any() || (b.hi.array() < a.lo.array()).any());
}

/// @brief Boxes of the triangles that can intersect anything: finite corners, non-zero area.
void add_boxes(const TriangleMesh& mesh, int which, std::vector<TriangleBox>& boxes);

/// @brief Uniform grid over boxes (as is_self_intersecting builds it: cells about a triangle's size, grown
/// until the grid holds at most ~16 entries per box). Calls `test(i, j)` (indices into `boxes`, i < j in
/// cell order) once for every pair of overlapping boxes, from several threads; stops early once `stop`
/// is set.
class BoxGrid {
public:
    explicit BoxGrid(const std::vector<TriangleBox>& boxes);

    template <typename Test>
    void for_each_overlap(Test&& test, const std::atomic<bool>& stop) const {
        const long long num_cells = static_cast<long long>(cell_start_.size()) - 1;
        const uint64_t dx = static_cast<uint64_t>(dims_(0)), dy = static_cast<uint64_t>(dims_(1));
#pragma omp parallel for schedule(dynamic, 64) num_threads(o3d::utility::resolve_num_threads())
        for (long long c = 0; c < num_cells; ++c) {
            if (stop.load(std::memory_order_relaxed)) continue;
            const uint64_t key = entries_[cell_start_[c]].first;
            const Eigen::Array3i here(static_cast<int>(key % dx), static_cast<int>(key / dx % dy),
                                      static_cast<int>(key / dx / dy));
            for (size_t i = cell_start_[c]; i < cell_start_[c + 1]; ++i)
                for (size_t j = i + 1; j < cell_start_[c + 1]; ++j) {
                    const size_t a = entries_[i].second, b = entries_[j].second;
                    // Each pair once: in the first cell that both boxes cover.
                    if ((first_cell_[a].max(first_cell_[b]) != here).any()) continue;
                    if (boxes_overlap(boxes_[a], boxes_[b])) test(a, b);
                }
        }
    }

private:
    // Clamped so that overflowing extents (coordinates near DBL_MAX) give NaN or infinity, never UB.
    int cell_index(double offset, int k) const {
        const double q = offset / cell_;
        return q >= 0 && q < dims_(k) ? static_cast<int>(q) : (q >= dims_(k) ? dims_(k) - 1 : 0);
    }
    void cell_range(const TriangleBox& b, Eigen::Array3i& from, Eigen::Array3i& to) const {
        for (int k = 0; k < 3; ++k) {
            from(k) = cell_index(b.lo(k) - lo_(k), k);
            to(k) = cell_index(b.hi(k) - lo_(k), k);
        }
    }
    uint64_t key_of(int x, int y, int z) const {
        return (static_cast<uint64_t>(z) * static_cast<uint64_t>(dims_(1)) + static_cast<uint64_t>(y)) *
                   static_cast<uint64_t>(dims_(0)) +
               static_cast<uint64_t>(x);
    }

    const std::vector<TriangleBox>& boxes_;
    Eigen::Vector3d lo_;
    double cell_ = 1;
    Eigen::Array3i dims_ = Eigen::Array3i::Ones();
    std::vector<Eigen::Array3i> first_cell_;
    std::vector<std::pair<uint64_t, size_t>> entries_;
    std::vector<size_t> cell_start_;
};

/// @brief Whether two triangles have a vertex index in common.
bool share_vertex(const Eigen::Vector3i& a, const Eigen::Vector3i& b);


}  // namespace o3d::geometry::detail
