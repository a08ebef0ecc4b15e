// SPDX-License-Identifier: MIT
#include "o3d/registration/fpfh_neighbourhoods.h"

#include <algorithm>
#include <cmath>
#include <string>
#include <utility>

#include "o3d/utility/error.h"
#include "o3d/utility/parallel.h"

namespace o3d::registration::detail {
namespace {

// The dense cell array may hold at most this many cells per point (and at least kMinCells).
constexpr double kMaxCellsPerPoint = 8.0;
constexpr double kMinCells = 65536.0;
// Queries per task: fixed, so the split (and the output) never depends on the thread count.
constexpr size_t kChunk = 256;

}  // namespace

struct FpfhNeighbourhoods::Grid {
    Eigen::Vector3d origin;
    double inverse_cell = 0.0;
    int64_t dims[3] = {0, 0, 0};
    std::vector<int64_t> start;          // points of cell c: sorted slots start[c] .. start[c + 1]
    std::vector<double> xs, ys, zs;      // coordinates in cell order, contiguous per cell row
    std::vector<int32_t> ids;            // their point indices
    double points_per_cell = 0.0;        // mean over the occupied cells

    int64_t coord(double v, int axis) const {
        const double c = std::floor((v - origin[axis]) * inverse_cell);
        return std::clamp<int64_t>(static_cast<int64_t>(std::clamp(c, -1.0, 1e15)), 0, dims[axis] - 1);
    }
    int64_t cell(int64_t x, int64_t y, int64_t z) const { return x + dims[0] * (y + dims[1] * z); }

    /// @brief A grid of cells slightly wider than `radius`, or null when it would need too many cells.
    static std::unique_ptr<const Grid> build(const std::vector<Eigen::Vector3d>& points, double radius) {
        Eigen::Vector3d lo = points[0], hi = points[0];
        for (const auto& p : points) {
            lo = lo.cwiseMin(p);
            hi = hi.cwiseMax(p);
        }
        // Wider than the radius by a margin far above rounding, so a neighbour is never two cells away.
        const double cell = radius * (1.0 + 1e-9);
        auto g = std::make_unique<Grid>();
        g->origin = lo;
        g->inverse_cell = 1.0 / cell;
        double cells = 1.0;
        for (int a = 0; a < 3; ++a) {
            const double d = std::floor((hi[a] - lo[a]) / cell) + 1.0;
            cells *= d;
            g->dims[a] = static_cast<int64_t>(std::min(d, 1e15));
        }
        if (!(cells <= std::max(kMinCells, kMaxCellsPerPoint * static_cast<double>(points.size())))) return nullptr;
        const size_t n = points.size();
        std::vector<int64_t> cell_of(n);
        g->start.assign(static_cast<size_t>(cells) + 1, 0);
        for (size_t i = 0; i < n; ++i) {
            const auto& p = points[i];
            cell_of[i] = g->cell(g->coord(p[0], 0), g->coord(p[1], 1), g->coord(p[2], 2));
            ++g->start[static_cast<size_t>(cell_of[i]) + 1];
        }
        size_t occupied = 0;
        for (size_t c = 1; c < g->start.size(); ++c) {
            occupied += g->start[c] > 0;
            g->start[c] += g->start[c - 1];
        }
        g->points_per_cell = static_cast<double>(n) / static_cast<double>(std::max<size_t>(occupied, 1));
        std::vector<int64_t> fill(g->start.begin(), g->start.end() - 1);
        g->xs.resize(n);
        g->ys.resize(n);
        g->zs.resize(n);
        g->ids.resize(n);
        for (size_t i = 0; i < n; ++i) {  // ascending point index within each cell: deterministic
            const size_t at = static_cast<size_t>(fill[static_cast<size_t>(cell_of[i])]++);
            g->xs[at] = points[i][0];
            g->ys[at] = points[i][1];
            g->zs[at] = points[i][2];
            g->ids[at] = static_cast<int32_t>(i);
        }
        return g;
    }

    /// @brief Every point closer than sqrt(radius2) to q, into `hits` (scan order).
    void within(const Eigen::Vector3d& q, double radius2, std::vector<std::pair<double, int32_t>>& hits) const {
        hits.clear();
        const int64_t cx = coord(q[0], 0), cy = coord(q[1], 1), cz = coord(q[2], 2);
        const int64_t x0 = std::max<int64_t>(cx - 1, 0), x1 = std::min<int64_t>(cx + 1, dims[0] - 1);
        for (int64_t z = std::max<int64_t>(cz - 1, 0); z <= std::min<int64_t>(cz + 1, dims[2] - 1); ++z)
            for (int64_t y = std::max<int64_t>(cy - 1, 0); y <= std::min<int64_t>(cy + 1, dims[1] - 1); ++y) {
                // Cells x0..x1 of a row are adjacent in memory: one contiguous run of points.
                const int64_t b = start[static_cast<size_t>(cell(x0, y, z))];
                const int64_t e = start[static_cast<size_t>(cell(x1, y, z)) + 1];
                for (int64_t j = b; j < e; ++j) {
                    // FLANN's L2_3D arithmetic (query minus point, summed in axis order): the KD-tree's bits.
                    const double d0 = q[0] - xs[static_cast<size_t>(j)], d1 = q[1] - ys[static_cast<size_t>(j)],
                                 d2 = q[2] - zs[static_cast<size_t>(j)];
                    const double dist = d0 * d0 + d1 * d1 + d2 * d2;
                    if (dist < radius2) hits.emplace_back(dist, ids[static_cast<size_t>(j)]);
                }
            }
    }
};

FpfhNeighbourhoods::FpfhNeighbourhoods(const std::vector<Eigen::Vector3d>& points, const kdtree::SearchParam& param)
    : points_(points), param_(param) {
    kdtree::validate(param);
    for (size_t i = 0; i < points.size(); ++i)
        if (!points[i].allFinite())
            throw InvalidArgument("point " + std::to_string(i) + " has a non-finite coordinate");
    if (param.kind != kdtree::SearchParam::Kind::Knn && !points.empty() &&
        points.size() < static_cast<size_t>(INT32_MAX))
        grid_ = Grid::build(points, param.radius);
    // A hybrid search whose radius spans far more points than max_nn is a KNN search: the grid would
    // scan them all, the tree visits about max_nn.
    if (grid_ && param.kind == kdtree::SearchParam::Kind::Hybrid &&
        27.0 * grid_->points_per_cell > 8.0 * param.knn + 64.0)
        grid_.reset();
    if (!grid_) tree_ = std::make_unique<const kdtree::KDTree>(points);
}

void FpfhNeighbourhoods::neighbours(size_t i, std::vector<std::pair<double, int32_t>>& hits, std::vector<int>& idx,
                                    std::vector<double>& d2) const {
    using Kind = kdtree::SearchParam::Kind;
    const Eigen::Vector3d& q = points_[i];
    hits.clear();
    if (grid_) {
        grid_->within(q, param_.radius * param_.radius, hits);
    } else if (param_.kind == Kind::Radius) {
        tree_->search_radius(q, param_.radius, idx, d2);
    } else {
        tree_->search(q, param_, idx, d2);
        // Ties at the max_nn cut: the tree keeps whichever it met first; take every point as close as
        // the last one found, so that the cut below breaks ties by index, as on the grid.
        if (param_.kind == Kind::Hybrid && idx.size() == static_cast<size_t>(param_.knn)) {
            const double last = d2.back();
            // (At least 1e-150: its square must not underflow when `last` is 0.)
            tree_->search_radius(q, std::max(std::sqrt(last) * (1.0 + 1e-12), 1e-150), idx, d2);
            size_t keep = 0;
            for (size_t k = 0; k < idx.size(); ++k)
                if (d2[k] <= last && d2[k] < param_.radius * param_.radius) {
                    idx[keep] = idx[k];
                    d2[keep++] = d2[k];
                }
            idx.resize(keep);
            d2.resize(keep);
        }
    }
    if (!grid_)
        for (size_t k = 0; k < idx.size(); ++k) hits.emplace_back(d2[k], static_cast<int32_t>(idx[k]));
    const size_t max_nn = static_cast<size_t>(param_.knn);
    if (param_.kind == Kind::Hybrid && hits.size() > max_nn) {
        // The max_nn nearest; (distance, index) pairs compare uniquely, so the set is fixed.
        std::nth_element(hits.begin(), hits.begin() + static_cast<std::ptrdiff_t>(max_nn - 1), hits.end());
        hits.resize(max_nn);
    }
    // Entry 0 at distance 0: the point itself, or (when max_nn coincident points crowd it out) the
    // smallest-index one of them.
    const int32_t self = static_cast<int32_t>(i);
    auto first = std::find_if(hits.begin(), hits.end(), [&](const auto& h) { return h.second == self; });
    if (first == hits.end()) first = std::min_element(hits.begin(), hits.end());
    if (first != hits.end()) std::iter_swap(hits.begin(), first);
}

FpfhNeighbourhoods::~FpfhNeighbourhoods() = default;

kdtree::SearchResult FpfhNeighbourhoods::search(const std::vector<int64_t>& which, int num_threads) const {
    const int threads = utility::resolve_num_threads(num_threads);
    const size_t nq = which.size();
    const int64_t num_chunks = static_cast<int64_t>((nq + kChunk - 1) / kChunk);
    struct Chunk {
        std::vector<int32_t> indices;
        std::vector<double> distances2;
    };
    std::vector<Chunk> chunks(static_cast<size_t>(num_chunks));
    std::vector<size_t> counts(nq, 0);
#pragma omp parallel num_threads(threads)
    {
        std::vector<std::pair<double, int32_t>> hits;
        std::vector<int> idx;
        std::vector<double> d2;
#pragma omp for schedule(dynamic, 1)
        for (int64_t c = 0; c < num_chunks; ++c) {
            Chunk& chunk = chunks[static_cast<size_t>(c)];
            const size_t end = std::min(nq, static_cast<size_t>(c + 1) * kChunk);
            for (size_t j = static_cast<size_t>(c) * kChunk; j < end; ++j) {
                neighbours(static_cast<size_t>(which[j]), hits, idx, d2);
                for (const auto& [dist, i] : hits) {
                    chunk.indices.push_back(i);
                    chunk.distances2.push_back(dist);
                }
                counts[j] = hits.size();
            }
        }
    }
    kdtree::SearchResult result;
    result.offsets.assign(nq + 1, 0);
    for (size_t j = 0; j < nq; ++j) result.offsets[j + 1] = result.offsets[j] + static_cast<int64_t>(counts[j]);
    result.indices.reserve(static_cast<size_t>(result.offsets[nq]));
    result.distances2.reserve(static_cast<size_t>(result.offsets[nq]));
    for (const Chunk& chunk : chunks) {
        result.indices.insert(result.indices.end(), chunk.indices.begin(), chunk.indices.end());
        result.distances2.insert(result.distances2.end(), chunk.distances2.begin(), chunk.distances2.end());
    }
    return result;
}

}  // namespace o3d::registration::detail
