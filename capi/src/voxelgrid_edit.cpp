// SPDX-License-Identifier: MIT
// C API: the editing half of voxelgrid.h and octree.h (dense grids, adding and removing voxels, cell geometry,
// carving, and the conversions between octrees and voxel grids).
#include <Eigen/Core>
#include <string>

#include "camera_internal.h"
#include "internal.h"
#include "o3d/geometry/octree_edit.h"
#include "o3d/geometry/octree_voxel_conversion.h"
#include "o3d/geometry/voxel_grid_carving.h"
#include "o3d/geometry/voxel_grid_edit.h"
#include "o3d/geometry/voxel_grid_mesh_bounds.h"
#include "o3d/octree.h"
#include "o3d/voxelgrid.h"

using o3d::capi::emit_handle;
using o3d::capi::guard;
using o3d::capi::require;
using o3d::capi::require_out_handle;
using o3d::capi::vec3;
using o3d::capi::write3;
using o3d::geometry::VoxelGrid;

namespace {

Eigen::Vector3i index3(const int32_t* index) {
    require(index, "grid_index");
    return Eigen::Vector3i(index[0], index[1], index[2]);
}

o3d::camera::PinholeCameraParameters camera_of(const o3d_pinhole_intrinsic_t* intrinsic, const double* extrinsic) {
    o3d::camera::PinholeCameraParameters params;
    params.intrinsic = o3d::capi::to_core(*require(intrinsic, "intrinsic"));
    params.extrinsic = o3d::capi::matrix_from_row_major(require(extrinsic, "extrinsic"));
    return params;
}

}  // namespace

O3D_API o3d_status o3d_voxelgrid_create_dense(o3d_voxelgrid_t** out, const double origin[3], const double color[3],
                                              double voxel_size, double width, double height, double depth) {
    return guard(__func__, [&] {
        require_out_handle(out);
        emit_handle(out, o3d::geometry::voxel_grid_create_dense(vec3(origin, "origin"), vec3(color, "color"),
                                                                voxel_size, width, height, depth));
    });
}

O3D_API o3d_status o3d_voxelgrid_create_from_triangle_mesh_within_bounds(o3d_voxelgrid_t** out,
                                                                         const o3d_trianglemesh_t* mesh,
                                                                         double voxel_size, const double min_bound[3],
                                                                         const double max_bound[3]) {
    return guard(__func__, [&] {
        require_out_handle(out);
        emit_handle(out, o3d::geometry::voxel_grid_from_triangle_mesh_within_bounds(
                             require(mesh, "mesh")->mesh, voxel_size, vec3(min_bound, "min_bound"),
                             vec3(max_bound, "max_bound")));
    });
}

O3D_API o3d_status o3d_voxelgrid_add_voxel(o3d_voxelgrid_t* grid, const int32_t grid_index[3], const double color[3]) {
    return guard(__func__, [&] {
        const Eigen::Vector3d c = vec3(color, "color");
        if (!c.allFinite()) throw o3d::InvalidArgument("color must be finite");
        o3d::geometry::add_voxel(require(grid, "grid")->grid, o3d::geometry::Voxel{index3(grid_index), c});
    });
}

O3D_API o3d_status o3d_voxelgrid_remove_voxel(o3d_voxelgrid_t* grid, const int32_t grid_index[3]) {
    return guard(__func__, [&] { o3d::geometry::remove_voxel(require(grid, "grid")->grid, index3(grid_index)); });
}

O3D_API o3d_status o3d_voxelgrid_get_voxel_center_coordinate(double out[3], const o3d_voxelgrid_t* grid,
                                                             const int32_t grid_index[3]) {
    return guard(__func__, [&] {
        require(out, "out");
        write3(out, "out", o3d::geometry::voxel_center_coordinate(require(grid, "grid")->grid, index3(grid_index)));
    });
}

O3D_API o3d_status o3d_voxelgrid_get_voxel_bounding_points(double out[24], const o3d_voxelgrid_t* grid,
                                                           const int32_t grid_index[3]) {
    return guard(__func__, [&] {
        require(out, "out");
        const auto corners = o3d::geometry::voxel_bounding_points(require(grid, "grid")->grid, index3(grid_index));
        for (int i = 0; i < 8; ++i) write3(out + 3 * i, "out", corners[i]);
    });
}

O3D_API o3d_status o3d_voxelgrid_carve_depth_map(o3d_voxelgrid_t* grid, const o3d_image_t* depth,
                                                 const o3d_pinhole_intrinsic_t* intrinsic, const double extrinsic[16],
                                                 o3d_bool keep_voxels_outside_image) {
    return guard(__func__, [&] {
        o3d::geometry::carve_depth_map(require(grid, "grid")->grid, require(depth, "depth")->image,
                                       camera_of(intrinsic, extrinsic), keep_voxels_outside_image != 0);
    });
}

O3D_API o3d_status o3d_voxelgrid_carve_silhouette(o3d_voxelgrid_t* grid, const o3d_image_t* mask,
                                                  const o3d_pinhole_intrinsic_t* intrinsic, const double extrinsic[16],
                                                  o3d_bool keep_voxels_outside_image) {
    return guard(__func__, [&] {
        o3d::geometry::carve_silhouette(require(grid, "grid")->grid, require(mask, "mask")->image,
                                        camera_of(intrinsic, extrinsic), keep_voxels_outside_image != 0);
    });
}

O3D_API o3d_status o3d_voxelgrid_create_from_octree(o3d_voxelgrid_t** out, const o3d_octree_t* octree) {
    return guard(__func__, [&] {
        require_out_handle(out);
        emit_handle(out, o3d::geometry::octree_to_voxel_grid(require(octree, "octree")->octree));
    });
}

O3D_API o3d_status o3d_octree_create_with_bounds(o3d_octree_t** out, int32_t max_depth, const double origin[3],
                                                 double size) {
    return guard(__func__, [&] {
        require_out_handle(out);
        emit_handle(out, o3d::geometry::make_octree_with_bounds(max_depth, vec3(origin, "origin"), size));
    });
}

O3D_API o3d_status o3d_octree_is_point_in_bound(int32_t* out, const double point[3], const double origin[3],
                                                double size) {
    return guard(__func__, [&] {
        require(out, "out");
        *out = o3d::geometry::is_point_in_bound(vec3(point, "point"), vec3(origin, "origin"), size) ? 1 : 0;
    });
}

O3D_API o3d_status o3d_octree_insert_point(int32_t* out_inserted, o3d_octree_t* octree, const double point[3],
                                           int32_t index, const double color[3]) {
    return guard(__func__, [&] {
        require(out_inserted, "out_inserted");
        const Eigen::Vector3d p = vec3(point, "point"), c = vec3(color, "color");
        if (!p.allFinite() || !c.allFinite()) throw o3d::InvalidArgument("point and color must be finite");
        if (index < 0) throw o3d::InvalidArgument("index must be >= 0, got " + std::to_string(index));
        *out_inserted = o3d::geometry::octree_insert_point(require(octree, "octree")->octree, p, index, c) ? 1 : 0;
    });
}

O3D_API o3d_status o3d_octree_create_from_voxel_grid(o3d_octree_t* octree, const o3d_voxelgrid_t* grid) {
    return guard(__func__, [&] {
        o3d::geometry::octree_from_voxel_grid(require(octree, "octree")->octree, require(grid, "grid")->grid);
    });
}
