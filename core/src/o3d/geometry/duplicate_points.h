// SPDX-License-Identifier: MIT
#pragma once
/// @file duplicate_points.h
/// @brief Removal of exactly repeated points (Open3D 0.20 PointCloud.remove_duplicated_points).
#include <cstdint>
#include <vector>

#include "o3d/geometry/point_cloud.h"

namespace o3d::geometry {

/// @brief Keep only the first of each set of points with equal coordinates (compared with ==, so -0
/// equals 0 and a point with a NaN coordinate is never a duplicate), in their original order; normals,
/// colors and covariances present for every point follow their points. In place, as Open3D.
/// @return The indices (ascending) of the kept points in the input cloud.
std::vector<int64_t> remove_duplicated_points(PointCloud& cloud);

}  // namespace o3d::geometry
