// SPDX-License-Identifier: MIT
#pragma once
/// @file octree.hpp
/// @brief o3dpp::Octree (move-only owner of an o3d_octree_t) over a point cloud, with color leaves.
#include <cstdint>
#include <optional>
#include <vector>

#include "o3d/octree.h"
#include "o3dpp/error.hpp"
#include "o3dpp/handle.hpp"
#include "o3dpp/pointcloud.hpp"
#include "o3dpp/span.hpp"

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
class Octree {
public:
    /// @brief Empty octree of depth `max_depth` >= 1.
    explicit Octree(int max_depth) {
        o3d_octree_t* p = nullptr;
        check(o3d_octree_create(&p, max_depth));
        h_.reset(p);
    }
    /// @brief Take ownership of `owned` (must not be NULL).
    explicit Octree(o3d_octree_t* owned) : h_(owned) {
        if (!owned) throw Error(O3D_ERROR_INVALID_ARGUMENT, "o3dpp::Octree: NULL handle");
    }
    Octree(Octree&&) noexcept = default;
    Octree& operator=(Octree&&) noexcept = default;
    Octree(const Octree&) = delete;
    Octree& operator=(const Octree&) = delete;

    o3d_octree_t* get() const noexcept { return h_.get(); }
    o3d_octree_t* release() noexcept { return h_.release(); }
    explicit operator bool() const noexcept { return static_cast<bool>(h_); }

    /// @brief Rebuild from `cloud`: the root is its bounding cube enlarged by `size_expand` (>= 0).
    Octree& convert_from_point_cloud(const PointCloud& cloud, double size_expand = 0.01) {
        check(o3d_octree_convert_from_point_cloud(get(), cloud.get(), size_expand));
        return *this;
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
    std::size_t num_leaf_nodes() const {
        size_t n = 0;
        check(o3d_octree_num_leaf_nodes(&n, get()));
        return n;
    }
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

private:
    UniqueHandle<o3d_octree_t, &o3d_octree_destroy> h_;
};

}  // namespace o3dpp
