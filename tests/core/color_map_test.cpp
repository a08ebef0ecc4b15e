// SPDX-License-Identifier: MIT
// Colour-map optimization on data whose answer is known: the inside of a box room with a smooth colour texture
// (a function of the world position), ray-cast here into RGB-D images from known poses; the optimizers start from
// those poses perturbed by about 1.5 degrees and 2 cm. Checked: the photometric error (mean squared difference
// between the vertex intensities and the images at the poses, computed here, not by the library) falls, the poses
// move toward the true ones, the vertex colours toward the texture; non-rigid does at least as well as rigid, and
// better than any pose can on images with lens distortion; no iterations give the plain average (hand-computed on a tiny case); results do not depend on the thread count;
// cancelling; and the argument checks.
#include <Eigen/Geometry>
#include <cmath>
#include <cstdint>
#include <string>

#include "o3d/color_map/color_map.h"
#include "o3d/geometry/image_ops.h"
#include "o3d/utility/error.h"
#include "test_data.h"

namespace {

using o3d::camera::PinholeCameraIntrinsic;
using o3d::camera::PinholeCameraTrajectory;
using o3d::color_map::NonRigidOptimizerOption;
using o3d::color_map::RigidOptimizerOption;
using o3d::geometry::Image;
using o3d::geometry::RGBDImage;
using o3d::geometry::TriangleMesh;

constexpr int W = 160, H = 120;
const PinholeCameraIntrinsic kCamera{W, H, 140.0, 140.0, 79.5, 59.5};
const Eigen::Vector3d kRoomLo(-1.2, -1.0, -1.0), kRoomHi(1.2, 1.0, 1.6);

/// @brief The true colour of the room's surface at `p` (each channel in about [0.1, 0.9]).
Eigen::Vector3d texture(const Eigen::Vector3d& p) {
    return {0.5 + 0.2 * std::sin(5.0 * p.x() + 2.0 * p.z()) * std::cos(4.0 * p.y()) + 0.15 * std::sin(11.0 * p.z() + 3.0 * p.y()),
            0.5 + 0.2 * std::cos(4.5 * p.y() + 1.0) * std::sin(5.5 * p.z() - p.x()) + 0.15 * std::cos(10.0 * p.x() - 4.0 * p.y()),
            0.5 + 0.25 * std::sin(3.0 * (p.x() + p.y() + p.z())) + 0.15 * std::cos(12.0 * p.y() - 5.0 * p.z() + 3.0 * p.x())};
}

double gray(const Eigen::Vector3d& rgb) { return 0.299 * rgb[0] + 0.587 * rgb[1] + 0.114 * rgb[2]; }

/// @brief Camera-to-world pose of a camera at `centre` looking at `target` (x right, y down, z forward; the
/// world's y points down too).
Eigen::Matrix4d look_at(const Eigen::Vector3d& centre, const Eigen::Vector3d& target) {
    const Eigen::Vector3d z = (target - centre).normalized();
    const Eigen::Vector3d x = Eigen::Vector3d::UnitY().cross(z).normalized();
    const Eigen::Vector3d y = z.cross(x);
    Eigen::Matrix4d m = Eigen::Matrix4d::Identity();
    m.block<3, 1>(0, 0) = x;
    m.block<3, 1>(0, 1) = y;
    m.block<3, 1>(0, 2) = z;
    m.topRightCorner<3, 1>() = centre;
    return m;
}

/// @brief 8-bit RGB colour and float depth (metres) of the room seen from camera-to-world `pose`: every pixel's
/// ray leaves the box through the wall ahead of it, so there is no background and no occlusion.
RGBDImage render_room(const Eigen::Matrix4d& pose, double distortion) {
    Image color = o3d::geometry::make_image(W, H, 3, 1), depth = o3d::geometry::make_image(W, H, 1, 4);
    const Eigen::Matrix3d r = pose.topLeftCorner<3, 3>();
    const Eigen::Vector3d c = pose.topRightCorner<3, 1>();
    for (int v = 0; v < H; ++v)
        for (int u = 0; u < W; ++u) {
            const Eigen::Vector2d n((u - kCamera.cx) / kCamera.fx, (v - kCamera.cy) / kCamera.fy);
            const Eigen::Vector3d d = r * (n * (1 + distortion * n.squaredNorm())).homogeneous();
            double t = INFINITY;
            for (int axis = 0; axis < 3; ++axis)
                if (d[axis] != 0) t = std::min(t, ((d[axis] > 0 ? kRoomHi : kRoomLo)[axis] - c[axis]) / d[axis]);
            const Eigen::Vector3d rgb = texture(c + t * d);
            for (int k = 0; k < 3; ++k) color.pixel<uint8_t>(u, v)[k] = uint8_t(std::lround(255.0 * rgb[k]));
            *depth.pixel<float>(u, v) = float(t);  // the camera ray has z = 1, so t is the depth
        }
    return {color, depth};
}

/// @brief The room's six walls, each an n x n grid of vertices (triangulated, though only vertices matter).
TriangleMesh room_mesh(int n) {
    TriangleMesh mesh;
    for (int axis = 0; axis < 3; ++axis)
        for (int side = 0; side < 2; ++side) {
            const int a = (axis + 1) % 3, b = (axis + 2) % 3;
            const int base = int(mesh.vertices.size());
            for (int j = 0; j < n; ++j)
                for (int i = 0; i < n; ++i) {
                    Eigen::Vector3d p;
                    p[axis] = side ? kRoomHi[axis] : kRoomLo[axis];
                    p[a] = kRoomLo[a] + (kRoomHi[a] - kRoomLo[a]) * i / (n - 1);
                    p[b] = kRoomLo[b] + (kRoomHi[b] - kRoomLo[b]) * j / (n - 1);
                    mesh.vertices.push_back(p);
                }
            for (int j = 0; j + 1 < n; ++j)
                for (int i = 0; i + 1 < n; ++i) {
                    const int q = base + j * n + i;
                    mesh.triangles.emplace_back(q, q + 1, q + n);
                    mesh.triangles.emplace_back(q + 1, q + n + 1, q + n);
                }
        }
    return mesh;
}

Eigen::Matrix4d small_motion(const Eigen::Vector3d& axis, double deg, const Eigen::Vector3d& t) {
    Eigen::Matrix4d m = Eigen::Matrix4d::Identity();
    m.topLeftCorner<3, 3>() = Eigen::AngleAxisd(deg * M_PI / 180, axis.normalized()).toRotationMatrix();
    m.topRightCorner<3, 1>() = t;
    return m;
}

/// @brief The scene: images from the true poses, and the trajectory the optimizer is given (perturbed).
struct Scene {
    TriangleMesh mesh = room_mesh(41);
    std::vector<RGBDImage> images;
    PinholeCameraTrajectory truth, start;

    /// `distortion`: the images' radial lens distortion k1 (a pixel at normalised radius r shows the ray at
    /// r (1 + k1 r^2)), which no pose can undo.
    explicit Scene(double distortion) {
        // Spread apart, all looking into one corner of the room. Photometric consistency cannot see a motion common
        // to all cameras that keeps the surface they see on itself (e.g. sliding along one wall); three walls at
        // right angles, seen with parallax, leave no such motion.
        const Eigen::Vector3d corner = kRoomHi;
        const Eigen::Matrix4d poses[] = {look_at({0, 0, 0}, corner), look_at({-0.6, -0.4, -0.5}, corner + Eigen::Vector3d(-0.2, 0, 0)),
                                         look_at({0.5, -0.5, 0.3}, corner + Eigen::Vector3d(0, -0.2, 0)),
                                         look_at({-0.5, 0.5, 0.5}, corner + Eigen::Vector3d(0, 0, -0.2)),
                                         look_at({0.4, 0.4, -0.6}, corner + Eigen::Vector3d(-0.1, -0.1, -0.1))};
        const Eigen::Matrix4d perturbations[] = {
            small_motion({1, 2, 0}, 1.5, {0.02, -0.01, 0.01}), small_motion({-1, 0, 2}, 1.5, {-0.01, 0.02, 0.0}),
            small_motion({0, 1, 1}, 1.5, {0.0, -0.02, -0.015}), small_motion({2, -1, 1}, 1.5, {0.015, 0.01, 0.01}),
            small_motion({1, 1, -1}, 1.5, {-0.02, 0.0, 0.01})};
        for (size_t i = 0; i < std::size(poses); ++i) {
            images.push_back(render_room(poses[i], distortion));
            o3d::camera::PinholeCameraParameters p;
            p.intrinsic = kCamera;
            p.extrinsic = poses[i].inverse();
            truth.parameters.push_back(p);
            p.extrinsic = perturbations[i] * p.extrinsic;
            start.parameters.push_back(p);
        }
    }
};

/// @brief Options for these small images: the room's walls seen at a slant change depth by several cm per pixel
/// at 160 x 120 (four times Open3D's 640 x 480 pixel size), which is no discontinuity; the room is up to 3 m deep.
template <typename Option>
Option scene_option(int iterations) {
    Option o;
    o.maximum_iteration = iterations;
    o.maximum_allowable_depth = 4.0;
    o.depth_threshold_for_discontinuity_check = 1.0;
    o.depth_threshold_for_visibility_check = 0.2;
    o.image_boundary_margin = 4;
    return o;
}

/// @brief Bilinear weighted-gray intensity of an 8-bit RGB image at (u, v); false off the image.
bool image_gray(const Image& color, double u, double v, double& out) {
    if (!(u >= 0 && v >= 0 && u < W - 1 && v < H - 1)) return false;
    const int u0 = int(u), v0 = int(v);
    const double a = u - u0, b = v - v0;
    auto g = [&](int x, int y) {
        const uint8_t* p = color.pixel<uint8_t>(x, y);
        return gray(Eigen::Vector3d(p[0], p[1], p[2]) / 255.0);
    };
    out = (1 - b) * ((1 - a) * g(u0, v0) + a * g(u0 + 1, v0)) + b * ((1 - a) * g(u0, v0 + 1) + a * g(u0 + 1, v0 + 1));
    return true;
}

/// @brief Mean over every (image, vertex) pair where the vertex projects into the image of (image intensity at
/// its projection - the vertex colour's intensity)^2: the paper's objective, computed independently here.
double photometric_error(const Scene& s, const TriangleMesh& colored, const PinholeCameraTrajectory& trajectory) {
    double sum = 0.0;
    long n = 0;
    for (size_t c = 0; c < s.images.size(); ++c) {
        const Eigen::Matrix4d& t = trajectory.parameters[c].extrinsic;
        for (size_t i = 0; i < colored.vertices.size(); ++i) {
            const Eigen::Vector3d p = t.topLeftCorner<3, 3>() * colored.vertices[i] + t.topRightCorner<3, 1>();
            if (p.z() <= 0) continue;
            const double u = kCamera.fx * p.x() / p.z() + kCamera.cx, v = kCamera.fy * p.y() / p.z() + kCamera.cy;
            if (u < 4 || v < 4 || u > W - 5 || v > H - 5) continue;  // the optimizer's margin
            double g = 0;
            if (!image_gray(s.images[c].color, u, v, g)) continue;
            const double r = g - gray(colored.vertex_colors[i]);
            sum += r * r;
            ++n;
        }
    }
    return sum / double(n);
}

/// @brief Mean over the images of the rotation (degrees) and camera-centre (metres) errors.
std::pair<double, double> pose_error(const PinholeCameraTrajectory& a, const PinholeCameraTrajectory& b) {
    double rot = 0, trans = 0;
    for (size_t c = 0; c < a.parameters.size(); ++c) {
        const Eigen::Matrix4d e = a.parameters[c].extrinsic * b.parameters[c].extrinsic.inverse();
        rot += Eigen::AngleAxisd(Eigen::Matrix3d(e.topLeftCorner<3, 3>())).angle() * 180 / M_PI;
        trans += (a.parameters[c].extrinsic.inverse().topRightCorner<3, 1>() -
                  b.parameters[c].extrinsic.inverse().topRightCorner<3, 1>())
                     .norm();
    }
    return {rot / double(a.parameters.size()), trans / double(a.parameters.size())};
}

/// @brief Mean RGB distance of the vertex colours from the texture, over the vertices some true camera sees.
double color_error(const Scene& s, const TriangleMesh& colored) {
    double sum = 0;
    long n = 0;
    for (size_t i = 0; i < colored.vertices.size(); ++i) {
        bool seen = false;
        for (const auto& p : s.truth.parameters) {
            const Eigen::Vector3d q = p.extrinsic.topLeftCorner<3, 3>() * colored.vertices[i] + p.extrinsic.topRightCorner<3, 1>();
            const double u = kCamera.fx * q.x() / q.z() + kCamera.cx, v = kCamera.fy * q.y() / q.z() + kCamera.cy;
            seen = seen || (q.z() > 0 && u >= 4 && v >= 4 && u <= W - 5 && v <= H - 5);
        }
        if (!seen) continue;
        sum += (colored.vertex_colors[i] - texture(colored.vertices[i])).norm();
        ++n;
    }
    return sum / double(n);
}

const Scene& scene() {
    static const Scene s(0.0);
    return s;
}

TEST(ColorMap, RigidRecoversPerturbedPoses) {
    const Scene& s = scene();
    const auto before = o3d::color_map::run_rigid_optimizer(s.mesh, s.images, s.start, scene_option<RigidOptimizerOption>(0));
    const auto after = o3d::color_map::run_rigid_optimizer(s.mesh, s.images, s.start, scene_option<RigidOptimizerOption>(100));
    // No iterations: the poses come back unchanged.
    for (size_t c = 0; c < s.start.parameters.size(); ++c)
        EXPECT_EQ(before.trajectory.parameters[c].extrinsic, s.start.parameters[c].extrinsic);

    const double e0 = photometric_error(s, before.mesh, s.start), e1 = photometric_error(s, after.mesh, after.trajectory);
    const auto [rot0, trans0] = pose_error(s.start, s.truth);
    const auto [rot1, trans1] = pose_error(after.trajectory, s.truth);
    const double c0 = color_error(s, before.mesh), c1 = color_error(s, after.mesh);
    std::printf("rigid: photometric error %.3g -> %.3g, pose error %.3f deg %.4f m -> %.3f deg %.4f m, "
                "colour error %.4f -> %.4f\n", e0, e1, rot0, trans0, rot1, trans1, c0, c1);
    EXPECT_LT(e1, 0.05 * e0);
    EXPECT_LT(after.residuals.back(), 0.05 * after.residuals.front());  // the optimizer's own objective agrees
    EXPECT_LT(rot1, 0.5 * rot0);
    EXPECT_LT(trans1, 0.5 * trans0);
    EXPECT_LT(c1, 0.5 * c0);
    // Close to what the exact poses give (with the library's own averaging of the images at them).
    const auto exact = o3d::color_map::run_rigid_optimizer(s.mesh, s.images, s.truth, scene_option<RigidOptimizerOption>(0));
    EXPECT_LT(e1, 3 * photometric_error(s, exact.mesh, s.truth) + 1e-5);
}

TEST(ColorMap, NonRigidDoesAtLeastAsWellAsRigid) {
    const Scene& s = scene();
    auto o = scene_option<NonRigidOptimizerOption>(100);
    o.number_of_vertical_anchors = 6;
    const auto before = o3d::color_map::run_non_rigid_optimizer(s.mesh, s.images, s.start,
                                                                scene_option<NonRigidOptimizerOption>(0));
    const auto non_rigid = o3d::color_map::run_non_rigid_optimizer(s.mesh, s.images, s.start, o);
    const auto rigid = o3d::color_map::run_rigid_optimizer(s.mesh, s.images, s.start, scene_option<RigidOptimizerOption>(100));
    const double e0 = photometric_error(s, before.mesh, s.start);
    const double e_rigid = photometric_error(s, rigid.mesh, rigid.trajectory);
    const double e_non_rigid = photometric_error(s, non_rigid.mesh, non_rigid.trajectory);
    const auto [rot0, trans0] = pose_error(s.start, s.truth);
    const auto [rot1, trans1] = pose_error(non_rigid.trajectory, s.truth);
    std::printf("non-rigid: photometric error %.3g -> %.3g (rigid %.3g), pose error %.3f deg %.4f m -> %.3f deg "
                "%.4f m, colour error %.4f -> %.4f (rigid %.4f)\n", e0, e_non_rigid, e_rigid, rot0, trans0, rot1, trans1,
                color_error(s, before.mesh), color_error(s, non_rigid.mesh), color_error(s, rigid.mesh));
    EXPECT_LT(e_non_rigid, 0.05 * e0);
    EXPECT_LT(rot1, 0.5 * rot0);
    EXPECT_LT(trans1, 0.5 * trans0);
    EXPECT_LT(e_non_rigid, 1.05 * e_rigid);
    EXPECT_LT(color_error(s, non_rigid.mesh), 1.05 * color_error(s, rigid.mesh));
}

TEST(ColorMap, NonRigidFitsWhatNoPoseCan) {
    // Lens distortion moves the image corners by about 3 pixels, so no poses make the images agree exactly;
    // the warp can. (Agreement is what the method optimizes: judged against the texture, a weakly regularised
    // warp is free to drift with the images, so only the optimizer's own objective is compared here.)
    static const Scene s(0.06);
    auto o = scene_option<NonRigidOptimizerOption>(100);
    o.number_of_vertical_anchors = 6;
    o.non_rigid_anchor_point_weight = 0.03;
    const auto non_rigid = o3d::color_map::run_non_rigid_optimizer(s.mesh, s.images, s.start, o);
    const auto rigid = o3d::color_map::run_rigid_optimizer(s.mesh, s.images, s.start, scene_option<RigidOptimizerOption>(100));
    std::printf("distorted images: mean squared residual %.3g -> rigid %.3g, non-rigid %.3g\n", rigid.residuals.front(),
                rigid.residuals.back(), non_rigid.residuals.back());
    EXPECT_LT(rigid.residuals.back(), 0.05 * rigid.residuals.front());
    EXPECT_LT(non_rigid.residuals.back(), 0.8 * rigid.residuals.back());
}

TEST(ColorMap, ResultDoesNotDependOnThreadCount) {
    const Scene& s = scene();
    for (bool non_rigid : {false, true}) {
        auto o = scene_option<NonRigidOptimizerOption>(5);
        o.number_of_vertical_anchors = 4;
        auto run = [&](int threads) {
            o.num_threads = threads;
            RigidOptimizerOption rigid;
            static_cast<o3d::color_map::OptimizerOption&>(rigid) = o;
            return non_rigid ? o3d::color_map::run_non_rigid_optimizer(s.mesh, s.images, s.start, o)
                             : o3d::color_map::run_rigid_optimizer(s.mesh, s.images, s.start, rigid);
        };
        const auto one = run(1), four = run(4);
        ASSERT_EQ(one.mesh.vertex_colors.size(), four.mesh.vertex_colors.size());
        for (size_t i = 0; i < one.mesh.vertex_colors.size(); ++i)
            ASSERT_EQ(one.mesh.vertex_colors[i], four.mesh.vertex_colors[i]) << i;
        for (size_t c = 0; c < one.trajectory.parameters.size(); ++c)
            EXPECT_EQ(one.trajectory.parameters[c].extrinsic, four.trajectory.parameters[c].extrinsic);
    }
}

// ---- the plain average, by hand ---------------------------------------------------------------------------------

constexpr int kTinyW = 32, kTinyH = 24;
const PinholeCameraIntrinsic kTiny{kTinyW, kTinyH, 20.0, 20.0, 15.5, 11.5};

/// @brief An 8-bit RGB image whose pixel (u, v) is f(u, v) / 255 and a depth of 1 m everywhere.
template <typename F>
RGBDImage tiny_image(F f) {
    Image color = o3d::geometry::make_image(kTinyW, kTinyH, 3, 1), depth = o3d::geometry::make_image(kTinyW, kTinyH, 1, 4);
    for (int v = 0; v < kTinyH; ++v)
        for (int u = 0; u < kTinyW; ++u) {
            const Eigen::Vector3i rgb = f(u, v);
            for (int k = 0; k < 3; ++k) color.pixel<uint8_t>(u, v)[k] = uint8_t(rgb[k]);
            *depth.pixel<float>(u, v) = 1.0f;
        }
    return {color, depth};
}

/// @brief The point at depth `z` that the tiny camera at the identity sees at pixel (u, v).
Eigen::Vector3d at_pixel(double u, double v, double z) {
    return {(u - kTiny.cx) / kTiny.fx * z, (v - kTiny.cy) / kTiny.fy * z, z};
}

TEST(ColorMap, NoIterationsGiveThePlainAverage) {
    std::vector<RGBDImage> images = {tiny_image([](int u, int v) { return Eigen::Vector3i(u, 2 * v, 100); }),
                                     tiny_image([](int u, int v) { return Eigen::Vector3i(50, u + v, 0); })};
    PinholeCameraTrajectory trajectory;
    trajectory.parameters.resize(2);
    for (auto& p : trajectory.parameters) p.intrinsic = kTiny;
    TriangleMesh mesh;
    mesh.vertices = {at_pixel(10.5, 7.25, 1.0), at_pixel(20.0, 12.0, 1.0),
                     at_pixel(12.0, 10.0, 1.5),  // 0.5 m behind the depth: unseen
                     {0.0, 0.0, -1.0}};          // behind the cameras: unseen
    RigidOptimizerOption o;
    o.maximum_iteration = 0;
    o.image_boundary_margin = 2;
    o.invisible_vertex_color_knn = 2;
    const auto out = o3d::color_map::run_rigid_optimizer(mesh, images, trajectory, o);
    ASSERT_EQ(out.mesh.vertex_colors.size(), 4u);
    // Bilinear samples: image 0 gives (u, 2v, 100), image 1 gives (50, u + v, 0); the colour is their mean.
    const Eigen::Vector3d c0 = Eigen::Vector3d((10.5 + 50) / 2, (14.5 + 17.75) / 2, 50) / 255.0;
    const Eigen::Vector3d c1 = Eigen::Vector3d((20 + 50) / 2.0, (24 + 32) / 2.0, 50) / 255.0;
    EXPECT_LT((out.mesh.vertex_colors[0] - c0).norm(), 1e-6);
    EXPECT_LT((out.mesh.vertex_colors[1] - c1).norm(), 1e-6);
    // The unseen vertices take the mean of their two nearest seen ones (there are only two).
    EXPECT_LT((out.mesh.vertex_colors[2] - (c0 + c1) / 2).norm(), 1e-6);
    EXPECT_LT((out.mesh.vertex_colors[3] - (c0 + c1) / 2).norm(), 1e-6);
    // With one neighbour, vertex 2 copies the nearer seen vertex.
    o.invisible_vertex_color_knn = 1;
    const auto one = o3d::color_map::run_rigid_optimizer(mesh, images, trajectory, o);
    const size_t nearest = (mesh.vertices[2] - mesh.vertices[0]).norm() < (mesh.vertices[2] - mesh.vertices[1]).norm() ? 0 : 1;
    EXPECT_LT((one.mesh.vertex_colors[2] - one.mesh.vertex_colors[nearest]).norm(), 1e-12);
    // A float intensity image colours gray.
    images[0].color = o3d::geometry::create_float_image(images[0].color, o3d::geometry::ImageConvertType::Weighted);
    const auto g = o3d::color_map::run_rigid_optimizer(mesh, images, trajectory, o);
    const double g0 = (0.299 * 10.5 + 0.587 * 14.5 + 0.114 * 100) / 255.0;
    EXPECT_NEAR(g.mesh.vertex_colors[0][0], (g0 + 50 / 255.0) / 2, 1e-6);
    EXPECT_NEAR(g.mesh.vertex_colors[0][2], (g0 + 0.0) / 2, 1e-6);
}

TEST(ColorMap, ProgressReportsAndCancels) {
    const Scene& s = scene();
    auto o = scene_option<RigidOptimizerOption>(4);
    std::vector<double> seen;
    o.progress = [&](double f) {
        seen.push_back(f);
        return true;
    };
    o3d::color_map::run_rigid_optimizer(s.mesh, s.images, s.start, o);
    EXPECT_EQ(seen, (std::vector<double>{0.25, 0.5, 0.75, 1.0}));
    o.progress = [](double f) { return f < 0.5; };
    EXPECT_THROW(o3d::color_map::run_rigid_optimizer(s.mesh, s.images, s.start, o), o3d::Cancelled);
}

TEST(ColorMap, RejectsBadArguments) {
    const Scene& s = scene();
    const RigidOptimizerOption o = scene_option<RigidOptimizerOption>(1);
    using o3d::InvalidArgument;
    using o3d::color_map::run_rigid_optimizer;
    EXPECT_THROW(run_rigid_optimizer(TriangleMesh{}, s.images, s.start, o), InvalidArgument);
    TriangleMesh nan_mesh = s.mesh;
    nan_mesh.vertices[3].x() = NAN;
    EXPECT_THROW(run_rigid_optimizer(nan_mesh, s.images, s.start, o), InvalidArgument);
    EXPECT_THROW(run_rigid_optimizer(s.mesh, std::vector<RGBDImage>{}, PinholeCameraTrajectory{}, o), InvalidArgument);
    PinholeCameraTrajectory short_trajectory = s.start;
    short_trajectory.parameters.pop_back();
    EXPECT_THROW(run_rigid_optimizer(s.mesh, s.images, short_trajectory, o), InvalidArgument);
    std::vector<RGBDImage> bad = s.images;
    bad[1].depth = bad[1].color;  // 8-bit RGB depth
    EXPECT_THROW(run_rigid_optimizer(s.mesh, bad, s.start, o), InvalidArgument);
    bad = s.images;
    bad[2].color = o3d::geometry::make_image(W, H, 4, 1);  // RGBA
    EXPECT_THROW(run_rigid_optimizer(s.mesh, bad, s.start, o), InvalidArgument);
    PinholeCameraTrajectory wrong = s.start;
    wrong.parameters[0].intrinsic.width = W / 2;
    EXPECT_THROW(run_rigid_optimizer(s.mesh, s.images, wrong, o), InvalidArgument);
    wrong = s.start;
    wrong.parameters[0].extrinsic(0, 3) = NAN;
    EXPECT_THROW(run_rigid_optimizer(s.mesh, s.images, wrong, o), InvalidArgument);
    auto bad_option = [&](auto edit) {
        RigidOptimizerOption b = o;
        edit(b);
        EXPECT_THROW(run_rigid_optimizer(s.mesh, s.images, s.start, b), InvalidArgument);
    };
    bad_option([](RigidOptimizerOption& b) { b.maximum_iteration = -1; });
    bad_option([](RigidOptimizerOption& b) { b.maximum_allowable_depth = NAN; });
    bad_option([](RigidOptimizerOption& b) { b.depth_threshold_for_visibility_check = 0; });
    bad_option([](RigidOptimizerOption& b) { b.depth_threshold_for_discontinuity_check = NAN; });
    bad_option([](RigidOptimizerOption& b) { b.half_dilation_kernel_size_for_discontinuity_map = -1; });
    bad_option([](RigidOptimizerOption& b) { b.image_boundary_margin = -1; });
    bad_option([](RigidOptimizerOption& b) { b.invisible_vertex_color_knn = 0; });
    bad_option([](RigidOptimizerOption& b) { b.num_threads = -1; });
    NonRigidOptimizerOption n = scene_option<NonRigidOptimizerOption>(1);
    n.number_of_vertical_anchors = 1;
    EXPECT_THROW(o3d::color_map::run_non_rigid_optimizer(s.mesh, s.images, s.start, n), InvalidArgument);
    n.number_of_vertical_anchors = 4;
    n.non_rigid_anchor_point_weight = NAN;
    EXPECT_THROW(o3d::color_map::run_non_rigid_optimizer(s.mesh, s.images, s.start, n), InvalidArgument);
}

TEST(ColorMap, DefaultsAreOpen3Ds) {
    const NonRigidOptimizerOption o;
    EXPECT_EQ(o.maximum_iteration, 300);
    EXPECT_EQ(o.maximum_allowable_depth, 2.5);
    EXPECT_EQ(o.depth_threshold_for_visibility_check, 0.03);
    EXPECT_EQ(o.depth_threshold_for_discontinuity_check, 0.1);
    EXPECT_EQ(o.half_dilation_kernel_size_for_discontinuity_map, 3);
    EXPECT_EQ(o.image_boundary_margin, 10);
    EXPECT_EQ(o.invisible_vertex_color_knn, 3);
    EXPECT_EQ(o.number_of_vertical_anchors, 16);
    EXPECT_EQ(o.non_rigid_anchor_point_weight, 0.316);
}

}  // namespace
