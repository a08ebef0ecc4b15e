// SPDX-License-Identifier: MIT
#pragma once
/// @file feature_matching.h
/// @brief Correspondences from nearest descriptors (Open3D's CorrespondencesFromFeatures).
#include "o3d/registration/feature.h"
#include "o3d/registration/registration_result.h"

namespace o3d::registration {

/// @brief For each source descriptor, its nearest target descriptor (L2), as (source, target) pairs in
/// ascending source order. With `mutual_filter`, only pairs that are also nearest the other way are kept,
/// unless fewer than mutual_consistency_ratio * num(source) survive: then all pairs are returned
/// (Open3D's rule). Deterministic for any thread count.
/// @throws o3d::InvalidArgument on differing dimensions, an empty feature, a ratio outside [0, 1] or NaN,
/// or num_threads < 0.
CorrespondenceSet correspondences_from_features(const Feature& source, const Feature& target,
                                                bool mutual_filter = false, double mutual_consistency_ratio = 0.1,
                                                int num_threads = 0);

}  // namespace o3d::registration
