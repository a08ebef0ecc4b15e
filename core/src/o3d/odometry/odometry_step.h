// SPDX-License-Identifier: MIT
#pragma once
/// @file odometry_step.h
/// @brief The normal equations of one Gauss-Newton step (Open3D's ComputeJacobianAndResidual summed over the
/// correspondences), built in one pass over the source pixels: each pixel is warped, tested and, when it
/// corresponds, its rows are added at once, without a correspondence list in between.
#include <cstddef>

#include "o3d/odometry/odometry_level.h"
#include "o3d/registration/estimation_point_to_plane.h"

namespace o3d::odometry::detail {

struct StepSums {
    registration::detail::NormalEquations6 equations;
    size_t correspondences = 0;  ///< 0: nothing overlaps, no step can be taken
};

/// @brief The sums for `motion` (source to target) over the correspondences visit_matches finds. They are
/// over fixed blocks of source rows added in order (odometry_reduce.h): the same bits for any thread count.
StepSums step_sums(const PackedLevel& level, const Eigen::Matrix4d& motion, Jacobian jacobian, double depth_diff_max);

}  // namespace o3d::odometry::detail
