// SPDX-License-Identifier: MIT
#pragma once
/// @file voxelgrid.hpp
/// @brief o3dpp::VoxelGrid (move-only owner of an o3d_voxelgrid_t): the occupied cells of a regular grid.
#include <array>
#include <cstdint>
#include <vector>

#include "o3d/voxelgrid.h"
#include "o3dpp/arrays.hpp"
#include "o3dpp/camera.hpp"
#include "o3dpp/error.hpp"
#include "o3dpp/generated/enums.hpp"
#include "o3dpp/generated/voxelgrid.hpp"
#include "o3dpp/handle.hpp"
#include "o3dpp/image.hpp"
#include "o3dpp/pointcloud.hpp"
#include "o3dpp/span.hpp"
#include "o3dpp/trianglemesh.hpp"

namespace o3dpp {

class Octree;  // octree.hpp (included at the end: VoxelGrid::create_from_octree is defined there)

using GridIndex = std::array<int32_t, 3>;

/// @brief One occupied cell (o3d.geometry.Voxel).
struct Voxel {
    GridIndex grid_index{};
    Vec3 color{};  ///< mean color of what fell in the cell (0 without colors)
};

namespace detail {
using VoxelGridArrayFns = ArrayFns<&o3d_voxelgrid_has_array, &o3d_voxelgrid_array_shape, &o3d_voxelgrid_get_array,
                                   nullptr, nullptr, nullptr, nullptr, &o3d_voxelgrid_get_index_array>;
}  // namespace detail

/// @brief o3d.geometry.VoxelGrid: cells of edge voxel_size(), cell (0,0,0) starting at origin().
/// Its arrays are read-only (has_array, array_shape and get_array); add_voxel, remove_voxel and the carving
/// methods edit the cells. Voxels come out sorted by grid index (x, then y, then z). The methods that pass their
/// arguments to one C function are generated (detail::VoxelGridCalls).
class VoxelGrid : public Owner<VoxelGrid, o3d_voxelgrid_t, &o3d_voxelgrid_destroy>,
                  public Arrays<VoxelGrid, VoxelGridArray, detail::VoxelGridArrayFns>,
                  public detail::VoxelGridCalls<VoxelGrid> {
public:
    /// @brief Take ownership of `owned` (must not be NULL).
    explicit VoxelGrid(o3d_voxelgrid_t* owned) : Owner(owned) {}
    /// @brief The occupied cells, sorted by grid index.
    std::vector<Voxel> get_voxels() const {
        const std::vector<GridIndex> index = get_array<GridIndex>(VoxelGridArray::GridIndices);
        const std::vector<Vec3> color = get_array<Vec3>(VoxelGridArray::Colors);
        std::vector<Voxel> out(index.size() < color.size() ? index.size() : color.size());
        for (std::size_t i = 0; i < out.size(); ++i) out[i] = Voxel{index[i], color[i]};
        return out;
    }
    /// @brief For each query point, whether its cell is occupied.
    std::vector<bool> check_if_included(const std::vector<Vec3>& queries) const {
        const auto flags = copy_out<int32_t>(&o3d_voxelgrid_check_if_included,
                                             queries.empty() ? nullptr : queries.front().data(), queries.size());
        return std::vector<bool>(flags.begin(), flags.end());
    }
    /// @brief Add `voxel`, replacing the one at its grid index (Open3D's add_voxel).
    VoxelGrid& add_voxel(const Voxel& voxel) {
        return done(o3d_voxelgrid_add_voxel(get(), voxel.grid_index.data(), voxel.color.data()));
    }
    /// @brief Remove the voxel at `idx`; nothing happens when there is none (Open3D's remove_voxel).
    VoxelGrid& remove_voxel(const GridIndex& idx) { return done(o3d_voxelgrid_remove_voxel(get(), idx.data())); }
    /// @brief The centre of cell `idx`, occupied or not.
    Vec3 get_voxel_center_coordinate(const GridIndex& idx) const {
        Vec3 out{};
        check(o3d_voxelgrid_get_voxel_center_coordinate(out.data(), get(), idx.data()));
        return out;
    }
    /// @brief The 8 corners of cell `index`, in Open3D's order.
    std::array<Vec3, 8> get_voxel_bounding_points(const GridIndex& index) const {
        std::array<double, 24> flat{};
        check(o3d_voxelgrid_get_voxel_bounding_points(flat.data(), get(), index.data()));
        std::array<Vec3, 8> out{};
        for (std::size_t i = 0; i < 8; ++i) out[i] = Vec3{flat[3 * i], flat[3 * i + 1], flat[3 * i + 2]};
        return out;
    }
    /// @brief Space carving with a 1-channel float32 depth map (metres) of the intrinsic's size: a voxel stays when a
    /// corner inside the image lies on or behind the observed depth, or, with `keep_voxels_outside_image`, when a
    /// corner falls outside the image. The extrinsic (world to camera) must be rigid.
    VoxelGrid& carve_depth_map(const Image& depth_map, const PinholeCameraParameters& camera_params,
                               bool keep_voxels_outside_image = false) {
        return done(o3d_voxelgrid_carve_depth_map(get(), depth_map.get(), &camera_params.intrinsic,
                                                  camera_params.extrinsic.data(), keep_voxels_outside_image));
    }
    /// @brief Space carving with a 1-channel float32 mask of the intrinsic's size: as carve_depth_map, a voxel staying
    /// when a corner inside the image falls on the mask (value > 0).
    VoxelGrid& carve_silhouette(const Image& silhouette_mask, const PinholeCameraParameters& camera_params,
                                bool keep_voxels_outside_image = false) {
        return done(o3d_voxelgrid_carve_silhouette(get(), silhouette_mask.get(), &camera_params.intrinsic,
                                                   camera_params.extrinsic.data(), keep_voxels_outside_image));
    }
    /// @brief The grid of `octree`'s leaves (as Octree::to_voxel_grid): voxel size = size / 2^max_depth, origin at
    /// the octree's origin, one voxel per leaf with the leaf's color.
    static VoxelGrid create_from_octree(const Octree& octree);
};

}  // namespace o3dpp

#include "o3dpp/octree.hpp"  // defines VoxelGrid::create_from_octree
