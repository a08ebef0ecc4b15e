// SPDX-License-Identifier: MIT
#pragma once
/// @file tsdf_test_scenes.h
/// @brief Exact depth and colour frames of analytic shapes (a sphere, an oriented box) from cameras around
/// them, ray cast per pixel, for the TSDF tests.
#include <Eigen/Dense>
#include <cmath>
#include <functional>
#include <limits>
#include <vector>

#include "o3d/camera/pinhole_camera.h"
#include "o3d/geometry/rgbd_image.h"

namespace o3d_test {

/// Distance along a unit-z ray (camera z of the hit), or +inf on a miss.
using RayCaster = std::function<double(const Eigen::Vector3d& origin, const Eigen::Vector3d& direction)>;

inline o3d::camera::PinholeCameraIntrinsic small_camera() {
    o3d::camera::PinholeCameraIntrinsic k;
    k.width = 320;
    k.height = 240;
    k.fx = k.fy = 300.0;
    k.cx = 159.5;
    k.cy = 119.5;
    return k;
}

/// World-to-camera extrinsic of a camera at `eye` looking at the origin.
inline Eigen::Matrix4d look_at_origin(const Eigen::Vector3d& eye) {
    const Eigen::Vector3d z = (-eye).normalized();
    const Eigen::Vector3d helper = std::abs(z.y()) < 0.9 ? Eigen::Vector3d::UnitY() : Eigen::Vector3d::UnitX();
    const Eigen::Vector3d x = helper.cross(z).normalized();
    const Eigen::Vector3d y = z.cross(x);
    Eigen::Matrix4d e = Eigen::Matrix4d::Identity();
    e.block<1, 3>(0, 0) = x.transpose();
    e.block<1, 3>(1, 0) = y.transpose();
    e.block<1, 3>(2, 0) = z.transpose();
    e.topRightCorner<3, 1>() = -e.topLeftCorner<3, 3>() * eye;
    return e;
}

/// Eyes on a sphere of radius `distance`: the six axis directions and the eight diagonals.
inline std::vector<Eigen::Vector3d> eyes_around(double distance) {
    std::vector<Eigen::Vector3d> eyes;
    for (int axis = 0; axis < 3; ++axis)
        for (double s : {-1.0, 1.0}) eyes.push_back(distance * s * Eigen::Vector3d::Unit(axis));
    for (double x : {-1.0, 1.0})
        for (double y : {-1.0, 1.0})
            for (double z : {-1.0, 1.0}) eyes.push_back(distance * Eigen::Vector3d(x, y, z).normalized());
    return eyes;
}

/// An RGB-D frame (RGB8 colour, float depth in metres; 0 where the ray misses).
inline o3d::geometry::RGBDImage render(const RayCaster& cast, const o3d::camera::PinholeCameraIntrinsic& k,
                                       const Eigen::Matrix4d& extrinsic, const uint8_t rgb[3]) {
    o3d::geometry::RGBDImage frame;
    frame.depth = {k.width, k.height, 1, 4, std::vector<uint8_t>(size_t(k.width) * size_t(k.height) * 4)};
    frame.color = {k.width, k.height, 3, 1, std::vector<uint8_t>(size_t(k.width) * size_t(k.height) * 3)};
    const Eigen::Matrix3d rotation_t = extrinsic.topLeftCorner<3, 3>().transpose();
    const Eigen::Vector3d eye = -rotation_t * extrinsic.topRightCorner<3, 1>();
    for (int v = 0; v < k.height; ++v) {
        for (int u = 0; u < k.width; ++u) {
            const Eigen::Vector3d ray((u - k.cx) / k.fx, (v - k.cy) / k.fy, 1.0);
            const double depth = cast(eye, rotation_t * ray);
            *frame.depth.pixel<float>(u, v) = std::isfinite(depth) ? float(depth) : 0.0f;
            if (std::isfinite(depth))
                for (int c = 0; c < 3; ++c) frame.color.pixel<uint8_t>(u, v)[c] = rgb[c];
        }
    }
    return frame;
}

inline RayCaster sphere(const Eigen::Vector3d& centre, double radius) {
    return [=](const Eigen::Vector3d& o, const Eigen::Vector3d& d) {
        const Eigen::Vector3d oc = o - centre;
        const double a = d.squaredNorm(), b = 2.0 * oc.dot(d), c = oc.squaredNorm() - radius * radius;
        const double disc = b * b - 4 * a * c;
        if (disc < 0) return std::numeric_limits<double>::infinity();
        const double s = (-b - std::sqrt(disc)) / (2 * a);
        return s > 0 ? s : std::numeric_limits<double>::infinity();
    };
}

/// A box of half sizes `half` rotated by `rotation` about the origin (slab test in the box's frame).
inline RayCaster box(const Eigen::Matrix3d& rotation, const Eigen::Vector3d& half) {
    return [=](const Eigen::Vector3d& o, const Eigen::Vector3d& d) {
        const Eigen::Vector3d ob = rotation.transpose() * o, db = rotation.transpose() * d;
        double t_near = -std::numeric_limits<double>::infinity(), t_far = std::numeric_limits<double>::infinity();
        for (int i = 0; i < 3; ++i) {
            const double t0 = (-half(i) - ob(i)) / db(i), t1 = (half(i) - ob(i)) / db(i);
            t_near = std::max(t_near, std::min(t0, t1));
            t_far = std::min(t_far, std::max(t0, t1));
        }
        return (t_near <= t_far && t_near > 0) ? t_near : std::numeric_limits<double>::infinity();
    };
}

/// Distance from p to the surface of that box.
inline double box_surface_distance(const Eigen::Matrix3d& rotation, const Eigen::Vector3d& half,
                                   const Eigen::Vector3d& p) {
    const Eigen::Vector3d q = (rotation.transpose() * p).cwiseAbs() - half;
    const double outside = q.cwiseMax(0.0).norm();
    const double inside = std::min(q.maxCoeff(), 0.0);
    return std::abs(outside + inside);
}

}  // namespace o3d_test
