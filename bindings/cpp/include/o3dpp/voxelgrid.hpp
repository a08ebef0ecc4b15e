// SPDX-License-Identifier: MIT
#pragma once
/// @file voxelgrid.hpp
/// @brief o3dpp::VoxelGrid (move-only owner of an o3d_voxelgrid_t): the occupied cells of a regular grid.
#include <array>
#include <cstdint>
#include <vector>

#include "o3d/voxelgrid.h"
#include "o3dpp/error.hpp"
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

/// @brief o3d.geometry.VoxelGrid: cells of edge voxel_size(), cell (0,0,0) starting at origin().
/// Immutable once built. Voxels come out sorted by grid index (x, then y, then z).
class VoxelGrid {
public:
    /// @brief Take ownership of `owned` (must not be NULL).
    explicit VoxelGrid(o3d_voxelgrid_t* owned) : h_(owned) {
        if (!owned) throw Error(O3D_ERROR_INVALID_ARGUMENT, "o3dpp::VoxelGrid: NULL handle");
    }
    VoxelGrid(VoxelGrid&&) noexcept = default;
    VoxelGrid& operator=(VoxelGrid&&) noexcept = default;
    VoxelGrid(const VoxelGrid&) = delete;
    VoxelGrid& operator=(const VoxelGrid&) = delete;

    o3d_voxelgrid_t* get() const noexcept { return h_.get(); }
    o3d_voxelgrid_t* release() noexcept { return h_.release(); }
    explicit operator bool() const noexcept { return static_cast<bool>(h_); }

    /// @brief Cells holding at least one point; origin = the cloud's min bound - voxel_size / 2.
    static VoxelGrid create_from_point_cloud(const PointCloud& cloud, double voxel_size) {
        return adopt(
            [&](o3d_voxelgrid_t** o) { return o3d_voxelgrid_create_from_point_cloud(o, cloud.get(), voxel_size); });
    }
    /// @brief As create_from_point_cloud on the grid starting at min_bound; points outside are ignored.
    static VoxelGrid create_from_point_cloud_within_bounds(const PointCloud& cloud, double voxel_size,
                                                           const Vec3& min_bound, const Vec3& max_bound) {
        return adopt([&](o3d_voxelgrid_t** o) {
            return o3d_voxelgrid_create_from_point_cloud_within_bounds(o, cloud.get(), voxel_size, min_bound.data(),
                                                                       max_bound.data());
        });
    }
    /// @brief Cells intersecting at least one triangle.
    static VoxelGrid create_from_triangle_mesh(const TriangleMesh& mesh, double voxel_size) {
        return adopt(
            [&](o3d_voxelgrid_t** o) { return o3d_voxelgrid_create_from_triangle_mesh(o, mesh.get(), voxel_size); });
    }

    double voxel_size() const {
        double v = 0.0;
        check(o3d_voxelgrid_get_voxel_size(&v, get()));
        return v;
    }
    Vec3 origin() const {
        Vec3 v{};
        check(o3d_voxelgrid_get_origin(v.data(), get()));
        return v;
    }
    std::size_t num_voxels() const {
        size_t n = 0;
        check(o3d_voxelgrid_num_voxels(&n, get()));
        return n;
    }
    /// @brief The occupied cells, sorted by grid index.
    std::vector<Voxel> get_voxels() const {
        size_t n = 0;
        check(o3d_voxelgrid_get_voxels(nullptr, nullptr, 0, &n, get()));
        std::vector<GridIndex> index(n);
        std::vector<Vec3> color(n);
        check(o3d_voxelgrid_get_voxels(n ? index.front().data() : nullptr, n ? color.front().data() : nullptr, n, &n,
                                       get()));
        std::vector<Voxel> out(n < index.size() ? n : index.size());
        for (std::size_t i = 0; i < out.size(); ++i) out[i] = Voxel{index[i], color[i]};
        return out;
    }
    /// @brief Grid index of the cell containing `point` (occupied or not).
    GridIndex get_voxel(const Vec3& point) const {
        GridIndex out{};
        check(o3d_voxelgrid_get_voxel(out.data(), get(), point.data()));
        return out;
    }
    /// @brief For each query point, whether its cell is occupied.
    std::vector<bool> check_if_included(const std::vector<Vec3>& queries) const {
        std::vector<int32_t> flags(queries.size());
        check(o3d_voxelgrid_check_if_included(flags.data(), get(), queries.empty() ? nullptr : queries.front().data(),
                                              queries.size()));
        return std::vector<bool>(flags.begin(), flags.end());
    }

    /// @brief Run `create(o3d_voxelgrid_t**)` and own what it returns.
    template <typename F>
    static VoxelGrid adopt(F&& create) {
        o3d_voxelgrid_t* p = nullptr;
        check(create(&p));
        return VoxelGrid(p);
    }

private:
    UniqueHandle<o3d_voxelgrid_t, &o3d_voxelgrid_destroy> h_;
};

}  // namespace o3dpp
