// SPDX-License-Identifier: MIT
#pragma once
/// @file fragment_graph.h
/// @brief Pieces of the reconstruction shared by several stages: the pose-graph optimization settings Open3D's
/// optimize_posegraph.py uses, reading a stage's input files, and the TSDF every stage integrates into.
#include <memory>
#include <string>

#include "o3d/geometry/triangle_mesh.h"
#include "o3d/integration/scalable_tsdf_volume.h"
#include "o3d/reconstruction/config.h"
#include "o3d/registration/pose_graph.h"

namespace o3d::reconstruction {

/// @brief Levenberg-Marquardt with the line process: edge_prune_threshold 0.25, reference node 0, and the
/// given line-process distance and loop-closure preference (optimize_posegraph.py).
void optimize_pose_graph(registration::PoseGraph& graph, double max_correspondence_distance,
                         double preference_loop_closure);

/// @brief The scene graph's two files, as Open3D's register and refine stages write them: the graph as built at
/// `graph_path`, then optimized (line-process distance 1.4 voxel_size, preference_loop_closure_registration) at
/// `optimized_path`, last, so that the stage counts as done only when both exist.
void write_optimized_scene_graph(registration::PoseGraph graph, const Config& config, const std::string& graph_path,
                                 const std::string& optimized_path);

/// @brief read_pose_graph, with a missing file reported as the output of `writer` (the stage to run first).
registration::PoseGraph read_stage_pose_graph(const std::string& path, const char* writer);

/// @brief The scalable TSDF of Open3D's system: voxel tsdf_cubic_size / 512, sdf_trunc 0.04, RGB8 colour.
std::unique_ptr<integration::ScalableTSDFVolume> make_scene_volume(const Config& config);

/// @brief extract_triangle_mesh with vertex normals, as the system writes its meshes and fragment clouds.
geometry::TriangleMesh extract_mesh_with_normals(const integration::TSDFVolume& volume);

}  // namespace o3d::reconstruction
