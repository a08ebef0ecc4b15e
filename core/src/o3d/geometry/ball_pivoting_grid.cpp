// SPDX-License-Identifier: MIT
#include "o3d/geometry/ball_pivoting_grid.h"

#include <algorithm>
#include <cmath>
#include <utility>

namespace o3d::geometry::ball_pivoting {
namespace {

constexpr int kBits = 21;  ///< bits per axis in a cell key
constexpr uint64_t kGolden = 0x9E3779B97F4A7C15ULL;

uint64_t pack(int64_t x, int64_t y, int64_t z) {
    return static_cast<uint64_t>(x) | (static_cast<uint64_t>(y) << kBits) | (static_cast<uint64_t>(z) << (2 * kBits));
}

}  // namespace

PointGrid::PointGrid(const std::vector<Eigen::Vector3d>& points, double cell_size) {
    Eigen::Vector3d lo = points.front(), hi = points.front();
    for (const auto& p : points) {
        lo = lo.cwiseMin(p);
        hi = hi.cwiseMax(p);
    }
    origin_ = lo;
    // Keys hold 21 bits per axis: a ball tiny against the cloud gets coarser cells (still correct, only
    // more points to test per query).
    max_coordinate_ = (int64_t{1} << kBits) - 1;
    const double extent = (hi - lo).maxCoeff();
    const double cell = std::max(cell_size, extent / static_cast<double>(max_coordinate_ - 1));
    inv_cell_ = cell > 0.0 ? 1.0 / cell : 1.0;

    std::vector<std::pair<uint64_t, int32_t>> keyed(points.size());
    for (size_t i = 0; i < points.size(); ++i) {
        const Eigen::Vector3d& p = points[i];
        keyed[i] = {pack(cell_coordinate(p.x(), 0), cell_coordinate(p.y(), 1), cell_coordinate(p.z(), 2)),
                    static_cast<int32_t>(i)};
    }
    std::sort(keyed.begin(), keyed.end());
    sorted_points_.resize(points.size());
    sorted_index_.resize(points.size());
    for (size_t i = 0; i < keyed.size(); ++i) {
        sorted_index_[i] = keyed[i].second;
        sorted_points_[i] = points[keyed[i].second];
        if (i == 0 || keyed[i].first != keyed[i - 1].first) {
            cell_key_.push_back(keyed[i].first);
            cell_start_.push_back(static_cast<int64_t>(i));
        }
    }
    cell_start_.push_back(static_cast<int64_t>(keyed.size()));

    int bits = 1;
    while ((size_t{1} << bits) < 2 * cell_key_.size()) ++bits;
    table_shift_ = 64 - bits;
    table_.assign(size_t{1} << bits, -1);
    const size_t mask = table_.size() - 1;
    for (size_t c = 0; c < cell_key_.size(); ++c) {
        size_t slot = static_cast<size_t>((cell_key_[c] * kGolden) >> table_shift_);
        while (table_[slot] >= 0) slot = (slot + 1) & mask;
        table_[slot] = static_cast<int64_t>(c);
    }
}

int64_t PointGrid::cell_coordinate(double x, int axis) const {
    const double c = std::floor((x - origin_(axis)) * inv_cell_);
    return c < 0.0 ? 0 : (c > static_cast<double>(max_coordinate_) ? max_coordinate_ : static_cast<int64_t>(c));
}

int64_t PointGrid::find_cell(uint64_t key) const {
    const size_t mask = table_.size() - 1;
    for (size_t slot = static_cast<size_t>((key * kGolden) >> table_shift_);; slot = (slot + 1) & mask) {
        const int64_t c = table_[slot];
        if (c < 0) return -1;
        if (cell_key_[static_cast<size_t>(c)] == key) return c;
    }
}

void PointGrid::search(const Eigen::Vector3d& query, double radius, std::vector<int>& indices,
                       std::vector<double>& distances2) const {
    indices.clear();
    distances2.clear();
    const double r2 = radius * radius;
    int64_t lo[3], hi[3];
    for (int k = 0; k < 3; ++k) {
        lo[k] = cell_coordinate(query(k) - radius, k);
        hi[k] = cell_coordinate(query(k) + radius, k);
    }
    for (int64_t z = lo[2]; z <= hi[2]; ++z)
        for (int64_t y = lo[1]; y <= hi[1]; ++y)
            for (int64_t x = lo[0]; x <= hi[0]; ++x) {
                const int64_t c = find_cell(pack(x, y, z));
                if (c < 0) continue;
                for (int64_t i = cell_start_[c], end = cell_start_[c + 1]; i < end; ++i) {
                    const double d2 = (sorted_points_[i] - query).squaredNorm();
                    if (d2 <= r2) {
                        indices.push_back(sorted_index_[i]);
                        distances2.push_back(d2);
                    }
                }
            }
}

}  // namespace o3d::geometry::ball_pivoting
