// SPDX-License-Identifier: MIT
#pragma once
/// @file feature.h
/// @brief Per-point descriptors (Open3D's registration::Feature).
#include <Eigen/Core>
#include <cstddef>

namespace o3d::registration {

/// @brief `dimension` x `num` descriptors; column i describes point i (contiguous, as Open3D's).
struct Feature {
    Eigen::MatrixXd data;

    size_t dimension() const { return static_cast<size_t>(data.rows()); }
    size_t num() const { return static_cast<size_t>(data.cols()); }
};

}  // namespace o3d::registration
