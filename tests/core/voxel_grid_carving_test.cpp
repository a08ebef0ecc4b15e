// SPDX-License-Identifier: MIT
// Carving a dense cube with a depth map and a silhouette seen by a pinhole camera: analytic cases, and
// Open3D 0.20's numbers on the same synthetic images recorded by tools/reference/record_voxel_edit_octree.py.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <functional>
#include <limits>

#include "o3d/geometry/image_ops.h"
#include "o3d/geometry/voxel_grid_carving.h"
#include "o3d/geometry/voxel_grid_edit.h"
#include "o3d/utility/error.h"

using namespace o3d::geometry;
using o3d::camera::PinholeCameraParameters;

namespace {

constexpr int kW = 40, kH = 30;
constexpr double kCx = 19.5, kCy = 14.25;

int64_t index_checksum(const VoxelGrid& g) {
    int64_t sum = 0;
    for (size_t r = 0; r < g.voxels.size(); ++r) {
        const Eigen::Vector3i& v = g.voxels[r].grid_index;
        sum += static_cast<int64_t>(r + 1) * (v(0) + 1009LL * v(1) + 1009LL * 1009LL * v(2));
    }
    return sum;
}

/// The record script's camera: 40 x 30, fx 30, fy 31, principal point (19.5, 14.25), translation
/// (0.05, -0.03, 3); rotated: R = RX @ RY with the entries numpy printed.
PinholeCameraParameters camera(bool rotated) {
    PinholeCameraParameters p;
    p.intrinsic = {kW, kH, 30.0, 31.0, kCx, kCy};
    if (rotated)
        p.extrinsic.block<3, 3>(0, 0) << 0.8, 0.0, -0.6, -0.168, 0.96, -0.22400000000000003, 0.576, 0.28, 0.768;
    p.extrinsic.block<3, 1>(0, 3) = Eigen::Vector3d(0.05, -0.03, 3.0);
    return p;
}

/// 1000 voxels of 0.1 filling [-0.5, 0.5]^3.
VoxelGrid cube() { return voxel_grid_create_dense(Eigen::Vector3d::Constant(-0.5), {0.2, 0.3, 0.4}, 0.1, 1, 1, 1); }

/// A float32 image whose pixel (u, v) is f(u, v), rounded to float as numpy's astype(float32).
Image float_image(const std::function<double(int, int)>& f, int width = kW, int height = kH) {
    Image img = make_image(width, height, 1, 4);
    for (int v = 0; v < height; ++v)
        for (int u = 0; u < width; ++u) *img.pixel<float>(u, v) = static_cast<float>(f(u, v));
    return img;
}

/// The script's depth ramp 2.6 + 0.02 u + 0.015 v, with a 4 x 4 hole of zeros at rows 5..8, columns 10..13.
Image ramp() {
    return float_image([](int u, int v) {
        if (v >= 5 && v < 9 && u >= 10 && u < 14) return 0.0;
        return 2.6 + 0.02 * u + 0.015 * v;
    });
}

/// The script's disc of radius `r` pixels around the principal point (1 inside, 0 outside).
Image disc(double r) {
    return float_image([r](int u, int v) { return (u - kCx) * (u - kCx) + (v - kCy) * (v - kCy) <= r * r ? 1.0 : 0.0; });
}

/// Pixel coordinates of `x` (world) through `p`; z is the camera depth.
Eigen::Vector3d project(const PinholeCameraParameters& p, const Eigen::Vector3d& x) {
    const Eigen::Vector3d c = p.extrinsic.block<3, 3>(0, 0) * x + p.extrinsic.block<3, 1>(0, 3);
    return {p.intrinsic.fx * c.x() / c.z() + p.intrinsic.cx, p.intrinsic.fy * c.y() / c.z() + p.intrinsic.cy, c.z()};
}

}  // namespace

TEST(VoxelGridCarving, DepthMapMatchesOpen3D) {
    // record_voxel_edit_octree.py: every corner projects inside the image, so keep_voxels_outside_image
    // changes nothing; 359 voxels remain on both cameras.
    for (const bool rotated : {false, true})
        for (const bool keep : {false, true}) {
            VoxelGrid g = cube();
            carve_depth_map(g, ramp(), camera(rotated), keep);
            EXPECT_EQ(g.voxels.size(), 359u) << rotated << keep;
            EXPECT_EQ(index_checksum(g), rotated ? 461860284044LL : 513370035593LL) << rotated << keep;
            for (const Voxel& v : g.voxels) EXPECT_EQ(v.color, Eigen::Vector3d(0.2, 0.3, 0.4));
        }
}

TEST(VoxelGridCarving, ConstantDepthKeepsTheLayersBehindIt) {
    // The camera looks down +z at the cube 3 m away: layer k (camera depth 2.5 + 0.1 k .. 2.6 + 0.1 k) stays
    // iff its far face reaches the surface at 3.05: k >= 5, 500 voxels (Open3D 0.20: 500).
    VoxelGrid g = cube();
    carve_depth_map(g, float_image([](int, int) { return 3.05; }), camera(false), false, 2);
    ASSERT_EQ(g.voxels.size(), 500u);
    for (const Voxel& v : g.voxels) EXPECT_GE(v.grid_index.z(), 5);
    // A depth in front of the whole cube carves nothing; no measurement (0) carves everything.
    g = cube();
    carve_depth_map(g, float_image([](int, int) { return 2.0; }), camera(false));
    EXPECT_EQ(g.voxels.size(), 1000u);
    g = cube();
    carve_depth_map(g, float_image([](int, int) { return 0.0; }), camera(false));
    EXPECT_TRUE(g.voxels.empty());
    // NaN pixels are no measurement either.
    g = cube();
    carve_depth_map(g, float_image([](int, int) { return std::nan(""); }), camera(false));
    EXPECT_TRUE(g.voxels.empty());
}

TEST(VoxelGridCarving, SilhouetteMatchesOpen3D) {
    // record_voxel_edit_octree.py: disc of radius 3 pixels.
    for (const bool rotated : {false, true})
        for (const bool keep : {false, true}) {
            VoxelGrid g = cube();
            carve_silhouette(g, disc(3.0), camera(rotated), keep);
            EXPECT_EQ(g.voxels.size(), rotated ? 611u : 561u) << rotated << keep;
            EXPECT_EQ(index_checksum(g), rotated ? 1036255453305LL : 840626374965LL) << rotated << keep;
        }
    // A camera close to the cube sees only part of it: keep_voxels_outside_image matters.
    PinholeCameraParameters near = camera(true);
    near.extrinsic.block<3, 1>(0, 3) = Eigen::Vector3d(0.4, 0.1, 1.4);
    VoxelGrid g = cube();
    carve_silhouette(g, disc(3.0), near, false);
    EXPECT_EQ(g.voxels.size(), 117u);
    EXPECT_EQ(index_checksum(g), 54472624004LL);
    g = cube();
    carve_silhouette(g, disc(3.0), near, true);
    EXPECT_EQ(g.voxels.size(), 307u);
    EXPECT_EQ(index_checksum(g), 120098539116LL);
}

TEST(VoxelGridCarving, CentredDiscKeepsTheVoxelsInsideItsCone) {
    // A voxel stays iff some corner projects where the bilinear mask is > 0. The pixel at the floor of a
    // corner's (u, v) weighs > 0 and is within sqrt(2) pixels, and every pixel weighing > 0 is too: a corner
    // within r - sqrt(2) pixels of the disc centre keeps its voxel, and a voxel all of whose corners are
    // beyond r + sqrt(2) goes. Voxels on the optical axis stay.
    const double r = 3.5, slack = std::sqrt(2.0);
    for (const bool rotated : {false, true}) {
        const PinholeCameraParameters p = camera(rotated);
        const VoxelGrid full = cube();
        VoxelGrid g = cube();
        carve_silhouette(g, disc(r), p);
        ASSERT_GT(g.voxels.size(), 0u);
        ASSERT_LT(g.voxels.size(), full.voxels.size());
        size_t must_keep = 0, must_go = 0;
        for (const Voxel& v : full.voxels) {
            double nearest = std::numeric_limits<double>::infinity();
            for (const Eigen::Vector3d& corner : voxel_bounding_points(full, v.grid_index)) {
                const Eigen::Vector3d uvz = project(p, corner);
                nearest = std::min(nearest, std::hypot(uvz.x() - kCx, uvz.y() - kCy));
            }
            const bool kept = find_voxel(g, v.grid_index) != nullptr;
            if (nearest <= r - slack) {
                ++must_keep;
                EXPECT_TRUE(kept) << v.grid_index.transpose();
            }
            if (nearest > r + slack) {
                ++must_go;
                EXPECT_FALSE(kept) << v.grid_index.transpose();
            }
        }
        EXPECT_GT(must_keep, 100u);
        EXPECT_GT(must_go, 100u) << must_keep << " " << must_go << " " << g.voxels.size();
    }
    // The camera's own axis: (x, y) = -t(x, y) for the unrotated camera, i.e. the column around (-0.05, 0.03).
    VoxelGrid g = cube();
    carve_silhouette(g, disc(r), camera(false));
    for (double z = -0.45; z < 0.5; z += 0.1) {
        const Eigen::Vector3i cell = ((Eigen::Vector3d(-0.05, 0.03, z) - g.origin) / 0.1).array().floor().cast<int>();
        EXPECT_NE(find_voxel(g, cell), nullptr) << z;
    }
}

TEST(VoxelGridCarving, OutsideTheImageAndBehindTheCamera) {
    // The cube behind the camera: every corner has z < 0, so it is outside the image; kept only on request.
    PinholeCameraParameters p = camera(false);
    p.extrinsic(2, 3) = -3.0;
    VoxelGrid g = cube();
    carve_silhouette(g, float_image([](int, int) { return 1.0; }), p, false);
    EXPECT_TRUE(g.voxels.empty());
    g = cube();
    carve_silhouette(g, float_image([](int, int) { return 1.0; }), p, true);
    EXPECT_EQ(g.voxels.size(), 1000u);
    // A one-pixel image: only corners projecting exactly onto (cx, cy) = (0, 0) are inside; the bilinear
    // read at the border never leaves the image.
    PinholeCameraParameters one;
    one.intrinsic = {1, 1, 30.0, 30.0, 0.0, 0.0};
    one.extrinsic(2, 3) = 3.0;
    g = voxel_grid_create_dense(Eigen::Vector3d::Constant(-0.5), Eigen::Vector3d::Zero(), 0.5, 1, 1, 1);
    carve_silhouette(g, float_image([](int, int) { return 1.0; }, 1, 1), one, false);
    EXPECT_EQ(g.voxels.size(), 8u);  // the 8 voxels share the corner (0, 0, 0), on the optical axis
}

TEST(VoxelGridCarving, ThreadCountDoesNotMatter) {
    // 8000 voxels: enough for the parallel path.
    const VoxelGrid dense = voxel_grid_create_dense(Eigen::Vector3d::Constant(-0.5), Eigen::Vector3d::Zero(), 0.05, 1, 1, 1);
    ASSERT_EQ(dense.voxels.size(), 8000u);
    VoxelGrid one = dense, two = dense;
    carve_depth_map(one, ramp(), camera(true), false, 1);
    carve_depth_map(two, ramp(), camera(true), false, 2);
    ASSERT_GT(one.voxels.size(), 0u);
    ASSERT_LT(one.voxels.size(), dense.voxels.size());
    EXPECT_EQ(index_checksum(one), index_checksum(two));
    one = dense, two = dense;
    carve_silhouette(one, disc(5.0), camera(true), true, 1);
    carve_silhouette(two, disc(5.0), camera(true), true, 2);
    ASSERT_LT(one.voxels.size(), dense.voxels.size());
    EXPECT_EQ(index_checksum(one), index_checksum(two));
}

TEST(VoxelGridCarving, BadInputsAreErrors) {
    VoxelGrid g = cube();
    const PinholeCameraParameters p = camera(false);
    // Formats Open3D 0.20 silently treats as "outside the image everywhere".
    EXPECT_THROW(carve_silhouette(g, make_image(kW, kH, 1, 2), p), o3d::InvalidArgument);
    EXPECT_THROW(carve_silhouette(g, make_image(kW, kH, 1, 1), p), o3d::InvalidArgument);
    EXPECT_THROW(carve_depth_map(g, make_image(kW, kH, 3, 4), p), o3d::InvalidArgument);
    // Size against the intrinsic, and data that does not match the header.
    EXPECT_THROW(carve_depth_map(g, make_image(kW, kH + 1, 1, 4), p), o3d::InvalidArgument);
    EXPECT_THROW(carve_silhouette(g, make_image(kW - 1, kH, 1, 4), p), o3d::InvalidArgument);
    Image short_data = make_image(kW, kH, 1, 4);
    short_data.data.resize(10);
    EXPECT_THROW(carve_depth_map(g, short_data, p), o3d::InvalidArgument);
    Image empty;
    empty.num_channels = 1;
    empty.bytes_per_channel = 4;
    EXPECT_THROW(carve_depth_map(g, empty, p), o3d::InvalidArgument);
    // Camera parameters.
    PinholeCameraParameters bad = p;
    bad.intrinsic.fx = std::nan("");
    EXPECT_THROW(carve_depth_map(g, ramp(), bad), o3d::InvalidArgument);
    bad = p;
    bad.intrinsic.fy = 0.0;
    EXPECT_THROW(carve_silhouette(g, disc(3), bad), o3d::InvalidArgument);
    bad = p;
    bad.extrinsic(0, 3) = std::numeric_limits<double>::infinity();
    EXPECT_THROW(carve_depth_map(g, ramp(), bad), o3d::InvalidArgument);
    bad = p;
    bad.extrinsic(3, 0) = 1.0;
    EXPECT_THROW(carve_depth_map(g, ramp(), bad), o3d::InvalidArgument);
    // The grid itself.
    VoxelGrid broken = cube();
    broken.voxel_size = 0.0;
    EXPECT_THROW(carve_depth_map(broken, ramp(), p), o3d::InvalidArgument);
    broken = cube();
    broken.origin.x() = std::nan("");
    EXPECT_THROW(carve_silhouette(broken, disc(3), p), o3d::InvalidArgument);
    // Nothing was carved by the failed calls.
    EXPECT_EQ(g.voxels.size(), 1000u);
}
