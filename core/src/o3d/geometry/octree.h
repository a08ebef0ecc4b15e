// SPDX-License-Identifier: MIT
#pragma once
/// @file octree.h
/// @brief The octree container over a point cloud (Open3D's OctreePointColorLeafNode leaves).
#include <Eigen/Core>
#include <vector>

namespace o3d::geometry {

/// @brief A cube of edge `size` at `origin`, split to `max_depth`. Nodes are stored in one array: an
/// internal node lists its eight children (-1 for none); a leaf holds point indices and their mean color.
struct OctreeNode {
    int children[8] = {-1, -1, -1, -1, -1, -1, -1, -1};
    bool is_leaf = false;
    std::vector<int> indices;  ///< leaves only, ascending
    Eigen::Vector3d color = Eigen::Vector3d::Zero();
};

struct Octree {
    int max_depth = 0;
    Eigen::Vector3d origin = Eigen::Vector3d::Zero();
    double size = 0.0;
    std::vector<OctreeNode> nodes;  ///< nodes[0] is the root when not empty
};

}  // namespace o3d::geometry
