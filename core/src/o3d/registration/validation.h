// SPDX-License-Identifier: MIT
#pragma once
/// @file validation.h
/// @brief Internal: argument checks shared by the registration entry points.
#include <Eigen/Core>

#include "o3d/geometry/point_cloud.h"

namespace o3d::registration::detail {

/// @brief Throw o3d::InvalidArgument on an empty cloud, a distance that is not > 0 (NaN included),
/// a non-finite transformation or a negative thread count.
void check_registration_inputs(const geometry::PointCloud& source, const geometry::PointCloud& target,
                               double max_correspondence_distance, const Eigen::Matrix4d& transformation,
                               int num_threads);

}  // namespace o3d::registration::detail
