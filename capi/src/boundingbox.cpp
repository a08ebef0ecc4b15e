// SPDX-License-Identifier: MIT
// C API: boundingbox.h (oriented boxes and ellipsoids, cropping by boxes) and the bounding-volume calls of
// pointcloud.h / trianglemesh.h, over o3d::geometry.
#include <Eigen/Core>
#include <memory>
#include <string>
#include <vector>

#include "internal.h"
#include "o3d/boundingbox.h"
#include "o3d/geometry/mesh_primitives_bounded.h"
#include "o3d/geometry/minimal_bounding_box.h"
#include "o3d/geometry/oriented_bounding_box.h"
#include "o3d/geometry/oriented_bounding_ellipsoid_fit.h"
#include "o3d/pointcloud.h"
#include "o3d/trianglemesh.h"

using o3d::capi::guard;
using o3d::capi::require;
using o3d::capi::vec3;
using o3d::capi::write3;
using o3d::geometry::OrientedBoundingBox;

namespace {

OrientedBoundingBox from_c(const o3d_obb_t* obb) {
    require(obb, "obb");
    OrientedBoundingBox box;
    box.center = Eigen::Vector3d(obb->center[0], obb->center[1], obb->center[2]);
    for (int r = 0; r < 3; ++r)
        for (int c = 0; c < 3; ++c) box.R(r, c) = obb->R[3 * r + c];
    box.extent = Eigen::Vector3d(obb->extent[0], obb->extent[1], obb->extent[2]);
    return box;
}

void to_c(const OrientedBoundingBox& box, o3d_obb_t* out) {
    for (int k = 0; k < 3; ++k) {
        out->center[k] = box.center(k);
        out->extent[k] = box.extent(k);
    }
    for (int r = 0; r < 3; ++r)
        for (int c = 0; c < 3; ++c) out->R[3 * r + c] = box.R(r, c);
}

std::vector<Eigen::Vector3d> rows_of(const double* xyz, size_t n) {
    if (n > 0) require(xyz, "xyz");
    std::vector<Eigen::Vector3d> points(n);
    for (size_t i = 0; i < n; ++i) points[i] = Eigen::Vector3d(xyz[3 * i], xyz[3 * i + 1], xyz[3 * i + 2]);
    return points;
}


}  // namespace

extern "C" {

O3D_API o3d_status o3d_obb_create_from_points(o3d_obb_t* out, const double* xyz, size_t n, int32_t robust) {
    return guard(__func__, [&] {
        require(out, "out");
        to_c(o3d::geometry::obb_from_points(rows_of(xyz, n), robust != 0), out);
    });
}

O3D_API o3d_status o3d_obb_create_from_axis_aligned_bounding_box(o3d_obb_t* out, const double min_bound[3],
                                                                 const double max_bound[3]) {
    return guard(__func__, [&] {
        require(out, "out");
        to_c(o3d::geometry::obb_from_aabb(vec3(min_bound, "min_bound"), vec3(max_bound, "max_bound")), out);
    });
}

O3D_API o3d_status o3d_obb_get_box_points(double out[24], const o3d_obb_t* obb) {
    return guard(__func__, [&] {
        const OrientedBoundingBox box = from_c(obb);
        require(out, "out");
        o3d::geometry::validate_obb(box);
        const auto corners = o3d::geometry::box_points(box);
        for (size_t i = 0; i < 8; ++i)
            for (int k = 0; k < 3; ++k) out[3 * i + static_cast<size_t>(k)] = corners[i](k);
    });
}

O3D_API o3d_status o3d_obb_get_point_indices_within(int32_t* out_indices, size_t capacity, size_t* out_n,
                                                    const o3d_obb_t* obb, const double* xyz, size_t n) {
    return guard(__func__, [&] {
        const OrientedBoundingBox box = from_c(obb);
        require(out_n, "out_n");
        const std::vector<int64_t> inside = o3d::geometry::indices_in_obb(rows_of(xyz, n), box);
        const std::vector<int32_t> narrow(inside.begin(), inside.end());
        o3d::capi::copy_out(narrow.data(), narrow.size(), out_indices, capacity, out_n);
    });
}

O3D_API o3d_status o3d_pointcloud_get_oriented_bounding_box(o3d_obb_t* out, const o3d_pointcloud_t* pc, int32_t robust) {
    return guard(__func__, [&] {
        const auto& points = require(pc, "pc")->cloud.points;
        require(out, "out");
        to_c(o3d::geometry::obb_from_points(points, robust != 0), out);
    });
}

O3D_API o3d_status o3d_trianglemesh_get_oriented_bounding_box(o3d_obb_t* out, const o3d_trianglemesh_t* mesh,
                                                              int32_t robust) {
    return guard(__func__, [&] {
        const auto& vertices = require(mesh, "mesh")->mesh.vertices;
        require(out, "out");
        to_c(o3d::geometry::obb_from_points(vertices, robust != 0), out);
    });
}

O3D_API o3d_status o3d_pointcloud_crop_obb(o3d_pointcloud_t** out, const o3d_pointcloud_t* pc, const o3d_obb_t* obb,
                                           int32_t invert) {
    return guard(__func__, [&] {
        require(out, "out");
        *out = nullptr;
        const auto& cloud = require(pc, "pc")->cloud;
        auto handle = std::make_unique<o3d_pointcloud>();
        handle->cloud = o3d::geometry::crop_obb(cloud, from_c(obb), invert != 0);
        *out = handle.release();
    });
}

O3D_API o3d_status o3d_trianglemesh_crop_obb(o3d_trianglemesh_t** out, const o3d_trianglemesh_t* mesh,
                                             const o3d_obb_t* obb) {
    return guard(__func__, [&] {
        require(out, "out");
        *out = nullptr;
        const auto& m = require(mesh, "mesh")->mesh;
        auto handle = std::make_unique<o3d_trianglemesh>();
        handle->mesh = o3d::geometry::crop_obb(m, from_c(obb));
        *out = handle.release();
    });
}

}  // extern "C"

// ---- Minimal boxes and ellipsoids (boundingbox.h, pointcloud.h, trianglemesh.h) ----

namespace {

o3d::geometry::OrientedBoundingEllipsoid ellipsoid_from_c(const o3d_obe_t* obe) {
    require(obe, "obe");
    o3d::geometry::OrientedBoundingEllipsoid e;
    e.center = Eigen::Vector3d(obe->center[0], obe->center[1], obe->center[2]);
    for (int r = 0; r < 3; ++r)
        for (int c = 0; c < 3; ++c) e.R(r, c) = obe->R[3 * r + c];
    e.radii = Eigen::Vector3d(obe->radii[0], obe->radii[1], obe->radii[2]);
    return e;
}

void ellipsoid_to_c(const o3d::geometry::OrientedBoundingEllipsoid& e, o3d_obe_t* out) {
    for (int k = 0; k < 3; ++k) {
        out->center[k] = e.center(k);
        out->radii[k] = e.radii(k);
    }
    for (int r = 0; r < 3; ++r)
        for (int c = 0; c < 3; ++c) out->R[3 * r + c] = e.R(r, c);
}

Eigen::Vector3d scale_or_ones(const double* scale) {
    return scale ? Eigen::Vector3d(scale[0], scale[1], scale[2]) : Eigen::Vector3d::Ones();
}

}  // namespace

O3D_API o3d_status o3d_obb_create_from_points_minimal(o3d_obb_t* out, const double* xyz, size_t n, o3d_bool robust) {
    return guard(__func__, [&] {
        require(out, "out");
        to_c(o3d::geometry::minimal_obb_from_points(rows_of(xyz, n), robust != 0), out);
    });
}

O3D_API o3d_status o3d_obe_create_from_points(o3d_obe_t* out, const double* xyz, size_t n, o3d_bool robust) {
    return guard(__func__, [&] {
        require(out, "out");
        ellipsoid_to_c(o3d::geometry::ellipsoid_from_points(rows_of(xyz, n), robust != 0), out);
    });
}

O3D_API o3d_status o3d_pointcloud_get_minimal_oriented_bounding_box(o3d_obb_t* out, const o3d_pointcloud_t* pc,
                                                                    o3d_bool robust) {
    return guard(__func__, [&] {
        const auto& points = require(pc, "pc")->cloud.points;
        require(out, "out");
        to_c(o3d::geometry::minimal_obb_from_points(points, robust != 0), out);
    });
}

O3D_API o3d_status o3d_pointcloud_get_oriented_bounding_ellipsoid(o3d_obe_t* out, const o3d_pointcloud_t* pc,
                                                                  o3d_bool robust) {
    return guard(__func__, [&] {
        const auto& points = require(pc, "pc")->cloud.points;
        require(out, "out");
        ellipsoid_to_c(o3d::geometry::ellipsoid_from_points(points, robust != 0), out);
    });
}

O3D_API o3d_status o3d_trianglemesh_get_minimal_oriented_bounding_box(o3d_obb_t* out, const o3d_trianglemesh_t* mesh,
                                                                      o3d_bool robust) {
    return guard(__func__, [&] {
        const auto& vertices = require(mesh, "mesh")->mesh.vertices;
        require(out, "out");
        to_c(o3d::geometry::minimal_obb_from_points(vertices, robust != 0), out);
    });
}

O3D_API o3d_status o3d_trianglemesh_get_oriented_bounding_ellipsoid(o3d_obe_t* out, const o3d_trianglemesh_t* mesh,
                                                                    o3d_bool robust) {
    return guard(__func__, [&] {
        const auto& vertices = require(mesh, "mesh")->mesh.vertices;
        require(out, "out");
        ellipsoid_to_c(o3d::geometry::ellipsoid_from_points(vertices, robust != 0), out);
    });
}

O3D_API o3d_status o3d_trianglemesh_create_from_oriented_bounding_box(o3d_trianglemesh_t** out, const o3d_obb_t* obb,
                                                                      const double scale[3], o3d_bool create_uv_map) {
    return guard(__func__, [&] {
        o3d::capi::require_out_handle(out);
        o3d::capi::emit_handle(out, o3d::geometry::mesh_from_oriented_bounding_box(from_c(obb), scale_or_ones(scale),
                                                                                   create_uv_map != 0));
    });
}

O3D_API o3d_status o3d_trianglemesh_create_from_oriented_bounding_ellipsoid(o3d_trianglemesh_t** out,
                                                                            const o3d_obe_t* obe, const double scale[3],
                                                                            int32_t resolution, o3d_bool create_uv_map) {
    return guard(__func__, [&] {
        o3d::capi::require_out_handle(out);
        o3d::capi::emit_handle(out, o3d::geometry::mesh_from_oriented_bounding_ellipsoid(
                                        ellipsoid_from_c(obe), scale_or_ones(scale), resolution, create_uv_map != 0));
    });
}
