// SPDX-License-Identifier: MIT
// Back-projection of depth and RGB-D images: the analytic pinhole formula on synthetic depth, and the real
// frame RGBD/{color,depth}/00000 against Open3D 0.20.0 (pip wheel), numbers printed by
// tools/reference/record_rgbd.py (section "back-projection"; POINT_INDICES = 0, 1000, 50000, 123456).
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <vector>

#include "o3d/camera/intrinsic_presets.h"
#include "o3d/camera/trajectory_log_io.h"
#include "o3d/camera/camera_io.h"
#include "o3d/geometry/depth_projection.h"
#include "o3d/geometry/image_ops.h"
#include "o3d/geometry/rgbd_image_ops.h"
#include "o3d/io/image_io.h"
#include "o3d/utility/error.h"
#include "test_data.h"

namespace {

using namespace o3d::geometry;
using o3d::camera::PinholeCameraIntrinsic;

constexpr int kW = 7, kH = 5;
const PinholeCameraIntrinsic kIntrinsic{kW, kH, 2.0, 3.0, 3.1, 2.2};

/// Depth z(u, v) = 1 + 0.25 u + 0.5 v metres, with invalid samples at a few pixels.
float synthetic_depth(int u, int v) {
    if (u == 1 && v == 0) return 0.0f;
    if (u == 2 && v == 2) return NAN;
    if (u == 4 && v == 2) return -1.0f;
    if (u == 6 && v == 4) return INFINITY;
    return 1.0f + 0.25f * u + 0.5f * v;
}

Image float_depth() {
    Image image = make_image(kW, kH, 1, 4);
    for (int v = 0; v < kH; ++v)
        for (int u = 0; u < kW; ++u) {
            const float z = synthetic_depth(u, v);
            std::memcpy(image.pixel<uint8_t>(u, v), &z, sizeof z);
        }
    return image;
}

bool valid(float z) { return z > 0 && std::isfinite(z); }

Eigen::Vector3d camera_point(int u, int v, double z) {
    return {(u - kIntrinsic.cx) * z / kIntrinsic.fx, (v - kIntrinsic.cy) * z / kIntrinsic.fy, z};
}

/// A world-to-camera rigid transform: rotation about a tilted axis and a translation.
Eigen::Matrix4d sample_extrinsic() {
    Eigen::Matrix4d e = Eigen::Matrix4d::Identity();
    const Eigen::Vector3d axis = Eigen::Vector3d(1, 2, -0.5).normalized();
    const double a = 0.7;
    Eigen::Matrix3d k;
    k << 0, -axis.z(), axis.y(), axis.z(), 0, -axis.x(), -axis.y(), axis.x(), 0;
    e.block<3, 3>(0, 0) = Eigen::Matrix3d::Identity() + std::sin(a) * k + (1 - std::cos(a)) * k * k;
    e.block<3, 1>(0, 3) << 0.3, -1.2, 2.5;
    return e;
}

TEST(depthProjection, SyntheticFloatDepthFollowsThePinholeFormula) {
    const PointCloud cloud = create_point_cloud_from_depth_image(float_depth(), kIntrinsic, Eigen::Matrix4d::Identity());
    EXPECT_FALSE(cloud.has_colors());
    size_t k = 0;
    for (int v = 0; v < kH; ++v)
        for (int u = 0; u < kW; ++u) {
            const float z = synthetic_depth(u, v);
            if (!valid(z)) continue;
            ASSERT_LT(k, cloud.size());
            EXPECT_TRUE(cloud.points[k] == camera_point(u, v, z)) << "pixel (" << u << "," << v << ")";
            ++k;
        }
    EXPECT_EQ(cloud.size(), k);
    EXPECT_EQ(k, size_t(kW * kH - 4));
}

TEST(depthProjection, ExtrinsicIsInvertedStrideAndTruncation) {
    const Eigen::Matrix4d extrinsic = sample_extrinsic();
    DepthToCloudOptions opts;
    opts.stride = 2;
    opts.depth_trunc = 3.0;
    opts.project_valid_depth_only = false;
    const PointCloud cloud = create_point_cloud_from_depth_image(float_depth(), kIntrinsic, extrinsic, opts);
    ASSERT_EQ(cloud.size(), 4u * 3u);  // columns 0, 2, 4, 6 x rows 0, 2, 4
    size_t k = 0, nan = 0;
    for (int v = 0; v < kH; v += 2)
        for (int u = 0; u < kW; u += 2, ++k) {
            const float z = synthetic_depth(u, v);
            const Eigen::Vector3d& p = cloud.points[k];
            if (!valid(z) || z >= 3.0f) {
                EXPECT_TRUE(p.array().isNaN().all()) << "pixel (" << u << "," << v << ")";
                ++nan;
                continue;
            }
            // The extrinsic maps the world point back to the camera point.
            const Eigen::Vector3d back = extrinsic.block<3, 3>(0, 0) * p + extrinsic.block<3, 1>(0, 3);
            EXPECT_LT((back - camera_point(u, v, z)).norm(), 1e-12) << "pixel (" << u << "," << v << ")";
        }
    // Row 2: (2,2) NaN, (4,2) negative, (6,2) z = 3.5; row 4: z = 3, 3.5, 4 (at or beyond 3 m) and +inf.
    EXPECT_EQ(nan, 7u);
}

TEST(depthProjection, HugeStrideVisitsTheFirstPixelOnly) {
    DepthToCloudOptions opts;
    opts.stride = 2147483647;
    opts.project_valid_depth_only = false;
    const PointCloud cloud = create_point_cloud_from_depth_image(float_depth(), kIntrinsic, Eigen::Matrix4d::Identity(),
                                                                 opts);
    ASSERT_EQ(cloud.size(), 1u);
    EXPECT_TRUE(cloud.points[0] == camera_point(0, 0, synthetic_depth(0, 0)));
}

TEST(depthProjection, RawDepthUsesScale) {
    Image depth = make_image(3, 2, 1, 2);
    const uint16_t raw[6] = {0, 5000, 12345, 2, 65535, 7};
    std::memcpy(depth.data.data(), raw, sizeof raw);
    DepthToCloudOptions opts;
    opts.depth_scale = 5000.0;
    opts.depth_trunc = 10.0;
    const PointCloud cloud = create_point_cloud_from_depth_image(depth, kIntrinsic, Eigen::Matrix4d::Identity(), opts);
    ASSERT_EQ(cloud.size(), 4u);  // raw 0 is invalid, 65535 / 5000 = 13.1 m is truncated
    EXPECT_TRUE(cloud.points[0] == camera_point(1, 0, 5000.0f / 5000.0f));
    EXPECT_TRUE(cloud.points[1] == camera_point(2, 0, 12345.0f / 5000.0f));
    EXPECT_TRUE(cloud.points[2] == camera_point(0, 1, 2.0f / 5000.0f));
    EXPECT_TRUE(cloud.points[3] == camera_point(2, 1, 7.0f / 5000.0f));
}

TEST(depthProjection, RgbdColorsFollowTheirPoints) {
    Image color = make_image(kW, kH, 3, 1);
    for (size_t i = 0; i < color.data.size(); ++i) color.data[i] = static_cast<uint8_t>(i * 7);
    RGBDImage rgbd{color, float_depth()};
    const PointCloud cloud = create_point_cloud_from_rgbd_image(rgbd, kIntrinsic, Eigen::Matrix4d::Identity(), false);
    ASSERT_EQ(cloud.size(), size_t(kW * kH));
    ASSERT_TRUE(cloud.has_colors());
    for (int v = 0; v < kH; ++v)
        for (int u = 0; u < kW; ++u) {
            const size_t k = size_t(v * kW + u);
            const uint8_t* c = color.pixel<uint8_t>(u, v);
            if (valid(synthetic_depth(u, v))) {
                EXPECT_TRUE(cloud.points[k] == camera_point(u, v, synthetic_depth(u, v)));
                EXPECT_EQ(cloud.colors[k], Eigen::Vector3d(c[0] / 255.0, c[1] / 255.0, c[2] / 255.0));
            } else {
                EXPECT_TRUE(std::isnan(cloud.points[k].x()));
                EXPECT_EQ(cloud.colors[k], Eigen::Vector3d::Zero());  // Open3D gives black to NaN points
            }
        }
    // A float intensity and an 8-bit gray image are repeated in R, G and B.
    rgbd.color = create_float_image(color, ImageConvertType::Weighted);
    const PointCloud gray = create_point_cloud_from_rgbd_image(rgbd, kIntrinsic, Eigen::Matrix4d::Identity());
    float i0;
    std::memcpy(&i0, rgbd.color.pixel<uint8_t>(0, 0), sizeof i0);
    EXPECT_EQ(gray.colors[0], Eigen::Vector3d::Constant(i0));
    rgbd.color = make_image(kW, kH, 1, 1);
    rgbd.color.data[0] = 51;
    EXPECT_EQ(create_point_cloud_from_rgbd_image(rgbd, kIntrinsic, Eigen::Matrix4d::Identity()).colors[0],
              Eigen::Vector3d::Constant(0.2));
}

TEST(depthProjection, RejectsBadInput) {
    const Image depth = float_depth();
    const Eigen::Matrix4d id = Eigen::Matrix4d::Identity();
    DepthToCloudOptions opts;
    opts.stride = 0;
    EXPECT_THROW(create_point_cloud_from_depth_image(depth, kIntrinsic, id, opts), o3d::InvalidArgument);
    opts = {};
    opts.depth_scale = -1;
    EXPECT_THROW(create_point_cloud_from_depth_image(depth, kIntrinsic, id, opts), o3d::InvalidArgument);
    opts = {};
    opts.depth_trunc = NAN;
    EXPECT_THROW(create_point_cloud_from_depth_image(depth, kIntrinsic, id, opts), o3d::InvalidArgument);
    Eigen::Matrix4d projective = id;
    projective(3, 2) = 0.5;
    EXPECT_THROW(create_point_cloud_from_depth_image(depth, kIntrinsic, projective), o3d::InvalidArgument);
    Eigen::Matrix4d singular = id;
    singular(1, 1) = 0;
    EXPECT_THROW(create_point_cloud_from_depth_image(depth, kIntrinsic, singular), o3d::InvalidArgument);
    Eigen::Matrix4d nan = id;
    nan(0, 3) = NAN;
    EXPECT_THROW(create_point_cloud_from_depth_image(depth, kIntrinsic, nan), o3d::InvalidArgument);
    PinholeCameraIntrinsic bad = kIntrinsic;
    bad.fx = 0;
    EXPECT_THROW(create_point_cloud_from_depth_image(depth, bad, id), o3d::InvalidArgument);
    bad = kIntrinsic;
    bad.cy = INFINITY;
    EXPECT_THROW(create_point_cloud_from_depth_image(depth, bad, id), o3d::InvalidArgument);
    EXPECT_THROW(create_point_cloud_from_depth_image(Image{}, kIntrinsic, id), o3d::InvalidArgument);
    EXPECT_THROW(create_point_cloud_from_depth_image(make_image(kW, kH, 3, 2), kIntrinsic, id), o3d::InvalidArgument);
    EXPECT_THROW(create_point_cloud_from_depth_image(make_image(kW, kH, 1, 1), kIntrinsic, id), o3d::InvalidArgument);
    // RGB-D: depth must be float, color a supported format of the same size.
    EXPECT_THROW(create_point_cloud_from_rgbd_image({make_image(kW, kH, 3, 1), make_image(kW, kH, 1, 2)}, kIntrinsic,
                                                    id),
                 o3d::InvalidArgument);
    EXPECT_THROW(create_point_cloud_from_rgbd_image({make_image(kW + 1, kH, 3, 1), depth}, kIntrinsic, id),
                 o3d::InvalidArgument);
    EXPECT_THROW(create_point_cloud_from_rgbd_image({make_image(kW, kH, 4, 1), depth}, kIntrinsic, id),
                 o3d::InvalidArgument);
}

void expect_vec(const Eigen::Vector3d& p, const Eigen::Vector3d& ref, double tol, const char* what) {
    EXPECT_LE((p - ref).cwiseAbs().maxCoeff(), tol) << what << ": " << p.transpose() << " vs " << ref.transpose();
}

Eigen::Vector3d mean(const std::vector<Eigen::Vector3d>& v) {
    Eigen::Vector3d s = Eigen::Vector3d::Zero();
    for (const auto& p : v) s += p;
    return s / double(v.size());
}

struct RealFrame {
    Image color, depth;
};

const size_t kIndices[4] = {0, 1000, 50000, 123456};
// Open3D: depth_point[i] = rgbd_rgb_point[i] = rgbd_gray_point[i].
const Eigen::Vector3d kPoints[4] = {{-0.5494885611534118, -0.5993228459358215, 1.3769999742507935},
                                    {-0.1562895173118228, -0.9655694836661929, 2.247999906539917},
                                    {-0.5940771317481994, -0.35539713621139524, 1.3769999742507935},
                                    {0.043559999465942384, -0.04770857084365118, 2.177999973297119}};
const Eigen::Vector3d kCentroid{-0.04790395589573783, -0.05202429268729524, 1.793887336424306};

void expect_real_frame_points(const PointCloud& cloud) {
    ASSERT_EQ(cloud.size(), 267129u);
    for (int i = 0; i < 4; ++i) expect_vec(cloud.points[kIndices[i]], kPoints[i], 1e-15, "point");
    expect_vec(mean(cloud.points), kCentroid, 1e-12, "centroid");
}

TEST(depthProjection, RealFrameMatchesOpen3D) {
    O3D_TEST_DATA_OR_SKIP(color_path, "open3d/RGBD/color/00000.jpg");
    O3D_TEST_DATA_OR_SKIP(depth_path, "open3d/RGBD/depth/00000.png");
    O3D_TEST_DATA_OR_SKIP(log_path, "open3d/RGBD/trajectory.log");
    const Image color = o3d::io::read_image(color_path);
    const Image depth = o3d::io::read_image(depth_path);
    const PinholeCameraIntrinsic ps = o3d::camera::intrinsic_preset(o3d::camera::IntrinsicPreset::PrimeSenseDefault);
    const Eigen::Matrix4d id = Eigen::Matrix4d::Identity();

    expect_real_frame_points(create_point_cloud_from_depth_image(depth, ps, id));

    RGBDOptions keep;
    keep.convert_rgb_to_intensity = false;
    const RGBDImage rgb = create_rgbd_from_color_and_depth(color, depth, keep);
    const PointCloud rgb_cloud = create_point_cloud_from_rgbd_image(rgb, ps, id);
    expect_real_frame_points(rgb_cloud);
    expect_vec(rgb_cloud.colors[0], {0.5725490196078431, 0.611764705882353, 0.6470588235294118}, 0, "color 0");
    expect_vec(rgb_cloud.colors[1000], {0.5607843137254902, 0.5764705882352941, 0.5803921568627451}, 0, "color 1000");
    expect_vec(mean(rgb_cloud.colors), {0.8401963096483908, 0.7798637494595275, 0.7436728924169724}, 1e-12,
               "color mean");

    const PointCloud gray_cloud = create_point_cloud_from_rgbd_image(create_rgbd_from_color_and_depth(color, depth), ps, id);
    expect_real_frame_points(gray_cloud);
    expect_vec(gray_cloud.colors[0], Eigen::Vector3d::Constant(0.6040627360343933), 1e-7, "gray 0");
    expect_vec(gray_cloud.colors[1000], Eigen::Vector3d::Constant(0.572227418422699), 1e-7, "gray 1000");
    expect_vec(mean(gray_cloud.colors), Eigen::Vector3d::Constant(0.7937774265857311), 1e-7, "gray mean");

    const PointCloud organised = create_point_cloud_from_rgbd_image(rgb, ps, id, false);
    ASSERT_EQ(organised.size(), 307200u);
    size_t nan = 0;
    for (const auto& p : organised.points) nan += std::isnan(p.x());
    EXPECT_EQ(nan, 40071u);

    // Posed, truncated, strided: Open3D's depth_posed_*.
    const Eigen::Matrix4d extrinsic = o3d::camera::read_pinhole_camera_trajectory(log_path).parameters[0].extrinsic;
    DepthToCloudOptions opts;
    opts.depth_trunc = 3.0;
    opts.stride = 2;
    const PointCloud posed = create_point_cloud_from_depth_image(depth, ps, extrinsic, opts);
    ASSERT_EQ(posed.size(), 66782u);
    expect_vec(posed.points[0], {-2.5597347557368066, 1.6822763251021273, 4.187966427331297}, 1e-12, "posed 0");
    expect_vec(posed.points[1000], {-2.433407128010601, 1.4209313598726303, 2.5761222404293065}, 1e-12, "posed 1000");
    expect_vec(posed.points[50000], {-1.7749912164579915, 0.13529464029996047, 3.484867663817271}, 1e-12,
               "posed 50000");
    expect_vec(mean(posed.points), {-2.0230179062752183, 0.5859064797827817, 2.665732601535152}, 1e-12, "posed mean");

    // The same points on one thread and on four.
    const PointCloud one = create_point_cloud_from_rgbd_image(rgb, ps, extrinsic, false, 1);
    const PointCloud four = create_point_cloud_from_rgbd_image(rgb, ps, extrinsic, false, 4);
    ASSERT_EQ(one.size(), four.size());
    EXPECT_EQ(std::memcmp(one.points.data(), four.points.data(), one.size() * sizeof(Eigen::Vector3d)), 0);
    EXPECT_EQ(std::memcmp(one.colors.data(), four.colors.data(), one.size() * sizeof(Eigen::Vector3d)), 0);
}

}  // namespace
