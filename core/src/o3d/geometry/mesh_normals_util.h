// SPDX-License-Identifier: MIT
#pragma once
/// @file mesh_normals_util.h
/// @brief Internal: fresh unit triangle normals for a mesh whose processing moved its vertices (what
/// Open3D's ComputeTriangleNormals gives; a zero-area triangle gets (0, 0, 0)).
#include <Eigen/Geometry>  // cross(), used by triangle_cross
#include <vector>

#include "o3d/geometry/triangle_mesh.h"
#include "o3d/geometry/triangle_mesh_basics.h"

namespace o3d::geometry {

inline std::vector<Eigen::Vector3d> unit_triangle_normals(const TriangleMesh& mesh) {
    std::vector<Eigen::Vector3d> normals(mesh.triangles.size());
    for (size_t t = 0; t < mesh.triangles.size(); ++t) {
        const Eigen::Vector3d n = triangle_cross(mesh, t);
        const double len = n.norm();
        normals[t] = len > 0 ? Eigen::Vector3d(n / len) : Eigen::Vector3d::Zero();
    }
    return normals;
}

}  // namespace o3d::geometry
