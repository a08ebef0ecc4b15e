// SPDX-License-Identifier: MIT
#pragma once
/// @file voxel_down_sample_trace.h
/// @brief Voxel down-sampling that records which input points made each output point
/// (Open3D's PointCloud.voxel_down_sample_and_trace).
#include <Eigen/Core>
#include <array>
#include <vector>

#include "o3d/geometry/point_cloud.h"

namespace o3d::geometry {

/// @brief The down-sampled cloud and its trace back to the input.
struct VoxelTrace {
    PointCloud cloud;
    /// Per output point, per octant of its voxel (bit 0: x, bit 1: y, bit 2: z set when the point lies in
    /// the upper half of the voxel along that axis): the largest input index that fell in that octant, or
    /// -1 (Open3D's N x 8 cubic_id; its last-written point is the largest index).
    std::vector<std::array<int, 8>> cubic_ids;
    /// Output point i came from input points indices[offsets[i] .. offsets[i+1]), ascending;
    /// offsets has cloud.size() + 1 entries.
    std::vector<int> offsets;
    std::vector<int> indices;
};

/// @brief Average the points falling in each voxel of edge `voxel_size` of the grid anchored at `min_bound`
/// (voxel index floor((p - min_bound) / voxel_size), so voxel corners sit on min_bound + k voxel_size),
/// as Open3D's voxel_down_sample_and_trace. Points outside [min_bound, max_bound] are kept in the voxels
/// they fall in, as Open3D; max_bound only bounds the grid's extent. Normals are averaged (not
/// re-normalised) and colors averaged; with `approximate_class` each output color is (k, k, k) for the most
/// frequent class k = int(red) (truncated) of its voxel, ties going to the class first seen last (the order
/// Open3D's hash map happens to give). Covariances are not carried.
///
/// Output order: voxels sorted by (z, y, x) index, as voxel_down_sample (Open3D's is hash order).
/// @throws InvalidArgument when voxel_size is not finite and > 0, a bound is non-finite, min_bound > max_bound
/// on an axis (Open3D accepts it), a point is non-finite, a voxel index or the input size would overflow an
/// int, or (with approximate_class and colors) a red value is non-finite or outside int's range.
VoxelTrace voxel_down_sample_and_trace(const PointCloud& cloud, double voxel_size, const Eigen::Vector3d& min_bound,
                                       const Eigen::Vector3d& max_bound, bool approximate_class = false);

}  // namespace o3d::geometry
