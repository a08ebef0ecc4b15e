// SPDX-License-Identifier: MIT
#pragma once
/// @file voxel_grid.h
/// @brief The sparse voxel-grid container.
#include <Eigen/Core>
#include <vector>

namespace o3d::geometry {

struct Voxel {
    Eigen::Vector3i grid_index;
    Eigen::Vector3d color;
};

/// @brief Occupied cells of edge `voxel_size`; cell (i, j, k) spans origin + voxel_size * [i, i+1) x ...
/// `voxels` is kept sorted by grid index (x, then y, then z) and unique, so lookups are binary searches
/// and every export is in the same order on every run.
struct VoxelGrid {
    double voxel_size = 0.0;
    Eigen::Vector3d origin = Eigen::Vector3d::Zero();
    std::vector<Voxel> voxels;
};

}  // namespace o3d::geometry
