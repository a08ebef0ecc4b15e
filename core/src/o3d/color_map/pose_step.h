// SPDX-License-Identifier: MIT
#pragma once
/// @file pose_step.h
/// @brief The image side of the alternation: one Gauss-Newton step on one image's pose (and warp) with the
/// vertex intensities held fixed, minimising sum over the vertices it sees of (I(project(T v)) - C(v))^2
/// (plus, with a warp, lambda^2 * sum ||offset||^2). Images are independent here, so they can run in parallel.
#include <Eigen/Core>
#include <vector>

#include "o3d/color_map/view.h"
#include "o3d/color_map/view_images.h"

namespace o3d::color_map::detail {

struct StepStatistics {
    double squared_error = 0.0;  ///< sum of squared photometric residuals at the pose the step started from
    int residuals = 0;           ///< how many vertices could be sampled there
};

/// @brief Move `view` by one Gauss-Newton step (a left-multiplied rotation and translation; anchor offsets
/// added). A step that cannot be solved (too few residuals, a singular or non-finite system) leaves `view`
/// unchanged. `anchor_weight` is lambda; unused without a warp.
StepStatistics gauss_newton_step(View& view, const ViewImages& images, const std::vector<int>& visible,
                                 const std::vector<Eigen::Vector3d>& vertices, const std::vector<double>& proxy,
                                 double anchor_weight);

}  // namespace o3d::color_map::detail
