// SPDX-License-Identifier: MIT
#pragma once
/// @file global_registration.hpp
/// @brief Global registration: correspondence checkers, RANSAC over feature matches or given
/// correspondences, Fast Global Registration, and the global random seed.
#include <array>
#include <cstdint>
#include <optional>
#include <vector>

#include "o3d/registration.h"
#include "o3dpp/common.hpp"
#include "o3dpp/error.hpp"
#include "o3dpp/feature.hpp"
#include "o3dpp/pointcloud.hpp"
#include "o3dpp/registration.hpp"
#include "o3dpp/span.hpp"

namespace o3dpp {

/// @brief (source index, target index) pairs.
using Correspondences = std::vector<std::array<int32_t, 2>>;

/// @brief Prunes RANSAC hypotheses early (Open3D's CorrespondenceChecker*). The threshold must be
/// finite and positive.
struct CorrespondenceChecker {
    enum class Kind : int32_t {
        EdgeLength = O3D_CHECKER_EDGE_LENGTH,  ///< similarity_threshold in (0, 1]
        Distance = O3D_CHECKER_DISTANCE,       ///< distance_threshold
        Normal = O3D_CHECKER_NORMAL            ///< normal_angle_threshold (radians); both clouds need normals
    };
    Kind kind = Kind::EdgeLength;
    double threshold = 0.9;

    /// @brief CorrespondenceCheckerBasedOnEdgeLength (Open3D default 0.9).
    static CorrespondenceChecker EdgeLength(double similarity_threshold = 0.9) {
        return {Kind::EdgeLength, similarity_threshold};
    }
    /// @brief CorrespondenceCheckerBasedOnDistance.
    static CorrespondenceChecker Distance(double distance_threshold) { return {Kind::Distance, distance_threshold}; }
    /// @brief CorrespondenceCheckerBasedOnNormal (radians).
    static CorrespondenceChecker Normal(double normal_angle_threshold) {
        return {Kind::Normal, normal_angle_threshold};
    }
    /// @brief The library's default checker of `kind` (o3d_correspondence_checker_init).
    static CorrespondenceChecker library_default(Kind kind) {
        const o3d_correspondence_checker_t c = raw(kind);
        return {kind, c.threshold};
    }

    o3d_correspondence_checker_t to_c() const {
        o3d_correspondence_checker_t c = raw(kind);
        c.threshold = threshold;
        return c;
    }

    /// @brief Does the hypothesis `transformation` pass on `corres`? @see CorrespondenceChecker.Check
    bool check(const PointCloud& source, const PointCloud& target, const Correspondences& corres,
               const Mat4& transformation = identity4()) const {
        const o3d_correspondence_checker_t c = to_c();
        int32_t passed = 0;
        o3dpp::check(o3d_correspondence_checker_check(&passed, &c, source.get(), target.get(),
                                                      corres.empty() ? nullptr : corres.front().data(), corres.size(),
                                                      transformation.data()));
        return passed != 0;
    }

private:
    static o3d_correspondence_checker_t raw(Kind kind) {
        o3d_correspondence_checker_t c;
        o3dpp::check(o3d_correspondence_checker_init(&c, sizeof c, static_cast<int32_t>(kind)));
        return c;
    }
};

/// @brief Seed the global generator RANSAC and FGR draw from when given no seed. @see o3d.utility.random.seed
inline void random_seed(uint64_t seed) { check(o3d_random_seed(seed)); }

/// @brief RANSAC options (estimation, ransac_n, RANSACConvergenceCriteria, seed), Open3D defaults.
struct RansacOptions {
    Estimation estimation = Estimation::PointToPoint;  ///< PointToPoint or PointToPlane
    bool with_scaling = false;
    int ransac_n = 3;
    int max_iteration = 100000;
    double confidence = 0.999;
    bool mutual_filter = false;  ///< feature matching only
    /// @brief Draw from this seed; empty: take one from the global generator (random_seed()).
    /// The same seed gives the same result on any thread count.
    std::optional<uint64_t> seed;
    int num_threads = 0;
    /// @brief Fraction of max_iteration done (1 when confident); return false to cancel. An
    /// exception it throws cancels the call and is rethrown.
    ProgressCallback progress;

    o3d_ransac_options_t to_c() const {
        o3d_ransac_options_t c;
        check(o3d_ransac_options_init(&c, sizeof c));
        c.estimation = static_cast<int32_t>(estimation);
        c.with_scaling = with_scaling ? 1 : 0;
        c.ransac_n = ransac_n;
        c.max_iteration = max_iteration;
        c.confidence = confidence;
        c.mutual_filter = mutual_filter ? 1 : 0;
        c.use_seed = seed ? 1 : 0;
        c.seed = seed.value_or(0);
        c.num_threads = num_threads;
        return c;
    }
};

/// @brief FastGlobalRegistrationOption plus seed, threads and progress, Open3D defaults.
struct FgrOptions {
    double division_factor = 1.4;
    bool use_absolute_scale = false;
    bool decrease_mu = true;
    double maximum_correspondence_distance = 0.025;
    int iteration_number = 64;
    double tuple_scale = 0.95;
    int maximum_tuple_count = 1000;
    bool tuple_test = true;
    std::optional<uint64_t> seed;  ///< as RansacOptions::seed
    int num_threads = 0;
    /// @brief Fraction of iteration_number done; return false to cancel.
    ProgressCallback progress;

    o3d_fgr_options_t to_c() const {
        o3d_fgr_options_t c;
        check(o3d_fgr_options_init(&c, sizeof c));
        c.division_factor = division_factor;
        c.use_absolute_scale = use_absolute_scale ? 1 : 0;
        c.decrease_mu = decrease_mu ? 1 : 0;
        c.maximum_correspondence_distance = maximum_correspondence_distance;
        c.iteration_number = iteration_number;
        c.tuple_scale = tuple_scale;
        c.maximum_tuple_count = maximum_tuple_count;
        c.tuple_test = tuple_test ? 1 : 0;
        c.use_seed = seed ? 1 : 0;
        c.seed = seed.value_or(0);
        c.num_threads = num_threads;
        return c;
    }
};

namespace detail {
/// @brief Wire `progress` into a C options struct, run `call(&c)`, adopt the result.
template <typename COptions, typename Call>
RegistrationResult run_with_progress(COptions c, const ProgressCallback& progress, Call&& call) {
    ProgressContext ctx;
    if (progress) {
        ctx.callback = &progress;
        c.progress = &progress_trampoline;
        c.user_data = &ctx;
    }
    o3d_registration_result_t* r = nullptr;
    check_progress(call(&r, &c), ctx);
    return RegistrationResult(r);
}
inline std::vector<o3d_correspondence_checker_t> to_c(const std::vector<CorrespondenceChecker>& checkers) {
    std::vector<o3d_correspondence_checker_t> out;
    out.reserve(checkers.size());
    for (const auto& c : checkers) out.push_back(c.to_c());
    return out;
}
inline const int32_t* pairs(const Correspondences& corres) {
    return corres.empty() ? nullptr : corres.front().data();
}
}  // namespace detail

/// @brief RANSAC over feature matches (nearest target descriptor of each source descriptor).
/// @see o3d.pipelines.registration.registration_ransac_based_on_feature_matching
inline RegistrationResult registration_ransac_based_on_feature_matching(
    const PointCloud& source, const PointCloud& target, const Feature& source_feature, const Feature& target_feature,
    double max_correspondence_distance, const std::vector<CorrespondenceChecker>& checkers = {},
    const RansacOptions& options = {}) {
    const auto cs = detail::to_c(checkers);
    return detail::run_with_progress(
        options.to_c(), options.progress, [&](o3d_registration_result_t** out, const o3d_ransac_options_t* c) {
            return o3d_register_ransac_based_on_feature_matching(out, source.get(), target.get(), source_feature.get(),
                                                                 target_feature.get(), max_correspondence_distance,
                                                                 cs.empty() ? nullptr : cs.data(), cs.size(), c);
        });
}

/// @brief RANSAC over given (source, target) pairs (options.mutual_filter is ignored).
/// @see o3d.pipelines.registration.registration_ransac_based_on_correspondence
inline RegistrationResult registration_ransac_based_on_correspondence(
    const PointCloud& source, const PointCloud& target, const Correspondences& corres,
    double max_correspondence_distance, const std::vector<CorrespondenceChecker>& checkers = {},
    const RansacOptions& options = {}) {
    const auto cs = detail::to_c(checkers);
    return detail::run_with_progress(
        options.to_c(), options.progress, [&](o3d_registration_result_t** out, const o3d_ransac_options_t* c) {
            return o3d_register_ransac_based_on_correspondence(out, source.get(), target.get(), detail::pairs(corres),
                                                               corres.size(), max_correspondence_distance,
                                                               cs.empty() ? nullptr : cs.data(), cs.size(), c);
        });
}

/// @brief Fast Global Registration (Zhou et al. 2016) on mutual feature matches.
/// @see o3d.pipelines.registration.registration_fgr_based_on_feature_matching
inline RegistrationResult registration_fgr_based_on_feature_matching(const PointCloud& source,
                                                                     const PointCloud& target,
                                                                     const Feature& source_feature,
                                                                     const Feature& target_feature,
                                                                     const FgrOptions& options = {}) {
    return detail::run_with_progress(
        options.to_c(), options.progress, [&](o3d_registration_result_t** out, const o3d_fgr_options_t* c) {
            return o3d_register_fgr_based_on_feature_matching(out, source.get(), target.get(), source_feature.get(),
                                                              target_feature.get(), c);
        });
}

/// @brief Fast Global Registration on given (source, target) pairs.
/// @see o3d.pipelines.registration.registration_fgr_based_on_correspondence
inline RegistrationResult registration_fgr_based_on_correspondence(const PointCloud& source,
                                                                   const PointCloud& target,
                                                                   const Correspondences& corres,
                                                                   const FgrOptions& options = {}) {
    return detail::run_with_progress(
        options.to_c(), options.progress, [&](o3d_registration_result_t** out, const o3d_fgr_options_t* c) {
            return o3d_register_fgr_based_on_correspondence(out, source.get(), target.get(), detail::pairs(corres),
                                                            corres.size(), c);
        });
}

}  // namespace o3dpp
