// SPDX-License-Identifier: MIT
// C API: voxelgrid.h (VoxelGrid from point clouds and meshes, and its queries).
#include <Eigen/Core>
#include <memory>
#include <string>

#include "array_family.h"
#include "internal.h"
#include "o3d/geometry/voxel_grid_ops.h"
#include "o3d/voxelgrid.h"

using o3d::capi::guard;
using o3d::capi::require;
using o3d::capi::vec3;
using o3d::capi::write3;
using o3d::geometry::VoxelGrid;

namespace {

const VoxelGrid& grid_of(const o3d_voxelgrid_t* g) { return require(g, "grid")->grid; }


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

/// @brief Copy one field of every voxel (sorted by grid index) out, with the copy-out convention.
template <typename T, typename Field>
void copy_voxels(const VoxelGrid& g, T* out, size_t capacity, size_t* out_rows, Field field) {
    *require(out_rows, "out_rows") = g.voxels.size();
    if (!out) return;
    if (capacity < g.voxels.size())
        throw o3d::BufferTooSmall("buffer holds " + std::to_string(capacity) + " voxels but " +
                                  std::to_string(g.voxels.size()) + " are needed");
    for (size_t i = 0; i < g.voxels.size(); ++i)
        for (int k = 0; k < 3; ++k) out[3 * i + k] = static_cast<T>(field(g.voxels[i])(k));
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

O3D_API o3d_status o3d_voxelgrid_get_voxel_size(double* out, const o3d_voxelgrid_t* grid) {
    return guard(__func__, [&] { *require(out, "out") = grid_of(grid).voxel_size; });
}

O3D_API o3d_status o3d_voxelgrid_get_origin(double out[3], const o3d_voxelgrid_t* grid) {
    return guard(__func__, [&] {
        const VoxelGrid& g = grid_of(grid);
        require(out, "out");
        for (int k = 0; k < 3; ++k) out[k] = g.origin(k);
    });
}

O3D_API o3d_status o3d_voxelgrid_num_voxels(size_t* out_n, const o3d_voxelgrid_t* grid) {
    return guard(__func__, [&] { *require(out_n, "out_n") = grid_of(grid).voxels.size(); });
}

namespace {
void check_voxel_which(int32_t which) {
    if (which != O3D_VOXELGRID_COLORS && which != O3D_VOXELGRID_GRID_INDEX)
        o3d::capi::bad_which(which, "a voxel-grid array (O3D_VOXELGRID_COLORS, O3D_VOXELGRID_GRID_INDEX)");
}
}  // namespace

O3D_API o3d_status o3d_voxelgrid_has_array(int32_t* out, const o3d_voxelgrid_t* grid, int32_t which) {
    return guard(__func__, [&] {
        const VoxelGrid& g = grid_of(grid);
        check_voxel_which(which);
        *require(out, "out") = g.voxels.empty() ? 0 : 1;
    });
}

O3D_API o3d_status o3d_voxelgrid_array_shape(size_t* out_rows, size_t* out_cols, const o3d_voxelgrid_t* grid,
                                             int32_t which) {
    return guard(__func__, [&] {
        const VoxelGrid& g = grid_of(grid);
        check_voxel_which(which);
        *require(out_rows, "out_rows") = g.voxels.size();
        *require(out_cols, "out_cols") = 3;
    });
}

O3D_API o3d_status o3d_voxelgrid_get_array(double* out, size_t capacity, size_t* out_rows, const o3d_voxelgrid_t* grid,
                                           int32_t which) {
    return guard(__func__, [&] {
        const VoxelGrid& g = grid_of(grid);
        if (which != O3D_VOXELGRID_COLORS) o3d::capi::bad_which(which, "a float64 voxel-grid array (O3D_VOXELGRID_COLORS)");
        copy_voxels(g, out, capacity, out_rows, [](const auto& v) { return v.color; });
    });
}

O3D_API o3d_status o3d_voxelgrid_get_index_array(int32_t* out, size_t capacity, size_t* out_rows,
                                                 const o3d_voxelgrid_t* grid, int32_t which) {
    return guard(__func__, [&] {
        const VoxelGrid& g = grid_of(grid);
        if (which != O3D_VOXELGRID_GRID_INDEX)
            o3d::capi::bad_which(which, "an int32 voxel-grid array (O3D_VOXELGRID_GRID_INDEX)");
        copy_voxels(g, out, capacity, out_rows, [](const auto& v) { return v.grid_index; });
    });
}

O3D_API o3d_status o3d_voxelgrid_get_voxel(int32_t out_index[3], const o3d_voxelgrid_t* grid, const double point[3]) {
    return guard(__func__, [&] {
        const VoxelGrid& g = grid_of(grid);
        require(out_index, "out_index");
        const Eigen::Vector3i cell = o3d::geometry::voxel_index_of(g, vec3(point, "point"));
        for (int k = 0; k < 3; ++k) out_index[k] = cell(k);
    });
}

O3D_API o3d_status o3d_voxelgrid_check_if_included(int32_t* out_included, size_t capacity, size_t* out_n,
                                                   const o3d_voxelgrid_t* grid, const double* xyz, size_t n) {
    return guard(__func__, [&] {
        const VoxelGrid& g = grid_of(grid);
        *require(out_n, "out_n") = n;
        if (n > 0) require(xyz, "xyz");
        if (!out_included || n == 0) return;
        if (capacity < n)
            throw o3d::BufferTooSmall("buffer holds " + std::to_string(capacity) + " flags but " + std::to_string(n) +
                                      " are needed");
        if (n > SIZE_MAX / (3 * sizeof(double))) throw o3d::InvalidArgument("n is too large");
        std::vector<Eigen::Vector3d> points(n);
        for (size_t i = 0; i < n; ++i) points[i] = Eigen::Vector3d(xyz[3 * i], xyz[3 * i + 1], xyz[3 * i + 2]);
        const std::vector<bool> included = o3d::geometry::voxels_include(g, points);
        for (size_t i = 0; i < n; ++i) out_included[i] = included[i] ? 1 : 0;
    });
}

}  // extern "C"
