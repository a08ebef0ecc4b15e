// SPDX-License-Identifier: MIT
#pragma once
/// @file config.h
/// @brief The reconstruction system's JSON config, in the layout of Open3D's reconstruction-system config
/// (examples/python/reconstruction_system/config/*.json and initialize_config.py): the same keys with the same
/// defaults, so an Open3D config file runs unchanged. Keys this system does not use (the SLAC ones, "name",
/// "depth_map_type", ...) are accepted and ignored.
#include <string>
#include <string_view>

namespace o3d::reconstruction {

/// @brief Every setting the stages read. Paths are as given (relative ones are relative to the working
/// directory, as in Open3D).
struct Config {
    std::string path_dataset;       ///< folder with image/ (or rgb/ or color/) and depth/; required
    std::string path_intrinsic;     ///< an intrinsic JSON; "" = the PrimeSense default (640x480, f 525)
    /// o3d extra: where fragments/ and scene/ are written ("" = path_dataset, as Open3D), so a read-only
    /// dataset can be reconstructed.
    std::string path_output;
    double depth_scale = 1000.0;    ///< depth units per metre
    double depth_min = 0.3;         ///< metres (kept for Open3D's layout; its odometry does not use it)
    double depth_max = 3.0;         ///< metres: deeper pixels are dropped ("max_depth" is read as an alias)
    double voxel_size = 0.05;       ///< metres: fragment registration's down-sampling and ICP scale
    double depth_diff_max = 0.07;   ///< metres: odometry's depth_diff_max and the fragment graphs' line-process scale
    int n_frames_per_fragment = 100;
    int n_keyframes_per_n_frame = 5;  ///< every n-th frame is a keyframe (loop closures in a fragment)
    double preference_loop_closure_odometry = 0.1;
    double preference_loop_closure_registration = 5.0;
    double tsdf_cubic_size = 3.0;   ///< metres: TSDF voxels are tsdf_cubic_size / 512
    std::string icp_method = "color";             ///< point_to_point, point_to_plane, color or generalized
    std::string global_registration = "ransac";   ///< ransac or fgr
    bool python_multi_threading = true;           ///< false: fragments and pairs run one at a time
    /// o3d extra: loop closures between the keyframes of a fragment, odometry started from the chained poses
    /// (Open3D starts them from an OpenCV ORB estimate and skips them without OpenCV).
    bool loop_closure_odometry = true;
    /// o3d extra: iterations of the optional colour-map stage (rigid optimizer over the keyframes).
    int color_map_maximum_iteration = 100;

    // Output layout: printf templates (one %d field for fragment ids) below path_output, as Open3D's.
    std::string template_fragment_posegraph = "fragments/fragment_%03d.json";
    std::string template_fragment_posegraph_optimized = "fragments/fragment_optimized_%03d.json";
    std::string template_fragment_pointcloud = "fragments/fragment_%03d.ply";
    std::string template_global_posegraph = "scene/global_registration.json";
    std::string template_global_posegraph_optimized = "scene/global_registration_optimized.json";
    std::string template_refined_posegraph = "scene/refined_registration.json";
    std::string template_refined_posegraph_optimized = "scene/refined_registration_optimized.json";
    std::string template_global_mesh = "scene/integrated.ply";
    std::string template_global_traj = "scene/trajectory.log";
    std::string template_color_map_mesh = "scene/color_map_optimized.ply";  ///< o3d extra

    /// @brief path_output (or path_dataset) joined with `relative`.
    std::string output(const std::string& relative) const;
    /// @brief output() of a fragment template with `id` filled in.
    std::string fragment_output(const std::string& fragment_template, int id) const;
};

/// @brief Parse a config file. @throws o3d::IoError when it cannot be read; o3d::ParseError naming the file and
/// the key on malformed JSON, a value of the wrong type, or a value out of range (non-positive sizes, scales or
/// counts, an unknown icp_method or global_registration, a fragment template without exactly one %d field).
Config read_config(const std::string& path);
/// @brief read_config on text in memory; `name` prefixes error messages.
Config parse_config(std::string_view text, const std::string& name);

}  // namespace o3d::reconstruction
