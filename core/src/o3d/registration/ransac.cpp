// SPDX-License-Identifier: MIT
#include "o3d/registration/ransac.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <exception>
#include <limits>
#include <memory>
#include <optional>
#include <string>

#include "o3d/kdtree/kd_tree.h"
#include "o3d/kdtree/kd_tree_xd.h"
#include "o3d/registration/estimation_point_to_plane.h"
#include "o3d/registration/estimation_point_to_point.h"
#include "o3d/registration/evaluation.h"
#include "o3d/registration/feature_matching.h"
#include "o3d/utility/error.h"
#include "o3d/utility/parallel.h"
#include "o3d/utility/random.h"

namespace o3d::registration {

namespace {

/// Hypotheses per block. Fixed (never derived from the thread count): the blocks are the units in
/// which results are merged, so the result is the same on any number of threads.
constexpr int kBlockSize = 256;
/// ransac_n above this is drawn by a partial shuffle instead of rejection.
constexpr size_t kMaxRejectionDraw = 16;

void validate(const geometry::PointCloud& source, const geometry::PointCloud& target,
              double max_correspondence_distance, const std::vector<CorrespondenceChecker>& checkers,
              const RansacOptions& o) {
    if (!source.has_points()) throw InvalidArgument("source point cloud is empty");
    if (!target.has_points()) throw InvalidArgument("target point cloud is empty");
    for (size_t i = 0; i < target.size(); ++i)
        if (!target.points[i].allFinite())
            throw InvalidArgument("target point " + std::to_string(i) + " has a non-finite coordinate");
    if (!std::isfinite(max_correspondence_distance) || max_correspondence_distance <= 0.0)
        throw InvalidArgument("max_correspondence_distance must be finite and > 0, got " +
                              std::to_string(max_correspondence_distance));
    if (o.ransac_n < 3) throw InvalidArgument("ransac_n must be >= 3, got " + std::to_string(o.ransac_n));
    if (o.criteria.max_iteration < 0)
        throw InvalidArgument("max_iteration must be >= 0, got " + std::to_string(o.criteria.max_iteration));
    if (!(o.criteria.confidence >= 0.0 && o.criteria.confidence <= 1.0))
        throw InvalidArgument("confidence must be in [0, 1], got " + std::to_string(o.criteria.confidence));
    if (o.num_threads < 0) throw InvalidArgument("num_threads must be >= 0, got " + std::to_string(o.num_threads));
    if (o.estimation == Estimation::PointToPlane) {
        if (!target.has_normals()) throw InvalidArgument("point-to-plane estimation needs target normals");
    } else if (o.estimation != Estimation::PointToPoint) {
        throw InvalidArgument("RANSAC estimates point-to-point or point-to-plane transformations only");
    }
    for (const auto& checker : checkers)
        if (checker.kind() == CorrespondenceChecker::Kind::Normal && (!source.has_normals() || !target.has_normals()))
            throw InvalidArgument("the normal correspondence checker needs normals on both clouds");
}

/// Nearest-point-within-r queries on a dense uniform grid of cell 2r (just over), for scoring
/// hypotheses: the ball of radius r around any query meets at most 2 x 2 x 2 cells, and queries that
/// land away from the target touch no point at all. Several times faster than a KD-tree here.
class NeighbourGrid {
public:
    /// The grid over `points`, or nothing when it would need more than `max_cells` cells.
    static std::optional<NeighbourGrid> build(const std::vector<Eigen::Vector3d>& points, double radius,
                                              size_t max_cells) {
        NeighbourGrid g;
        g.radius2_ = radius * radius;
        // Slightly over 2r, so that rounding in the cell index never hides a point within r.
        const double cell = 2.0 * radius * (1.0 + 1e-6);
        g.inv_cell_ = 1.0 / cell;
        Eigen::Vector3d lo = points[0], hi = points[0];
        for (const auto& p : points) {
            lo = lo.cwiseMin(p);
            hi = hi.cwiseMax(p);
        }
        g.origin_ = lo;
        double cells = 1.0;
        for (int a = 0; a < 3; ++a) {
            const double extent = std::floor((hi(a) - lo(a)) * g.inv_cell_) + 1.0;
            cells *= extent;
            if (!(cells <= static_cast<double>(max_cells))) return std::nullopt;
            g.size_[a] = static_cast<int64_t>(extent);
        }
        // Counting sort of the points by cell: CSR offsets and the points in cell order.
        const size_t num_cells = static_cast<size_t>(cells);
        std::vector<uint32_t> cell_of(points.size());
        g.start_.assign(num_cells + 1, 0);
        for (size_t i = 0; i < points.size(); ++i) {
            cell_of[i] = static_cast<uint32_t>(g.cell_index(g.cell_coordinates(points[i])));
            ++g.start_[cell_of[i] + 1];
        }
        for (size_t c = 0; c < num_cells; ++c) g.start_[c + 1] += g.start_[c];
        g.points_.resize(points.size());
        std::vector<uint32_t> fill(g.start_.begin(), g.start_.end() - 1);
        for (size_t i = 0; i < points.size(); ++i) g.points_[fill[cell_of[i]]++] = points[i];
        return g;
    }

    /// Squared distance from `q` to its nearest point closer than r, if there is one.
    bool nearest(const Eigen::Vector3d& q, double& distance2) const {
        int64_t first[3];
        for (int a = 0; a < 3; ++a) {
            const double x = (q(a) - origin_(a)) * inv_cell_;
            // Also rejects NaN. Beyond one cell outside the grid nothing can be within r.
            if (!(x >= -1.0 && x < static_cast<double>(size_[a]) + 1.0)) return false;
            const double cell = std::floor(x);
            first[a] = static_cast<int64_t>(cell) - (x - cell < 0.5 ? 1 : 0);
        }
        double best = radius2_;
        bool found = false;
        for (int64_t z = std::max<int64_t>(first[2], 0); z <= std::min(first[2] + 1, size_[2] - 1); ++z)
            for (int64_t y = std::max<int64_t>(first[1], 0); y <= std::min(first[1] + 1, size_[1] - 1); ++y)
                for (int64_t x = std::max<int64_t>(first[0], 0); x <= std::min(first[0] + 1, size_[0] - 1); ++x) {
                    const size_t c = static_cast<size_t>((z * size_[1] + y) * size_[0] + x);
                    for (uint32_t k = start_[c]; k < start_[c + 1]; ++k) {
                        const Eigen::Vector3d& p = points_[k];
                        const double dx = q(0) - p(0), dy = q(1) - p(1), dz = q(2) - p(2);
                        const double d2 = dx * dx + dy * dy + dz * dz;
                        if (d2 < best) {
                            best = d2;
                            found = true;
                        }
                    }
                }
        if (found) distance2 = best;
        return found;
    }

private:
    std::array<int64_t, 3> cell_coordinates(const Eigen::Vector3d& p) const {
        std::array<int64_t, 3> c;
        for (int a = 0; a < 3; ++a)
            c[static_cast<size_t>(a)] = std::min<int64_t>(
                static_cast<int64_t>(std::floor((p(a) - origin_(a)) * inv_cell_)), size_[a] - 1);
        return c;
    }
    int64_t cell_index(const std::array<int64_t, 3>& c) const { return (c[2] * size_[1] + c[1]) * size_[0] + c[0]; }

    Eigen::Vector3d origin_;
    double inv_cell_ = 0.0;
    double radius2_ = 0.0;
    int64_t size_[3] = {1, 1, 1};
    std::vector<uint32_t> start_;          ///< cell c holds points_[start_[c], start_[c + 1])
    std::vector<Eigen::Vector3d> points_;  ///< the target points in cell order
};

/// Cells the scoring grid may use: generous for small clouds, bounded for huge ones (beyond it the
/// KD-tree is used instead).
size_t grid_cell_budget(size_t num_points) {
    return std::clamp<size_t>(16 * num_points, size_t{1} << 18, size_t{1} << 26);
}

/// One hypothesis of a block, as its worker left it.
struct Hypothesis {
    enum class State : uint8_t { Rejected, Pruned, Scored };
    State state = State::Rejected;
    int64_t inliers = 0;
    double inlier_rmse = 0.0;
    Eigen::Matrix4d transformation;
};

/// The best hypothesis so far, in the walk's (serial) order.
struct Best {
    bool found = false;
    int64_t inliers = 0;
    double inlier_rmse = 0.0;
    Eigen::Matrix4d transformation = Eigen::Matrix4d::Identity();

    /// Open3D's IsBetterRANSACThan: higher fitness, or equal fitness and lower RMSE.
    bool improved_by(const Hypothesis& h) const {
        return h.inliers > inliers || (h.inliers == inliers && h.inlier_rmse < inlier_rmse);
    }
};

class Ransac {
public:
    Ransac(const geometry::PointCloud& source, const geometry::PointCloud& target, const CorrespondenceSet& corres,
           double max_distance, const std::vector<CorrespondenceChecker>& checkers, const RansacOptions& options)
        : source_(source),
          target_(target),
          corres_(corres),
          max_distance_(max_distance),
          max_distance2_(max_distance * max_distance),
          options_(options),
          seed_(options.seed ? *options.seed : utility::random::draw_call_seed()),
          grid_(NeighbourGrid::build(target.points, max_distance, grid_cell_budget(target.size()))) {
        if (!grid_) tree_ = std::make_unique<kdtree::KDTree>(target.points);
        for (const auto& checker : checkers)
            (checker.requires_alignment() ? aligned_checkers_ : unaligned_checkers_).push_back(checker);
    }

    /// The best transformation found (identity when none passed) and whether there was one.
    Best run() {
        const int max_iteration = options_.criteria.max_iteration;
        const int threads = utility::resolve_num_threads(options_.num_threads);
        std::vector<Hypothesis> block(kBlockSize);
        Best best;
        int64_t bound = max_iteration;  // Open3D's est_k: iterations at or past it are not run
        for (int64_t start = 0; start < bound; start += kBlockSize) {
            const int count = static_cast<int>(std::min<int64_t>(kBlockSize, bound - start));
            run_block(start, count, best.found ? best.inliers : 1, threads, block);
            // Merge in iteration order, exactly as a serial loop would have seen the hypotheses.
            for (int k = 0; k < count && start + k < bound; ++k) {
                const Hypothesis& h = block[static_cast<size_t>(k)];
                if (h.state != Hypothesis::State::Scored || !best.improved_by(h)) continue;
                best.found = true;
                best.inliers = h.inliers;
                best.inlier_rmse = h.inlier_rmse;
                best.transformation = h.transformation;
                bound = std::min(bound, iteration_bound(h.transformation, bound));
            }
            if (options_.progress) {
                const double done = start + count >= bound ? 1.0
                                                           : static_cast<double>(start + count) /
                                                                 static_cast<double>(max_iteration);
                if (!options_.progress(done)) throw Cancelled("RANSAC cancelled by the progress callback");
            }
        }
        return best;
    }

private:
    void run_block(int64_t start, int count, int64_t min_inliers, int threads, std::vector<Hypothesis>& block) const {
        std::exception_ptr error;
        const int workers = std::max(1, std::min(threads, count));
#pragma omp parallel num_threads(workers) if (workers > 1)
        {
            std::vector<size_t> sample(static_cast<size_t>(options_.ransac_n));
            std::vector<Eigen::Vector2i> pairs(static_cast<size_t>(options_.ransac_n));
#pragma omp for schedule(dynamic, 4)
            for (int k = 0; k < count; ++k) {
                try {
                    evaluate(start + k, min_inliers, sample, pairs, block[static_cast<size_t>(k)]);
                } catch (...) {
#pragma omp critical(o3d_ransac_error)
                    if (!error) error = std::current_exception();
                }
            }
        }
        if (error) std::rethrow_exception(error);
    }

    /// Hypothesis number `iteration`: draw, check, fit, check, score.
    void evaluate(int64_t iteration, int64_t min_inliers, std::vector<size_t>& sample,
                  std::vector<Eigen::Vector2i>& pairs, Hypothesis& out) const {
        out.state = Hypothesis::State::Rejected;
        draw(static_cast<uint64_t>(iteration), sample);
        for (size_t j = 0; j < sample.size(); ++j) pairs[j] = corres_[sample[j]];
        // Checkers that ignore the transformation run before the fit: same verdict, less work.
        const Eigen::Matrix4d identity = Eigen::Matrix4d::Identity();
        for (const auto& checker : unaligned_checkers_)
            if (!checker.passes(source_, target_, pairs.data(), pairs.size(), identity)) return;
        const Eigen::Matrix4d t = fit(pairs);
        if (!t.allFinite()) return;
        for (const auto& checker : aligned_checkers_)
            if (!checker.passes(source_, target_, pairs.data(), pairs.size(), t)) return;
        score(t, min_inliers, out);
    }

    /// ransac_n distinct indices into corres_, a function of (seed, iteration) only.
    void draw(uint64_t iteration, std::vector<size_t>& sample) const {
        auto rng = utility::random::stream(seed_, iteration);
        const uint64_t n = corres_.size();
        const size_t want = sample.size();
        const auto taken = [&sample](size_t j, size_t idx) {
            return std::find(sample.begin(), sample.begin() + static_cast<std::ptrdiff_t>(j), idx) !=
                   sample.begin() + static_cast<std::ptrdiff_t>(j);
        };
        if (want <= kMaxRejectionDraw) {
            for (size_t j = 0; j < want;) {
                const size_t idx = static_cast<size_t>(rng.below(n));
                if (!taken(j, idx)) sample[j++] = idx;
            }
            return;
        }
        // Floyd's algorithm: `want` distinct values in `want` draws, without a buffer of size n.
        size_t j = 0;
        for (uint64_t m = n - want; m < n; ++m) {
            const size_t idx = static_cast<size_t>(rng.below(m + 1));
            sample[j] = taken(j, idx) ? static_cast<size_t>(m) : idx;
            ++j;
        }
    }

    Eigen::Matrix4d fit(const std::vector<Eigen::Vector2i>& pairs) const {
        if (options_.estimation == Estimation::PointToPlane) return estimate_point_to_plane(source_, target_, pairs);
        // Moments relative to one of the pairs' points keep far-from-origin clouds precise.
        const Eigen::Vector3d reference = target_.points[pairs[0](1)];
        detail::PointToPointSums sums;
        for (const auto& c : pairs) sums.accumulate(source_.points[c(0)] - reference, target_.points[c(1)] - reference);
        return detail::solve_point_to_point(sums, reference, options_.with_scaling);
    }

    /// Score `t` over every source point (Open3D's full evaluation), giving up as soon as fewer than
    /// `min_inliers` inliers are reachable: such a hypothesis cannot beat the best of earlier blocks.
    void score(const Eigen::Matrix4d& t, int64_t min_inliers, Hypothesis& out) const {
        const Eigen::Matrix3d rotation = t.topLeftCorner<3, 3>();
        const Eigen::Vector3d translation = t.topRightCorner<3, 1>();
        const auto& points = source_.points;
        const int64_t n = static_cast<int64_t>(points.size());
        int64_t inliers = 0;
        double error2 = 0.0;
        for (int64_t i = 0; i < n; ++i) {
            if (inliers + (n - i) < min_inliers) {
                out.state = Hypothesis::State::Pruned;
                return;
            }
            const Eigen::Vector3d moved = rotation * points[static_cast<size_t>(i)] + translation;
            double d2 = 0.0;
            const bool hit = grid_ ? grid_->nearest(moved, d2)
                                   : moved.allFinite() && tree_->search_nearest(moved, max_distance_, d2) >= 0;
            if (hit) {
                ++inliers;
                error2 += d2;
            }
        }
        if (inliers < min_inliers) {
            out.state = Hypothesis::State::Pruned;
            return;
        }
        out.state = Hypothesis::State::Scored;
        out.inliers = inliers;
        out.inlier_rmse = inliers ? std::sqrt(error2 / static_cast<double>(inliers)) : 0.0;
        out.transformation = t;
    }

    /// Open3D's est_k after an improvement: enough iterations to draw one all-inlier sample with
    /// probability `confidence`, the inlier share being taken over the correspondences.
    int64_t iteration_bound(const Eigen::Matrix4d& t, int64_t current) const {
        const Eigen::Matrix3d rotation = t.topLeftCorner<3, 3>();
        const Eigen::Vector3d translation = t.topRightCorner<3, 1>();
        int64_t inliers = 0;
        for (const auto& c : corres_)
            if ((rotation * source_.points[c(0)] + translation - target_.points[c(1)]).squaredNorm() < max_distance2_)
                ++inliers;
        const double ratio = static_cast<double>(inliers) / static_cast<double>(corres_.size());
        // No inlier pair says nothing (the bound would be infinite); log1p keeps tiny ratios from
        // rounding 1 - ratio^n to 1, which would divide by zero.
        if (ratio <= 0.0) return current;
        const double k = std::log1p(-options_.criteria.confidence) / std::log1p(-std::pow(ratio, options_.ransac_n));
        if (!(k < static_cast<double>(current))) return current;  // also NaN
        return static_cast<int64_t>(std::ceil(k));
    }

    const geometry::PointCloud& source_;
    const geometry::PointCloud& target_;
    const CorrespondenceSet& corres_;
    const double max_distance_;
    const double max_distance2_;
    const RansacOptions& options_;
    const uint64_t seed_;
    /// Scoring index: the grid when its size is reasonable, else a KD-tree.
    std::optional<NeighbourGrid> grid_;
    std::unique_ptr<kdtree::KDTree> tree_;
    std::vector<CorrespondenceChecker> unaligned_checkers_;
    std::vector<CorrespondenceChecker> aligned_checkers_;
};

}  // namespace

RegistrationResult registration_ransac_based_on_correspondence(const geometry::PointCloud& source,
                                                               const geometry::PointCloud& target,
                                                               const CorrespondenceSet& corres,
                                                               double max_correspondence_distance,
                                                               const std::vector<CorrespondenceChecker>& checkers,
                                                               const RansacOptions& options) {
    validate(source, target, max_correspondence_distance, checkers, options);
    detail::check_correspondences(corres, source.size(), target.size());
    if (corres.size() < static_cast<size_t>(options.ransac_n)) return RegistrationResult();
    Ransac ransac(source, target, corres, max_correspondence_distance, checkers, options);
    const Best best = ransac.run();
    if (!best.found) return RegistrationResult();
    // What Open3D returns: the best transformation evaluated on the whole clouds.
    return evaluate_registration(source, target, max_correspondence_distance, best.transformation,
                                 options.num_threads);
}

namespace detail {

CorrespondenceSet feature_correspondences(const geometry::PointCloud& source, const geometry::PointCloud& target,
                                          const Feature& source_feature, const Feature& target_feature,
                                          bool mutual_filter, size_t min_mutual, int num_threads) {
    if (source_feature.num() != source.size())
        throw InvalidArgument("source feature has " + std::to_string(source_feature.num()) + " descriptors but the " +
                              "source cloud " + std::to_string(source.size()) + " points");
    if (target_feature.num() != target.size())
        throw InvalidArgument("target feature has " + std::to_string(target_feature.num()) + " descriptors but the " +
                              "target cloud " + std::to_string(target.size()) + " points");
    CorrespondenceSet forward = correspondences_from_features(source_feature, target_feature, false, 0.0, num_threads);
    if (!mutual_filter) return forward;
    // Only targets that some source point chose can be mutual: search back from those alone (on the
    // paper's scans about 40% of the target), which gives the same pairs as a full backward pass.
    std::vector<int32_t> slot(target.size(), -1);
    std::vector<int> chosen;
    for (const auto& c : forward)
        if (slot[static_cast<size_t>(c(1))] < 0) {
            slot[static_cast<size_t>(c(1))] = static_cast<int32_t>(chosen.size());
            chosen.push_back(c(1));
        }
    Eigen::MatrixXd queries(target_feature.data.rows(), static_cast<Eigen::Index>(chosen.size()));
    for (size_t k = 0; k < chosen.size(); ++k)
        queries.col(static_cast<Eigen::Index>(k)) = target_feature.data.col(chosen[k]);
    const kdtree::KDTreeXd source_tree(source_feature.data);
    const kdtree::SearchResult back =
        source_tree.search_batch(queries.data(), chosen.size(), kdtree::SearchParam::make_knn(1), num_threads);
    CorrespondenceSet mutual;
    mutual.reserve(forward.size());
    for (const auto& c : forward) {
        const size_t k = static_cast<size_t>(slot[static_cast<size_t>(c(1))]);
        if (back.offsets[k + 1] > back.offsets[k] && back.indices[static_cast<size_t>(back.offsets[k])] == c(0))
            mutual.push_back(c);
    }
    return mutual.size() >= min_mutual ? mutual : forward;
}

}  // namespace detail

RegistrationResult registration_ransac_based_on_feature_matching(
    const geometry::PointCloud& source, const geometry::PointCloud& target, const Feature& source_feature,
    const Feature& target_feature, bool mutual_filter, double max_correspondence_distance,
    const std::vector<CorrespondenceChecker>& checkers, const RansacOptions& options) {
    validate(source, target, max_correspondence_distance, checkers, options);
    const CorrespondenceSet corres =
        detail::feature_correspondences(source, target, source_feature, target_feature, mutual_filter,
                                        3 * static_cast<size_t>(options.ransac_n), options.num_threads);
    return registration_ransac_based_on_correspondence(source, target, corres, max_correspondence_distance, checkers,
                                                       options);
}

}  // namespace o3d::registration
