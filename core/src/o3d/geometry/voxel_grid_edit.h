// SPDX-License-Identifier: MIT
#pragma once
/// @file voxel_grid_edit.h
/// @brief Building a dense voxel grid, adding and removing single voxels, and the geometry of one cell
/// (Open3D's VoxelGrid.create_dense, add_voxel, remove_voxel, get_voxel_center_coordinate,
/// get_voxel_bounding_points).
#include <Eigen/Core>
#include <array>
#include <cstdint>

#include "o3d/geometry/voxel_grid.h"

namespace o3d::geometry {

/// Largest dense grid create_dense builds (voxels in all): the count is checked before anything is allocated.
constexpr int64_t kMaxDenseVoxels = int64_t(1) << 31;

/// @brief The order of VoxelGrid::voxels: x, then y, then z.
bool voxel_index_less(const Eigen::Vector3i& a, const Eigen::Vector3i& b);

/// @brief Every cell of a box filled with `color` (Open3D's VoxelGrid.create_dense): the grid starts at
/// `origin` (index (0, 0, 0) spans origin + [0, voxel_size)^3) and has round(width / voxel_size) x
/// round(height / voxel_size) x round(depth / voxel_size) voxels (std::round, halves away from zero:
/// Open3D 0.20 gives 3 voxels for width 0.75 at voxel size 0.3, none for 0.14). Throws InvalidArgument
/// for voxel_size <= 0 or non-finite, a negative or non-finite width / height / depth, a non-finite origin
/// or color, or more than kMaxDenseVoxels voxels (Open3D accepts a negative voxel size and returns an
/// empty grid for negative extents).
VoxelGrid voxel_grid_create_dense(const Eigen::Vector3d& origin, const Eigen::Vector3d& color, double voxel_size,
                                  double width, double height, double depth);

/// @brief Put `voxel` in the grid, replacing the color of the voxel already at its index (Open3D's
/// add_voxel assigns into its hash map); `voxels` stays sorted and unique. Throws InvalidArgument for a
/// non-finite color.
void add_voxel(VoxelGrid& grid, const Voxel& voxel);

/// @brief Remove the voxel at `index`; nothing happens when there is none (as Open3D's remove_voxel).
/// `voxels` stays sorted and unique.
void remove_voxel(VoxelGrid& grid, const Eigen::Vector3i& index);

/// @brief The voxel at `index`, or nullptr when that cell is empty (binary search).
const Voxel* find_voxel(const VoxelGrid& grid, const Eigen::Vector3i& index);

/// @brief Centre of cell `index`: origin + (index + 0.5) * voxel_size. Defined for every cell, occupied or
/// not (Open3D 0.20 returns (0, 0, 0) for an empty cell).
Eigen::Vector3d voxel_center_coordinate(const VoxelGrid& grid, const Eigen::Vector3i& index);

/// @brief The 8 corners of cell `index`, in Open3D's order: corner k is centre + r * (sx, sy, sz) with
/// r = voxel_size / 2 and signs sz from bit 0, sx from bit 1, sy from bit 2 of k (bit set = +):
/// (-,-,-), (-,-,+), (+,-,-), (+,-,+), (-,+,-), (-,+,+), (+,+,-), (+,+,+) as (x, y, z). Defined for every
/// cell (Open3D 0.20 puts an empty cell's corners around (0, 0, 0)).
std::array<Eigen::Vector3d, 8> voxel_bounding_points(const VoxelGrid& grid, const Eigen::Vector3i& index);

}  // namespace o3d::geometry
