// SPDX-License-Identifier: MIT
#pragma once
/// @file voxelgrid.hpp
/// @brief o3dpp::VoxelGrid (move-only owner of an o3d_voxelgrid_t): the occupied cells of a regular grid.
#include <array>
#include <cstdint>
#include <vector>

#include "o3d/voxelgrid.h"
#include "o3dpp/arrays.hpp"
#include "o3dpp/error.hpp"
#include "o3dpp/generated/enums.hpp"
#include "o3dpp/generated/voxelgrid.hpp"
#include "o3dpp/handle.hpp"
#include "o3dpp/pointcloud.hpp"
#include "o3dpp/span.hpp"
#include "o3dpp/trianglemesh.hpp"

namespace o3dpp {

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
/// Immutable once built (has_array, array_shape and get_array only). Voxels come out sorted by grid index
/// (x, then y, then z). The methods that pass their arguments to one C function are generated
/// (detail::VoxelGridCalls).
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
};

}  // namespace o3dpp
