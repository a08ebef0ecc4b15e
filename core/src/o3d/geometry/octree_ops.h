// SPDX-License-Identifier: MIT
#pragma once
/// @file octree_ops.h
/// @brief Building an octree over a point cloud and locating leaves, as Open3D's Octree with
/// OctreePointColorLeafNode leaves.
#include <Eigen/Core>

#include "o3d/geometry/octree.h"
#include "o3d/geometry/point_cloud.h"

namespace o3d::geometry {

/// Deepest tree accepted: keeps node cubes well above double resolution and cell indices in int32.
constexpr int kMaxOctreeDepth = 21;

/// @brief An empty octree of `max_depth` in [1, kMaxOctreeDepth] (InvalidArgument otherwise).
Octree make_octree(int max_depth);

/// @brief Rebuild `tree` from `cloud` (Open3D's convert_from_point_cloud): the root cube starts at
/// min(min_bound, centre - max half extent) with edge 2 * max half extent * (1 + size_expand) (size_expand
/// itself for a single distinct point); every point inside the half-open root cube is inserted, each leaf
/// keeping its point indices (ascending) and their mean color (the C header octree.h asks for the mean;
/// Open3D 0.20 keeps the last inserted point's color). Throws InvalidArgument for an empty cloud,
/// non-finite points, or size_expand < 0 / non-finite.
void octree_from_point_cloud(Octree& tree, const PointCloud& cloud, double size_expand);

/// @brief Where a node sits (Open3D's OctreeNodeInfo).
struct OctreeNodeInfo {
    Eigen::Vector3d origin = Eigen::Vector3d::Zero();
    double size = 0.0;
    int depth = 0;
    int child_index = 0;
};

/// @brief The leaf holding `point`: its node index in tree.nodes and its info, or -1 when the point is
/// outside the root cube or in an empty cell.
int locate_leaf(const Octree& tree, const Eigen::Vector3d& point, OctreeNodeInfo* info);

/// @brief The child of the cube (origin, size) that holds `p`: numbered x + 2y + 4z, each bit set when `p` is
/// in the upper half along that axis (Open3D's numbering). Moves `origin` and `size` to the child's cube.
int descend(const Eigen::Vector3d& p, Eigen::Vector3d& origin, double& size);
/// @brief The leaf at max depth whose cube holds `point` (which the caller has checked is inside the root
/// cube), made with the internal nodes on the way when missing; its index in tree.nodes.
int leaf_path(Octree& tree, const Eigen::Vector3d& point);
/// @brief Number of leaves (all are non-empty).
size_t count_leaves(const Octree& tree);

}  // namespace o3d::geometry
