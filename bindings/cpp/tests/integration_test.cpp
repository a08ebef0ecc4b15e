// SPDX-License-Identifier: MIT
// TSDF volumes through the wrapper: a fronto-parallel plane comes back at its depth (exact projective distances),
// Open3D's tutorial frames against Open3D 0.20's uniform volume (tools/reference/record_tsdf.py: 147927 vertices,
// 280605 triangles; its scalable volume is empty there), and the errors.
#include <vector>

#include "test_util.hpp"

using o3dpp::PinholeIntrinsic;
using o3dpp::RgbdImage;
using o3dpp::TSDFVolume;
using o3dpp::TSDFVolumeColorType;

namespace {
constexpr int W = 160, H = 120;
const PinholeIntrinsic kSmall(W, H, 100.0, 100.0, 79.5, 59.5);

RgbdImage plane_frame(bool rgb) {
    std::vector<uint8_t> color;
    for (int i = 0; i < W * H; ++i) color.insert(color.end(), {200, 100, 50});
    o3dpp::RgbdOptions o;
    o.depth_scale = 1.0;
    o.convert_rgb_to_intensity = !rgb;
    return RgbdImage::create_from_color_and_depth(o3dpp::Image::from_values<uint8_t>(W, H, color, 3),
                                                  o3dpp::Image::from_values<float>(W, H, std::vector<float>(W * H, 1.0f)), o);
}
}  // namespace

TEST(TSDFVolume, PlaneComesBackAtItsDepth) {
    TSDFVolume volume = TSDFVolume::uniform(1.0, 64, 0.04, TSDFVolumeColorType::RGB8, {-0.5, -0.5, 0.5});
    volume.integrate(plane_frame(true), kSmall, o3dpp::identity4());
    const o3dpp::TriangleMesh mesh = volume.extract_triangle_mesh();
    ASSERT_EQ(mesh.num_vertices(), 64u * 64u);
    EXPECT_EQ(mesh.num_triangles(), 2u * 63u * 63u);
    for (const auto& v : mesh.get_vertices()) ASSERT_NEAR(v[2], 1.0, 1e-4);
    const auto tsdf = volume.extract_volume_tsdf();
    ASSERT_EQ(tsdf.size(), 64u * 64u * 64u);
    EXPECT_NEAR(tsdf[(32 * 64 + 32) * 64 + 30][0], (1.0 - (0.5 + 30.5 / 64)) / 0.04, 1e-4);
    EXPECT_EQ(tsdf[(32 * 64 + 32) * 64 + 30][1], 1.0f);
    EXPECT_EQ(volume.color_type(), TSDFVolumeColorType::RGB8);
    EXPECT_EQ(volume.resolution(), 64);
    EXPECT_FALSE(volume.is_scalable());
    EXPECT_EQ(volume.extract_point_cloud().size(), 64u * 64u);
    volume.reset();
    EXPECT_EQ(volume.extract_triangle_mesh().num_vertices(), 0u);
}

TEST(TSDFVolume, Open3dTutorialFrames) {
    O3DPP_DATA_OR_SKIP(log, "open3d/RGBD/trajectory.log");
    const o3dpp::CameraTrajectory poses = o3dpp::read_pinhole_camera_trajectory(log);
    TSDFVolume volume = TSDFVolume::scalable(4.0 / 512, 0.04, TSDFVolumeColorType::RGB8);
    o3dpp::RgbdOptions o;
    o.depth_trunc = 4.0;
    o.convert_rgb_to_intensity = false;
    for (std::size_t i = 0; i < poses.size(); ++i) {
        const std::string n = "0000" + std::to_string(i);
        O3DPP_DATA_OR_SKIP(color, "open3d/RGBD/color/" + n + ".jpg");
        O3DPP_DATA_OR_SKIP(depth, "open3d/RGBD/depth/" + n + ".png");
        const auto camera = poses.at(i);
        volume.integrate(RgbdImage::create_from_color_and_depth(o3dpp::read_image(color), o3dpp::read_image(depth), o),
                         camera.intrinsic, camera.extrinsic);
    }
    const o3dpp::TriangleMesh mesh = volume.extract_triangle_mesh();
    EXPECT_NEAR(double(mesh.num_vertices()), 147927.0, 0.002 * 147927);
    EXPECT_NEAR(double(mesh.num_triangles()), 280605.0, 0.002 * 280605);
}

TEST(TSDFVolume, Errors) {
    EXPECT_O3D_ERROR(TSDFVolume::scalable(0.0, 0.04, TSDFVolumeColorType::NoColor), O3D_ERROR_INVALID_ARGUMENT);
    TSDFVolume volume = TSDFVolume::scalable(0.01, 0.04, TSDFVolumeColorType::RGB8);
    EXPECT_O3D_ERROR(volume.integrate(plane_frame(false), kSmall, o3dpp::identity4()), O3D_ERROR_INVALID_ARGUMENT);
    EXPECT_O3D_ERROR(volume.extract_volume_tsdf(), O3D_ERROR_INVALID_ARGUMENT);  // uniform volumes only
    EXPECT_EQ(volume.block_count(), 0u);
}
