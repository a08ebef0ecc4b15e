// SPDX-License-Identifier: MIT
#pragma once
/// @file reconstruction.h
/// @brief The scene reconstruction system of Choi, Zhou and Koltun, "Robust Reconstruction of Indoor Scenes"
/// (CVPR 2015), as Open3D's tutorial system runs it (examples/python/reconstruction_system): an RGB-D sequence
/// in, a scene mesh and a camera trajectory out, in five stages that each read the previous stages' files.
///
/// 1. make fragments: per run of n_frames_per_fragment frames, RGB-D odometry between neighbours and loop
///    closures between keyframes, a pose graph optimized with the line process, and the fragment's TSDF surface
///    as a coloured point cloud;
/// 2. register fragments: FPFH features with RANSAC (or FGR) between every pair of fragments, ICP from the
///    odometry between neighbouring ones, and a global pose graph optimized with the line process;
/// 3. refine registration: multi-scale ICP (coloured by default) on every kept edge, and the graph again;
/// 4. integrate scene: every frame into one scalable TSDF with its final pose; the mesh and a .log trajectory;
/// 5. colour map (optional): the rigid colour-map optimizer over the keyframes recolours the scene mesh.
///
/// Every stage resumes: work whose output file exists is not redone (per fragment in stage 1, per stage after).
/// Output files appear whole, through a rename. Results do not depend on the thread count.
#include <functional>

#include "o3d/reconstruction/config.h"

namespace o3d::reconstruction {

enum class Stage { MakeFragments = 0, RegisterFragments = 1, RefineRegistration = 2, IntegrateScene = 3, ColorMap = 4 };

/// @brief "make fragments", "register fragments", ... (for messages).
const char* stage_name(Stage stage);

struct StageOptions {
    bool resume = true;   ///< skip work whose outputs are on disk; false redoes it
    int num_threads = 0;  ///< 0 = library default
    /// Called on the calling thread with the fraction of the stage done; false cancels (o3d::Cancelled).
    std::function<bool(double)> progress;
};

/// @brief Threads for a stage's independent items (pairs, fragments): Open3D's python_multi_threading false runs
/// them one at a time.
inline int item_threads(const Config& config, const StageOptions& options) {
    return config.python_multi_threading ? options.num_threads : 1;
}

/// @brief Run one stage. @throws o3d::IoError / ParseError / InvalidArgument with the stage, and where it applies
/// the frame, fragment or pair, in the message (a missing input names the stage that writes it);
/// o3d::Cancelled when the progress callback asks to stop (finished outputs are kept).
void run_stage(Stage stage, const Config& config, const StageOptions& options = {});

void make_fragments(const Config& config, const StageOptions& options);
void register_fragments(const Config& config, const StageOptions& options);
void refine_registration(const Config& config, const StageOptions& options);
void integrate_scene(const Config& config, const StageOptions& options);
void color_map_scene(const Config& config, const StageOptions& options);

}  // namespace o3d::reconstruction
