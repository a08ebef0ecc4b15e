// SPDX-License-Identifier: MIT
#pragma once
/// @file pose_graph.h
/// @brief Pose graphs for multiway registration (Open3D's PoseGraph, PoseGraphNode, PoseGraphEdge).
/// An edge (s, t, T) says that T maps points of node s's frame into node t's frame:
/// inverse(pose_t) * pose_s ~ T. The 6x6 information matrix orders rotation before translation,
/// as Open3D's get_information_matrix_from_point_clouds does.
#include <Eigen/Core>
#include <vector>

namespace o3d::registration {

using Matrix6d = Eigen::Matrix<double, 6, 6>;

/// @brief One frame of the graph: its pose in the world.
struct PoseGraphNode {
    Eigen::Matrix4d pose = Eigen::Matrix4d::Identity();
};

/// @brief A relative-pose measurement between two nodes.
struct PoseGraphEdge {
    int source_node_id = -1;  ///< Open3D's default; optimization rejects ids outside the node list
    int target_node_id = -1;
    Eigen::Matrix4d transformation = Eigen::Matrix4d::Identity();
    Matrix6d information = Matrix6d::Identity();
    /// A loop closure the line process may down-weight and prune; odometry edges are certain.
    bool uncertain = false;
    /// The line-process weight in [0, 1]; certain edges keep 1.
    double confidence = 1.0;
};

/// @brief Nodes and edges; edges refer to nodes by index.
struct PoseGraph {
    std::vector<PoseGraphNode> nodes;
    std::vector<PoseGraphEdge> edges;
};

}  // namespace o3d::registration
