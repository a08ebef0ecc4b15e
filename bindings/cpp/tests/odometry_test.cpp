// SPDX-License-Identifier: MIT
// compute_rgbd_odometry through the wrapper: a frame onto itself, Open3D's result on its RGBD frames 0 -> 1
// (open3d 0.20, hybrid term, default options, PrimeSense intrinsics) and the errors.
#include <cmath>
#include <vector>

#include "test_util.hpp"

using o3dpp::Image;
using o3dpp::OdometryJacobian;
using o3dpp::OdometryOption;
using o3dpp::PinholeIntrinsic;
using o3dpp::RgbdImage;

namespace {
constexpr int W = 160, H = 120;
const PinholeIntrinsic kSmall(W, H, 130.0, 130.0, 79.5, 59.5);

/// A textured float intensity on a slanted plane of float depth (metres).
RgbdImage synthetic_frame() {
    std::vector<float> color, depth;
    for (int v = 0; v < H; ++v)
        for (int u = 0; u < W; ++u) {
            color.push_back(static_cast<float>(0.5 + 0.2 * std::sin(0.3 * u) * std::cos(0.25 * v) +
                                               0.1 * std::sin(0.11 * (u + v))));
            depth.push_back(static_cast<float>(1.5 + 0.004 * u + 0.002 * v));
        }
    o3dpp::RgbdOptions o;
    o.depth_scale = 1.0;  // already metres
    return RgbdImage::create_from_color_and_depth(Image::from_values<float>(W, H, color),
                                                  Image::from_values<float>(W, H, depth), o);
}

RgbdImage open3d_frame(const std::string& color_path, const std::string& depth_path) {
    return RgbdImage::create_from_color_and_depth(o3dpp::read_image(color_path), o3dpp::read_image(depth_path));
}
}  // namespace

TEST(Odometry, AFrameOntoItselfIsTheIdentity) {
    const RgbdImage frame = synthetic_frame();
    for (OdometryJacobian j : {OdometryJacobian::ColorTerm, OdometryJacobian::HybridTerm}) {
        const auto r = o3dpp::compute_rgbd_odometry(frame, frame, kSmall, o3dpp::identity4(), j);
        EXPECT_TRUE(r.success);
        for (int i = 0; i < 16; ++i) EXPECT_NEAR(r.transformation[i], (i % 5 == 0) ? 1.0 : 0.0, 1e-12) << i;
        // Every pixel but the border the smoothing and the pyramid eat corresponds.
        EXPECT_GT(r.information[3 * 6 + 3], 0.9 * W * H);
    }
}

TEST(Odometry, Open3dFramesZeroToOne) {
    O3DPP_DATA_OR_SKIP(c0, "open3d/RGBD/color/00000.jpg");
    O3DPP_DATA_OR_SKIP(d0, "open3d/RGBD/depth/00000.png");
    O3DPP_DATA_OR_SKIP(c1, "open3d/RGBD/color/00001.jpg");
    O3DPP_DATA_OR_SKIP(d1, "open3d/RGBD/depth/00001.png");
    const RgbdImage source = open3d_frame(c0, d0), target = open3d_frame(c1, d1);
    const PinholeIntrinsic primesense(640, 480, 525.0, 525.0, 319.5, 239.5);
    const auto r = o3dpp::compute_rgbd_odometry(source, target, primesense, o3dpp::identity4(),
                                                OdometryJacobian::HybridTerm);
    ASSERT_TRUE(r.success);
    EXPECT_NEAR(r.transformation[3], -0.0010704978, 1e-5);
    EXPECT_NEAR(r.transformation[7], 0.0232280983, 1e-5);
    EXPECT_NEAR(r.transformation[11], 0.0014059205, 1e-5);
    EXPECT_NEAR(r.information[3 * 6 + 3], 252387, 0.001 * 252387);
    // Nothing within 0.3 m: no solution, no error, the identity.
    OdometryOption near;
    near.depth_max = 0.3;
    const auto none = o3dpp::compute_rgbd_odometry(source, target, primesense, o3dpp::identity4(),
                                                   OdometryJacobian::HybridTerm, near);
    EXPECT_FALSE(none.success);
    EXPECT_EQ(none.transformation, o3dpp::identity4());
}

TEST(Odometry, Errors) {
    const RgbdImage frame = synthetic_frame();
    EXPECT_O3D_ERROR(o3dpp::compute_rgbd_odometry(frame, frame, PinholeIntrinsic(2 * W, 2 * H, 130, 130, 79.5, 59.5)),
                     O3D_ERROR_INVALID_ARGUMENT);
    OdometryOption nine_levels;
    nine_levels.iteration_number_per_pyramid_level.assign(9, 1);
    EXPECT_O3D_ERROR(o3dpp::compute_rgbd_odometry(frame, frame, kSmall, o3dpp::identity4(),
                                                  OdometryJacobian::ColorTerm, nine_levels),
                     O3D_ERROR_INVALID_ARGUMENT);
    OdometryOption no_levels;
    no_levels.iteration_number_per_pyramid_level.clear();
    EXPECT_O3D_ERROR(o3dpp::compute_rgbd_odometry(frame, frame, kSmall, o3dpp::identity4(),
                                                  OdometryJacobian::ColorTerm, no_levels),
                     O3D_ERROR_INVALID_ARGUMENT);
}
