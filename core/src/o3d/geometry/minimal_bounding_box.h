// SPDX-License-Identifier: MIT
#pragma once
/// @file minimal_bounding_box.h
/// @brief Minimum-volume oriented bounding boxes (Open3D's OrientedBoundingBox.create_from_points_minimal,
/// Geometry3D.get_minimal_oriented_bounding_box).
#include <Eigen/Core>
#include <vector>

#include "o3d/geometry/oriented_bounding_box.h"

namespace o3d::geometry {

/// @brief The smallest-volume box holding `points` that this search finds over the convex hull's vertices:
/// for every hull face normal n, the box with one axis n and the minimum-area rectangle of the hull
/// projected along n (rotating calipers); the best few are then refined by a local search over the axis
/// direction, which also reaches boxes with no face flush with the hull (O'Rourke's edge-edge case).
/// On the tests it is never larger than Open3D 0.20's result (Jylanki's algorithm), and it recovers a
/// sampled rotated box exactly.
///
/// The returned frame is right-handed; its axes are listed in the order and with the signs that bring R
/// closest to the identity (largest trace over the 24 rotations that permute and flip the axes), so an
/// axis-aligned set gives R = I with the extents along x, y, z. Open3D 0.20 means to do the same (its
/// axis remapping runs on a copy and is lost), so its order is whatever its search met first: compare
/// boxes as sets of axes, not column by column.
///
/// `robust` joggles the hull ("QJ") so flat sets still give a (flat) box: the minimum-area rectangle in
/// the plane, with zero extent along the plane's normal.
/// @throws InvalidArgument as compute_convex_hull (fewer than 4 points, non-finite, coplanar without robust).
OrientedBoundingBox minimal_obb_from_points(const std::vector<Eigen::Vector3d>& points, bool robust = false);

/// @brief The proper rotation among R's 24 signed axis permutations with the largest trace (closest to the
/// identity), with `extent` permuted to follow its axes; ties keep the first in a fixed enumeration order.
/// Shared by the minimal box and the ellipsoid fit, whose axes have no order of their own.
void permute_axes_closest_to_identity(Eigen::Matrix3d& R, Eigen::Vector3d& extent);

/// @brief True when the centred points (`centred`, mean removed) lie within 1e-12 of their size of the plane
/// normal to `axes.col(0)` (the smallest principal axis, as SelfAdjointEigenSolver orders them): the
/// joggled-hull case of `robust`, where no solid box or ellipsoid exists.
bool is_flat(const std::vector<Eigen::Vector3d>& centred, const Eigen::Matrix3d& axes);

}  // namespace o3d::geometry
