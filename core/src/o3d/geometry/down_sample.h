// SPDX-License-Identifier: MIT
#pragma once
/// @file down_sample.h
/// @brief Down-sampling with Open3D's semantics: voxel grid, every k-th, random, farthest point.
#include <cstddef>
#include <cstdint>

#include "o3d/geometry/point_cloud.h"

namespace o3d::geometry {

/// @brief Average the points (and normals, colors) falling in each voxel of edge `voxel_size`.
/// The grid is Open3D's: origin min_bound - voxel_size/2, index floor((p - origin) / voxel_size).
/// Voxels come out sorted by (z, y, x) index, so the output is deterministic.
/// @throws InvalidArgument when voxel_size is not > 0, a point is non-finite, or the grid index
/// would overflow a 32-bit int (voxel too small for the extent).
PointCloud voxel_down_sample(const PointCloud& cloud, double voxel_size, int num_threads = 0);

/// @brief Points 0, k, 2k, ... @throws InvalidArgument when every_k_points == 0.
PointCloud uniform_down_sample(const PointCloud& cloud, size_t every_k_points);

/// @brief floor(ratio * N) points drawn without replacement by a generator seeded with `seed`,
/// in their original order. @throws InvalidArgument when ratio is not in [0,1].
PointCloud random_down_sample(const PointCloud& cloud, double sampling_ratio, uint64_t seed);

/// @brief Farthest-point sampling from `start_index`; the picked points keep their original order.
/// @throws InvalidArgument when num_samples > N or start_index >= N (with num_samples > 0).
PointCloud farthest_point_down_sample(const PointCloud& cloud, size_t num_samples, size_t start_index = 0,
                                      int num_threads = 0);

}  // namespace o3d::geometry
