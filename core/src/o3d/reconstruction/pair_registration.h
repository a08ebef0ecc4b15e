// SPDX-License-Identifier: MIT
#pragma once
/// @file pair_registration.h
/// @brief Registering two fragment clouds, as Open3D's register_fragments.py / refine_registration.py do:
/// FPFH + RANSAC (or FGR) with its two sanity tests, multi-scale ICP, and the scene graph's chained nodes.
#include <Eigen/Core>
#include <cstdint>
#include <vector>

#include "o3d/geometry/point_cloud.h"
#include "o3d/reconstruction/config.h"
#include "o3d/registration/feature.h"
#include "o3d/registration/pose_graph.h"

namespace o3d::reconstruction {

/// @brief A fragment cloud down-sampled at voxel_size, with normals (radius 2 voxels, 30 neighbours) and FPFH
/// features (radius 5 voxels, 100 neighbours): Open3D's preprocess_point_cloud.
struct PreparedCloud {
    geometry::PointCloud down;
    registration::Feature fpfh;
};
PreparedCloud prepare_cloud(const geometry::PointCloud& cloud, double voxel_size);

/// @brief A pair's relative pose (source to target) and its information matrix; success false when the pair
/// was rejected.
struct PairResult {
    bool success = false;
    Eigen::Matrix4d transformation = Eigen::Matrix4d::Identity();
    registration::Matrix6d information = registration::Matrix6d::Zero();
};

/// @brief Global registration on features (register_point_cloud_fpfh): RANSAC (point-to-point, 4 points per
/// hypothesis, edge-length 0.9 and distance checkers, 1e6 iterations at confidence 0.999, no mutual filter) or
/// FGR, both with distance 1.4 voxel_size. Rejected when the result is the identity or when fewer than 30% of
/// the smaller cloud's points correspond. `seed` makes RANSAC's draw reproducible.
PairResult register_by_features(const PreparedCloud& source, const PreparedCloud& target, const Config& config,
                                uint64_t seed);

/// @brief Open3D's multiscale_icp: at each scale, down-sample both clouds at voxel_sizes[k] and run
/// `max_iterations[k]` iterations of config.icp_method from the previous scale's result; the information matrix
/// comes from the last scale (distance 1.4 voxel_sizes.back()). Always succeeds.
PairResult multiscale_icp(const geometry::PointCloud& source, const geometry::PointCloud& target,
                          const std::vector<double>& voxel_sizes, const std::vector<int>& max_iterations,
                          const Config& config, const Eigen::Matrix4d& init);

/// @brief Add a pair to the scene graph as Open3D's update_posegraph_for_scene: a neighbouring pair (t = s + 1)
/// chains `odometry` and adds node t with its inverse, plus a certain edge; any other pair is an uncertain edge.
void add_scene_pair(int s, int t, const PairResult& pair, Eigen::Matrix4d& odometry, registration::PoseGraph& graph);

}  // namespace o3d::reconstruction
