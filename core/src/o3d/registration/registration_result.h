// SPDX-License-Identifier: MIT
#pragma once
/// @file registration_result.h
/// @brief What a registration returns (Open3D's RegistrationResult).
#include <Eigen/Core>
#include <vector>

namespace o3d::registration {

/// @brief (source index, target index) pairs, in ascending source index.
using CorrespondenceSet = std::vector<Eigen::Vector2i>;

/// @brief Transformation plus how well it aligns the clouds.
struct RegistrationResult {
    Eigen::Matrix4d transformation = Eigen::Matrix4d::Identity();
    double fitness = 0.0;      ///< inlier pairs / source points
    double inlier_rmse = 0.0;  ///< RMS distance of the inlier pairs (0 when there are none)
    CorrespondenceSet correspondence_set;
};

}  // namespace o3d::registration
