// SPDX-License-Identifier: MIT
#pragma once
/// @file fast_global_registration.h
/// @brief Fast Global Registration (Zhou, Park, Koltun, ECCV 2016), as Open3D's
/// registration_fgr_based_on_correspondence / _based_on_feature_matching.
#include <cstdint>
#include <functional>
#include <optional>

#include "o3d/geometry/point_cloud.h"
#include "o3d/registration/feature.h"
#include "o3d/registration/registration_result.h"

namespace o3d::registration {

/// @brief Open3D's FastGlobalRegistrationOption, plus seed, threads and progress (mirrors o3d_fgr_options_t).
struct FastGlobalRegistrationOption {
    double division_factor = 1.4;      ///< > 1: mu is divided by it every 4th iteration
    bool use_absolute_scale = false;   ///< false: both clouds are centred and divided by their joint radius
    bool decrease_mu = true;           ///< graduated non-convexity
    double maximum_correspondence_distance = 0.025;  ///< mu stops decreasing below it; also the final evaluation's
    int iteration_number = 64;
    double tuple_scale = 0.95;         ///< in (0, 1]: edge-length similarity of the tuple test
    int maximum_tuple_count = 1000;
    bool tuple_test = true;
    /// Seed of the random tuples; without one, a seed is drawn from the global generator.
    std::optional<uint64_t> seed;
    int num_threads = 0;  ///< 0 = library default; the result does not depend on it
    /// Called on the calling thread after each iteration with (iteration + 1) / iteration_number.
    /// Returning false cancels (o3d::Cancelled).
    std::function<bool(double)> progress;
};

/// @brief FGR on given (source, target) pairs. With tuple_test, up to 100 x |corres| random triples of
/// pairs are drawn and the triples whose three edge lengths agree within tuple_scale are kept, until
/// maximum_tuple_count triples; then iteration_number Gauss-Newton steps of the scaled Geman-McClure
/// objective move the normalised target onto the normalised source, mu starting at the normalisation
/// scale (1 with use_absolute_scale, as Open3D passes it) and divided by division_factor every 4th
/// step while above maximum_correspondence_distance. Fewer than 10 surviving pairs leave the rotation at
/// identity. Returns evaluate_registration of the source-to-target transformation at
/// maximum_correspondence_distance. @see o3d.pipelines.registration.registration_fgr_based_on_correspondence
/// @throws o3d::InvalidArgument on an empty cloud, a non-finite point, a correspondence out of range,
/// division_factor not > 1, maximum_correspondence_distance not finite and > 0, iteration_number < 0,
/// tuple_scale outside (0, 1], maximum_tuple_count < 0, num_threads < 0, or clouds that all sit on one
/// point (no scale). @throws o3d::Cancelled when `progress` returns false.
RegistrationResult registration_fgr_based_on_correspondence(const geometry::PointCloud& source,
                                                            const geometry::PointCloud& target,
                                                            const CorrespondenceSet& corres,
                                                            const FastGlobalRegistrationOption& option = {});

/// @brief FGR on the mutual nearest-descriptor pairs of the two features (both directions must agree).
/// @see o3d.pipelines.registration.registration_fgr_based_on_feature_matching
/// @throws o3d::InvalidArgument as registration_fgr_based_on_correspondence, and on features whose
/// dimensions differ, are 0, or whose counts differ from their clouds' point counts.
RegistrationResult registration_fgr_based_on_feature_matching(const geometry::PointCloud& source,
                                                              const geometry::PointCloud& target,
                                                              const Feature& source_feature,
                                                              const Feature& target_feature,
                                                              const FastGlobalRegistrationOption& option = {});

}  // namespace o3d::registration
