// SPDX-License-Identifier: MIT
#pragma once
/// @file octree_voxel_conversion.h
/// @brief Octree to voxel grid and back (Open3D's Octree.to_voxel_grid and Octree.create_from_voxel_grid).
#include "o3d/geometry/octree.h"
#include "o3d/geometry/voxel_grid.h"

namespace o3d::geometry {

/// @brief One voxel per leaf, with the leaf's color, on the grid of the tree's deepest cells: origin =
/// tree.origin, voxel_size = tree.size / 2^max_depth, and the leaf's cell index (the bits of its path from
/// the root), which is floor((leaf centre - origin) / voxel_size) as in Open3D's VoxelGrid.create_from_octree.
/// (Open3D 0.20 leaves voxel_size at 0 there and puts every leaf at index INT_MIN: its intent, the smallest
/// leaf size, is what is implemented.) A tree without nodes gives an empty grid with that voxel_size.
/// Throws InvalidArgument for a max_depth outside [1, kMaxOctreeDepth], a non-finite origin or size, or a
/// malformed tree (a leaf above max_depth or an internal node at it, a child index that is not a later node).
VoxelGrid octree_to_voxel_grid(const Octree& tree);

/// @brief Rebuild `tree` (keeping its max_depth) from the voxel centres (Open3D's create_from_voxel_grid):
/// voxel number r of grid.voxels is inserted as point index r at its centre (summed as Open3D:
/// (voxel_size / 2 + origin) + index * voxel_size) with its color, so each leaf lists the voxels it holds
/// and their mean color (Open3D 0.20 keeps one of their colors). The old nodes go first (Open3D 0.20 keeps
/// them and inserts into the old tree under the new cube). The root cube:
/// origin = grid.origin + voxel_size * min(0, lowest index) per axis, size = the largest extent from there
/// to the grid's max bound (origin + (highest index + 1) * voxel_size). For voxels at indices >= 0 this is
/// Open3D 0.20's cube (origin = grid.origin, size = max(max_bound - grid.origin)); Open3D drops the voxels
/// at negative indices, which are kept here. An empty grid gives a tree without nodes at grid.origin with
/// size 0 (as Open3D). Throws InvalidArgument for a tree max_depth outside [1, kMaxOctreeDepth], a grid
/// voxel_size that is not finite and > 0, a non-finite grid origin or voxel color, or voxels that are not
/// sorted and unique.
void octree_from_voxel_grid(Octree& tree, const VoxelGrid& grid);

}  // namespace o3d::geometry
