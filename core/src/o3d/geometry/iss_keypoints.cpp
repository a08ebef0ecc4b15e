// SPDX-License-Identifier: MIT
#include "o3d/geometry/iss_keypoints.h"

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>
#include <string>
#include <unordered_map>

#include "o3d/geometry/point_cloud_ops.h"
#include "o3d/geometry/self_knn_distances.h"
#include "o3d/utility/error.h"
#include "o3d/utility/parallel.h"

namespace o3d::geometry {
namespace {

// Uniform grid of cells at least `radius` wide: a ball of that radius around a point lies in the 3x3x3
// cells around it. Both ISS passes only accumulate over their balls, so they need no sorted KD-tree
// results, and visiting the cells in a fixed order makes every sum independent of the thread count.
class BallGrid {
public:
    BallGrid(const std::vector<Eigen::Vector3d>& pts, double radius) : pts_(pts) {
        lo_ = pts[0];
        Eigen::Vector3d hi = pts[0];
        for (const auto& p : pts) {
            lo_ = lo_.cwiseMin(p);
            hi = hi.cwiseMax(p);
        }
        // Cells never so small that a coordinate needs more than 20 bits: a tiny radius then just
        // scans more points per cell, never overflows the key.
        cell_ = std::max(radius, (hi - lo_).maxCoeff() / double(1 << 20));
        if (!(cell_ > 0.0)) cell_ = 1.0;
        std::vector<std::pair<uint64_t, uint32_t>> keyed(pts.size());
        for (size_t i = 0; i < pts.size(); ++i) keyed[i] = {key_of(coord(pts[i])), static_cast<uint32_t>(i)};
        std::sort(keyed.begin(), keyed.end());
        order_.resize(pts.size());
        sorted_.resize(pts.size());
        for (size_t s = 0; s < keyed.size(); ++s) {
            order_[s] = keyed[s].second;
            sorted_[s] = pts[keyed[s].second];
            if (s == 0 || keyed[s].first != keyed[s - 1].first) {
                cells_.emplace(keyed[s].first, static_cast<uint32_t>(starts_.size()));
                starts_.push_back(static_cast<uint32_t>(s));
            }
        }
        starts_.push_back(static_cast<uint32_t>(pts.size()));
    }

    size_t num_cells() const { return starts_.size() - 1; }
    /// Positions [begin, end) of cell c in the cell-sorted order.
    uint32_t cell_begin(size_t c) const { return starts_[c]; }
    uint32_t cell_end(size_t c) const { return starts_[c + 1]; }
    uint32_t point_at(uint32_t s) const { return order_[s]; }
    const Eigen::Vector3d& sorted_point(uint32_t s) const { return sorted_[s]; }

    /// The position ranges of the (up to 27) occupied cells around cell c, in a fixed order. Queries
    /// are answered cell by cell, so these lookups are shared by all the points of a cell.
    void neighbour_ranges(size_t c, std::vector<std::pair<uint32_t, uint32_t>>& out) const {
        out.clear();
        const Eigen::Array3i base = coord(sorted_[starts_[c]]);
        for (int dz = -1; dz <= 1; ++dz)
            for (int dy = -1; dy <= 1; ++dy)
                for (int dx = -1; dx <= 1; ++dx) {
                    const Eigen::Array3i nc = base + Eigen::Array3i(dx, dy, dz);
                    if ((nc < 0).any() || (nc >= (1 << 21)).any()) continue;
                    const auto it = cells_.find(key_of(nc));
                    if (it != cells_.end()) out.emplace_back(starts_[it->second], starts_[it->second + 1]);
                }
    }

private:
    Eigen::Array3i coord(const Eigen::Vector3d& p) const {
        const Eigen::Array3d c = ((p - lo_) / cell_).array().floor().min(double((1 << 21) - 1)).max(0.0);
        return c.cast<int>();
    }
    static uint64_t key_of(const Eigen::Array3i& c) {
        return (uint64_t(c[2]) << 42) | (uint64_t(c[1]) << 21) | uint64_t(c[0]);
    }

    const std::vector<Eigen::Vector3d>& pts_;
    Eigen::Vector3d lo_;
    double cell_ = 1.0;
    std::vector<uint32_t> order_, starts_;
    std::vector<Eigen::Vector3d> sorted_;
    std::unordered_map<uint64_t, uint32_t> cells_;
};

void validate(const PointCloud& cloud, const IssOptions& o) {
    if (!std::isfinite(o.salient_radius) || o.salient_radius < 0.0)
        throw InvalidArgument("salient_radius must be finite and >= 0, got " + std::to_string(o.salient_radius));
    if (!std::isfinite(o.non_max_radius) || o.non_max_radius < 0.0)
        throw InvalidArgument("non_max_radius must be finite and >= 0, got " + std::to_string(o.non_max_radius));
    if (!(o.gamma_21 > 0.0 && o.gamma_21 <= 1.0))
        throw InvalidArgument("gamma_21 must be in (0, 1], got " + std::to_string(o.gamma_21));
    if (!(o.gamma_32 > 0.0 && o.gamma_32 <= 1.0))
        throw InvalidArgument("gamma_32 must be in (0, 1], got " + std::to_string(o.gamma_32));
    if (o.min_neighbors < 0)
        throw InvalidArgument("min_neighbors must be >= 0, got " + std::to_string(o.min_neighbors));
    for (size_t i = 0; i < cloud.points.size(); ++i)
        if (!cloud.points[i].allFinite())
            throw InvalidArgument("point " + std::to_string(i) + " has a non-finite coordinate");
    if (cloud.points.size() >= (size_t(1) << 32))
        throw InvalidArgument("too many points for ISS keypoints: " + std::to_string(cloud.points.size()));
}

}  // namespace

std::vector<int64_t> compute_iss_keypoint_indices(const PointCloud& cloud, const IssOptions& options) {
    validate(cloud, options);
    const auto& pts = cloud.points;
    const size_t n = pts.size();
    if (n == 0) return {};
    const int threads = utility::resolve_num_threads(options.num_threads);

    double salient_radius = options.salient_radius, non_max_radius = options.non_max_radius;
    if (salient_radius == 0.0 || non_max_radius == 0.0) {
        // Resolution: mean distance to the nearest other point (k = 2 counts the point itself).
        double resolution = 0.0;
        if (n >= 2) {
            const std::vector<double> mean2 = mean_self_knn_distances(pts, 2, threads);
            for (double m : mean2) resolution += 2.0 * m;  // mean of {0, d1} is d1 / 2
            resolution /= static_cast<double>(n);
        }
        salient_radius = 6.0 * resolution;
        non_max_radius = 4.0 * resolution;
    }
    if (!(salient_radius > 0.0) || !(non_max_radius > 0.0)) return {};  // no non-degenerate ball

    // Pass 1: third eigenvalue of the covariance where the neighbourhood is salient, else 0.
    std::vector<double> third(n, 0.0);
    {
        const BallGrid grid(pts, salient_radius);
        const double r2 = salient_radius * salient_radius;
#pragma omp parallel num_threads(threads)
        {
            std::vector<std::pair<uint32_t, uint32_t>> ranges;
#pragma omp for schedule(dynamic, 8)
            for (int64_t c = 0; c < static_cast<int64_t>(grid.num_cells()); ++c) {
                grid.neighbour_ranges(static_cast<size_t>(c), ranges);
                for (uint32_t qs = grid.cell_begin(static_cast<size_t>(c)); qs < grid.cell_end(static_cast<size_t>(c));
                     ++qs) {
                    const Eigen::Vector3d& q = grid.sorted_point(qs);
                    // Moments about the query point itself: well conditioned whatever the cloud's offset.
                    int count = 0;
                    Eigen::Vector3d s1 = Eigen::Vector3d::Zero();
                    Eigen::Matrix3d s2 = Eigen::Matrix3d::Zero();
                    for (const auto& [b, e] : ranges)
                        for (uint32_t s = b; s < e; ++s) {
                            const Eigen::Vector3d d = grid.sorted_point(s) - q;
                            if (d.squaredNorm() >= r2) continue;
                            ++count;
                            s1 += d;
                            s2.noalias() += d * d.transpose();
                        }
                    if (count < options.min_neighbors || count == 0) continue;
                    // The covariance (scatter / count), as Open3D 0.20: its l3 is what the suppression
                    // compares.
                    const Eigen::Matrix3d cov =
                        (s2 - s1 * s1.transpose() / static_cast<double>(count)) / static_cast<double>(count);
                    const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> solver(cov, Eigen::EigenvaluesOnly);
                    const Eigen::Vector3d ev = solver.eigenvalues();  // ascending
                    if (ev[1] / ev[2] < options.gamma_21 && ev[0] / ev[1] < options.gamma_32)
                        third[grid.point_at(qs)] = ev[0];
                }
            }
        }
    }

    // Pass 2: non-maximum suppression of l3 within non_max_radius (ties keep every maximum).
    std::vector<uint8_t> keep(n, 0);
    {
        const BallGrid grid(pts, non_max_radius);
        const double r2 = non_max_radius * non_max_radius;
#pragma omp parallel num_threads(threads)
        {
            std::vector<std::pair<uint32_t, uint32_t>> ranges;
#pragma omp for schedule(dynamic, 8)
            for (int64_t c = 0; c < static_cast<int64_t>(grid.num_cells()); ++c) {
                bool fetched = false;
                for (uint32_t qs = grid.cell_begin(static_cast<size_t>(c)); qs < grid.cell_end(static_cast<size_t>(c));
                     ++qs) {
                    const uint32_t i = grid.point_at(qs);
                    if (!(third[i] > 0.0)) continue;
                    if (!fetched) grid.neighbour_ranges(static_cast<size_t>(c), ranges);
                    fetched = true;
                    const Eigen::Vector3d& q = grid.sorted_point(qs);
                    int count = 0;
                    bool is_max = true;
                    for (size_t r = 0; r < ranges.size() && is_max; ++r)
                        for (uint32_t s = ranges[r].first; s < ranges[r].second; ++s) {
                            if ((grid.sorted_point(s) - q).squaredNorm() >= r2) continue;
                            ++count;
                            if (third[grid.point_at(s)] > third[i]) {
                                is_max = false;  // decided: no need to count further
                                break;
                            }
                        }
                    keep[i] = is_max && count >= options.min_neighbors;
                }
            }
        }
    }
    std::vector<int64_t> indices;
    for (size_t i = 0; i < n; ++i)
        if (keep[i]) indices.push_back(static_cast<int64_t>(i));
    return indices;
}

PointCloud compute_iss_keypoints(const PointCloud& cloud, const IssOptions& options) {
    return select_by_index(cloud, compute_iss_keypoint_indices(cloud, options));
}

}  // namespace o3d::geometry
