// SPDX-License-Identifier: MIT
// Stage 5 (optional; Open3D's system stops at stage 4 and its colour-map tutorial runs separately): the rigid
// colour-map optimizer recolours the scene mesh from the keyframes at the stage-4 poses. Keyframes only: the
// images stay in memory for the whole optimization, and neighbouring frames add little colour information.
#include <vector>

#include "o3d/camera/camera_io.h"
#include "o3d/color_map/color_map.h"
#include "o3d/io/triangle_mesh_io.h"
#include "o3d/reconstruction/dataset.h"
#include "o3d/reconstruction/reconstruction.h"
#include "o3d/reconstruction/stage_runner.h"

namespace o3d::reconstruction {

void color_map_scene(const Config& config, const StageOptions& options) {
    const std::string out_path = config.output(config.template_color_map_mesh);
    if (options.resume && file_exists(out_path)) return;
    const Dataset dataset = open_dataset(config);
    const std::string mesh_path = config.output(config.template_global_mesh);
    const std::string trajectory_path = config.output(config.template_global_traj);
    for (const std::string& p : {mesh_path, trajectory_path})
        if (!file_exists(p)) throw IoError(p + ": missing; run the \"integrate scene\" stage first");
    const geometry::TriangleMesh mesh = io::read_triangle_mesh(mesh_path);
    const camera::PinholeCameraTrajectory all = camera::read_pinhole_camera_trajectory(trajectory_path, "log");
    if (static_cast<int>(all.parameters.size()) > dataset.frame_count())
        throw InvalidArgument(trajectory_path + ": more poses than the dataset has frames");

    std::vector<geometry::RGBDImage> images;
    camera::PinholeCameraTrajectory keyframes;
    for (int frame = 0; frame < static_cast<int>(all.parameters.size()); frame += config.n_keyframes_per_n_frame) {
        images.push_back(read_frame(config, dataset, frame, false));
        keyframes.parameters.push_back(all.parameters[static_cast<size_t>(frame)]);
        keyframes.parameters.back().intrinsic = dataset.intrinsic;  // a .log holds poses only
    }
    color_map::RigidOptimizerOption option;
    option.maximum_iteration = config.color_map_maximum_iteration;
    option.maximum_allowable_depth = config.depth_max;
    option.num_threads = options.num_threads;
    option.progress = options.progress;
    const color_map::ColorMapResult result = color_map::run_rigid_optimizer(mesh, images, keyframes, option);
    write_whole_file(out_path, io::write_triangle_mesh_to_memory(result.mesh, "ply"));
    if (options.progress) options.progress(1.0);
}

}  // namespace o3d::reconstruction
