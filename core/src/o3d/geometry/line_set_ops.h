// SPDX-License-Identifier: MIT
#pragma once
/// @file line_set_ops.h
/// @brief Building line sets (from correspondences, boxes and mesh edges) and editing them.
#include <Eigen/Core>
#include <array>
#include <vector>

#include "o3d/geometry/line_set.h"
#include "o3d/geometry/point_cloud.h"
#include "o3d/geometry/triangle_mesh.h"

namespace o3d::geometry {

/// @brief Throw o3d::InvalidArgument naming the first line with an index outside [0, points.size()).
void validate_lines(const LineSet& lines);

/// @brief Apply a 4x4 transform to the points (homogeneous divide, as point clouds).
void transform_line_set(LineSet& lines, const Eigen::Matrix4d& transform);

/// @brief Set every line's color to `rgb` (clamped to [0, 1], as point clouds do).
void paint_line_set(LineSet& lines, const Eigen::Vector3d& rgb);

/// @brief Both clouds' points (cloud0's first) and one line per (index into cloud0, index into cloud1)
/// pair; indices are range-checked (InvalidArgument).
LineSet line_set_from_correspondences(const PointCloud& cloud0, const PointCloud& cloud1,
                                      const std::vector<Eigen::Vector2i>& pairs);

/// @brief The 8 corners of the box center + R * diag(extent / 2) * s, s in {-1, 1}^3, in Open3D's
/// get_box_points order.
std::array<Eigen::Vector3d, 8> oriented_box_corners(const Eigen::Vector3d& center, const Eigen::Matrix3d& R,
                                                    const Eigen::Vector3d& extent);

/// @brief The 12 edges of an oriented box on its corners (oriented_box_corners order, Open3D's edges).
LineSet line_set_from_oriented_box(const Eigen::Vector3d& center, const Eigen::Matrix3d& R,
                                   const Eigen::Vector3d& extent);

/// @brief The 12 edges of an axis-aligned box (min_bound <= max_bound per axis).
LineSet line_set_from_axis_aligned_box(const Eigen::Vector3d& min_bound, const Eigen::Vector3d& max_bound);

/// @brief The mesh's vertices and each undirected edge once, in order of first appearance (triangles in
/// order, sides (0,1), (1,2), (2,0)) and oriented as first seen, as Open3D. Validates the triangles.
LineSet line_set_from_triangle_mesh(const TriangleMesh& mesh);

}  // namespace o3d::geometry
