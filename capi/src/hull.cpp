// SPDX-License-Identifier: MIT
// C API: hull.h (convex hulls, hidden-point removal) over o3d::geometry.
#include <Eigen/Core>
#include <memory>
#include <string>
#include <vector>

#include "internal.h"
#include "o3d/geometry/convex_hull.h"
#include "o3d/geometry/hidden_point_removal.h"
#include "o3d/pointcloud.h"
#include "o3d/trianglemesh.h"

using o3d::capi::guard;
using o3d::capi::require;
using o3d::geometry::ConvexHull;

namespace {

/// @brief Indices first (so BUFFER_TOO_SMALL leaves *out_mesh NULL), then the mesh handle.
o3d_status hand_out(ConvexHull&& hull, o3d_trianglemesh_t** out_mesh, int32_t* out_point_indices, size_t capacity,
                    size_t* out_n) {
    const std::vector<int32_t> indices(hull.point_indices.begin(), hull.point_indices.end());
    if (out_point_indices) require(out_n, "out_n");
    o3d::capi::copy_out(indices.data(), indices.size(), out_point_indices, capacity, out_n);
    auto handle = std::make_unique<o3d_trianglemesh>();
    handle->mesh = std::move(hull.mesh);
    *out_mesh = handle.release();
    return O3D_OK;
}

o3d_trianglemesh_t** require_out(o3d_trianglemesh_t** out_mesh) {
    require(out_mesh, "out_mesh");
    *out_mesh = nullptr;
    return out_mesh;
}

}  // namespace

extern "C" {

O3D_API o3d_status o3d_pointcloud_compute_convex_hull(o3d_trianglemesh_t** out_mesh, int32_t* out_point_indices,
                                                      size_t capacity, size_t* out_n, const o3d_pointcloud_t* pc,
                                                      int32_t joggle_inputs) {
    return guard(__func__, [&]() -> o3d_status {
        require_out(out_mesh);
        const auto& points = require(pc, "pc")->cloud.points;
        return hand_out(o3d::geometry::compute_convex_hull(points, joggle_inputs != 0), out_mesh, out_point_indices,
                        capacity, out_n);
    });
}

O3D_API o3d_status o3d_trianglemesh_compute_convex_hull(o3d_trianglemesh_t** out_mesh, int32_t* out_point_indices,
                                                        size_t capacity, size_t* out_n,
                                                        const o3d_trianglemesh_t* mesh, int32_t joggle_inputs) {
    return guard(__func__, [&]() -> o3d_status {
        require_out(out_mesh);
        const auto& vertices = require(mesh, "mesh")->mesh.vertices;
        return hand_out(o3d::geometry::compute_convex_hull(vertices, joggle_inputs != 0), out_mesh,
                        out_point_indices, capacity, out_n);
    });
}

O3D_API o3d_status o3d_pointcloud_hidden_point_removal(o3d_trianglemesh_t** out_mesh, int32_t* out_point_indices,
                                                       size_t capacity, size_t* out_n, const o3d_pointcloud_t* pc,
                                                       const double camera_location[3], double radius) {
    return guard(__func__, [&]() -> o3d_status {
        require_out(out_mesh);
        const auto& points = require(pc, "pc")->cloud.points;
        require(camera_location, "camera_location");
        const Eigen::Vector3d camera(camera_location[0], camera_location[1], camera_location[2]);
        return hand_out(o3d::geometry::hidden_point_removal(points, camera, radius), out_mesh, out_point_indices,
                        capacity, out_n);
    });
}

}  // extern "C"
