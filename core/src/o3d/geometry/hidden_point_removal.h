// SPDX-License-Identifier: MIT
#pragma once
/// @file hidden_point_removal.h
/// @brief Visible points from a viewpoint (Katz, Tal, Basri 2007), as PointCloud.hidden_point_removal.
#include <Eigen/Core>
#include <vector>

#include "o3d/geometry/convex_hull.h"

namespace o3d::geometry {

/// @brief Spherical flip of every point about `camera` (p' = p + 2 (radius - |p|) p / |p| in camera
/// coordinates), convex hull of the flipped points plus the camera, then the camera's vertex and its
/// triangles dropped. Mesh vertices are the visible original points; point_indices index `points`.
/// @throws InvalidArgument on radius <= 0 or non-finite, a non-finite camera or point, a point at the
/// camera, fewer than 4 points, or a degenerate hull.
ConvexHull hidden_point_removal(const std::vector<Eigen::Vector3d>& points, const Eigen::Vector3d& camera,
                                double radius);

}  // namespace o3d::geometry
