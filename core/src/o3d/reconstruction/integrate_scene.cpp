// SPDX-License-Identifier: MIT
// Stage 4 (Open3D's integrate_scene.py): every frame into one scalable TSDF at pose = fragment pose (refined
// scene graph) x frame pose (its fragment's graph); the mesh with vertex normals and the camera-to-world poses
// as a .log trajectory.
#include <Eigen/LU>  // Matrix4d::inverse
#include <vector>

#include "o3d/camera/trajectory_log_io.h"
#include "o3d/io/triangle_mesh_io.h"
#include "o3d/reconstruction/dataset.h"
#include "o3d/reconstruction/fragment_graph.h"
#include "o3d/reconstruction/reconstruction.h"
#include "o3d/reconstruction/stage_runner.h"

namespace o3d::reconstruction {
namespace {
constexpr const char* kStage = "integrate scene";
}  // namespace

void integrate_scene(const Config& config, const StageOptions& options) {
    const std::string mesh_path = config.output(config.template_global_mesh);
    const std::string trajectory_path = config.output(config.template_global_traj);
    if (options.resume && file_exists(mesh_path) && file_exists(trajectory_path)) return;
    const Dataset dataset = open_dataset(config);
    const registration::PoseGraph scene = read_stage_pose_graph(
        config.output(config.template_refined_posegraph_optimized), "refine registration");

    camera::PinholeCameraTrajectory trajectory;
    std::vector<int> frames;
    for (int id = 0; id < static_cast<int>(scene.nodes.size()); ++id) {
        const registration::PoseGraph fragment = read_stage_pose_graph(
            config.fragment_output(config.template_fragment_posegraph_optimized, id), "make fragments");
        for (size_t i = 0; i < fragment.nodes.size(); ++i) {
            const int frame = dataset.first_frame(id) + static_cast<int>(i);
            if (frame >= dataset.frame_count())
                throw InvalidArgument("fragment " + std::to_string(id) + " has more frames than the dataset: was it "
                                      "made with another n_frames_per_fragment?");
            camera::PinholeCameraParameters p;
            p.intrinsic = dataset.intrinsic;
            p.extrinsic = (scene.nodes[static_cast<size_t>(id)].pose * fragment.nodes[i].pose).inverse();
            trajectory.parameters.push_back(p);
            frames.push_back(frame);
        }
    }
    StageProgress progress(options.progress, frames.size() + 1);
    auto volume = make_scene_volume(config);
    for (size_t i = 0; i < frames.size(); ++i) {
        const geometry::RGBDImage rgbd = read_frame(config, dataset, frames[i], false);
        with_context("frame " + std::to_string(frames[i]),
                     [&] { volume->integrate(rgbd, dataset.intrinsic, trajectory.parameters[i].extrinsic); });
        progress.complete();
        if (!progress.report()) progress.throw_if_cancelled(kStage);
    }
    const geometry::TriangleMesh mesh = extract_mesh_with_normals(*volume);
    write_whole_file(mesh_path, io::write_triangle_mesh_to_memory(mesh, "ply"));
    write_whole_file(trajectory_path, camera::format_trajectory_log(trajectory));
    progress.complete();
    progress.report();
}

}  // namespace o3d::reconstruction
