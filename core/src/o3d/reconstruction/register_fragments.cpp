// SPDX-License-Identifier: MIT
// Stage 2 (Open3D's register_fragments.py): every pair of fragment clouds, neighbours by ICP from the fragment's
// own odometry, others by FPFH global registration; one scene pose graph, optimized with the line process.
#include <Eigen/LU>  // Matrix4d::inverse
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
constexpr const char* kStage = "register fragments";
}  // namespace

void register_fragments(const Config& config, const StageOptions& options) {
    const std::string graph_path = config.output(config.template_global_posegraph);
    const std::string optimized_path = config.output(config.template_global_posegraph_optimized);
    if (options.resume && file_exists(optimized_path)) return;
    const int threads = item_threads(config, options);
    const int n = open_dataset(config).fragment_count();
    std::vector<std::pair<int, int>> pairs;
    for (int s = 0; s < n; ++s)
        for (int t = s + 1; t < n; ++t) pairs.emplace_back(s, t);
    StageProgress progress(options.progress, 2 * static_cast<size_t>(n) + pairs.size() + 1);

    const std::vector<geometry::PointCloud> clouds = read_fragment_clouds(config, n, threads, progress, kStage);
    std::vector<PreparedCloud> prepared(static_cast<size_t>(n));
    parallel_for(prepared.size(), threads, progress, kStage, [&](size_t i) {
        prepared[i] = with_context("fragment " + std::to_string(i) + ": features",
                                   [&] { return prepare_cloud(clouds[i], config.voxel_size); });
    });

    std::vector<PairResult> results(pairs.size());
    parallel_for(pairs.size(), threads, progress, kStage, [&](size_t i) {
        const auto [s, t] = pairs[i];
        results[i] = with_context("fragments " + std::to_string(s) + " -> " + std::to_string(t), [&] {
            if (t != s + 1)  // the seed makes each pair's RANSAC draw reproducible and independent of threads
                return register_by_features(prepared[s], prepared[t], config,
                                            (static_cast<uint64_t>(s) << 32) | static_cast<uint64_t>(t));
            // Neighbours: the last frame of fragment s is the first of t's predecessor chain, so the fragment's
            // own odometry says where t starts.
            const registration::PoseGraph fragment = read_stage_pose_graph(
                config.fragment_output(config.template_fragment_posegraph_optimized, s), "make fragments");
            return multiscale_icp(prepared[s].down, prepared[t].down, {config.voxel_size}, {50}, config,
                                  fragment.nodes.back().pose.inverse());
        });
    });

    registration::PoseGraph graph;
    Eigen::Matrix4d odometry = Eigen::Matrix4d::Identity();
    graph.nodes.push_back({odometry});
    for (size_t i = 0; i < pairs.size(); ++i)
        if (results[i].success) add_scene_pair(pairs[i].first, pairs[i].second, results[i], odometry, graph);
    write_optimized_scene_graph(std::move(graph), config, graph_path, optimized_path);
    progress.complete();
    progress.report();
}

}  // namespace o3d::reconstruction
