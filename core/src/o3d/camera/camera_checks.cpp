// SPDX-License-Identifier: MIT
#include "o3d/camera/camera_checks.h"

#include <Eigen/LU>
#include <cmath>
#include <string>

#include "o3d/utility/error.h"

namespace o3d::camera {

void require_finite_intrinsic(const PinholeCameraIntrinsic& in, const char* what) {
    if (!std::isfinite(in.fx) || !std::isfinite(in.fy) || !std::isfinite(in.cx) || !std::isfinite(in.cy))
        throw InvalidArgument(std::string(what) + ": focal lengths and principal point must be finite");
}

void require_projectable_intrinsic(const PinholeCameraIntrinsic& in, const char* what) {
    require_finite_intrinsic(in, what);
    if (in.fx == 0.0 || in.fy == 0.0) throw InvalidArgument(std::string(what) + ": focal lengths must be non-zero");
}

void require_rigid_layout(const Eigen::Matrix4d& m, const char* what) {
    if (!m.allFinite()) throw InvalidArgument(std::string(what) + ": matrix has a NaN or infinite entry");
    if (m(3, 0) != 0.0 || m(3, 1) != 0.0 || m(3, 2) != 0.0 || m(3, 3) != 1.0)
        throw InvalidArgument(std::string(what) + ": last row must be (0, 0, 0, 1)");
}

void require_rigid(const Eigen::Matrix4d& m, const char* what) {
    require_rigid_layout(m, what);
    const Eigen::Matrix3d r = m.block<3, 3>(0, 0);
    // 1e-6: rotations written with 7 significant digits (trajectory files) still pass; a scale of 1.00001 does not.
    if ((r.transpose() * r - Eigen::Matrix3d::Identity()).cwiseAbs().maxCoeff() > 1e-6 || r.determinant() < 0.0)
        throw InvalidArgument(std::string(what) + ": the upper-left 3x3 block must be a rotation (rigid motion)");
}

Eigen::Matrix4d checked_inverse(const Eigen::Matrix4d& m, const char* what) {
    if (!m.allFinite()) throw InvalidArgument(std::string(what) + ": matrix has a NaN or infinite entry");
    Eigen::Matrix4d inverse;
    bool invertible = false;
    m.computeInverseWithCheck(inverse, invertible);
    if (!invertible || !inverse.allFinite()) throw InvalidArgument(std::string(what) + ": matrix is not invertible");
    return inverse;
}

}  // namespace o3d::camera
