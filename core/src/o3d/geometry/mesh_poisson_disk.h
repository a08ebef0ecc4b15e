// SPDX-License-Identifier: MIT
#pragma once
/// @file mesh_poisson_disk.h
/// @brief Poisson-disk sampling of a mesh by weighted sample elimination (Yuksel 2015), as Open3D does it.
#include <cstddef>
#include <cstdint>

#include "o3d/geometry/point_cloud.h"
#include "o3d/geometry/triangle_mesh.h"

namespace o3d::geometry {

/// @brief Draw floor(init_factor * number_of_points) uniform samples (sample_points_uniformly, same seed),
/// then repeatedly delete the sample of largest weight until `number_of_points` remain. A sample's weight
/// is the sum over the other live samples within r_max of (1 - max(d, r_min) / r_max)^8, with Yuksel's
/// r_max = 2 sqrt(area / (2 sqrt(3) N)) and r_min = r_max * 0.5 * (1 - (N / initial count)^1.5).
/// Ties go to the higher index, so the output depends on the seed only. Survivors keep their order.
/// @throws InvalidArgument as sample_points_uniformly, or when init_factor is not finite and >= 1, or the
/// initial sample count exceeds 2^31 - 1.
PointCloud sample_points_poisson_disk(const TriangleMesh& mesh, size_t number_of_points, double init_factor,
                                      bool use_triangle_normal, uint64_t seed, int num_threads = 0);

}  // namespace o3d::geometry
