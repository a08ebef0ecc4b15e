// SPDX-License-Identifier: MIT
#pragma once
/// @file surface_extraction.h
/// @brief The surface of a block map's tsdf, as a mesh (marching cubes) or as points; the volumes' extract
/// calls are these over their blocks.
#include "o3d/geometry/point_cloud.h"
#include "o3d/geometry/triangle_mesh.h"
#include "o3d/integration/voxel_block.h"

namespace o3d::integration::detail {

/// @brief Marching cubes over every cube of 8 observed voxels (weight > 0), blocks in key order: a vertex
/// per crossed edge, shared by the cubes around it, coloured when the map keeps colour.
geometry::TriangleMesh marching_cubes(const BlockMap& map);

/// @brief Points where the tsdf changes sign between neighbouring observed voxels with |tsdf| < 0.98, with
/// normals along the tsdf's gradient (toward free space) and colours.
geometry::PointCloud zero_crossings(const BlockMap& map);

}  // namespace o3d::integration::detail
