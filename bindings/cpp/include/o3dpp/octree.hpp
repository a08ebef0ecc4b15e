// SPDX-License-Identifier: MIT
#pragma once
/// @file octree.hpp
/// @brief o3dpp::Octree (move-only owner of an o3d_octree_t) over a point cloud or voxel grid, with color leaves.
#include <cstdint>
#include <optional>
#include <vector>

#include "o3d/octree.h"
#include "o3dpp/error.hpp"
#include "o3dpp/handle.hpp"
#include "o3dpp/pointcloud.hpp"
#include "o3dpp/span.hpp"
#include "o3dpp/voxelgrid.hpp"

namespace o3dpp {

/// @brief o3d.geometry.OctreeNodeInfo: where a node sits.
struct OctreeNodeInfo {
    Vec3 origin{};        ///< the node cube's min corner
    double size = 0.0;    ///< the node cube's edge
    int depth = 0;        ///< 0 for the root
    int child_index = 0;  ///< 0..7 within its parent
};

/// @brief A leaf: its node info, the mean color of its points and their indices (ascending).
struct OctreeLeaf {
    OctreeNodeInfo info;
    Vec3 color{};
    std::vector<int32_t> indices;
};

/// @brief o3d.geometry.Octree: a cube of edge size() at origin(), split to max_depth().
class Octree : public Owner<Octree, o3d_octree_t, &o3d_octree_destroy> {
public:
    /// @brief Empty octree of depth `max_depth` >= 1.
    explicit Octree(int max_depth) : Owner(make([&](o3d_octree_t** o) { return o3d_octree_create(o, max_depth); })) {}
    /// @brief Empty octree of depth `max_depth` (1 to 21) over the cube of edge `size` > 0 at `origin`.
    Octree(int max_depth, const Vec3& origin, double size)
        : Owner(make([&](o3d_octree_t** o) {
              return o3d_octree_create_with_bounds(o, max_depth, origin.data(), size);
          })) {}
    /// @brief Take ownership of `owned` (must not be NULL).
    explicit Octree(o3d_octree_t* owned) : Owner(owned) {}

    /// @brief Whether `point` lies in the half-open cube [origin, origin + size)^3.
    static bool is_point_in_bound(const Vec3& point, const Vec3& origin, double size) {
        int32_t in = 0;
        check(o3d_octree_is_point_in_bound(&in, point.data(), origin.data(), size));
        return in != 0;
    }
    /// @brief Insert point number `index` >= 0 with `color` into the max-depth leaf holding `point` (a color leaf:
    /// ascending unique indices, the mean color). False, changing nothing, when the point is outside the root cube.
    bool insert_point(const Vec3& point, int32_t index, const Vec3& color) {
        int32_t inserted = 0;
        check(o3d_octree_insert_point(&inserted, get(), point.data(), index, color.data()));
        return inserted != 0;
    }
    /// @brief Rebuild from `grid` (keeping max_depth()): one leaf per voxel centre, with the voxel's color and its
    /// position in the grid's voxel order.
    Octree& create_from_voxel_grid(const VoxelGrid& grid) {
        return done(o3d_octree_create_from_voxel_grid(get(), grid.get()));
    }
    /// @brief The grid of the leaves: voxel size = size() / 2^max_depth(), origin at origin(), leaf colors.
    VoxelGrid to_voxel_grid() const { return VoxelGrid::create_from_octree(*this); }

    /// @brief Rebuild from `cloud`: the root is its bounding cube enlarged by `size_expand` (>= 0).
    Octree& convert_from_point_cloud(const PointCloud& cloud, double size_expand = 0.01) {
        return done(o3d_octree_convert_from_point_cloud(get(), cloud.get(), size_expand));
    }
    Vec3 origin() const {
        Vec3 v{};
        check(o3d_octree_get_root(v.data(), nullptr, nullptr, get()));
        return v;
    }
    double size() const {
        double v = 0.0;
        check(o3d_octree_get_root(nullptr, &v, nullptr, get()));
        return v;
    }
    int max_depth() const {
        int32_t v = 0;
        check(o3d_octree_get_root(nullptr, nullptr, &v, get()));
        return v;
    }
    std::size_t num_leaf_nodes() const { return query(&o3d_octree_num_leaf_nodes); }
    /// @brief The leaf containing `point`; empty when it is outside the root or in an empty cell.
    std::optional<OctreeLeaf> locate_leaf_node(const Vec3& point) const {
        int32_t found = 0;
        o3d_octree_node_info_t info{};
        OctreeLeaf leaf;
        size_t n = 0;
        check(o3d_octree_locate_leaf_node(&found, &info, leaf.color.data(), nullptr, 0, &n, get(), point.data()));
        if (!found) return std::nullopt;
        leaf.indices.resize(n);
        check(o3d_octree_locate_leaf_node(&found, &info, leaf.color.data(), leaf.indices.data(), leaf.indices.size(),
                                          &n, get(), point.data()));
        leaf.indices.resize(n < leaf.indices.size() ? n : leaf.indices.size());
        leaf.info = OctreeNodeInfo{{info.origin[0], info.origin[1], info.origin[2]}, info.size, info.depth,
                                   info.child_index};
        return leaf;
    }
};

inline VoxelGrid VoxelGrid::create_from_octree(const Octree& octree) {
    return adopt([&](o3d_voxelgrid_t** out) { return o3d_voxelgrid_create_from_octree(out, octree.get()); });
}

}  // namespace o3dpp
