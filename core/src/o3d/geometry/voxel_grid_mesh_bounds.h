// SPDX-License-Identifier: MIT
#pragma once
/// @file voxel_grid_mesh_bounds.h
/// @brief Voxelizing a triangle mesh on a grid given by its bounds (Open3D's
/// VoxelGrid.create_from_triangle_mesh_within_bounds).
#include <Eigen/Core>

#include "o3d/geometry/triangle_mesh.h"
#include "o3d/geometry/voxel_grid.h"

namespace o3d::geometry {

/// @brief Voxels overlapping at least one triangle on the grid whose origin is `min_bound` (closed boxes:
/// touching counts; triangle_box_overlap). As Open3D, the cells tried for a triangle start at the floor of
/// its bounding box's min corner and run round(extent / voxel_size) + 2 cells along each axis. Only cells
/// holding a point of the closed box [min_bound, max_bound] are kept: index i along an axis in
/// [0, floor((max - min) / voxel_size)], the cells voxel_grid_from_point_cloud_within_bounds can fill
/// (Open3D 0.20 ignores max_bound and keeps every cell the mesh touches, even at negative indices; its
/// documentation says the bounds define the grid). Colors are zero. `num_threads`: 0 = the library
/// default; the result does not depend on it. Throws InvalidArgument for voxel_size <= 0 / non-finite,
/// a mesh without vertices, a triangle index out of range, a non-finite vertex, non-finite bounds,
/// min_bound > max_bound on an axis, or bounds too large for int32 indices at this voxel size.
VoxelGrid voxel_grid_from_triangle_mesh_within_bounds(const TriangleMesh& mesh, double voxel_size,
                                                      const Eigen::Vector3d& min_bound,
                                                      const Eigen::Vector3d& max_bound, int num_threads = 0);

}  // namespace o3d::geometry
