// SPDX-License-Identifier: MIT
#pragma once
/// @file mesh_element_removal.h
/// @brief Removing chosen vertices or triangles (Open3D's TriangleMesh.remove_vertices_by_index / _by_mask and
/// remove_triangles_by_index / _by_mask), e.g. the usual trim of a Poisson surface by its densities. Attributes
/// follow what they belong to; the order of what is kept does not change.
#include <cstdint>
#include <vector>

#include "o3d/geometry/triangle_mesh.h"

namespace o3d::geometry {

/// @brief Remove the vertices at `indices` (repeats allowed) and every triangle that uses one of them.
/// @throws InvalidArgument on an index outside [0, vertex count) or a triangle index out of range.
void remove_vertices_by_index(TriangleMesh& mesh, const std::vector<int64_t>& indices);
/// @brief Remove the vertices whose `mask` entry is non-zero, and every triangle that uses one of them.
/// @throws InvalidArgument when `mask` does not have one entry per vertex, or on a triangle index out of range.
void remove_vertices_by_mask(TriangleMesh& mesh, const std::vector<uint8_t>& mask);
/// @brief Remove the triangles at `indices` (repeats allowed); the vertices stay, as in Open3D.
/// @throws InvalidArgument on an index outside [0, triangle count).
void remove_triangles_by_index(TriangleMesh& mesh, const std::vector<int64_t>& indices);
/// @brief Remove the triangles whose `mask` entry is non-zero; the vertices stay.
/// @throws InvalidArgument when `mask` does not have one entry per triangle.
void remove_triangles_by_mask(TriangleMesh& mesh, const std::vector<uint8_t>& mask);

}  // namespace o3d::geometry
