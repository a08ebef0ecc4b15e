// SPDX-License-Identifier: MIT
#pragma once
/// @file hull.hpp
/// @brief Convex hulls (Qhull) and hidden-point removal (Katz, Tal, Basri 2007) as free functions
/// (a cloud cannot return a mesh from a member: trianglemesh.hpp builds on pointcloud.hpp).
/// Each returns {mesh with outward triangles, per mesh vertex the index of the input point it came from}.
#include <cstdint>
#include <utility>
#include <vector>

#include "o3d/hull.h"
#include "o3dpp/error.hpp"
#include "o3dpp/pointcloud.hpp"
#include "o3dpp/span.hpp"
#include "o3dpp/trianglemesh.hpp"

namespace o3dpp {

/// @brief Convex hull of the points (>= 4, not all coplanar unless `joggle_inputs`, Qhull's "QJ").
inline std::pair<TriangleMesh, std::vector<int32_t>> compute_convex_hull(const PointCloud& cloud,
                                                                         bool joggle_inputs = false) {
    std::vector<int32_t> indices(cloud.size());
    o3d_trianglemesh_t* hull = nullptr;
    size_t n = 0;
    const o3d_status status = o3d_pointcloud_compute_convex_hull(&hull, indices.data(), indices.size(), &n,
                                                                 cloud.get(), joggle_inputs ? 1 : 0);
    return TriangleMesh::adopt_with_indices(status, hull, std::move(indices), n);
}

/// @brief Convex hull of a mesh's vertices (TriangleMesh::compute_convex_hull).
inline std::pair<TriangleMesh, std::vector<int32_t>> compute_convex_hull(const TriangleMesh& mesh,
                                                                         bool joggle_inputs = false) {
    return mesh.compute_convex_hull(joggle_inputs);
}

/// @brief The points visible from `camera_location`: spherical flipping with `radius` (> 0; larger keeps
/// more points), then the hull of the flipped points and the camera.
inline std::pair<TriangleMesh, std::vector<int32_t>> hidden_point_removal(const PointCloud& cloud,
                                                                          const Vec3& camera_location,
                                                                          double radius) {
    std::vector<int32_t> indices(cloud.size());
    o3d_trianglemesh_t* mesh = nullptr;
    size_t n = 0;
    const o3d_status status = o3d_pointcloud_hidden_point_removal(&mesh, indices.data(), indices.size(), &n,
                                                                  cloud.get(), camera_location.data(), radius);
    return TriangleMesh::adopt_with_indices(status, mesh, std::move(indices), n);
}

}  // namespace o3dpp
