// SPDX-License-Identifier: MIT
#pragma once
/// @file voxel_grid_ops.h
/// @brief Voxelizing point clouds and triangle meshes, and querying voxel grids.
#include <Eigen/Core>
#include <vector>

#include "o3d/geometry/point_cloud.h"
#include "o3d/geometry/triangle_mesh.h"
#include "o3d/geometry/voxel_grid.h"

namespace o3d::geometry {

/// @brief Voxels holding a point, on the grid whose origin is the cloud's min bound - voxel_size / 2
/// (Open3D); each voxel's color is the mean color of its points (zero without colors).
/// Throws InvalidArgument for an empty cloud, non-finite points, voxel_size <= 0 / non-finite, or a grid
/// too fine for int32 indices.
VoxelGrid voxel_grid_from_point_cloud(const PointCloud& cloud, double voxel_size);

/// @brief As voxel_grid_from_point_cloud on the grid starting at min_bound; points outside the closed
/// box [min_bound, max_bound] are ignored (Open3D keeps them; o3d's header asks for them to be dropped).
VoxelGrid voxel_grid_from_point_cloud_within_bounds(const PointCloud& cloud, double voxel_size,
                                                    const Eigen::Vector3d& min_bound,
                                                    const Eigen::Vector3d& max_bound);

/// @brief Voxels overlapping at least one triangle (separating-axis box/triangle test, touching counts),
/// on the grid whose origin is the mesh's min bound - voxel_size / 2 (Open3D). Colors are zero.
VoxelGrid voxel_grid_from_triangle_mesh(const TriangleMesh& mesh, double voxel_size);

/// @brief True when the closed box centre +- half_size overlaps triangle (a, b, c) (Akenine-Moller's
/// separating-axis test: 3 box axes, the triangle normal, 9 edge cross products).
bool triangle_box_overlap(const Eigen::Vector3d& center, const Eigen::Vector3d& half_size, const Eigen::Vector3d& a,
                          const Eigen::Vector3d& b, const Eigen::Vector3d& c);

/// @brief Grid index of the cell holding `point` (occupied or not); throws InvalidArgument when the point
/// is not finite or its index does not fit int32.
Eigen::Vector3i voxel_index_of(const VoxelGrid& grid, const Eigen::Vector3d& point);

/// @brief Whether the cell holding each point is occupied (binary search in the sorted voxels).
std::vector<bool> voxels_include(const VoxelGrid& grid, const std::vector<Eigen::Vector3d>& points);

}  // namespace o3d::geometry
