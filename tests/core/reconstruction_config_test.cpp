// SPDX-License-Identifier: MIT
// The reconstruction system's config: Open3D's tutorial config (examples/python/reconstruction_system/config/
// tutorial.json) parses with initialize_config.py's defaults for the keys it leaves out; output templates are filled
// as Python's % operator fills them; bad values name their key.
#include <gtest/gtest.h>

#include <string>

#include "o3d/reconstruction/config.h"
#include "o3d/utility/error.h"

namespace rec = o3d::reconstruction;

TEST(ReconstructionConfig, OpenTutorialConfigGetsOpen3dDefaults) {
    const rec::Config c = rec::parse_config(R"({
        "name": "Open3D reconstruction tutorial",
        "path_dataset": "dataset/tutorial/", "path_intrinsic": "", "depth_max": 3.0, "voxel_size": 0.05,
        "depth_diff_max": 0.07, "preference_loop_closure_odometry": 0.1, "preference_loop_closure_registration": 5.0,
        "tsdf_cubic_size": 3.0, "icp_method": "color", "global_registration": "ransac",
        "python_multi_threading": true})",
                                            "tutorial.json");
    EXPECT_EQ(c.path_dataset, "dataset/tutorial/");
    EXPECT_EQ(c.n_frames_per_fragment, 100);  // initialize_config.py
    EXPECT_EQ(c.n_keyframes_per_n_frame, 5);
    EXPECT_DOUBLE_EQ(c.depth_scale, 1000.0);
    EXPECT_DOUBLE_EQ(c.depth_min, 0.3);
    EXPECT_EQ(c.template_fragment_posegraph_optimized, "fragments/fragment_optimized_%03d.json");
    EXPECT_EQ(c.output(c.template_global_traj), "dataset/tutorial/scene/trajectory.log");
    EXPECT_EQ(c.fragment_output(c.template_fragment_pointcloud, 7), "dataset/tutorial/fragments/fragment_007.ply");
}

TEST(ReconstructionConfig, TemplatesAndAliases) {
    const rec::Config c = rec::parse_config(
        R"({"path_dataset": "d", "path_output": "out", "max_depth": 2.5,
            "template_fragment_pointcloud": "f/%d.ply", "template_fragment_posegraph": "f/%4d.json"})",
        "c");
    EXPECT_DOUBLE_EQ(c.depth_max, 2.5);  // the issue's spelling of Open3D's depth_max
    EXPECT_EQ(c.fragment_output(c.template_fragment_pointcloud, 12), "out/f/12.ply");
    EXPECT_EQ(c.fragment_output(c.template_fragment_posegraph, 12), "out/f/  12.json");  // Python's "%4d" % 12
    EXPECT_EQ(c.fragment_output(c.template_fragment_posegraph_optimized, 1234), "out/fragments/fragment_optimized_1234.json");
}

TEST(ReconstructionConfig, BadValuesNameTheirKey) {
    const auto message = [](const std::string& json) {
        try {
            rec::parse_config(json, "bad.json");
        } catch (const o3d::ParseError& e) {
            return std::string(e.what());
        }
        return std::string("no error");
    };
    EXPECT_NE(message(R"({"path_dataset": "d", "voxel_size": 0})").find("bad.json: \"voxel_size\""), std::string::npos);
    EXPECT_NE(message(R"({"path_dataset": "d", "n_keyframes_per_n_frame": 2.5})").find("n_keyframes_per_n_frame"),
              std::string::npos);
    EXPECT_NE(message(R"({"path_dataset": "d", "python_multi_threading": 1})").find("expected true or false"),
              std::string::npos);
    EXPECT_NE(message(R"({"path_dataset": "d", "template_global_mesh": "scene/%d.ply"})").find("must not contain"),
              std::string::npos);
    EXPECT_NE(message(R"({"path_dataset": "d", "template_fragment_pointcloud": "%d_%d.ply"})").find("exactly one"),
              std::string::npos);
    EXPECT_NE(message(R"({"path_dataset": "d", "template_fragment_pointcloud": "%s.ply"})").find("exactly one"),
              std::string::npos);
    EXPECT_NE(message(R"({"path_dataset": ""})").find("required"), std::string::npos);
    EXPECT_EQ(message(R"({"path_dataset": "d", "slac_folder": "slac/", "depth_map_type": "redwood"})"), "no error");
}
