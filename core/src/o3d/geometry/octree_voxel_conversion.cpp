// SPDX-License-Identifier: MIT
#include "o3d/geometry/octree_voxel_conversion.h"

#include <algorithm>
#include <climits>
#include <cmath>
#include <string>

#include "o3d/geometry/octree_edit.h"
#include "o3d/geometry/octree_ops.h"
#include "o3d/geometry/voxel_grid_edit.h"
#include "o3d/utility/error.h"

namespace o3d::geometry {

namespace {

void check_tree(const Octree& tree) {
    if (tree.max_depth < 1 || tree.max_depth > kMaxOctreeDepth)
        throw o3d::InvalidArgument("the octree's max_depth must be in [1, " + std::to_string(kMaxOctreeDepth) +
                                   "] (got " + std::to_string(tree.max_depth) + ")");
    if (!tree.origin.allFinite() || !std::isfinite(tree.size))
        throw o3d::InvalidArgument("the octree's origin and size must be finite");
}

/// Leaves with their cell index at max depth: each level doubles the index and adds the child's bits.
/// A tree not built by octree_ops / octree_edit (a leaf above max depth, a child index that is not a later
/// node) throws rather than giving wrong cells.
void collect_leaves(const Octree& tree, int node, int depth, const Eigen::Vector3i& cell, std::vector<Voxel>& out) {
    const OctreeNode& n = tree.nodes[node];
    if (n.is_leaf != (depth == tree.max_depth))
        throw o3d::InvalidArgument("malformed octree: node " + std::to_string(node) + " at depth " +
                                   std::to_string(depth) + (n.is_leaf ? " is a leaf" : " is not a leaf"));
    if (n.is_leaf) {
        out.push_back({cell, n.color});
        return;
    }
    for (int child = 0; child < 8; ++child) {
        const int c = n.children[child];
        if (c < 0) continue;
        if (c <= node || c >= static_cast<int>(tree.nodes.size()))
            throw o3d::InvalidArgument("malformed octree: node " + std::to_string(node) + " has child " +
                                       std::to_string(c));
        const Eigen::Vector3i bits(child & 1, (child >> 1) & 1, (child >> 2) & 1);
        collect_leaves(tree, c, depth + 1, 2 * cell + bits, out);
    }
}

}  // namespace

VoxelGrid octree_to_voxel_grid(const Octree& tree) {
    check_tree(tree);
    VoxelGrid grid;
    grid.origin = tree.origin;
    grid.voxel_size = std::ldexp(tree.size, -tree.max_depth);
    if (tree.nodes.empty()) return grid;
    std::vector<Voxel> leaves;
    collect_leaves(tree, 0, 0, Eigen::Vector3i::Zero(), leaves);
    // Leaves sit at max depth, so every index has max_depth bits and the cell is the path; sort it into
    // the grid's order (the traversal order interleaves the axes).
    std::sort(leaves.begin(), leaves.end(),
              [](const Voxel& a, const Voxel& b) { return voxel_index_less(a.grid_index, b.grid_index); });
    grid.voxels = std::move(leaves);
    return grid;
}

void octree_from_voxel_grid(Octree& tree, const VoxelGrid& grid) {
    if (tree.max_depth < 1 || tree.max_depth > kMaxOctreeDepth)
        throw o3d::InvalidArgument("the octree's max_depth must be in [1, " + std::to_string(kMaxOctreeDepth) +
                                   "] (got " + std::to_string(tree.max_depth) + ")");
    if (!(grid.voxel_size > 0.0) || !std::isfinite(grid.voxel_size))
        throw o3d::InvalidArgument("the voxel grid's voxel_size must be finite and > 0");
    if (!grid.origin.allFinite()) throw o3d::InvalidArgument("the voxel grid's origin is not finite");
    for (size_t r = 0; r < grid.voxels.size(); ++r) {
        if (!grid.voxels[r].color.allFinite())
            throw o3d::InvalidArgument("voxel " + std::to_string(r) + "'s color is not finite");
        if (r > 0 && !voxel_index_less(grid.voxels[r - 1].grid_index, grid.voxels[r].grid_index))
            throw o3d::InvalidArgument("the voxel grid's voxels are not sorted and unique (at " + std::to_string(r) +
                                       ")");
    }
    if (grid.voxels.size() > static_cast<size_t>(INT_MAX))
        throw o3d::InvalidArgument("too many voxels for int point indices");
    tree.nodes.clear();
    tree.origin = grid.origin;
    tree.size = 0.0;
    if (grid.voxels.empty()) return;

    Eigen::Vector3i lo = grid.voxels.front().grid_index, hi = lo;
    for (const Voxel& v : grid.voxels) {
        lo = lo.cwiseMin(v.grid_index);
        hi = hi.cwiseMax(v.grid_index);
    }
    const Eigen::Vector3d max_bound = grid.origin + (hi.cast<double>().array() + 1.0).matrix() * grid.voxel_size;
    tree.origin = grid.origin + lo.cwiseMin(0).cast<double>() * grid.voxel_size;
    tree.size = (max_bound - tree.origin).maxCoeff();
    // The centre summed in Open3D's order, (voxel_size / 2 + origin) + index * voxel_size: a centre on a
    // node's mid-plane (the voxel grid and the tree share the origin) then falls on the same side as there.
    const Eigen::Vector3d half_plus_origin = (grid.voxel_size / 2.0 + grid.origin.array()).matrix();
    for (size_t r = 0; r < grid.voxels.size(); ++r) {
        const Eigen::Vector3d centre = half_plus_origin + grid.voxels[r].grid_index.cast<double>() * grid.voxel_size;
        octree_insert_point(tree, centre, static_cast<int>(r), grid.voxels[r].color);
    }
}

}  // namespace o3d::geometry
