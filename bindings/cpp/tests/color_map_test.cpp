// SPDX-License-Identifier: MIT
// Colour-map optimization through the wrapper, on tests/capi/test_color_map.c's scene whose answer is known: a box
// room with a smooth colour texture, ray-cast into five 8-bit RGB + float depth views of one corner, given with each
// pose turned by 1.5 degrees and moved about 2 cm. Both optimizers move the poses toward the truth and the colours
// toward the texture; and the errors.
#include <cmath>
#include <vector>

#include "test_util.hpp"

using o3dpp::CameraTrajectory;
using o3dpp::Mat4;
using o3dpp::RgbdImage;
using o3dpp::Vec3;

namespace {
constexpr int W = 160, H = 120, kViews = 5, kGrid = 31;
const o3dpp::PinholeIntrinsic kCamera(W, H, 140.0, 140.0, 79.5, 59.5);
const Vec3 kLo{-1.2, -1.0, -1.0}, kHi{1.2, 1.0, 1.6};

Vec3 texture(const Vec3& p) {
    return {0.5 + 0.2 * std::sin(5.0 * p[0] + 2.0 * p[2]) * std::cos(4.0 * p[1]) + 0.15 * std::sin(11.0 * p[2] + 3.0 * p[1]),
            0.5 + 0.2 * std::cos(4.5 * p[1] + 1.0) * std::sin(5.5 * p[2] - p[0]) + 0.15 * std::cos(10.0 * p[0] - 4.0 * p[1]),
            0.5 + 0.25 * std::sin(3.0 * (p[0] + p[1] + p[2])) + 0.15 * std::cos(12.0 * p[1] - 5.0 * p[2] + 3.0 * p[0])};
}

Mat4 mul(const Mat4& a, const Mat4& b) {
    Mat4 t{};
    for (int r = 0; r < 4; ++r)
        for (int c = 0; c < 4; ++c)
            for (int k = 0; k < 4; ++k) t[4 * r + c] += a[4 * r + k] * b[4 * k + c];
    return t;
}

Mat4 rigid_inverse(const Mat4& m) {
    Mat4 out{};
    for (int r = 0; r < 3; ++r)
        for (int c = 0; c < 3; ++c) {
            out[4 * r + c] = m[4 * c + r];
            out[4 * r + 3] -= m[4 * c + r] * m[4 * c + 3];
        }
    out[15] = 1;
    return out;
}

Vec3 unit(Vec3 v) {
    const double n = std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
    return {v[0] / n, v[1] / n, v[2] / n};
}

Vec3 cross(const Vec3& a, const Vec3& b) {
    return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}

/// Camera-to-world pose at `centre` looking at `target` (world y points down).
Mat4 look_at(const Vec3& centre, const Vec3& target) {
    const Vec3 z = unit({target[0] - centre[0], target[1] - centre[1], target[2] - centre[2]});
    const Vec3 x = unit(cross({0, 1, 0}, z)), y = cross(z, x);
    Mat4 m{};
    for (int r = 0; r < 3; ++r) m[4 * r] = x[r], m[4 * r + 1] = y[r], m[4 * r + 2] = z[r], m[4 * r + 3] = centre[r];
    m[15] = 1;
    return m;
}

/// Rotation by `deg` about `axis` (Rodrigues), then translation t.
Mat4 motion(const Vec3& axis, double deg, const Vec3& t) {
    const Vec3 k = unit(axis);
    const double a = deg * M_PI / 180, c = std::cos(a), s = std::sin(a);
    Mat4 m{};
    for (int r = 0; r < 3; ++r)
        for (int q = 0; q < 3; ++q) m[4 * r + q] = (1 - c) * k[r] * k[q] + (r == q ? c : 0);
    m[1] -= s * k[2], m[2] += s * k[1], m[4] += s * k[2], m[6] -= s * k[0], m[8] -= s * k[1], m[9] += s * k[0];
    for (int r = 0; r < 3; ++r) m[4 * r + 3] = t[r];
    m[15] = 1;
    return m;
}

/// The RGB-D view from camera-to-world `pose`: each ray meets the room's box where it leaves it.
RgbdImage render(const Mat4& pose) {
    std::vector<uint8_t> rgb;
    std::vector<float> depth;
    for (int v = 0; v < H; ++v)
        for (int u = 0; u < W; ++u) {
            const Vec3 dc{(u - kCamera.cx) / kCamera.fx, (v - kCamera.cy) / kCamera.fy, 1.0};
            Vec3 d{}, p{};
            double t = INFINITY;
            for (int r = 0; r < 3; ++r) d[r] = pose[4 * r] * dc[0] + pose[4 * r + 1] * dc[1] + pose[4 * r + 2] * dc[2];
            for (int a = 0; a < 3; ++a)
                if (d[a] != 0) t = std::min(t, ((d[a] > 0 ? kHi[a] : kLo[a]) - pose[4 * a + 3]) / d[a]);
            for (int r = 0; r < 3; ++r) p[r] = pose[4 * r + 3] + t * d[r];
            for (double c : texture(p)) rgb.push_back(uint8_t(std::lround(255.0 * c)));
            depth.push_back(float(t));  // the camera ray has z = 1: t is the depth
        }
    o3dpp::RgbdOptions o;
    o.depth_scale = 1.0;
    o.depth_trunc = 10.0;
    o.convert_rgb_to_intensity = false;
    return RgbdImage::create_from_color_and_depth(o3dpp::Image::from_values<uint8_t>(W, H, rgb, 3),
                                                  o3dpp::Image::from_values<float>(W, H, depth), o);
}

struct Scene {
    o3dpp::TriangleMesh mesh;
    std::vector<RgbdImage> images;
    CameraTrajectory start;
    std::vector<Mat4> truth;  // world to camera

    Scene() {
        std::vector<Vec3> xyz;
        for (int axis = 0; axis < 3; ++axis)
            for (int side = 0; side < 2; ++side)
                for (int j = 0; j < kGrid; ++j)
                    for (int i = 0; i < kGrid; ++i) {
                        const int a = (axis + 1) % 3, b = (axis + 2) % 3;
                        Vec3 p{};
                        p[axis] = side ? kHi[axis] : kLo[axis];
                        p[a] = kLo[a] + (kHi[a] - kLo[a]) * i / (kGrid - 1);
                        p[b] = kLo[b] + (kHi[b] - kLo[b]) * j / (kGrid - 1);
                        xyz.push_back(p);
                    }
        mesh.set_vertices(xyz);
        const Vec3 centres[kViews] = {{0, 0, 0}, {-0.6, -0.4, -0.5}, {0.5, -0.5, 0.3}, {-0.5, 0.5, 0.5}, {0.4, 0.4, -0.6}};
        const Vec3 targets[kViews] = {{1.2, 1.0, 1.6}, {1.0, 1.0, 1.6}, {1.2, 0.8, 1.6}, {1.2, 1.0, 1.4}, {1.1, 0.9, 1.5}};
        const Vec3 axes[kViews] = {{1, 2, 0}, {-1, 0, 2}, {0, 1, 1}, {2, -1, 1}, {1, 1, -1}};
        const Vec3 shifts[kViews] = {{0.02, -0.01, 0.01}, {-0.01, 0.02, 0}, {0, -0.02, -0.015}, {0.015, 0.01, 0.01}, {-0.02, 0, 0.01}};
        for (int c = 0; c < kViews; ++c) {
            const Mat4 pose = look_at(centres[c], targets[c]);
            images.push_back(render(pose));
            truth.push_back(rigid_inverse(pose));
            start.push_back(kCamera, mul(motion(axes[c], 1.5, shifts[c]), truth.back()));
        }
    }

    /// Mean rotation error (degrees) and camera-centre distance (metres) of a trajectory against the truth.
    std::pair<double, double> pose_error(const CameraTrajectory& t) const {
        double deg = 0, metres = 0;
        for (int c = 0; c < kViews; ++c) {
            const Mat4 a = t.at(std::size_t(c)).extrinsic, e = mul(a, rigid_inverse(truth[c]));
            deg += std::acos(std::clamp((e[0] + e[5] + e[10] - 1) / 2, -1.0, 1.0)) * 180 / M_PI / kViews;
            const Mat4 ia = rigid_inverse(a), ib = rigid_inverse(truth[c]);
            metres += std::hypot(ia[3] - ib[3], ia[7] - ib[7], ia[11] - ib[11]) / kViews;
        }
        return {deg, metres};
    }
};

/// Mean RGB distance from the texture over the vertices within 1 m of the corner the cameras look into.
double color_error(const o3dpp::TriangleMesh& mesh) {
    const auto xyz = mesh.get_vertices(), rgb = mesh.get_vertex_colors();
    EXPECT_EQ(rgb.size(), xyz.size());
    double sum = 0;
    int used = 0;
    for (std::size_t i = 0; i < xyz.size(); ++i) {
        const Vec3& p = xyz[i];
        if (std::abs(p[0] - kHi[0]) + std::abs(p[1] - kHi[1]) + std::abs(p[2] - kHi[2]) > 1.0 + 1e-9) continue;
        const Vec3 t = texture(p);
        sum += std::hypot(rgb[i][0] - t[0], rgb[i][1] - t[1], rgb[i][2] - t[2]);
        ++used;
    }
    EXPECT_GT(used, 50);
    return sum / used;
}

template <typename O>
O scene_options(int iterations) {
    O o;
    o.maximum_iteration = iterations;
    o.maximum_allowable_depth = 4.0;
    o.depth_threshold_for_discontinuity_check = 1.0;  // slanted walls at 160 x 120 are no discontinuity
    o.depth_threshold_for_visibility_check = 0.2;     // the poses start a few cm off
    o.image_boundary_margin = 4;
    return o;
}

const Scene& scene() {
    static const Scene s;
    return s;
}
}  // namespace

TEST(ColorMap, RigidRecoversThePoses) {
    const Scene& s = scene();
    const auto before = o3dpp::run_rigid_optimizer(s.mesh, s.images, s.start, scene_options<o3dpp::ColorMapRigidOptions>(0));
    int calls = 0;
    auto o = scene_options<o3dpp::ColorMapRigidOptions>(150);
    o.progress = [&](double) { return ++calls > 0; };
    const auto after = o3dpp::run_rigid_optimizer(s.mesh, s.images, s.start, o);
    const auto [deg0, m0] = s.pose_error(before.trajectory);
    const auto [deg1, m1] = s.pose_error(after.trajectory);
    EXPECT_NEAR(deg0, 1.5, 1e-9);  // no iterations: the poses as given
    EXPECT_LT(deg1, 0.5 * deg0);
    EXPECT_LT(m1, 0.6 * m0);
    EXPECT_LT(color_error(after.mesh), 0.5 * color_error(before.mesh));
    EXPECT_EQ(calls, 150);
    EXPECT_FALSE(s.mesh.has_vertex_colors());  // the result is a copy
}

TEST(ColorMap, NonRigidRecoversThePoses) {
    const Scene& s = scene();
    auto o = scene_options<o3dpp::ColorMapNonRigidOptions>(150);
    o.number_of_vertical_anchors = 6;
    const auto r = o3dpp::run_non_rigid_optimizer(s.mesh, o3dpp::Span<const RgbdImage>(s.images.data(), kViews), s.start, o);
    const auto [deg, m] = s.pose_error(r.trajectory);
    EXPECT_LT(deg, 0.75);
    EXPECT_LT(m, 0.015);
    EXPECT_LT(color_error(r.mesh), 0.01);  // from 0.055 at the given poses (the rigid optimizer reaches 0.005)
}

TEST(ColorMap, Errors) {
    const Scene& s = scene();
    const auto o = scene_options<o3dpp::ColorMapRigidOptions>(1);
    // fewer images than poses
    EXPECT_O3D_ERROR(o3dpp::run_rigid_optimizer(s.mesh, o3dpp::Span<const RgbdImage>(s.images.data(), 2), s.start, o),
                     O3D_ERROR_INVALID_ARGUMENT);
    auto n = scene_options<o3dpp::ColorMapNonRigidOptions>(1);
    n.number_of_vertical_anchors = 1;
    EXPECT_O3D_ERROR(o3dpp::run_non_rigid_optimizer(s.mesh, s.images, s.start, n), O3D_ERROR_INVALID_ARGUMENT);
    auto cancel = o;
    cancel.progress = [](double) { return false; };
    EXPECT_O3D_ERROR(o3dpp::run_rigid_optimizer(s.mesh, s.images, s.start, cancel), O3D_ERROR_CANCELLED);
}
