// SPDX-License-Identifier: MIT
#pragma once
/// @file ransac.h
/// @brief Global registration by RANSAC over correspondences (Open3D's
/// registration_ransac_based_on_correspondence / _based_on_feature_matching), parallel and
/// reproducible: the same seed gives bitwise the same result on any thread count.
#include <cstdint>
#include <functional>
#include <optional>
#include <vector>

#include "o3d/geometry/point_cloud.h"
#include "o3d/registration/correspondence_checker.h"
#include "o3d/registration/feature.h"
#include "o3d/registration/icp.h"  // Estimation
#include "o3d/registration/registration_result.h"

namespace o3d::registration {

/// @brief RANSACConvergenceCriteria: stop after max_iteration hypotheses, or earlier once the best
/// hypothesis makes it `confidence` likely that an all-inlier sample has been drawn.
struct RANSACConvergenceCriteria {
    int max_iteration = 100000;
    double confidence = 0.999;
};

/// @brief Mirrors o3d_ransac_options_t.
struct RansacOptions {
    Estimation estimation = Estimation::PointToPoint;  ///< PointToPoint or PointToPlane
    bool with_scaling = false;                         ///< point-to-point only
    int ransac_n = 3;                                  ///< correspondences per hypothesis, >= 3
    RANSACConvergenceCriteria criteria;
    /// Seed of the sample path; without one, a seed is drawn from the global generator
    /// (utility::random::seed), so unseeded calls repeat after a global reseed.
    std::optional<uint64_t> seed;
    int num_threads = 0;  ///< 0 = library default; the result does not depend on it
    /// Called on the calling thread between blocks of iterations with the fraction of max_iteration
    /// done (1 when the confidence stop is reached). Returning false cancels (o3d::Cancelled).
    std::function<bool(double)> progress;
};

/// @brief RANSAC over `corres` (source, target) pairs. Hypothesis i draws ransac_n distinct pairs from
/// the stream (seed, i), fits a transformation to them, must pass every checker, and is scored as
/// evaluate_registration scores it: fitness = share of all source points whose nearest moved-target
/// distance is below `max_correspondence_distance`, then inlier RMSE. The best is kept by (higher
/// fitness, then lower RMSE, then lower i). After an improvement the iteration bound drops to
/// ceil(log(1 - confidence) / log(1 - w^ransac_n)), w being the share of `corres` within the distance
/// under it (Open3D's rule). Returns the full evaluation of the best transformation, or the identity
/// with fitness 0 when no hypothesis passed (or `corres` holds fewer than ransac_n pairs).
/// Differs from Open3D 0.20 in drawing distinct pairs (Open3D draws with replacement) and in being
/// reproducible. @see o3d.pipelines.registration.registration_ransac_based_on_correspondence
/// @throws o3d::InvalidArgument on an empty cloud, a distance that is not finite and > 0, ransac_n < 3,
/// max_iteration < 0, confidence outside [0, 1], num_threads < 0, an estimation other than point-to-point
/// or point-to-plane, point-to-plane without target normals, a normal checker without normals on both
/// clouds, or a correspondence out of range. @throws o3d::Cancelled when `progress` returns false.
RegistrationResult registration_ransac_based_on_correspondence(
    const geometry::PointCloud& source, const geometry::PointCloud& target, const CorrespondenceSet& corres,
    double max_correspondence_distance, const std::vector<CorrespondenceChecker>& checkers = {},
    const RansacOptions& options = {});

/// @brief RANSAC over feature matches: each source point paired with the target point of nearest
/// descriptor. With `mutual_filter` only mutual nearest pairs are kept, unless fewer than
/// 3 * ransac_n survive (then all pairs are used, as Open3D).
/// @see o3d.pipelines.registration.registration_ransac_based_on_feature_matching
/// @throws o3d::InvalidArgument as registration_ransac_based_on_correspondence, and on features whose
/// dimensions differ, are 0, or whose counts differ from their clouds' point counts.
RegistrationResult registration_ransac_based_on_feature_matching(
    const geometry::PointCloud& source, const geometry::PointCloud& target, const Feature& source_feature,
    const Feature& target_feature, bool mutual_filter, double max_correspondence_distance,
    const std::vector<CorrespondenceChecker>& checkers = {}, const RansacOptions& options = {});

namespace detail {

/// @brief Mutual nearest-descriptor pairs with Open3D's fallback: `mutual_filter` off, or fewer than
/// `min_mutual` mutual pairs, gives every source point's nearest pair. Validates the features.
CorrespondenceSet feature_correspondences(const geometry::PointCloud& source, const geometry::PointCloud& target,
                                          const Feature& source_feature, const Feature& target_feature,
                                          bool mutual_filter, size_t min_mutual, int num_threads);

}  // namespace detail
}  // namespace o3d::registration
