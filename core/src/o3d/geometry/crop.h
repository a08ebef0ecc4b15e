// SPDX-License-Identifier: MIT
#pragma once
/// @file crop.h
/// @brief Cropping by an axis-aligned box (PointCloud::Crop(AxisAlignedBoundingBox) of Open3D).
#include <Eigen/Core>
#include <cstdint>
#include <vector>

#include "o3d/geometry/point_cloud.h"

namespace o3d::geometry {

/// @brief Ascending indices of the points with min_bound <= p <= max_bound on every axis (inclusive, as
/// AxisAlignedBoundingBox::GetPointIndicesWithinBoundingBox); a point with a NaN coordinate is never inside.
/// @throws InvalidArgument on a non-finite bound, or a box of zero volume / with max < min on an axis
/// (Open3D's Crop raises "AxisAlignedBoundingBox either has zeros size, or has wrong bounds" too).
std::vector<int64_t> indices_in_aabb(const PointCloud& cloud, const Eigen::Vector3d& min_bound,
                                     const Eigen::Vector3d& max_bound);

/// @brief The points inside the box (outside when `invert`), with their normals and colors, in order.
PointCloud crop_aabb(const PointCloud& cloud, const Eigen::Vector3d& min_bound, const Eigen::Vector3d& max_bound,
                     bool invert = false);

}  // namespace o3d::geometry
