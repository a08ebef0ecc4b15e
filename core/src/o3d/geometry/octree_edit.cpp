// SPDX-License-Identifier: MIT
#include "o3d/geometry/octree_edit.h"

#include <algorithm>
#include <cmath>
#include <string>

#include "o3d/utility/error.h"

namespace o3d::geometry {

namespace {

void check_depth(int max_depth) {
    if (max_depth < 1 || max_depth > kMaxOctreeDepth)
        throw o3d::InvalidArgument("max_depth must be in [1, " + std::to_string(kMaxOctreeDepth) + "] (got " +
                                   std::to_string(max_depth) + ")");
}


void visit_node(const Octree& tree, int node, const OctreeNodeInfo& info, const OctreeVisitor& visit) {
    const OctreeNode& n = tree.nodes[node];
    const bool skip_children = visit(node, info);
    if (n.is_leaf || skip_children) return;
    const double half = info.size / 2.0;
    for (int child = 0; child < 8; ++child) {
        const int c = n.children[child];
        if (c < 0) continue;
        // Children are appended after their parent, so this also rules out cycles.
        if (c <= node || c >= static_cast<int>(tree.nodes.size()) || info.depth >= tree.max_depth)
            throw o3d::InvalidArgument("malformed octree: node " + std::to_string(node) + " has child " +
                                       std::to_string(c));
        OctreeNodeInfo at;
        at.origin = info.origin + half * Eigen::Vector3d(child & 1, (child >> 1) & 1, (child >> 2) & 1);
        at.size = half;
        at.depth = info.depth + 1;
        at.child_index = child;
        visit_node(tree, c, at, visit);  // depth <= kMaxOctreeDepth: the recursion stays shallow
    }
}

}  // namespace

Octree make_octree_with_bounds(int max_depth, const Eigen::Vector3d& origin, double size) {
    check_depth(max_depth);
    if (!origin.allFinite()) throw o3d::InvalidArgument("the octree's origin is not finite");
    if (!(size > 0.0) || !std::isfinite(size))
        throw o3d::InvalidArgument("the octree's size must be finite and > 0 (got " + std::to_string(size) + ")");
    Octree tree;
    tree.max_depth = max_depth;
    tree.origin = origin;
    tree.size = size;
    return tree;
}

bool is_point_in_bound(const Eigen::Vector3d& point, const Eigen::Vector3d& origin, double size) {
    return (point.array() >= origin.array()).all() && (point.array() < origin.array() + size).all();
}

bool octree_insert_point(Octree& tree, const Eigen::Vector3d& point, int index, const Eigen::Vector3d& color) {
    if (index < 0) throw o3d::InvalidArgument("the point index must be >= 0 (got " + std::to_string(index) + ")");
    if (!point.allFinite()) throw o3d::InvalidArgument("the point is not finite");
    if (!color.allFinite()) throw o3d::InvalidArgument("the color is not finite");
    check_depth(tree.max_depth);
    if (!tree.origin.allFinite() || !std::isfinite(tree.size))
        throw o3d::InvalidArgument("the octree's origin and size must be finite");
    if (!is_point_in_bound(point, tree.origin, tree.size)) return false;

    OctreeNode& leaf = tree.nodes[leaf_path(tree, point)];
    const auto at = std::lower_bound(leaf.indices.begin(), leaf.indices.end(), index);
    if (at != leaf.indices.end() && *at == index) return true;
    const double n = static_cast<double>(leaf.indices.size());
    leaf.indices.insert(at, index);
    leaf.color = (leaf.color * n + color) / (n + 1.0);
    return true;
}

void octree_traverse(const Octree& tree, const OctreeVisitor& visit) {
    if (tree.nodes.empty()) return;
    OctreeNodeInfo root;
    root.origin = tree.origin;
    root.size = tree.size;
    visit_node(tree, 0, root, visit);
}

}  // namespace o3d::geometry
