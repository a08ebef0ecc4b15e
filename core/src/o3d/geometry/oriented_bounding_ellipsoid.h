// SPDX-License-Identifier: MIT
#pragma once
/// @file oriented_bounding_ellipsoid.h
/// @brief Oriented bounding ellipsoids (o3d.geometry.OrientedBoundingEllipsoid, Open3D 0.20).
#include <Eigen/Core>

namespace o3d::geometry {

/// @brief Centre, rotation (column k = direction of semi-axis k) and the three semi-axis lengths:
/// the solid {c + R diag(radii) u : |u| <= 1}.
struct OrientedBoundingEllipsoid {
    Eigen::Vector3d center = Eigen::Vector3d::Zero();
    Eigen::Matrix3d R = Eigen::Matrix3d::Identity();
    Eigen::Vector3d radii = Eigen::Vector3d::Zero();

    /// 4/3 pi abc.
    double volume() const { return 4.0 / 3.0 * 3.14159265358979323846 * radii.prod(); }
};

}  // namespace o3d::geometry
