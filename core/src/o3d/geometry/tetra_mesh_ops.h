// SPDX-License-Identifier: MIT
#pragma once
/// @file tetra_mesh_ops.h
/// @brief Basic TetraMesh operations with Open3D's semantics (TetraMesh.remove_*, get_min_bound, ...).
/// The in-place clean-ups keep the vertices and tetras they keep in their original order, and validate
/// the tetra indices first (InvalidArgument).
#include <Eigen/Core>

#include "o3d/geometry/tetra_mesh.h"

namespace o3d::geometry {

/// @brief Throw o3d::InvalidArgument naming the first tetra with an index outside [0, num_vertices).
void validate_tetras(const TetraMesh& mesh);
/// @brief Merge vertices with exactly equal coordinates (0.0 == -0.0; NaN never merges) into the first
/// of them, re-indexing the tetras.
void remove_duplicated_vertices(TetraMesh& mesh);
/// @brief Remove tetras with the same four vertex indices as an earlier one, in any order.
void remove_duplicated_tetras(TetraMesh& mesh);
/// @brief Remove vertices no tetra uses, re-indexing the tetras.
void remove_unreferenced_vertices(TetraMesh& mesh);
/// @brief Remove tetras that repeat a vertex index (Open3D's notion of degenerate; flat tetras with four
/// distinct vertices stay).
void remove_degenerate_tetras(TetraMesh& mesh);
/// @brief Component-wise minimum of the vertices (zero when there are none, as Open3D).
Eigen::Vector3d get_min_bound(const TetraMesh& mesh);
/// @brief Component-wise maximum of the vertices (zero when there are none, as Open3D).
Eigen::Vector3d get_max_bound(const TetraMesh& mesh);
/// @brief Mean of the vertices (zero when there are none, as Open3D).
Eigen::Vector3d get_center(const TetraMesh& mesh);

}  // namespace o3d::geometry
