// SPDX-License-Identifier: MIT
// C API: octree.h (Octree over a point cloud, with OctreePointColorLeafNode leaves).
#include <Eigen/Core>
#include <memory>
#include <string>

#include "internal.h"
#include "o3d/geometry/octree_ops.h"
#include "o3d/octree.h"

using o3d::capi::guard;
using o3d::capi::require;
using o3d::geometry::Octree;

extern "C" {

O3D_API o3d_status o3d_octree_create(o3d_octree_t** out, int32_t max_depth) {
    return guard(__func__, [&] {
        require(out, "out");
        *out = nullptr;
        auto handle = std::make_unique<o3d_octree>();
        handle->octree = o3d::geometry::make_octree(max_depth);
        *out = handle.release();
    });
}

O3D_API void o3d_octree_destroy(o3d_octree_t* octree) { delete octree; }

O3D_API o3d_status o3d_octree_convert_from_point_cloud(o3d_octree_t* octree, const o3d_pointcloud_t* pc,
                                                       double size_expand) {
    return guard(__func__, [&] {
        Octree& tree = require(octree, "octree")->octree;
        const auto& cloud = require(pc, "pc")->cloud;
        Octree rebuilt = o3d::geometry::make_octree(tree.max_depth);
        o3d::geometry::octree_from_point_cloud(rebuilt, cloud, size_expand);  // the tree is untouched on error
        tree = std::move(rebuilt);
    });
}

O3D_API o3d_status o3d_octree_get_root(double out_origin[3], double* out_size, int32_t* out_max_depth,
                                       const o3d_octree_t* octree) {
    return guard(__func__, [&] {
        const Octree& tree = require(octree, "octree")->octree;
        if (out_origin)
            for (int k = 0; k < 3; ++k) out_origin[k] = tree.origin(k);
        if (out_size) *out_size = tree.size;
        if (out_max_depth) *out_max_depth = tree.max_depth;
    });
}

O3D_API o3d_status o3d_octree_num_leaf_nodes(size_t* out_n, const o3d_octree_t* octree) {
    return guard(__func__, [&] {
        const Octree& tree = require(octree, "octree")->octree;
        *require(out_n, "out_n") = o3d::geometry::count_leaves(tree);
    });
}

O3D_API o3d_status o3d_octree_locate_leaf_node(int32_t* out_found, o3d_octree_node_info_t* out_info,
                                               double out_color[3], int32_t* out_indices, size_t capacity,
                                               size_t* out_n, const o3d_octree_t* octree, const double point[3]) {
    return guard(__func__, [&] {
        const Octree& tree = require(octree, "octree")->octree;
        require(point, "point");
        require(out_found, "out_found");
        const Eigen::Vector3d p(point[0], point[1], point[2]);
        if (!p.allFinite()) throw o3d::InvalidArgument("point is not finite");
        if (out_n) *out_n = 0;
        o3d::geometry::OctreeNodeInfo info;
        const int leaf = o3d::geometry::locate_leaf(tree, p, &info);
        *out_found = leaf >= 0 ? 1 : 0;
        if (leaf < 0) return;
        const o3d::geometry::OctreeNode& node = tree.nodes[leaf];
        if (out_indices && capacity < node.indices.size())
            throw o3d::BufferTooSmall("buffer holds " + std::to_string(capacity) + " indices but " +
                                      std::to_string(node.indices.size()) + " are needed");
        if (out_info) {
            for (int k = 0; k < 3; ++k) out_info->origin[k] = info.origin(k);
            out_info->size = info.size;
            out_info->depth = info.depth;
            out_info->child_index = info.child_index;
        }
        if (out_color)
            for (int k = 0; k < 3; ++k) out_color[k] = node.color(k);
        o3d::capi::copy_out<int32_t>(node.indices.data(), node.indices.size(), out_indices, capacity, out_n);
    });
}

}  // extern "C"
