// SPDX-License-Identifier: MIT
#include "o3d/registration/fast_global_registration.h"

#include <Eigen/LU>  // inverse
#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "o3d/registration/estimation_point_to_plane.h"  // NormalEquations6, euler_pose_to_matrix
#include "o3d/registration/evaluation.h"
#include "o3d/registration/ransac.h"  // feature_correspondences
#include "o3d/utility/error.h"
#include "o3d/utility/parallel.h"
#include "o3d/utility/random.h"

namespace o3d::registration {

namespace {

/// Pairs per reduction block of one Gauss-Newton step; fixed so that sums do not depend on threads.
constexpr int64_t kPairBlock = 1024;
/// Open3D keeps the identity rotation when fewer pairs survive the tuple test.
constexpr size_t kMinPairs = 10;

void validate(const geometry::PointCloud& source, const geometry::PointCloud& target,
              const FastGlobalRegistrationOption& o) {
    if (!source.has_points()) throw InvalidArgument("source point cloud is empty");
    if (!target.has_points()) throw InvalidArgument("target point cloud is empty");
    for (const auto* cloud : {&source, &target})
        for (size_t i = 0; i < cloud->size(); ++i)
            if (!cloud->points[i].allFinite())
                throw InvalidArgument(std::string(cloud == &source ? "source" : "target") + " point " +
                                      std::to_string(i) + " has a non-finite coordinate");
    if (!(o.division_factor > 1.0) || !std::isfinite(o.division_factor))
        throw InvalidArgument("division_factor must be finite and > 1, got " + std::to_string(o.division_factor));
    if (!std::isfinite(o.maximum_correspondence_distance) || o.maximum_correspondence_distance <= 0.0)
        throw InvalidArgument("maximum_correspondence_distance must be finite and > 0, got " +
                              std::to_string(o.maximum_correspondence_distance));
    if (o.iteration_number < 0)
        throw InvalidArgument("iteration_number must be >= 0, got " + std::to_string(o.iteration_number));
    if (!(o.tuple_scale > 0.0 && o.tuple_scale <= 1.0))
        throw InvalidArgument("tuple_scale must be in (0, 1], got " + std::to_string(o.tuple_scale));
    if (o.maximum_tuple_count < 0)
        throw InvalidArgument("maximum_tuple_count must be >= 0, got " + std::to_string(o.maximum_tuple_count));
    if (o.num_threads < 0) throw InvalidArgument("num_threads must be >= 0, got " + std::to_string(o.num_threads));
}

/// Open3D's AdvancedMatching: random triples of pairs whose source and target triangles have
/// edge lengths within tuple_scale of each other; the pairs of each kept triple, in draw order.
CorrespondenceSet tuple_test(const geometry::PointCloud& source, const geometry::PointCloud& target,
                             const CorrespondenceSet& corres, const FastGlobalRegistrationOption& o, uint64_t seed) {
    CorrespondenceSet kept;
    const uint64_t n = corres.size();
    if (n == 0) return kept;
    const double scale = o.tuple_scale;
    auto rng = utility::random::stream(seed, 0);
    const auto similar = [scale](double ls, double lt) { return ls * scale < lt && lt < ls / scale; };
    const uint64_t trials = n * 100;
    int64_t tuples = 0;
    for (uint64_t trial = 0; trial < trials; ++trial) {
        const Eigen::Vector2i& a = corres[rng.below(n)];
        const Eigen::Vector2i& b = corres[rng.below(n)];
        const Eigen::Vector2i& c = corres[rng.below(n)];
        const Eigen::Vector3d &s0 = source.points[a(0)], &s1 = source.points[b(0)], &s2 = source.points[c(0)];
        const Eigen::Vector3d &t0 = target.points[a(1)], &t1 = target.points[b(1)], &t2 = target.points[c(1)];
        if (similar((s0 - s1).norm(), (t0 - t1).norm()) && similar((s1 - s2).norm(), (t1 - t2).norm()) &&
            similar((s2 - s0).norm(), (t2 - t0).norm())) {
            kept.push_back(a);
            kept.push_back(b);
            kept.push_back(c);
            ++tuples;
        }
        // Checked after the trial, as Open3D: a count of 0 still keeps the first tuple found.
        if (tuples >= o.maximum_tuple_count) break;
    }
    return kept;
}

Eigen::Vector3d mean_of(const std::vector<Eigen::Vector3d>& points) {
    Eigen::Vector3d sum = Eigen::Vector3d::Zero();
    for (const auto& p : points) sum += p;
    return sum / static_cast<double>(points.size());
}

double max_distance_from(const std::vector<Eigen::Vector3d>& points, const Eigen::Vector3d& centre) {
    double radius = 0.0;
    for (const auto& p : points) radius = std::max(radius, (p - centre).norm());
    return radius;
}

/// Geman-McClure Gauss-Newton steps that move `q` (normalised target points) onto `p` (normalised
/// source points), pair by pair; returns the accumulated target-to-source motion.
Eigen::Matrix4d optimize_pairwise(const std::vector<Eigen::Vector3d>& p, std::vector<Eigen::Vector3d>& q, double mu,
                                  const FastGlobalRegistrationOption& o) {
    Eigen::Matrix4d trans = Eigen::Matrix4d::Identity();
    if (p.size() < kMinPairs) return trans;
    const int64_t n = static_cast<int64_t>(p.size());
    const int64_t num_blocks = (n + kPairBlock - 1) / kPairBlock;
    std::vector<detail::NormalEquations6> blocks(static_cast<size_t>(num_blocks));
    const int threads =
        static_cast<int>(std::min<int64_t>(utility::resolve_num_threads(o.num_threads), num_blocks));
    for (int itr = 0; itr < o.iteration_number; ++itr) {
#pragma omp parallel for schedule(static) num_threads(threads) if (threads > 1)
        for (int64_t b = 0; b < num_blocks; ++b) {
            detail::NormalEquations6 sums;
            const int64_t end = std::min(n, (b + 1) * kPairBlock);
            for (int64_t c = b * kPairBlock; c < end; ++c) {
                const Eigen::Vector3d& qc = q[static_cast<size_t>(c)];
                const Eigen::Vector3d r = p[static_cast<size_t>(c)] - qc;
                // The scaled Geman-McClure weight (mu / (|r|^2 + mu))^2 of the line process.
                const double g = mu / (r.squaredNorm() + mu);
                const double w = g * g;
                // Residual p - (q + omega x q + t), one row per coordinate.
                const double jx[6] = {0.0, -qc.z(), qc.y(), -1.0, 0.0, 0.0};
                const double jy[6] = {qc.z(), 0.0, -qc.x(), 0.0, -1.0, 0.0};
                const double jz[6] = {-qc.y(), qc.x(), 0.0, 0.0, 0.0, -1.0};
                sums.add_row(jx, r.x(), w);
                sums.add_row(jy, r.y(), w);
                sums.add_row(jz, r.z(), w);
            }
            blocks[static_cast<size_t>(b)] = sums;
        }
        detail::NormalEquations6 total;
        for (const auto& block : blocks) total.add(block);
        const Eigen::Matrix4d delta = detail::euler_pose_to_matrix(total.solve());  // identity if singular
        trans = delta * trans;
        const Eigen::Matrix3d rotation = delta.topLeftCorner<3, 3>();
        const Eigen::Vector3d translation = delta.topRightCorner<3, 1>();
        for (auto& qc : q) qc = rotation * qc + translation;
        // Graduated non-convexity: a wide kernel first, narrowed every 4th iteration.
        if (o.decrease_mu && itr % 4 == 0 && mu > o.maximum_correspondence_distance) mu /= o.division_factor;
        if (o.progress && !o.progress(static_cast<double>(itr + 1) / static_cast<double>(o.iteration_number)))
            throw Cancelled("FGR cancelled by the progress callback");
    }
    return trans;
}

RegistrationResult fgr(const geometry::PointCloud& source, const geometry::PointCloud& target,
                       const CorrespondenceSet& corres, const FastGlobalRegistrationOption& o, uint64_t seed) {
    // Normalise: centre each cloud on its mean, divide both by their joint radius (Open3D's
    // NormalizePointCloud); with use_absolute_scale only centre, and start mu at that radius instead.
    const Eigen::Vector3d source_mean = mean_of(source.points);
    const Eigen::Vector3d target_mean = mean_of(target.points);
    const double radius =
        std::max(max_distance_from(source.points, source_mean), max_distance_from(target.points, target_mean));
    if (!(radius > 0.0)) throw InvalidArgument("both clouds sit on a single point: FGR has no scale to normalise by");
    const double scale = o.use_absolute_scale ? 1.0 : radius;

    const CorrespondenceSet pairs = o.tuple_test ? tuple_test(source, target, corres, o, seed) : corres;
    std::vector<Eigen::Vector3d> p(pairs.size()), q(pairs.size());
    for (size_t c = 0; c < pairs.size(); ++c) {
        p[c] = (source.points[pairs[c](0)] - source_mean) / scale;
        q[c] = (target.points[pairs[c](1)] - target_mean) / scale;
    }
    // Open3D starts mu at the global scale (its scale_start, 1 for relative scale, goes unused).
    const Eigen::Matrix4d target_to_source = optimize_pairwise(p, q, scale, o);

    // Back to the clouds' units: x_s = R (x_t - mean_t) + scale t + mean_s.
    const Eigen::Matrix3d rotation = target_to_source.topLeftCorner<3, 3>();
    Eigen::Matrix4d original = Eigen::Matrix4d::Identity();
    original.topLeftCorner<3, 3>() = rotation;
    original.topRightCorner<3, 1>() =
        -rotation * target_mean + target_to_source.topRightCorner<3, 1>() * scale + source_mean;
    return evaluate_registration(source, target, o.maximum_correspondence_distance, original.inverse(),
                                 o.num_threads);
}

}  // namespace

RegistrationResult registration_fgr_based_on_correspondence(const geometry::PointCloud& source,
                                                            const geometry::PointCloud& target,
                                                            const CorrespondenceSet& corres,
                                                            const FastGlobalRegistrationOption& option) {
    validate(source, target, option);
    detail::check_correspondences(corres, source.size(), target.size());
    const uint64_t seed = option.seed ? *option.seed : utility::random::draw_call_seed();
    return fgr(source, target, corres, option, seed);
}

RegistrationResult registration_fgr_based_on_feature_matching(const geometry::PointCloud& source,
                                                              const geometry::PointCloud& target,
                                                              const Feature& source_feature,
                                                              const Feature& target_feature,
                                                              const FastGlobalRegistrationOption& option) {
    validate(source, target, option);
    const uint64_t seed = option.seed ? *option.seed : utility::random::draw_call_seed();
    // Mutual nearest descriptors in both directions, with no fallback (Open3D's InitialMatching).
    const CorrespondenceSet corres = detail::feature_correspondences(source, target, source_feature, target_feature,
                                                                     true, 0, option.num_threads);
    return fgr(source, target, corres, option, seed);
}

}  // namespace o3d::registration
