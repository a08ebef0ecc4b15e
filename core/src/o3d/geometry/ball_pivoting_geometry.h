// SPDX-License-Identifier: MIT
#pragma once
/// @file ball_pivoting_geometry.h
/// @brief Ball-pivoting internals: the ball resting on a triangle and the normal-agreement test.
#include <Eigen/Core>

namespace o3d::geometry::ball_pivoting {

/// @brief Centre of the ball of squared radius `radius2` touching p0, p1, p2 on the side of
/// (p1 - p0) x (p2 - p0) (the side a counter-clockwise triangle faces). False when the points are
/// (nearly) collinear or coincident, or their circumradius exceeds the radius.
bool ball_center(const Eigen::Vector3d& p0, const Eigen::Vector3d& p1, const Eigen::Vector3d& p2, double radius2,
                 Eigen::Vector3d& center);

/// @brief Triangle normal (p1 - p0) x (p2 - p0), unnormalised.
inline Eigen::Vector3d triangle_direction(const Eigen::Vector3d& p0, const Eigen::Vector3d& p1,
                                          const Eigen::Vector3d& p2) {
    return (p1 - p0).cross(p2 - p0);
}

/// @brief True when no vertex normal points against the triangle direction `d` (a zero normal has no
/// say), i.e. the triangle faces the side the points' normals call outside.
inline bool agrees_with_normals(const Eigen::Vector3d& d, const Eigen::Vector3d& n0, const Eigen::Vector3d& n1,
                                const Eigen::Vector3d& n2) {
    return d.dot(n0) >= 0.0 && d.dot(n1) >= 0.0 && d.dot(n2) >= 0.0;
}

}  // namespace o3d::geometry::ball_pivoting
