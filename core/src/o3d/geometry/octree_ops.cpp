// SPDX-License-Identifier: MIT
#include "o3d/geometry/octree_ops.h"

#include <cmath>
#include <string>

#include "o3d/utility/error.h"

namespace o3d::geometry {

namespace {

/// Half-open containment [origin, origin + size), as Open3D tests a point against a node cube.
bool in_cube(const Eigen::Vector3d& p, const Eigen::Vector3d& origin, double size) {
    return (p.array() >= origin.array()).all() && (p.array() < origin.array() + size).all();
}

}  // namespace

int descend(const Eigen::Vector3d& p, Eigen::Vector3d& origin, double& size) {
    const double half = size / 2.0;
    int child = 0;
    for (int axis = 0; axis < 3; ++axis) {
        if (p(axis) < origin(axis) + half) continue;
        child |= 1 << axis;
        origin(axis) += half;
    }
    size = half;
    return child;
}

int leaf_path(Octree& tree, const Eigen::Vector3d& point) {
    if (tree.nodes.empty()) tree.nodes.emplace_back();
    Eigen::Vector3d origin = tree.origin;
    double size = tree.size;
    int node = 0;
    for (int depth = 0; depth < tree.max_depth; ++depth) {
        const int child = descend(point, origin, size);
        int next = tree.nodes[node].children[child];
        if (next < 0) {
            next = static_cast<int>(tree.nodes.size());
            tree.nodes[node].children[child] = next;
            tree.nodes.emplace_back();  // invalidates references into nodes: index only
        }
        node = next;
    }
    tree.nodes[node].is_leaf = true;
    return node;
}

Octree make_octree(int max_depth) {
    if (max_depth < 1 || max_depth > kMaxOctreeDepth)
        throw o3d::InvalidArgument("max_depth must be in [1, " + std::to_string(kMaxOctreeDepth) + "] (got " +
                                   std::to_string(max_depth) + ")");
    Octree tree;
    tree.max_depth = max_depth;
    return tree;
}

void octree_from_point_cloud(Octree& tree, const PointCloud& cloud, double size_expand) {
    if (!(size_expand >= 0.0) || !std::isfinite(size_expand))
        throw o3d::InvalidArgument("size_expand must be finite and >= 0 (got " + std::to_string(size_expand) + ")");
    if (!cloud.has_points()) throw o3d::InvalidArgument("the point cloud is empty");
    for (size_t i = 0; i < cloud.points.size(); ++i)
        if (!cloud.points[i].allFinite())
            throw o3d::InvalidArgument("point " + std::to_string(i) + " is not finite");
    if (tree.max_depth < 1 || tree.max_depth > kMaxOctreeDepth)
        throw o3d::InvalidArgument("the octree's max_depth is out of range");

    Eigen::Vector3d min_bound = cloud.points[0], max_bound = cloud.points[0];
    for (const Eigen::Vector3d& p : cloud.points) {
        min_bound = min_bound.cwiseMin(p);
        max_bound = max_bound.cwiseMax(p);
    }
    const Eigen::Vector3d center = (min_bound + max_bound) / 2.0;
    const double max_half = (center - min_bound).maxCoeff();
    tree.origin = min_bound.cwiseMin(center - Eigen::Vector3d::Constant(max_half));
    tree.size = max_half == 0.0 ? size_expand : 2.0 * max_half * (1.0 + size_expand);
    tree.nodes.assign(1, OctreeNode{});

    const bool colored = cloud.has_colors();
    for (size_t i = 0; i < cloud.points.size(); ++i) {
        const Eigen::Vector3d& p = cloud.points[i];
        if (!in_cube(p, tree.origin, tree.size)) continue;  // Open3D drops these too (size_expand = 0)
        OctreeNode& leaf = tree.nodes[leaf_path(tree, p)];
        leaf.indices.push_back(static_cast<int>(i));
        if (colored) leaf.color += cloud.colors[i];  // a sum until the pass below
    }
    for (OctreeNode& n : tree.nodes)
        if (n.is_leaf) n.color /= static_cast<double>(n.indices.size());
}

int locate_leaf(const Octree& tree, const Eigen::Vector3d& point, OctreeNodeInfo* info) {
    if (tree.nodes.empty() || !point.allFinite() || !in_cube(point, tree.origin, tree.size)) return -1;
    OctreeNodeInfo at{tree.origin, tree.size, 0, 0};
    int node = 0;
    while (!tree.nodes[node].is_leaf) {
        const int child = descend(point, at.origin, at.size);
        node = tree.nodes[node].children[child];
        if (node < 0) return -1;
        ++at.depth;
        at.child_index = child;
    }
    if (info) *info = at;
    return node;
}

size_t count_leaves(const Octree& tree) {
    size_t n = 0;
    for (const OctreeNode& node : tree.nodes) n += node.is_leaf ? 1 : 0;
    return n;
}

}  // namespace o3d::geometry
