// SPDX-License-Identifier: MIT
#pragma once
/// @file normals.h
/// @brief Normal estimation (PCA over neighbourhoods) and orientation, with Open3D's semantics.
#include <Eigen/Core>

#include "o3d/geometry/point_cloud.h"
#include "o3d/kdtree/kd_tree.h"

namespace o3d::geometry {

/// @brief Normal of each point = smallest principal axis of its neighbourhood (the point itself
/// included). Fewer than 3 neighbours gives (0,0,1); a degenerate (all-equal) neighbourhood keeps
/// the old normal, else (0,0,1). When the cloud already had normals, each new one is flipped to agree
/// with the old one. The result does not depend on num_threads (0 = default).
/// @throws InvalidArgument on a bad search parameter or a non-finite point.
void estimate_normals(PointCloud& cloud, const kdtree::SearchParam& param, int num_threads = 0);
/// @brief As above with a tree already built over cloud.points.
void estimate_normals(PointCloud& cloud, const kdtree::KDTree& tree, const kdtree::SearchParam& param,
                      int num_threads = 0);

/// @brief Flip normals to have a non-negative dot product with `direction`; zero normals become
/// `direction`. @throws InvalidArgument when the cloud has no normals or direction is non-finite.
void orient_normals_to_align_with_direction(PointCloud& cloud,
                                            const Eigen::Vector3d& direction = Eigen::Vector3d::UnitZ());

/// @brief Flip normals to point towards `camera_location`; zero normals become the unit direction to
/// the camera ((0,0,1) when the point is the camera). @throws InvalidArgument as above.
void orient_normals_towards_camera_location(PointCloud& cloud,
                                            const Eigen::Vector3d& camera_location = Eigen::Vector3d::Zero());

}  // namespace o3d::geometry
