// SPDX-License-Identifier: MIT
// Cameras, RGB-D images and depth back-projection through the wrapper, against the pinhole model.
#include <cmath>
#include <cstdio>
#include <fstream>

#include "test_util.hpp"

using o3dpp::Image;
using o3dpp::PinholeIntrinsic;
using o3dpp::Vec3;

namespace {
constexpr int W = 4, H = 3;
const PinholeIntrinsic K(W, H, 2.0, 4.0, 1.5, 1.0);

uint16_t depth_mm(int u, int v) { return (u == 1 && v == 1) ? 0 : static_cast<uint16_t>(1000 + 250 * (u + v)); }

Image depth_image() {
    std::vector<uint16_t> d;
    for (int v = 0; v < H; ++v)
        for (int u = 0; u < W; ++u) d.push_back(depth_mm(u, v));
    return Image::from_values<uint16_t>(W, H, d);
}

/// ((u - cx) z / fx, (v - cy) z / fy, z) for valid pixels, rows then columns. As in Open3D 0.20, a
/// depth equal to `trunc` is dropped too.
std::vector<Vec3> expected_points(int stride = 1, double trunc = 1e9) {
    std::vector<Vec3> out;
    for (int v = 0; v < H; v += stride)
        for (int u = 0; u < W; u += stride) {
            const double z = depth_mm(u, v) / 1000.0;
            if (z > 0 && z < trunc) out.push_back({(u - K.cx) * z / K.fx, (v - K.cy) * z / K.fy, z});
        }
    return out;
}

void expect_close(const std::vector<Vec3>& a, const std::vector<Vec3>& b, double tol) {
    ASSERT_EQ(a.size(), b.size());
    for (std::size_t i = 0; i < a.size(); ++i)
        for (int k = 0; k < 3; ++k) EXPECT_NEAR(a[i][k], b[i][k], tol) << "point " << i;
}

o3dpp::Mat4 translation(double x, double y, double z) {
    auto m = o3dpp::identity4();
    m[3] = x;
    m[7] = y;
    m[11] = z;
    return m;
}
}  // namespace

TEST(Camera, PresetsMatchOpen3D) {
    EXPECT_EQ(PinholeIntrinsic(PinholeIntrinsic::Preset::PrimeSenseDefault),
              PinholeIntrinsic(640, 480, 525, 525, 319.5, 239.5));
    EXPECT_EQ(PinholeIntrinsic(PinholeIntrinsic::Preset::Kinect2DepthDefault),
              PinholeIntrinsic(512, 424, 365.456, 365.456, 254.878, 205.395));
    EXPECT_EQ(PinholeIntrinsic(PinholeIntrinsic::Preset::Kinect2ColorDefault),
              PinholeIntrinsic(1920, 1080, 1059.9718, 1059.9718, 975.7193, 545.9533));
    EXPECT_EQ(K.intrinsic_matrix(), (o3dpp::Mat3{2, 0, 1.5, 0, 4, 1, 0, 0, 1}));
}

TEST(Camera, TrajectoryAndFiles) {
    o3dpp::CameraTrajectory traj;
    EXPECT_TRUE(traj.empty());
    traj.push_back(K, translation(1, 0, 0));
    traj.push_back({K, translation(0, -2, 0)});
    EXPECT_EQ(traj.size(), 2u);
    EXPECT_EQ(traj.at(1).extrinsic, translation(0, -2, 0));
    EXPECT_O3D_ERROR(traj.at(2), O3D_ERROR_INVALID_ARGUMENT);
    auto bad = translation(0, 0, 0);
    bad[12] = 1;
    EXPECT_O3D_ERROR(traj.push_back(K, bad), O3D_ERROR_INVALID_ARGUMENT);

    const std::string kpath = o3dpp_test::tmp_path("rgbd_test_k.json");
    o3dpp::write_pinhole_camera_intrinsic(kpath, K);
    EXPECT_EQ(o3dpp::read_pinhole_camera_intrinsic(kpath), K);
    const std::string ppath = o3dpp_test::tmp_path("rgbd_test_p.json");
    o3dpp::write_pinhole_camera_parameters(ppath, {K, translation(0.25, 0, 0)});
    const auto p = o3dpp::read_pinhole_camera_parameters(ppath);
    EXPECT_EQ(p.intrinsic, K);
    EXPECT_EQ(p.extrinsic, translation(0.25, 0, 0));
    const std::string tpath = o3dpp_test::tmp_path("rgbd_test_t.json");
    o3dpp::write_pinhole_camera_trajectory(tpath, traj);
    const auto back = o3dpp::read_pinhole_camera_trajectory(tpath);
    ASSERT_EQ(back.size(), 2u);
    EXPECT_EQ(back.at(0).intrinsic, K);
    EXPECT_EQ(back.at(1).extrinsic, translation(0, -2, 0));
    const std::string lpath = o3dpp_test::tmp_path("rgbd_test_t.log");
    o3dpp::write_pinhole_camera_trajectory(lpath, traj, "log");
    const auto log = o3dpp::read_pinhole_camera_trajectory(lpath);
    ASSERT_EQ(log.size(), 2u);
    for (int i = 0; i < 16; ++i) EXPECT_NEAR(log.at(0).extrinsic[i], translation(1, 0, 0)[i], 1e-9);
    EXPECT_EQ(log.at(0).intrinsic.width, 640);
    traj.clear();
    EXPECT_EQ(traj.size(), 0u);

    std::ofstream(o3dpp_test::tmp_path("rgbd_test_broken.json")) << "{ not json";
    EXPECT_THROW(o3dpp::read_pinhole_camera_intrinsic(o3dpp_test::tmp_path("rgbd_test_broken.json")), o3dpp::Error);
    for (const auto& f : {kpath, ppath, tpath, lpath, o3dpp_test::tmp_path("rgbd_test_broken.json")})
        std::remove(f.c_str());
}

TEST(Rgbd, DepthBackProjectionMatchesThePinholeModel) {
    const auto depth = depth_image();
    expect_close(o3dpp::create_point_cloud_from_depth_image(depth, K).get_points(), expected_points(), 1e-12);

    std::vector<float> metres;
    for (int v = 0; v < H; ++v)
        for (int u = 0; u < W; ++u) metres.push_back(depth_mm(u, v) / 1000.0f);
    expect_close(o3dpp::create_point_cloud_from_depth_image(Image::from_values<float>(W, H, metres), K).get_points(),
                 expected_points(), 1e-6);

    o3dpp::DepthToCloudOptions opts;
    opts.stride = 2;
    opts.depth_trunc = 1.5;
    expect_close(o3dpp::create_point_cloud_from_depth_image(depth, K, o3dpp::identity4(), opts).get_points(),
                 expected_points(2, 1.5), 1e-12);

    auto shifted = expected_points();
    for (auto& p : shifted) p = {p[0] - 1, p[1] - 2, p[2] - 3};
    expect_close(o3dpp::create_point_cloud_from_depth_image(depth, K, translation(1, 2, 3)).get_points(), shifted,
                 1e-12);

    o3dpp::DepthToCloudOptions organised;
    organised.project_valid_depth_only = false;
    const auto all = o3dpp::create_point_cloud_from_depth_image(depth, K, o3dpp::identity4(), organised);
    ASSERT_EQ(all.size(), static_cast<std::size_t>(W * H));
    EXPECT_TRUE(std::isnan(all.points()[W + 1][0]));
}

TEST(Rgbd, ColorsAndIntensity) {
    std::vector<uint8_t> rgb;
    for (int i = 0; i < W * H; ++i) {
        rgb.push_back(static_cast<uint8_t>(10 * i));
        rgb.push_back(100);
        rgb.push_back(200);
    }
    const auto color = Image::from_values<uint8_t>(W, H, rgb, 3);
    o3dpp::RgbdOptions opts;
    opts.convert_rgb_to_intensity = false;
    opts.depth_trunc = 10.0;
    const auto rgbd = o3dpp::RgbdImage::create_from_color_and_depth(color, depth_image(), opts);
    EXPECT_EQ(rgbd.color().to_bytes(), rgb);
    EXPECT_EQ(rgbd.depth().to_values<float>()[0], 1.0f);
    const auto pcd = o3dpp::create_point_cloud_from_rgbd_image(rgbd, K);
    expect_close(pcd.get_points(), expected_points(), 1e-6);
    std::vector<Vec3> colors;
    for (int i = 0; i < W * H; ++i)
        if (depth_mm(i % W, i / W) > 0) colors.push_back({10.0 * i / 255.0, 100.0 / 255.0, 200.0 / 255.0});
    expect_close(pcd.get_colors(), colors, 1e-6);

    const auto gray = o3dpp::RgbdImage::create_from_color_and_depth(color, depth_image());
    EXPECT_EQ(gray.color().num_channels(), 1);
    EXPECT_EQ(gray.color().bytes_per_channel(), 4);
    for (const auto& c : o3dpp::create_point_cloud_from_rgbd_image(gray, K).get_colors()) {
        EXPECT_EQ(c[0], c[1]);
        EXPECT_EQ(c[1], c[2]);
    }
    const auto tum = o3dpp::RgbdImage::create_from_dataset_format(o3dpp::RgbdFormat::Tum, color, depth_image(), false);
    EXPECT_NEAR(tum.depth().to_values<float>()[0], 0.2f, 1e-6);
}

TEST(Rgbd, BadInputThrows) {
    EXPECT_O3D_ERROR(o3dpp::RgbdImage::create_from_color_and_depth(Image(2, 2, 3, 1), depth_image()),
                     O3D_ERROR_INVALID_ARGUMENT);
    PinholeIntrinsic bad = K;
    bad.fx = 0;
    EXPECT_THROW(o3dpp::create_point_cloud_from_depth_image(depth_image(), bad), o3dpp::Error);
    o3dpp::DepthToCloudOptions zero_stride;
    zero_stride.stride = 0;
    EXPECT_THROW(o3dpp::create_point_cloud_from_depth_image(depth_image(), K, o3dpp::identity4(), zero_stride),
                 o3dpp::Error);
}

TEST(Rgbd, SharedFrameToCloud) {
    O3DPP_DATA_OR_SKIP(color_path, "open3d/RGBD/color/00000.jpg");
    O3DPP_DATA_OR_SKIP(depth_path, "open3d/RGBD/depth/00000.png");
    o3dpp::RgbdOptions opts;
    opts.convert_rgb_to_intensity = false;
    const auto rgbd = o3dpp::RgbdImage::create_from_color_and_depth(o3dpp::read_image(color_path),
                                                                    o3dpp::read_image(depth_path), opts);
    const auto pcd = o3dpp::create_point_cloud_from_rgbd_image(
        rgbd, PinholeIntrinsic(PinholeIntrinsic::Preset::PrimeSenseDefault));
    EXPECT_EQ(pcd.size(), 267129u);  // Open3D 0.20: tools/reference/record_rgbd.py, "rgbd_rgb"
    EXPECT_TRUE(pcd.has_colors());
    for (const auto& p : pcd.get_points()) {
        EXPECT_GT(p[2], 0.0);
        EXPECT_LE(p[2], 3.0);
    }
}
