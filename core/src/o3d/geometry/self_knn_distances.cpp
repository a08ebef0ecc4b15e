// SPDX-License-Identifier: MIT
#include "o3d/geometry/self_knn_distances.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <string>

#include "o3d/kdtree/kd_tree.h"
#include "o3d/utility/error.h"
#include "o3d/utility/parallel.h"

namespace o3d::geometry {
namespace {

// Rings searched on the grid before a point is handed to the KD-tree (isolated outliers).
constexpr int kMaxRings = 6;
// The dense cell array may hold at most this many cells per point.
constexpr double kMaxCellsPerPoint = 8.0;
constexpr int64_t kChunk = 1024;

// Same operation order as FLANN's L2_3D, so squared distances are bit-identical to the KD-tree's.
inline double distance2(const Eigen::Vector3d& a, const Eigen::Vector3d& b) {
    const double d0 = a[0] - b[0], d1 = a[1] - b[1], d2 = a[2] - b[2];
    return d0 * d0 + d1 * d1 + d2 * d2;
}

double mean_of_sqrt(const double* sorted_d2, size_t count) {
    double sum = 0.0;
    for (size_t i = 0; i < count; ++i) sum += std::sqrt(sorted_d2[i]);
    return sum / static_cast<double>(count);
}

struct Grid {
    Eigen::Vector3d origin;
    double cell = 0.0;
    int64_t dims[3] = {0, 0, 0};
    std::vector<int64_t> start;           // points of cell c: order[start[c] .. start[c+1])
    std::vector<uint32_t> order;          // point indices sorted by cell
    std::vector<Eigen::Vector3d> sorted;  // their coordinates, contiguous per cell
    std::vector<int64_t> cell_of;         // cell of each point

    int64_t coord(double v, int axis) const {
        const int64_t c = static_cast<int64_t>(std::floor((v - origin[axis]) / cell));
        return std::clamp<int64_t>(c, 0, dims[axis] - 1);
    }
};

// A grid whose cells hold a few points each, or false when the bounding box is too sparse for a dense array.
bool build_grid(const std::vector<Eigen::Vector3d>& pts, int k, Grid& g) {
    const size_t n = pts.size();
    Eigen::Vector3d lo = pts[0], hi = pts[0];
    for (const auto& p : pts) {
        lo = lo.cwiseMin(p);
        hi = hi.cwiseMax(p);
    }
    const Eigen::Vector3d extent = hi - lo;
    const double largest = extent.maxCoeff();
    if (!(largest > 0.0)) return false;
    // Start from a volume estimate (about k/4 points per cell for a filled box) and shrink the cell
    // for surface-like clouds, where most cells are empty, until occupied cells hold about that many.
    const Eigen::Vector3d padded = extent.cwiseMax(largest * 1e-3);
    double cell = std::cbrt(padded.prod() * 0.25 * k / static_cast<double>(n));
    for (int attempt = 0; attempt < 4; ++attempt) {
        double cells = 1.0;
        for (int a = 0; a < 3; ++a) cells *= std::floor(extent[a] / cell) + 1.0;
        if (cells > kMaxCellsPerPoint * static_cast<double>(n)) return false;
        g.origin = lo;
        g.cell = cell;
        for (int a = 0; a < 3; ++a) g.dims[a] = static_cast<int64_t>(std::floor(extent[a] / cell)) + 1;
        g.cell_of.resize(n);
        std::vector<int64_t> counts(static_cast<size_t>(g.dims[0] * g.dims[1] * g.dims[2]) + 1, 0);
        size_t occupied = 0;
        for (size_t i = 0; i < n; ++i) {
            const int64_t c =
                g.coord(pts[i][0], 0) + g.dims[0] * (g.coord(pts[i][1], 1) + g.dims[1] * g.coord(pts[i][2], 2));
            g.cell_of[i] = c;
            if (counts[static_cast<size_t>(c) + 1]++ == 0) ++occupied;
        }
        const double per_cell = static_cast<double>(n) / static_cast<double>(occupied);
        if (per_cell > 2.0 * k && attempt < 3) {
            cell *= std::sqrt(0.25 * k / per_cell);  // surface-like: points per cell scale with area
            continue;
        }
        for (size_t c = 1; c < counts.size(); ++c) counts[c] += counts[c - 1];
        g.start = counts;
        g.order.resize(n);
        std::vector<int64_t> fill(counts.begin(), counts.end() - 1);
        for (size_t i = 0; i < n; ++i)
            g.order[static_cast<size_t>(fill[static_cast<size_t>(g.cell_of[i])]++)] = static_cast<uint32_t>(i);
        g.sorted.resize(n);
        for (size_t j = 0; j < n; ++j) g.sorted[j] = pts[g.order[j]];
        return true;
    }
    return false;
}

// The k smallest squared distances from p (sorted ascending in best[0..count)), ring by ring; false when
// kMaxRings rings did not settle them.
bool grid_knn(const Grid& g, const Eigen::Vector3d& p, size_t k, double* best, size_t& count) {
    count = 0;
    int64_t c[3];
    for (int a = 0; a < 3; ++a) c[a] = g.coord(p[a], a);
    for (int r = 0; r <= kMaxRings; ++r) {
        for (int64_t z = c[2] - r; z <= c[2] + r; ++z) {
            if (z < 0 || z >= g.dims[2]) continue;
            for (int64_t y = c[1] - r; y <= c[1] + r; ++y) {
                if (y < 0 || y >= g.dims[1]) continue;
                const bool inner_yz = std::abs(z - c[2]) < r && std::abs(y - c[1]) < r;
                for (int64_t x = c[0] - r; x <= c[0] + r; x += (inner_yz ? 2 * r : 1)) {
                    if (x >= 0 && x < g.dims[0]) {
                        const size_t cell = static_cast<size_t>(x + g.dims[0] * (y + g.dims[1] * z));
                        for (int64_t j = g.start[cell]; j < g.start[cell + 1]; ++j) {
                            const double d = distance2(g.sorted[static_cast<size_t>(j)], p);
                            if (count == k && d >= best[k - 1]) continue;
                            size_t at = count < k ? count++ : k - 1;
                            while (at > 0 && best[at - 1] > d) {
                                best[at] = best[at - 1];
                                --at;
                            }
                            best[at] = d;
                        }
                    }
                    if (r == 0) break;
                }
            }
        }
        // Every point not yet visited lies outside the (2r+1)^3 block: at least this far away.
        double reach = std::numeric_limits<double>::infinity();
        bool everything = true;
        for (int a = 0; a < 3; ++a) {
            if (c[a] - r > 0) {
                reach = std::min(reach, p[a] - (g.origin[a] + static_cast<double>(c[a] - r) * g.cell));
                everything = false;
            }
            if (c[a] + r < g.dims[a] - 1) {
                reach = std::min(reach, g.origin[a] + static_cast<double>(c[a] + r + 1) * g.cell - p[a]);
                everything = false;
            }
        }
        if (everything) return true;
        // Strictly closer only: a point at exactly `reach` could tie with the k-th and change nothing,
        // but a margin keeps rounding in the cell arithmetic from ever cutting a true neighbour.
        if (count == k && reach > 0.0 && best[k - 1] < reach * reach * (1.0 - 1e-9)) return true;
    }
    return false;
}

}  // namespace

std::vector<double> mean_self_knn_distances(const std::vector<Eigen::Vector3d>& points, int k, int num_threads) {
    if (k < 1) throw InvalidArgument("k must be >= 1, got " + std::to_string(k));
    for (size_t i = 0; i < points.size(); ++i)
        if (!points[i].allFinite())
            throw InvalidArgument("point " + std::to_string(i) + " has a non-finite coordinate");
    const size_t n = points.size();
    std::vector<double> avg(n, 0.0);
    if (n == 0) return avg;
    const size_t kk = std::min(static_cast<size_t>(k), n);
    const int threads = utility::resolve_num_threads(num_threads);

    Grid grid;
    std::vector<uint32_t> fallback;
    if (n >= 4 * kk && build_grid(points, static_cast<int>(kk), grid)) {
        std::vector<uint8_t> settled(n, 0);
        const int64_t chunks = static_cast<int64_t>((n + kChunk - 1) / kChunk);
#pragma omp parallel num_threads(threads)
        {
            std::vector<double> best(kk);
#pragma omp for schedule(dynamic, 1)
            for (int64_t ch = 0; ch < chunks; ++ch) {
                const size_t end = std::min(n, static_cast<size_t>(ch + 1) * kChunk);
                for (size_t j = static_cast<size_t>(ch) * kChunk; j < end; ++j) {
                    const uint32_t i = grid.order[j];
                    size_t count = 0;
                    if (grid_knn(grid, points[i], kk, best.data(), count) && count == kk) {
                        avg[i] = mean_of_sqrt(best.data(), kk);
                        settled[i] = 1;
                    }
                }
            }
        }
        for (size_t i = 0; i < n; ++i)
            if (!settled[i]) fallback.push_back(static_cast<uint32_t>(i));
    } else {
        fallback.resize(n);
        for (size_t i = 0; i < n; ++i) fallback[i] = static_cast<uint32_t>(i);
    }
    if (fallback.empty()) return avg;

    const kdtree::KDTree tree(points);
    std::vector<Eigen::Vector3d> queries(fallback.size());
    for (size_t j = 0; j < fallback.size(); ++j) queries[j] = points[fallback[j]];
    const kdtree::SearchResult res =
        tree.search_batch(queries, kdtree::SearchParam::make_knn(static_cast<int>(kk)), num_threads);
    for (size_t j = 0; j < fallback.size(); ++j) {
        const int64_t b = res.offsets[j], e = res.offsets[j + 1];
        avg[fallback[j]] = e > b ? mean_of_sqrt(res.distances2.data() + b, static_cast<size_t>(e - b)) : -1.0;
    }
    return avg;
}

}  // namespace o3d::geometry
