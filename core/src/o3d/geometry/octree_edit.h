// SPDX-License-Identifier: MIT
#pragma once
/// @file octree_edit.h
/// @brief An octree with given bounds, inserting single points, and visiting the nodes (Open3D's
/// Octree(max_depth, origin, size), insert_point, is_point_in_bound and traverse), for the point-colour
/// leaves of octree.h.
#include <Eigen/Core>
#include <functional>

#include "o3d/geometry/octree.h"
#include "o3d/geometry/octree_ops.h"

namespace o3d::geometry {

/// @brief An empty octree over the cube [origin, origin + size)^3 (Open3D's Octree(max_depth, origin,
/// size)). Throws InvalidArgument for max_depth outside [1, kMaxOctreeDepth], a non-finite origin, or a
/// size that is not finite and > 0.
Octree make_octree_with_bounds(int max_depth, const Eigen::Vector3d& origin, double size);

/// @brief Whether `point` is in the half-open cube [origin, origin + size) on every axis (Open3D's
/// Octree.is_point_in_bound: a point on the far faces is outside). False for NaN.
bool is_point_in_bound(const Eigen::Vector3d& point, const Eigen::Vector3d& origin, double size);

/// @brief Insert point number `index` with `color` (Open3D's insert_point with OctreePointColorLeafNode
/// leaves). Internal nodes are created down to the leaf at max_depth that holds the point (the root too,
/// when the tree has no node yet); the leaf gets `index` in its ascending indices and its color becomes
/// the mean of its points' colors (Open3D 0.20 keeps the last color). An index already in that leaf
/// changes nothing. Returns false, and changes nothing, when the point is outside the root cube (Open3D
/// still creates an empty root there). Throws InvalidArgument for a negative index, a non-finite point or
/// color, a max_depth outside [1, kMaxOctreeDepth], or a non-finite origin or size.
bool octree_insert_point(Octree& tree, const Eigen::Vector3d& point, int index, const Eigen::Vector3d& color);

/// @brief Called for each node with its index in tree.nodes and where it sits. For an internal node,
/// returning true skips that node's children (Open3D's traverse: "return true to stop" descending); a
/// leaf's return value is ignored.
using OctreeVisitor = std::function<bool(int node_index, const OctreeNodeInfo& info)>;

/// @brief Visit the nodes depth first, pre-order, children in child-index order 0..7 (x + 2y + 4z), the
/// root at depth 0 with child_index 0 (Open3D's Octree.traverse). Nothing is visited in a tree without
/// nodes. An exception thrown by `visit` ends the traversal and propagates. Throws InvalidArgument on a
/// malformed tree (a child index that is not a later node, or a child below max_depth).
void octree_traverse(const Octree& tree, const OctreeVisitor& visit);

}  // namespace o3d::geometry
