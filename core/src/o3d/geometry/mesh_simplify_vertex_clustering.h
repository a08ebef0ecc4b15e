// SPDX-License-Identifier: MIT
#pragma once
/// @file mesh_simplify_vertex_clustering.h
/// @brief Mesh simplification by vertex clustering on a voxel grid (Open3D's simplify_vertex_clustering).
#include "o3d/geometry/triangle_mesh.h"

namespace o3d::geometry {

enum class SimplificationContraction { Average = 0, Quadric = 1 };

/// @brief Merge the vertices of each voxel of edge `voxel_size` (grid origin min_bound - voxel_size / 2, as
/// Open3D) into one vertex: their mean (Average), or the minimiser of the summed area-weighted quadrics of
/// their triangles (Quadric; the mean when that quadric is singular). Normals and colors are averaged.
/// Output vertices are numbered by the first input vertex of their voxel; triangles whose corners fall in
/// three distinct voxels are kept once each (rotated so the smallest index comes first), in input order.
/// Triangle normals are recomputed when the input has them; UVs, material ids and textures are dropped.
/// @throws InvalidArgument on bad triangle indices, an empty mesh, a non-finite vertex, voxel_size not
/// finite and > 0, or a voxel so small that a grid index would overflow an int.
TriangleMesh simplify_vertex_clustering(const TriangleMesh& mesh, double voxel_size,
                                        SimplificationContraction contraction);

}  // namespace o3d::geometry
