// SPDX-License-Identifier: MIT
// The camera math of the renderer (view_camera.h), without OpenGL: pinhole projection through the OpenGL
// matrices, Open3D's ViewControl view (distance from zoom and the box, the intrinsic it reports), and the
// near/far planes.
#include "o3d/visualization/view_camera.h"

#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cmath>

#include "o3d/utility/error.h"

namespace o3d::visualization {
namespace {

constexpr double kPi = 3.14159265358979323846;

/// @brief Pixel (u, v) and depth of world point `p` through OpenGL's pipeline (projection, divide, viewport).
Eigen::Vector3d through_gl(const camera::PinholeCameraParameters& cam, const Eigen::Vector3d& p, double n, double f) {
    const Eigen::Vector4d clip = gl_projection(cam.intrinsic, n, f) * gl_view(cam.extrinsic) * p.homogeneous();
    const Eigen::Vector3d ndc = clip.head<3>() / clip.w();
    const double u = (ndc.x() + 1) / 2 * cam.intrinsic.width - 0.5;
    const double v = (1 - ndc.y()) / 2 * cam.intrinsic.height - 0.5;  // image rows go down
    return {u, v, clip.w()};
}

TEST(ViewCamera, GlMatricesReproduceThePinholeModel) {
    camera::PinholeCameraParameters cam;
    cam.intrinsic = {640, 480, 525.0, 520.0, 300.25, 250.75};  // principal point off centre
    Eigen::Matrix4d e = Eigen::Matrix4d::Identity();
    e.block<3, 3>(0, 0) = Eigen::AngleAxisd(0.3, Eigen::Vector3d(1, 2, 3).normalized()).toRotationMatrix();
    e.block<3, 1>(0, 3) = Eigen::Vector3d(0.1, -0.2, 0.5);
    cam.extrinsic = e;
    for (const Eigen::Vector3d p : {Eigen::Vector3d(0.2, 0.1, 2.0), Eigen::Vector3d(-0.7, 0.4, 3.5)}) {
        const Eigen::Vector3d c = (e * p.homogeneous()).head<3>();
        const Eigen::Vector3d gl = through_gl(cam, p, 0.1, 10.0);
        EXPECT_NEAR(gl.x(), 525.0 * c.x() / c.z() + 300.25, 1e-9);
        EXPECT_NEAR(gl.y(), 520.0 * c.y() / c.z() + 250.75, 1e-9);
        EXPECT_NEAR(gl.z(), c.z(), 1e-12);  // w_clip is the depth along the optical axis
    }
}

TEST(ViewCamera, LookatViewIsOpen3dsViewControl) {
    SceneBox box;
    box.add(Eigen::Vector3d(-1, -2, 0));
    box.add(Eigen::Vector3d(1, 2, 0.5));  // largest extent 4
    const auto p = view_from_lookat(Eigen::Vector3d(0, 0, 0.25), Eigen::Vector3d(0, 0, 1), Eigen::Vector3d(0, 1, 0),
                                    0.7, box, 640, 480);
    // fx = fy = h / (2 tan 30 deg); principal point at the centre (w / 2 - 0.5, h / 2 - 0.5).
    EXPECT_NEAR(p.intrinsic.fx, 480 / (2 * std::tan(kPi / 6)), 1e-9);
    EXPECT_EQ(p.intrinsic.fy, p.intrinsic.fx);
    EXPECT_EQ(p.intrinsic.cx, 319.5);
    EXPECT_EQ(p.intrinsic.cy, 239.5);
    // The eye sits zoom * extent / tan(30 deg) along front from lookat; the camera looks back along -front.
    const double distance = 0.7 * 4 / std::tan(kPi / 6);
    const Eigen::Matrix3d r = p.extrinsic.block<3, 3>(0, 0);
    const Eigen::Vector3d eye = -r.transpose() * p.extrinsic.block<3, 1>(0, 3);
    EXPECT_TRUE(eye.isApprox(Eigen::Vector3d(0, 0, 0.25 + distance), 1e-12));
    EXPECT_TRUE(r.row(2).transpose().isApprox(Eigen::Vector3d(0, 0, -1), 1e-12));
    EXPECT_TRUE(r.row(1).transpose().isApprox(Eigen::Vector3d(0, -1, 0), 1e-12));  // image y is -up
    EXPECT_THROW(view_from_lookat(Eigen::Vector3d::Zero(), Eigen::Vector3d(0, 1, 0), Eigen::Vector3d(0, 2, 0), 0.7,
                                  box, 640, 480),
                 InvalidArgument);
    EXPECT_THROW(view_from_lookat(Eigen::Vector3d::Zero(), Eigen::Vector3d(0, 0, 1), Eigen::Vector3d(0, 1, 0), 2.5,
                                  box, 640, 480),
                 InvalidArgument);
}

TEST(ViewCamera, EyeViewLooksAtTheCenter) {
    const auto p = view_from_eye(45.0, Eigen::Vector3d(1, 1, 1), Eigen::Vector3d(1, 1, 4), Eigen::Vector3d(0, 1, 0),
                                 200, 100);
    const Eigen::Vector3d center = (p.extrinsic * Eigen::Vector4d(1, 1, 1, 1)).head<3>();
    EXPECT_NEAR(center.x(), 0, 1e-12);
    EXPECT_NEAR(center.y(), 0, 1e-12);
    EXPECT_NEAR(center.z(), 3, 1e-12);
    EXPECT_NEAR(p.intrinsic.fy, 100 / (2 * std::tan(22.5 / 180 * kPi)), 1e-9);
}

TEST(ViewCamera, NearFarEncloseTheBox) {
    SceneBox box;
    box.add(Eigen::Vector3d(-1, -1, 2));
    box.add(Eigen::Vector3d(1, 1, 4));
    const auto [n, f] = near_far(Eigen::Matrix4d::Identity(), box);
    EXPECT_NEAR(n, 2 - 0.2, 1e-12);
    EXPECT_NEAR(f, 4 + 0.2, 1e-12);
    // A camera inside the box keeps far / near at 1e4.
    Eigen::Matrix4d inside = Eigen::Matrix4d::Identity();
    inside(2, 3) = -3;
    const auto [n2, f2] = near_far(inside, box);
    EXPECT_NEAR(f2 / n2, 1e4, 1e-6);
    EXPECT_THROW(check_rigid((Eigen::Matrix4d() << 2, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1).finished()),
                 InvalidArgument);
}

}  // namespace
}  // namespace o3d::visualization
