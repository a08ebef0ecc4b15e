// SPDX-License-Identifier: MIT
#include "o3d/geometry/triangle_box_grid.h"

#include <algorithm>
#include <cmath>

#include "o3d/geometry/radix_sort.h"
#include "o3d/geometry/triangle_mesh_basics.h"

namespace o3d::geometry::detail {

void add_boxes(const TriangleMesh& mesh, int which, std::vector<TriangleBox>& boxes) {
    for (size_t t = 0; t < mesh.triangles.size(); ++t) {
        const Eigen::Vector3i& tri = mesh.triangles[t];
        const Eigen::Vector3d &a = mesh.vertices[tri(0)], &b = mesh.vertices[tri(1)], &c = mesh.vertices[tri(2)];
        if (!a.allFinite() || !b.allFinite() || !c.allFinite()) continue;
        if (!(triangle_cross(mesh, t).squaredNorm() > 0)) continue;
        boxes.push_back({a.cwiseMin(b).cwiseMin(c), a.cwiseMax(b).cwiseMax(c), which, static_cast<int>(t)});
    }
}

bool share_vertex(const Eigen::Vector3i& a, const Eigen::Vector3i& b) {
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j)
            if (a(i) == b(j)) return true;
    return false;
}

BoxGrid::BoxGrid(const std::vector<TriangleBox>& boxes) : boxes_(boxes) {
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

}  // namespace o3d::geometry::detail
