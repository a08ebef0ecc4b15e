// SPDX-License-Identifier: MIT
#include "o3d/geometry/mesh_intersection_queries.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstdint>
#include <utility>

#include "o3d/geometry/mesh_self_intersection.h"
#include "o3d/geometry/radix_sort.h"
#include "o3d/geometry/triangle_mesh_basics.h"
#include "o3d/utility/parallel.h"

namespace o3d::geometry {
namespace {

/// @brief A triangle's axis-aligned box; `mesh` 0 or 1 and `index` its triangle there.
struct TriangleBox {
    Eigen::Vector3d lo, hi;
    int mesh;
    int index;
};

bool boxes_overlap(const TriangleBox& a, const TriangleBox& b) {
    return !((a.hi.array() < b.lo.array()).any() || (b.hi.array() < a.lo.array()).any());
}

/// @brief Boxes of the triangles that can intersect anything: finite corners, non-zero area.
void add_boxes(const TriangleMesh& mesh, int which, std::vector<TriangleBox>& boxes) {
    for (size_t t = 0; t < mesh.triangles.size(); ++t) {
        const Eigen::Vector3i& tri = mesh.triangles[t];
        const Eigen::Vector3d &a = mesh.vertices[tri(0)], &b = mesh.vertices[tri(1)], &c = mesh.vertices[tri(2)];
        if (!a.allFinite() || !b.allFinite() || !c.allFinite()) continue;
        if (!(triangle_cross(mesh, t).squaredNorm() > 0)) continue;
        boxes.push_back({a.cwiseMin(b).cwiseMin(c), a.cwiseMax(b).cwiseMax(c), which, static_cast<int>(t)});
    }
}

/// @brief Uniform grid over boxes (as is_self_intersecting builds it: cells about a triangle's size, grown
/// until the grid holds at most ~16 entries per box). Calls `test(i, j)` (indices into `boxes`, i < j in
/// cell order) once for every pair of overlapping boxes, from several threads; stops early once `stop`
/// is set.
class BoxGrid {
public:
    explicit BoxGrid(const std::vector<TriangleBox>& boxes) : boxes_(boxes) {
        lo_ = Eigen::Vector3d::Constant(INFINITY);
        Eigen::Vector3d hi = -lo_;
        double extent_sum = 0;
        for (const TriangleBox& b : boxes) {
            lo_ = lo_.cwiseMin(b.lo);
            hi = hi.cwiseMax(b.hi);
            extent_sum += (b.hi - b.lo).maxCoeff();
        }
        const Eigen::Vector3d extent = hi - lo_;
        cell_ = std::max(extent_sum / static_cast<double>(boxes.size()), extent.maxCoeff() / double(1 << 20));
        for (;;) {
            for (int k = 0; k < 3; ++k) {
                const double q = std::ceil(extent(k) / cell_);
                dims_(k) = q >= 1 && q <= double(1 << 21) ? static_cast<int>(q) : (q > 1 ? 1 << 21 : 1);
            }
            size_t total = 0;
            for (const TriangleBox& b : boxes) {
                Eigen::Array3i from, to;
                cell_range(b, from, to);
                total += static_cast<size_t>(to(0) - from(0) + 1) * static_cast<size_t>(to(1) - from(1) + 1) *
                         static_cast<size_t>(to(2) - from(2) + 1);
            }
            if (!(cell_ < INFINITY) || total <= 16 * boxes.size() + 1024) break;
            cell_ *= 2;
        }
        first_cell_.resize(boxes.size());
        for (size_t i = 0; i < boxes.size(); ++i) {
            Eigen::Array3i from, to;
            cell_range(boxes[i], from, to);
            first_cell_[i] = from;
            for (int z = from(2); z <= to(2); ++z)
                for (int y = from(1); y <= to(1); ++y)
                    for (int x = from(0); x <= to(0); ++x) entries_.emplace_back(key_of(x, y, z), i);
        }
        int key_bits = 0;
        for (uint64_t top = static_cast<uint64_t>(dims_(0)) * dims_(1) * dims_(2); top; top >>= 1) ++key_bits;
        radix_sort_by_key(entries_, key_bits);
        for (size_t i = 0; i < entries_.size(); ++i)
            if (i == 0 || entries_[i].first != entries_[i - 1].first) cell_start_.push_back(i);
        cell_start_.push_back(entries_.size());
    }

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

bool share_vertex(const Eigen::Vector3i& a, const Eigen::Vector3i& b) {
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j)
            if (a(i) == b(j)) return true;
    return false;
}

bool intersect(const TriangleMesh& ma, int ta, const TriangleMesh& mb, int tb) {
    const Eigen::Vector3i &p = ma.triangles[ta], &q = mb.triangles[tb];
    const auto &u = ma.vertices, &v = mb.vertices;
    return triangles_intersect(u[p(0)], u[p(1)], u[p(2)], v[q(0)], v[q(1)], v[q(2)]);
}

}  // namespace

std::vector<Eigen::Vector2i> self_intersecting_triangles(const TriangleMesh& mesh) {
    validate_triangles(mesh);
    std::vector<TriangleBox> boxes;
    add_boxes(mesh, 0, boxes);
    if (boxes.size() < 2) return {};
    const BoxGrid grid(boxes);
    std::vector<Eigen::Vector2i> out;
    std::atomic<bool> never{false};
    grid.for_each_overlap(
        [&](size_t a, size_t b) {
            const int ta = boxes[a].index, tb = boxes[b].index;
            if (share_vertex(mesh.triangles[ta], mesh.triangles[tb])) return;
            if (!intersect(mesh, ta, mesh, tb)) return;
#pragma omp critical(o3d_self_intersecting_triangles)
            out.emplace_back(std::min(ta, tb), std::max(ta, tb));
        },
        never);
    // Found in whatever order the threads reach the cells: sorting makes the list the same for any count.
    std::sort(out.begin(), out.end(), [](const Eigen::Vector2i& x, const Eigen::Vector2i& y) {
        return x(0) != y(0) ? x(0) < y(0) : x(1) < y(1);
    });
    return out;
}

bool meshes_intersect(const TriangleMesh& a, const TriangleMesh& b) {
    validate_triangles(a);
    validate_triangles(b);
    std::vector<TriangleBox> boxes_a, boxes_b;
    add_boxes(a, 0, boxes_a);
    add_boxes(b, 1, boxes_b);
    if (boxes_a.empty() || boxes_b.empty()) return false;
    // Only triangles inside the overlap of the two meshes' boxes can meet (Open3D's first test).
    auto bound = [](const std::vector<TriangleBox>& boxes) {
        TriangleBox all{boxes[0].lo, boxes[0].hi, 0, 0};
        for (const TriangleBox& x : boxes) {
            all.lo = all.lo.cwiseMin(x.lo);
            all.hi = all.hi.cwiseMax(x.hi);
        }
        return all;
    };
    const TriangleBox bound_a = bound(boxes_a), bound_b = bound(boxes_b);
    if (!boxes_overlap(bound_a, bound_b)) return false;
    const TriangleBox common{bound_a.lo.cwiseMax(bound_b.lo), bound_a.hi.cwiseMin(bound_b.hi), 0, 0};
    std::vector<TriangleBox> boxes;
    for (const auto* part : {&boxes_a, &boxes_b})
        for (const TriangleBox& x : *part)
            if (boxes_overlap(x, common)) boxes.push_back(x);
    if (boxes.size() < 2) return false;
    const BoxGrid grid(boxes);
    std::atomic<bool> found{false};
    grid.for_each_overlap(
        [&](size_t i, size_t j) {
            const TriangleBox &x = boxes[i], &y = boxes[j];
            if (x.mesh == y.mesh) return;
            const bool hit = x.mesh == 0 ? intersect(a, x.index, b, y.index) : intersect(a, y.index, b, x.index);
            if (hit) found.store(true, std::memory_order_relaxed);
        },
        found);
    return found.load();
}

}  // namespace o3d::geometry
