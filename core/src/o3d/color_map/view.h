// SPDX-License-Identifier: MIT
#pragma once
/// @file view.h
/// @brief One image's current camera (intrinsic, world-to-camera pose, and for the non-rigid optimizer its
/// warp), and where it sees a point.
#include <Eigen/Core>

#include "o3d/camera/pinhole_camera.h"
#include "o3d/color_map/warping_field.h"

namespace o3d::color_map::detail {

struct View {
    camera::PinholeCameraIntrinsic intrinsic;
    Eigen::Matrix4d extrinsic = Eigen::Matrix4d::Identity();
    WarpingField warp;  ///< empty for the rigid optimizer
};

/// @brief A world point as `view` sees it.
struct Projection {
    Eigen::Vector3d point;  ///< in the camera frame
    Eigen::Vector2d pinhole;  ///< pixel of the plain pinhole projection
    Eigen::Vector2d pixel;  ///< after the warp (equal to `pinhole` without one)
    WarpingField::Cell cell;  ///< the warp's anchors for this point (unused without a warp)
};

/// @brief Project `x`; false when it lies on or behind the camera plane.
inline bool project(const View& view, const Eigen::Vector3d& x, Projection& out) {
    out.point = view.extrinsic.topLeftCorner<3, 3>() * x + view.extrinsic.topRightCorner<3, 1>();
    if (!(out.point.z() > 0.0)) return false;
    const camera::PinholeCameraIntrinsic& k = view.intrinsic;
    out.pinhole = {k.fx * out.point.x() / out.point.z() + k.cx, k.fy * out.point.y() / out.point.z() + k.cy};
    out.pixel = out.pinhole;
    if (!view.warp.empty()) {
        out.cell = view.warp.cell(out.pinhole.x(), out.pinhole.y());
        out.pixel += view.warp.displacement(out.cell);
    }
    return true;
}

}  // namespace o3d::color_map::detail
