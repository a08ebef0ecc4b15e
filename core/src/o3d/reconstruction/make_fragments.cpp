// SPDX-License-Identifier: MIT
// Stage 1 (Open3D's make_fragments.py). The work is split into phases over all unfinished fragments at once,
// so that the cores stay busy even when there are fewer fragments than cores: neighbour odometry (independent
// pairs), loop closures (started from the chained poses, so after it), one graph optimization per fragment,
// then the fragment TSDFs one at a time (each integrates in parallel itself).
#include <Eigen/LU>  // Matrix4d::inverse
#include <vector>

#include "o3d/io/pose_graph_io.h"
#include "o3d/io/point_cloud_io.h"
#include "o3d/odometry/odometry.h"
#include "o3d/reconstruction/dataset.h"
#include "o3d/reconstruction/fragment_graph.h"
#include "o3d/reconstruction/reconstruction.h"
#include "o3d/reconstruction/stage_runner.h"

namespace o3d::reconstruction {
namespace {

constexpr const char* kStage = "make fragments";

struct FramePair {
    size_t slot;         ///< the fragment's index in the stage's work list
    int source, target;  ///< absolute frame numbers
};

struct FragmentWork {
    int id;
    registration::PoseGraph graph;
};

odometry::OdometryResult rgbd_odometry(const Config& config, const Dataset& dataset, int fragment,
                                       const FramePair& pair, const Eigen::Matrix4d& init) {
    return with_context("fragment " + std::to_string(fragment) + ": odometry " + std::to_string(pair.source) +
                            " -> " + std::to_string(pair.target),
                        [&] {
                            const geometry::RGBDImage source = read_frame(config, dataset, pair.source, true);
                            const geometry::RGBDImage target = read_frame(config, dataset, pair.target, true);
                            odometry::OdometryOption option;
                            option.depth_diff_max = config.depth_diff_max;
                            return odometry::compute_rgbd_odometry(source, target, dataset.intrinsic, init,
                                                                   odometry::Jacobian::HybridTerm, option);
                        });
}

registration::PoseGraphEdge edge_of(const FramePair& pair, int first_frame, const odometry::OdometryResult& r,
                                    bool uncertain) {
    registration::PoseGraphEdge edge;
    edge.source_node_id = pair.source - first_frame;
    edge.target_node_id = pair.target - first_frame;
    edge.transformation = r.transformation;
    edge.information = r.information;
    edge.uncertain = uncertain;
    return edge;
}

bool fragment_done(const Config& config, int id) {
    return file_exists(config.fragment_output(config.template_fragment_posegraph_optimized, id)) &&
           file_exists(config.fragment_output(config.template_fragment_pointcloud, id));
}

}  // namespace

void make_fragments(const Config& config, const StageOptions& options) {
    const Dataset dataset = open_dataset(config);
    const int threads = item_threads(config, options);
    std::vector<FragmentWork> work;
    for (int id = 0; id < dataset.fragment_count(); ++id)
        if (!options.resume || !fragment_done(config, id)) work.push_back({id, {}});

    std::vector<FramePair> neighbours, loops;
    for (size_t slot = 0; slot < work.size(); ++slot) {
        const int first = dataset.first_frame(work[slot].id), end = dataset.end_frame(work[slot].id);
        for (int s = first; s + 1 < end; ++s) neighbours.push_back({slot, s, s + 1});
        const int k = config.n_keyframes_per_n_frame;
        if (config.loop_closure_odometry)
            for (int s = first; s < end; ++s)
                for (int t = s + 2; t < end; ++t)
                    if (s % k == 0 && t % k == 0) loops.push_back({slot, s, t});
    }
    size_t frames = 0;
    for (const FragmentWork& f : work) frames += static_cast<size_t>(dataset.end_frame(f.id) - dataset.first_frame(f.id));
    // Units: each odometry pair, each graph optimization, each frame integrated, each fragment written.
    StageProgress progress(options.progress, neighbours.size() + loops.size() + 2 * work.size() + frames);

    // Neighbour odometry from the identity, as Open3D; its edges are kept even when odometry reports failure.
    std::vector<odometry::OdometryResult> steps(neighbours.size());
    parallel_for(neighbours.size(), threads, progress, kStage, [&](size_t i) {
        const FramePair& p = neighbours[i];
        steps[i] = rgbd_odometry(config, dataset, work[p.slot].id, p, Eigen::Matrix4d::Identity());
    });
    size_t next_step = 0;
    for (FragmentWork& f : work) {
        const int first = dataset.first_frame(f.id), end = dataset.end_frame(f.id);
        Eigen::Matrix4d chained = Eigen::Matrix4d::Identity();  // fragment frame -> current camera
        f.graph.nodes.push_back({chained});
        for (int s = first; s + 1 < end; ++s, ++next_step) {
            chained = steps[next_step].transformation * chained;
            f.graph.nodes.push_back({chained.inverse()});
            f.graph.edges.push_back(edge_of(neighbours[next_step], first, steps[next_step], false));
        }
    }

    // Loop closures between keyframes, from the relative pose the chain predicts.
    std::vector<odometry::OdometryResult> closures(loops.size());
    parallel_for(loops.size(), threads, progress, kStage, [&](size_t i) {
        const FramePair& p = loops[i];
        const FragmentWork& f = work[p.slot];
        const registration::PoseGraph& g = f.graph;
        const int first = dataset.first_frame(f.id);
        const Eigen::Matrix4d predicted = g.nodes[static_cast<size_t>(p.target - first)].pose.inverse() *
                                          g.nodes[static_cast<size_t>(p.source - first)].pose;
        closures[i] = rgbd_odometry(config, dataset, f.id, p, predicted);
    });
    for (size_t i = 0; i < loops.size(); ++i)
        if (closures[i].success) {
            FragmentWork& f = work[loops[i].slot];
            f.graph.edges.push_back(edge_of(loops[i], dataset.first_frame(f.id), closures[i], true));
        }

    parallel_for(work.size(), threads, progress, kStage, [&](size_t i) {
        FragmentWork& f = work[i];
        with_context("fragment " + std::to_string(f.id) + ": pose graph", [&] {
            write_whole_file(config.fragment_output(config.template_fragment_posegraph, f.id),
                             io::format_pose_graph_json(f.graph));
            optimize_pose_graph(f.graph, config.depth_diff_max, config.preference_loop_closure_odometry);
        });
    });

    // The fragment clouds: TSDF surface vertices with their colours. The optimized graph is written last,
    // after the cloud, so that a fragment counts as done only when both exist.
    for (FragmentWork& f : work) {
        auto volume = make_scene_volume(config);
        for (int frame = dataset.first_frame(f.id); frame < dataset.end_frame(f.id); ++frame) {
            with_context("fragment " + std::to_string(f.id) + ": integrate", [&] {
                const geometry::RGBDImage rgbd = read_frame(config, dataset, frame, false);
                const Eigen::Matrix4d& pose = f.graph.nodes[static_cast<size_t>(frame - dataset.first_frame(f.id))].pose;
                volume->integrate(rgbd, dataset.intrinsic, pose.inverse());
            });
            progress.complete();
            if (!progress.report()) progress.throw_if_cancelled(kStage);
        }
        const geometry::TriangleMesh mesh = volume->extract_triangle_mesh();
        geometry::PointCloud cloud;  // points and colours, as Open3D: registration estimates its own normals
        cloud.points = mesh.vertices;
        cloud.colors = mesh.vertex_colors;
        with_context("fragment " + std::to_string(f.id), [&] {
            write_whole_file(config.fragment_output(config.template_fragment_pointcloud, f.id),
                             io::write_point_cloud_to_memory(cloud, "ply"));
            write_whole_file(config.fragment_output(config.template_fragment_posegraph_optimized, f.id),
                             io::format_pose_graph_json(f.graph));
        });
        progress.complete();
        if (!progress.report()) progress.throw_if_cancelled(kStage);
    }
}

}  // namespace o3d::reconstruction
