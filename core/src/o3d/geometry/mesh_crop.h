// SPDX-License-Identifier: MIT
#pragma once
/// @file mesh_crop.h
/// @brief Cropping a triangle mesh by an axis-aligned box (Open3D's TriangleMesh::Crop(AxisAlignedBoundingBox)).
#include <Eigen/Core>
#include <cstdint>
#include <vector>

#include "o3d/geometry/triangle_mesh.h"

namespace o3d::geometry {

/// @brief The triangles whose three vertices lie in [min_bound, max_bound] (inclusive, as Open3D), in order,
/// with their normals, UVs and material ids; the vertices they use, in order, with their normals and colors;
/// textures kept. Unlike Open3D's SelectByIndex clean-up, duplicated vertices and triangles are not merged
/// (the header promises only the triangles inside, and unused vertices dropped).
/// @throws InvalidArgument on bad triangle indices, no vertices, a non-finite bound, or a box with zero
/// volume or max < min on an axis (the point-cloud crop's rule, Open3D's "zeros size, or wrong bounds").
/// @brief The triangles whose three vertices are marked in `inside` (one flag per vertex; triangles
/// already validated), with their attributes; unused vertices dropped, the rest kept in order.
TriangleMesh keep_triangles_inside(const TriangleMesh& mesh, const std::vector<uint8_t>& inside);

TriangleMesh crop_aabb(const TriangleMesh& mesh, const Eigen::Vector3d& min_bound, const Eigen::Vector3d& max_bound);

}  // namespace o3d::geometry
