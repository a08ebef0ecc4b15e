// SPDX-License-Identifier: MIT
// C API: voxelgrid.h (VoxelGrid from point clouds and meshes, and its queries).
#include <Eigen/Core>
#include <memory>
#include <string>

#include "internal.h"
#include "o3d/geometry/voxel_grid_ops.h"
#include "o3d/voxelgrid.h"

using o3d::capi::guard;
using o3d::capi::require;
using o3d::geometry::VoxelGrid;

namespace {

const VoxelGrid& grid_of(const o3d_voxelgrid_t* g) { return require(g, "grid")->grid; }

Eigen::Vector3d vec3(const double* v, const char* name) {
    require(v, name);
    return Eigen::Vector3d(v[0], v[1], v[2]);
}

o3d_voxelgrid_t** require_out(o3d_voxelgrid_t** out) {
    require(out, "out");
    *out = nullptr;
    return out;
}

void give(o3d_voxelgrid_t** out, VoxelGrid grid) {
    auto handle = std::make_unique<o3d_voxelgrid>();
    handle->grid = std::move(grid);
    *out = handle.release();
}

}  // namespace

extern "C" {

O3D_API o3d_status o3d_voxelgrid_create_from_point_cloud(o3d_voxelgrid_t** out, const o3d_pointcloud_t* pc,
                                                         double voxel_size) {
    return guard(__func__, [&] {
        require_out(out);
        give(out, o3d::geometry::voxel_grid_from_point_cloud(require(pc, "pc")->cloud, voxel_size));
    });
}

O3D_API o3d_status o3d_voxelgrid_create_from_point_cloud_within_bounds(o3d_voxelgrid_t** out,
                                                                       const o3d_pointcloud_t* pc, double voxel_size,
                                                                       const double min_bound[3],
                                                                       const double max_bound[3]) {
    return guard(__func__, [&] {
        require_out(out);
        const auto& cloud = require(pc, "pc")->cloud;
        give(out, o3d::geometry::voxel_grid_from_point_cloud_within_bounds(
                      cloud, voxel_size, vec3(min_bound, "min_bound"), vec3(max_bound, "max_bound")));
    });
}

O3D_API o3d_status o3d_voxelgrid_create_from_triangle_mesh(o3d_voxelgrid_t** out, const o3d_trianglemesh_t* mesh,
                                                           double voxel_size) {
    return guard(__func__, [&] {
        require_out(out);
        give(out, o3d::geometry::voxel_grid_from_triangle_mesh(require(mesh, "mesh")->mesh, voxel_size));
    });
}

O3D_API void o3d_voxelgrid_destroy(o3d_voxelgrid_t* grid) { delete grid; }

O3D_API o3d_status o3d_voxelgrid_get_voxel_size(const o3d_voxelgrid_t* grid, double* out) {
    return guard(__func__, [&] { *require(out, "out") = grid_of(grid).voxel_size; });
}

O3D_API o3d_status o3d_voxelgrid_get_origin(const o3d_voxelgrid_t* grid, double out[3]) {
    return guard(__func__, [&] {
        const VoxelGrid& g = grid_of(grid);
        require(out, "out");
        for (int k = 0; k < 3; ++k) out[k] = g.origin(k);
    });
}

O3D_API o3d_status o3d_voxelgrid_num_voxels(const o3d_voxelgrid_t* grid, size_t* out_n) {
    return guard(__func__, [&] { *require(out_n, "out_n") = grid_of(grid).voxels.size(); });
}

O3D_API o3d_status o3d_voxelgrid_get_voxels(const o3d_voxelgrid_t* grid, int32_t* out_grid_index, double* out_colors,
                                            size_t capacity, size_t* out_n) {
    return guard(__func__, [&] {
        const VoxelGrid& g = grid_of(grid);
        require(out_n, "out_n");
        const size_t n = g.voxels.size();
        *out_n = n;
        if ((out_grid_index || out_colors) && capacity < n)
            throw o3d::BufferTooSmall("buffer holds " + std::to_string(capacity) + " voxels but " + std::to_string(n) +
                                      " are needed");
        for (size_t i = 0; i < n; ++i) {
            for (int k = 0; k < 3; ++k) {
                if (out_grid_index) out_grid_index[3 * i + k] = g.voxels[i].grid_index(k);
                if (out_colors) out_colors[3 * i + k] = g.voxels[i].color(k);
            }
        }
    });
}

O3D_API o3d_status o3d_voxelgrid_get_voxel(const o3d_voxelgrid_t* grid, const double point[3], int32_t out_index[3]) {
    return guard(__func__, [&] {
        const VoxelGrid& g = grid_of(grid);
        require(out_index, "out_index");
        const Eigen::Vector3i cell = o3d::geometry::voxel_index_of(g, vec3(point, "point"));
        for (int k = 0; k < 3; ++k) out_index[k] = cell(k);
    });
}

O3D_API o3d_status o3d_voxelgrid_check_if_included(const o3d_voxelgrid_t* grid, const double* xyz, size_t n,
                                                   int32_t* out_included) {
    return guard(__func__, [&] {
        const VoxelGrid& g = grid_of(grid);
        if (n == 0) return;
        require(xyz, "xyz");
        require(out_included, "out_included");
        if (n > SIZE_MAX / (3 * sizeof(double))) throw o3d::InvalidArgument("n is too large");
        std::vector<Eigen::Vector3d> points(n);
        for (size_t i = 0; i < n; ++i) points[i] = Eigen::Vector3d(xyz[3 * i], xyz[3 * i + 1], xyz[3 * i + 2]);
        const std::vector<bool> included = o3d::geometry::voxels_include(g, points);
        for (size_t i = 0; i < n; ++i) out_included[i] = included[i] ? 1 : 0;
    });
}

}  // extern "C"
