// SPDX-License-Identifier: MIT
#pragma once
/// @file point_cloud_ops.h
/// @brief Basic point-cloud operations with Open3D's semantics (o3d.geometry.PointCloud methods).
#include <Eigen/Core>
#include <cstdint>
#include <vector>

#include "o3d/geometry/point_cloud.h"

namespace o3d::geometry {

/// @brief `target += source` (Open3D operator+=): normals/colors survive only when both clouds have
/// them, or when `target` was empty. An empty `source` changes nothing.
void append(PointCloud& target, const PointCloud& source);

/// @brief Component-wise min / max of the points; (0,0,0) for an empty cloud.
Eigen::Vector3d min_bound(const PointCloud& cloud);
Eigen::Vector3d max_bound(const PointCloud& cloud);
/// @brief Mean of the points; (0,0,0) for an empty cloud.
Eigen::Vector3d center(const PointCloud& cloud);

/// @brief p <- (T [p;1]) / w; normals <- upper-left 3x3 of T times n. @throws InvalidArgument if T is non-finite.
void transform(PointCloud& cloud, const Eigen::Matrix4d& transformation);
/// @brief relative: p <- p + t; else the center moves to t.
void translate(PointCloud& cloud, const Eigen::Vector3d& translation, bool relative);
/// @brief p <- R (p - c) + c; normals <- R n.
void rotate(PointCloud& cloud, const Eigen::Matrix3d& rotation, const Eigen::Vector3d& center);
/// @brief p <- s (p - c) + c (normals unchanged, as Open3D).
void scale(PointCloud& cloud, double factor, const Eigen::Vector3d& center);

/// @brief Every color set to `rgb`, clipped to [0,1] as Open3D does. @throws InvalidArgument if non-finite.
void paint_uniform_color(PointCloud& cloud, const Eigen::Vector3d& rgb);

/// @brief The points at `indices` (or all the others when `invert`), in their original order;
/// duplicate indices count once (Open3D builds a mask). @throws InvalidArgument on an index out of range.
PointCloud select_by_index(const PointCloud& cloud, const std::vector<int64_t>& indices, bool invert = false);
/// @brief Same selection from a keep-mask of cloud.size() entries.
PointCloud select_by_mask(const PointCloud& cloud, const std::vector<uint8_t>& keep);

/// @brief Drop points with a NaN (remove_nan) and/or an infinite (remove_infinite) coordinate,
/// with their normals and colors.
void remove_non_finite_points(PointCloud& cloud, bool remove_nan, bool remove_infinite);

/// @brief Scale each non-zero normal to unit length.
void normalize_normals(PointCloud& cloud);

/// @brief InvalidArgument unless normals/colors are empty or have one entry per point.
void check_attribute_sizes(const PointCloud& cloud);

}  // namespace o3d::geometry
