// SPDX-License-Identifier: MIT
// Stage 3 (Open3D's refine_registration.py): multi-scale ICP (voxel, voxel/2, voxel/4; 50, 30, 14 iterations)
// on every edge the global optimization kept, from its transformation; the scene graph rebuilt and optimized.
#include <utility>
#include <vector>

#include "o3d/reconstruction/dataset.h"
#include "o3d/reconstruction/fragment_clouds.h"
#include "o3d/reconstruction/fragment_graph.h"
#include "o3d/reconstruction/pair_registration.h"
#include "o3d/reconstruction/reconstruction.h"
#include "o3d/reconstruction/stage_runner.h"

namespace o3d::reconstruction {
namespace {
constexpr const char* kStage = "refine registration";
}  // namespace

void refine_registration(const Config& config, const StageOptions& options) {
    const std::string graph_path = config.output(config.template_refined_posegraph);
    const std::string optimized_path = config.output(config.template_refined_posegraph_optimized);
    if (options.resume && file_exists(optimized_path)) return;
    const int threads = item_threads(config, options);
    const registration::PoseGraph global = read_stage_pose_graph(
        config.output(config.template_global_posegraph_optimized), "register fragments");
    const int n = static_cast<int>(global.nodes.size());
    StageProgress progress(options.progress, static_cast<size_t>(n) + global.edges.size() + 1);
    const std::vector<geometry::PointCloud> clouds = read_fragment_clouds(config, n, threads, progress, kStage);

    const double v = config.voxel_size;
    std::vector<PairResult> results(global.edges.size());
    parallel_for(results.size(), threads, progress, kStage, [&](size_t i) {
        const registration::PoseGraphEdge& e = global.edges[i];
        results[i] = with_context(
            "fragments " + std::to_string(e.source_node_id) + " -> " + std::to_string(e.target_node_id), [&] {
                return multiscale_icp(clouds[static_cast<size_t>(e.source_node_id)],
                                      clouds[static_cast<size_t>(e.target_node_id)], {v, v / 2.0, v / 4.0},
                                      {50, 30, 14}, config, e.transformation);
            });
    });

    registration::PoseGraph graph;
    Eigen::Matrix4d odometry = Eigen::Matrix4d::Identity();
    graph.nodes.push_back({odometry});
    for (size_t i = 0; i < results.size(); ++i)
        add_scene_pair(global.edges[i].source_node_id, global.edges[i].target_node_id, results[i], odometry, graph);
    if (graph.nodes.size() != global.nodes.size())  // a neighbour edge is certain, so never pruned
        throw InvalidArgument("the global graph lacks an edge between neighbouring fragments");
    write_optimized_scene_graph(std::move(graph), config, graph_path, optimized_path);
    progress.complete();
    progress.report();
}

}  // namespace o3d::reconstruction
