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
#include "o3dpp/generated/options.hpp"
#include "o3dpp/pointcloud.hpp"
#include "o3dpp/registration.hpp"
#include "o3dpp/span.hpp"

namespace o3dpp {

/// @brief (source index, target index) pairs.
using Correspondences = std::vector<std::array<int32_t, 2>>;

/// @brief Prunes RANSAC hypotheses early (Open3D's CorrespondenceChecker*). The threshold must be
/// finite and positive; without one, the library's default for the kind (o3d_correspondence_checker_init).
struct CorrespondenceChecker {
    using Kind = CorrespondenceCheckerKind;
    Kind kind;
    double threshold;

    /// @brief The library's default checker of `kind`.
    explicit CorrespondenceChecker(Kind k = Kind::EdgeLength) : kind(k), threshold(raw(k).threshold) {}
    CorrespondenceChecker(Kind k, double t) : kind(k), threshold(t) {}
    /// @brief CorrespondenceCheckerBasedOnEdgeLength.
    static CorrespondenceChecker EdgeLength() { return CorrespondenceChecker(Kind::EdgeLength); }
    static CorrespondenceChecker EdgeLength(double similarity_threshold) {
        return {Kind::EdgeLength, similarity_threshold};
    }
    /// @brief CorrespondenceCheckerBasedOnDistance.
    static CorrespondenceChecker Distance(double distance_threshold) { return {Kind::Distance, distance_threshold}; }
    /// @brief CorrespondenceCheckerBasedOnNormal (radians).
    static CorrespondenceChecker Normal(double normal_angle_threshold) {
        return {Kind::Normal, normal_angle_threshold};
    }
    /// @brief The library's default checker of `kind` (o3d_correspondence_checker_init).
    static CorrespondenceChecker library_default(Kind kind) { return CorrespondenceChecker(kind); }

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

namespace detail {
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
    return detail::register_with(options, [&](o3d_registration_result_t** out, const o3d_ransac_options_t* c) {
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
    return detail::register_with(options, [&](o3d_registration_result_t** out, const o3d_ransac_options_t* c) {
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
    return detail::register_with(options, [&](o3d_registration_result_t** out, const o3d_fgr_options_t* c) {
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
    return detail::register_with(options, [&](o3d_registration_result_t** out, const o3d_fgr_options_t* c) {
        return o3d_register_fgr_based_on_correspondence(out, source.get(), target.get(), detail::pairs(corres),
                                                        corres.size(), c);
    });
}

}  // namespace o3dpp
