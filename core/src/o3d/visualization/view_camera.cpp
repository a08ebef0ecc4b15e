// SPDX-License-Identifier: MIT
#include "o3d/visualization/view_camera.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <string>

#include "o3d/utility/error.h"

namespace o3d::visualization {
namespace {

constexpr double kPi = 3.14159265358979323846;

/// @brief ViewControl's camera frame: right = up x front, then up re-orthogonalized; the camera looks along
/// -front, with image x = right and image y = -up.
camera::PinholeCameraParameters frame_to_parameters(const Eigen::Vector3d& eye, Eigen::Vector3d front,
                                                    Eigen::Vector3d up, double fov_deg, int width, int height) {
    front.normalize();
    const Eigen::Vector3d right = up.cross(front).normalized();
    up = front.cross(right).normalized();
    camera::PinholeCameraParameters p;
    const double f = height / (2.0 * std::tan(fov_deg * 0.5 / 180.0 * kPi));
    p.intrinsic = {width, height, f, f, width / 2.0 - 0.5, height / 2.0 - 0.5};
    Eigen::Matrix4d e = Eigen::Matrix4d::Identity();
    e.block<1, 3>(0, 0) = right.transpose();
    e.block<1, 3>(1, 0) = -up.transpose();
    e.block<1, 3>(2, 0) = -front.transpose();
    e.block<3, 1>(0, 3) = -e.block<3, 3>(0, 0) * eye;
    p.extrinsic = e;
    return p;
}

void check_direction_pair(const Eigen::Vector3d& front, const Eigen::Vector3d& up, const char* front_name) {
    if (!front.allFinite() || !up.allFinite()) throw InvalidArgument("camera vectors must be finite");
    if (front.norm() < 1e-12) throw InvalidArgument(std::string(front_name) + " must be non-zero");
    if (up.norm() < 1e-12) throw InvalidArgument("up must be non-zero");
    if (front.normalized().cross(up.normalized()).norm() < 1e-9)
        throw InvalidArgument(std::string("up must not be parallel to ") + front_name);
}

}  // namespace

void SceneBox::add(const Eigen::Vector3d& p) {
    if (!p.allFinite()) return;
    if (empty()) {
        min_bound = max_bound = p;
        return;
    }
    min_bound = min_bound.cwiseMin(p);
    max_bound = max_bound.cwiseMax(p);
}

void SceneBox::add(const SceneBox& other) {
    if (other.empty()) return;
    add(other.min_bound);
    add(other.max_bound);
}

double SceneBox::max_extent() const {
    if (empty()) return 1.0;
    const double e = (max_bound - min_bound).maxCoeff();
    return e > 0 ? e : 1.0;
}

camera::PinholeCameraParameters view_from_lookat(const Eigen::Vector3d& lookat, const Eigen::Vector3d& front,
                                                 const Eigen::Vector3d& up, double zoom, const SceneBox& box,
                                                 int width, int height, double fov_deg) {
    if (!lookat.allFinite()) throw InvalidArgument("lookat must be finite");
    check_direction_pair(front, up, "front");
    if (!(zoom >= kMinZoom && zoom <= kMaxZoom))
        throw InvalidArgument("zoom must be in [0.02, 2] (Open3D's ViewControl range), got " + std::to_string(zoom));
    if (!(fov_deg >= kMinFieldOfView && fov_deg <= kMaxFieldOfView))
        throw InvalidArgument("field of view must be in [5, 90] degrees, got " + std::to_string(fov_deg));
    const double distance = zoom * box.max_extent() / std::tan(fov_deg * 0.5 / 180.0 * kPi);
    return frame_to_parameters(lookat + front.normalized() * distance, front, up, fov_deg, width, height);
}

camera::PinholeCameraParameters view_from_eye(double vertical_fov_deg, const Eigen::Vector3d& center,
                                              const Eigen::Vector3d& eye, const Eigen::Vector3d& up, int width,
                                              int height) {
    if (!(vertical_fov_deg > 0 && vertical_fov_deg < 180))
        throw InvalidArgument("vertical field of view must be in (0, 180) degrees, got " +
                              std::to_string(vertical_fov_deg));
    if (!center.allFinite() || !eye.allFinite()) throw InvalidArgument("center and eye must be finite");
    check_direction_pair(eye - center, up, "eye - center");
    return frame_to_parameters(eye, eye - center, up, vertical_fov_deg, width, height);
}

void check_rigid(const Eigen::Matrix4d& e) {
    if (!e.allFinite()) throw InvalidArgument("extrinsic must be finite");
    const Eigen::Matrix3d r = e.block<3, 3>(0, 0);
    const bool last_row = e(3, 0) == 0 && e(3, 1) == 0 && e(3, 2) == 0 && e(3, 3) == 1;
    if (!last_row || (r * r.transpose() - Eigen::Matrix3d::Identity()).norm() > 1e-6 || r.determinant() < 0)
        throw InvalidArgument("extrinsic must be a rigid transform (rotation + translation, last row 0 0 0 1)");
}

std::pair<double, double> near_far(const Eigen::Matrix4d& extrinsic, const SceneBox& box) {
    if (box.empty()) return {0.01, 100.0};
    const double margin = 0.1 * box.max_extent();
    double z_min = INFINITY, z_max = -INFINITY;
    for (int corner = 0; corner < 8; ++corner) {
        const Eigen::Vector3d p((corner & 1) ? box.max_bound.x() : box.min_bound.x(),
                                (corner & 2) ? box.max_bound.y() : box.min_bound.y(),
                                (corner & 4) ? box.max_bound.z() : box.min_bound.z());
        const double z = extrinsic.block<1, 3>(2, 0).dot(p) + extrinsic(2, 3);
        z_min = std::min(z_min, z);
        z_max = std::max(z_max, z);
    }
    const double z_far = std::max(z_max + margin, 1e-6);
    const double z_near = std::max(z_min - margin, z_far * 1e-4);
    return {z_near, z_far};
}

Eigen::Matrix4d gl_projection(const camera::PinholeCameraIntrinsic& k, double n, double f) {
    // x_ndc = 2 (u + 0.5) / W - 1 and y_ndc = 1 - 2 (v + 0.5) / H (OpenGL's y is up, the image's down).
    Eigen::Matrix4d p = Eigen::Matrix4d::Zero();
    p(0, 0) = 2.0 * k.fx / k.width;
    p(0, 2) = 1.0 - 2.0 * (k.cx + 0.5) / k.width;
    p(1, 1) = 2.0 * k.fy / k.height;
    p(1, 2) = 2.0 * (k.cy + 0.5) / k.height - 1.0;
    p(2, 2) = -(f + n) / (f - n);
    p(2, 3) = -2.0 * f * n / (f - n);
    p(3, 2) = -1.0;
    return p;
}

Eigen::Matrix4d gl_view(const Eigen::Matrix4d& extrinsic) {
    // The camera's y points down and z forward; OpenGL's eye space has y up and looks along -z.
    Eigen::Matrix4d flip = Eigen::Matrix4d::Identity();
    flip(1, 1) = -1;
    flip(2, 2) = -1;
    return flip * extrinsic;
}

}  // namespace o3d::visualization
