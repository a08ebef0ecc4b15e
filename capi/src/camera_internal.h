// SPDX-License-Identifier: MIT
#pragma once
/// @file camera_internal.h
/// @brief Conversions between the C camera types (row-major matrices) and the core's.
#include <Eigen/Core>

#include "internal.h"
#include "o3d/camera.h"

namespace o3d::capi {

inline o3d::camera::PinholeCameraIntrinsic to_core(const o3d_pinhole_intrinsic_t& in) {
    return {in.width, in.height, in.fx, in.fy, in.cx, in.cy};
}

inline o3d_pinhole_intrinsic_t to_c(const o3d::camera::PinholeCameraIntrinsic& in) {
    return {in.width, in.height, in.fx, in.fy, in.cx, in.cy};
}

/// @brief A row-major 4x4 from the caller; NULL gives the identity.
inline Eigen::Matrix4d matrix_from_row_major(const double* m) {
    if (!m) return Eigen::Matrix4d::Identity();
    return Eigen::Map<const Eigen::Matrix<double, 4, 4, Eigen::RowMajor>>(m);
}

inline void matrix_to_row_major(const Eigen::Matrix4d& m, double* out) {
    Eigen::Map<Eigen::Matrix<double, 4, 4, Eigen::RowMajor>> row_major(out);
    row_major = m;
}

}  // namespace o3d::capi
