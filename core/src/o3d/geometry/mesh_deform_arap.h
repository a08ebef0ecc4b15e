// SPDX-License-Identifier: MIT
#pragma once
/// @file mesh_deform_arap.h
/// @brief As-rigid-as-possible deformation (Open3D's TriangleMesh.deform_as_rigid_as_possible).
#include <Eigen/Core>
#include <vector>

#include "o3d/geometry/triangle_mesh.h"

namespace o3d::geometry {

/// @brief The energy minimised: Sorkine & Alexa's spokes energy, or that plus Levi & Gotsman's rotation
/// smoothness term (Open3D's DeformAsRigidAsPossibleEnergy, same values).
enum class ArapEnergy { Spokes = 0, Smoothed = 1 };

/// @brief Deform `mesh` so that each vertex constraint_vertex_indices[k] lands on
/// constraint_vertex_positions[k] while every one-ring stays as rigid as possible (Sorkine & Alexa 2007,
/// "As-rigid-as-possible surface modeling"). Open3D's semantics: edge weights are the mean of the
/// cotangents opposite the edge (half their sum on an interior edge, the one cotangent on a boundary edge),
/// negative means clamped to 0; the deformed positions start at the input ones and each of `max_iter`
/// iterations fits every vertex's rotation (SVD, reflections flipped) and then solves the constrained
/// Laplacian system (factorised once, SimplicialLDLT on the free vertices). With ArapEnergy::Smoothed the
/// rotation fit from the second iteration on adds the previous rotations of the neighbours, weighted by
/// 2 * smoothed_alpha * surface area / (number of neighbours) (Levi & Gotsman 2015), as Open3D does.
/// `max_iter` = 0 returns the input positions (constraints unapplied, as Open3D).
/// The result holds the deformed vertices and the triangles only (as Open3D: no normals, colors, UVs).
/// A connected part (through edges of positive weight) holding no constrained vertex keeps its input
/// positions: any rigid motion of it is a minimiser, and Open3D's solve is singular there. A triangle
/// with zero area adds a zero cotangent (Open3D divides by zero). Deterministic for any thread count.
/// @throws InvalidArgument on bad triangle indices, no vertices, non-finite vertex coordinates, an empty
/// constraint list (the system is singular; Open3D returns garbage), sizes that differ, a constraint index
/// out of range or repeated, a non-finite constraint position, max_iter < 0, a non-finite smoothed_alpha or
/// an unknown energy.
TriangleMesh deform_as_rigid_as_possible(const TriangleMesh& mesh, const std::vector<int>& constraint_vertex_indices,
                                         const std::vector<Eigen::Vector3d>& constraint_vertex_positions,
                                         int max_iter, ArapEnergy energy = ArapEnergy::Spokes,
                                         double smoothed_alpha = 0.01, int num_threads = 0);

}  // namespace o3d::geometry
