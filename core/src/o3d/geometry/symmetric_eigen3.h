// SPDX-License-Identifier: MIT
#pragma once
/// @file symmetric_eigen3.h
/// @brief Closed-form eigen-analysis of symmetric 3x3 matrices (covariances), for normals.
#include <Eigen/Core>

namespace o3d::geometry {

/// @brief Unit eigenvector of the smallest eigenvalue of the symmetric matrix `a`.
/// Closed form (trigonometric eigenvalues, then cross products of the shifted rows), scaled first
/// so it neither overflows nor underflows; when the two smallest eigenvalues are (nearly) equal it
/// takes the vector orthogonal to the well-separated largest one. Returns zero for a zero matrix;
/// for a diagonal matrix, the axis of the smallest entry (ties: the last axis, so I gives +Z).
Eigen::Vector3d smallest_eigenvector(const Eigen::Matrix3d& a);

}  // namespace o3d::geometry
