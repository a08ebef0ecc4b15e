// SPDX-License-Identifier: MIT
// One RGB-D frame to a coloured point cloud through the C++ wrapper (o3dpp), as in Open3D's RGBD
// tutorial: read color + depth (depth in mm), pair them (depth truncated at 3 m, color kept as RGB),
// back-project with the PrimeSense default intrinsic, flip to a y-up view, write.
// Usage: rgbd_to_point_cloud <color image> <depth image> <output cloud>
#include <iostream>

#include "o3dpp/o3dpp.hpp"

int main(int argc, char** argv) {
    if (argc != 4) {
        std::cerr << "usage: " << argv[0] << " <color image> <depth image> <output cloud>\n";
        return 2;
    }
    try {
        const auto color = o3dpp::read_image(argv[1]);
        const auto depth = o3dpp::read_image(argv[2]);
        std::cout << "color " << color.width() << "x" << color.height() << "x" << color.num_channels() << ", depth "
                  << depth.width() << "x" << depth.height() << " (" << 8 * depth.bytes_per_channel() << "-bit)\n";

        o3dpp::RgbdOptions options;  // depth_scale 1000 (mm), depth_trunc 3 m
        options.convert_rgb_to_intensity = false;
        const auto rgbd = o3dpp::RgbdImage::create_from_color_and_depth(color, depth, options);

        const o3dpp::PinholeIntrinsic intrinsic(o3dpp::PinholeIntrinsic::Preset::PrimeSenseDefault);
        auto cloud = o3dpp::create_point_cloud_from_rgbd_image(rgbd, intrinsic);
        // The camera looks down +z with y down; flip so that the cloud is upright in a y-up viewer.
        cloud.transform({1, 0, 0, 0, 0, -1, 0, 0, 0, 0, -1, 0, 0, 0, 0, 1});

        o3dpp::write_point_cloud(argv[3], cloud);
        std::cout << "wrote " << cloud.size() << " colored points to " << argv[3] << "\n";
        return !cloud.empty() && cloud.has_colors() ? 0 : 1;
    } catch (const o3dpp::Error& e) {
        std::cerr << "rgbd_to_point_cloud: " << e.code_name() << ": " << e.what() << "\n";
        return 1;
    }
}
