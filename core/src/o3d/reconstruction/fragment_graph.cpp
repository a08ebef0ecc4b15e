// SPDX-License-Identifier: MIT
#include "o3d/reconstruction/fragment_graph.h"

#include "o3d/geometry/triangle_mesh_ops.h"
#include "o3d/io/pose_graph_io.h"
#include "o3d/reconstruction/stage_runner.h"
#include "o3d/registration/global_optimization.h"

namespace o3d::reconstruction {

void optimize_pose_graph(registration::PoseGraph& graph, double max_correspondence_distance,
                         double preference_loop_closure) {
    registration::GlobalOptimizationOptions options;
    options.method = registration::GlobalOptimizationMethod::LevenbergMarquardt;
    options.option.max_correspondence_distance = max_correspondence_distance;
    options.option.edge_prune_threshold = 0.25;
    options.option.preference_loop_closure = preference_loop_closure;
    options.option.reference_node = 0;
    registration::global_optimization(graph, options);
}

void write_optimized_scene_graph(registration::PoseGraph graph, const Config& config, const std::string& graph_path,
                                 const std::string& optimized_path) {
    with_context("scene pose graph", [&] {
        write_whole_file(graph_path, io::format_pose_graph_json(graph));
        optimize_pose_graph(graph, config.voxel_size * 1.4, config.preference_loop_closure_registration);
        write_whole_file(optimized_path, io::format_pose_graph_json(graph));
    });
}

registration::PoseGraph read_stage_pose_graph(const std::string& path, const char* writer) {
    if (!file_exists(path)) throw IoError(path + ": missing; run the \"" + std::string(writer) + "\" stage first");
    return io::read_pose_graph(path);
}

std::unique_ptr<integration::ScalableTSDFVolume> make_scene_volume(const Config& config) {
    return std::make_unique<integration::ScalableTSDFVolume>(config.tsdf_cubic_size / 512.0, 0.04,
                                                             integration::ColorType::RGB8);
}

geometry::TriangleMesh extract_mesh_with_normals(const integration::TSDFVolume& volume) {
    geometry::TriangleMesh mesh = volume.extract_triangle_mesh();
    geometry::compute_vertex_normals(mesh);
    return mesh;
}

}  // namespace o3d::reconstruction
