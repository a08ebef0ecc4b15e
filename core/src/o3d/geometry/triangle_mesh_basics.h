// SPDX-License-Identifier: MIT
#pragma once
/// @file triangle_mesh_basics.h
/// @brief What every mesh algorithm needs first: trusting the triangle indices, and per-triangle geometry.
#include <Eigen/Core>
#include <Eigen/Geometry>

#include "o3d/geometry/triangle_mesh.h"

namespace o3d::geometry {

/// @brief Throw o3d::InvalidArgument naming the first triangle with an index outside [0, num_vertices).
/// Attribute arrays of the wrong size are not errors: as in Open3D they just do not count (has_*()).
void validate_triangles(const TriangleMesh& mesh);

/// @brief (b - a) x (c - a) of triangle t (twice the area, along the normal). Assumes a validated mesh.
inline Eigen::Vector3d triangle_cross(const TriangleMesh& mesh, size_t t) {
    const Eigen::Vector3i& tri = mesh.triangles[t];
    const Eigen::Vector3d& a = mesh.vertices[tri(0)];
    return (mesh.vertices[tri(1)] - a).cross(mesh.vertices[tri(2)] - a);
}

inline double triangle_area(const TriangleMesh& mesh, size_t t) { return 0.5 * triangle_cross(mesh, t).norm(); }

}  // namespace o3d::geometry
