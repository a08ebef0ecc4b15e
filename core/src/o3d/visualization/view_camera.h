// SPDX-License-Identifier: MIT
#pragma once
/// @file view_camera.h
/// @brief The camera of a render: Open3D's ViewControl views (lookat/front/up/zoom, eye/center/up with
/// a field of view) resolved to pinhole parameters, and pinhole parameters turned into OpenGL matrices.
#include <Eigen/Core>
#include <utility>

#include "o3d/camera/pinhole_camera.h"

namespace o3d::visualization {

/// @brief An axis-aligned box that grows as points are added; empty until the first finite point.
struct SceneBox {
    Eigen::Vector3d min_bound = Eigen::Vector3d::Constant(1.0);
    Eigen::Vector3d max_bound = Eigen::Vector3d::Constant(-1.0);

    bool empty() const { return (min_bound.array() > max_bound.array()).any(); }
    void add(const Eigen::Vector3d& p);
    void add(const SceneBox& other);
    Eigen::Vector3d center() const { return empty() ? Eigen::Vector3d::Zero() : Eigen::Vector3d(0.5 * (min_bound + max_bound)); }
    /// @brief The largest edge, or 1 for an empty box or a single point (so that views stay defined).
    double max_extent() const;
};

/// @brief Open3D's ViewControl defaults.
constexpr double kDefaultFieldOfView = 60.0;
constexpr double kDefaultZoom = 0.7;
constexpr double kMinZoom = 0.02;
constexpr double kMaxZoom = 2.0;
constexpr double kMinFieldOfView = 5.0;
constexpr double kMaxFieldOfView = 90.0;

/// @brief ViewControl.set_lookat/front/up/zoom resolved against `box` as Open3D does: the eye sits at
/// lookat + front * zoom * extent / tan(fov / 2); fx = fy = height / (2 tan(fov / 2)), principal point
/// at the image centre (width / 2 - 0.5, height / 2 - 0.5). `fov_deg` is the vertical field of view.
camera::PinholeCameraParameters view_from_lookat(const Eigen::Vector3d& lookat, const Eigen::Vector3d& front,
                                                 const Eigen::Vector3d& up, double zoom, const SceneBox& box,
                                                 int width, int height, double fov_deg = kDefaultFieldOfView);
/// @brief A camera at `eye` looking at `center` with a vertical field of view (degrees).
camera::PinholeCameraParameters view_from_eye(double vertical_fov_deg, const Eigen::Vector3d& center,
                                              const Eigen::Vector3d& eye, const Eigen::Vector3d& up, int width,
                                              int height);

/// @brief Throws InvalidArgument unless `extrinsic` is finite and rigid (orthonormal, det +1, last row 0 0 0 1).
void check_rigid(const Eigen::Matrix4d& extrinsic);

/// @brief Near and far planes enclosing `box` as seen by `extrinsic` (a margin of a tenth of its extent;
/// far / near at most 1e4 so the depth buffer keeps its precision).
std::pair<double, double> near_far(const Eigen::Matrix4d& extrinsic, const SceneBox& box);

/// @brief OpenGL projection for a pinhole camera: pixel (u, v), with pixel centres at integers and v
/// downwards, maps exactly as u = fx x / z + cx, v = fy y / z + cy.
Eigen::Matrix4d gl_projection(const camera::PinholeCameraIntrinsic& intrinsic, double z_near, double z_far);
/// @brief World to OpenGL eye coordinates (y up, looking along -z) for a world-to-camera extrinsic.
Eigen::Matrix4d gl_view(const Eigen::Matrix4d& extrinsic);

}  // namespace o3d::visualization
