// SPDX-License-Identifier: MIT
#pragma once
/// @file mesh_sampling.h
/// @brief Uniform (area-weighted) point sampling of a triangle mesh, seeded.
#include <cstddef>
#include <cstdint>

#include "o3d/geometry/point_cloud.h"
#include "o3d/geometry/triangle_mesh.h"

namespace o3d::geometry {

/// @brief `number_of_points` points on the surface. As in Open3D 0.20, each point picks a triangle with
/// probability area / total area (independently, so counts per triangle are random), then a uniform
/// point in it (barycentric (1 - sqrt(r1), sqrt(r1) (1 - r2), sqrt(r1) r2)).
/// Normals: the triangle's normal when `use_triangle_normal` (the mesh's triangle normals when present,
/// else computed unit normals), else the barycentric blend of the vertex normals (not renormalised, as in
/// Open3D) when the mesh has them. Colors: the nearest texel of the triangle's texture when the mesh has
/// UVs and textures (Open3D 0.20), else the blend of the vertex colors when present.
/// Point i draws its random numbers from (seed, i) alone: same seed, same cloud, on any thread count.
/// @throws InvalidArgument on bad triangle indices, number_of_points == 0, no triangles, or a surface
/// area that is zero or not finite.
PointCloud sample_points_uniformly(const TriangleMesh& mesh, size_t number_of_points, bool use_triangle_normal,
                                   uint64_t seed, int num_threads = 0);

}  // namespace o3d::geometry
