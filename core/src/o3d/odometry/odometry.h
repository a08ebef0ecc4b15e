// SPDX-License-Identifier: MIT
#pragma once
/// @file odometry.h
/// @brief RGB-D odometry (Open3D's compute_rgbd_odometry): the rigid motion between two RGB-D frames by
/// dense photometric (Steinbruecker et al. 2011) or photometric + geometric (Park et al. 2017) alignment,
/// coarse to fine over image pyramids.
#include <Eigen/Core>
#include <vector>

#include "o3d/camera/pinhole_camera.h"
#include "o3d/geometry/rgbd_image.h"

namespace o3d::odometry {

using Matrix6d = Eigen::Matrix<double, 6, 6>;

/// @brief Open3D's OdometryOption and its defaults.
struct OdometryOption {
    /// Iterations per pyramid level, coarsest first; its length is the number of levels.
    std::vector<int> iteration_number_per_pyramid_level{20, 10, 5};
    double depth_diff_max = 0.03;  ///< metres: farther apart, two pixels do not correspond
    double depth_min = 0.0;        ///< metres: depth outside [depth_min, depth_max] is ignored
    double depth_max = 4.0;
};

/// @brief RGBDOdometryJacobianFromColorTerm and ...FromHybridTerm.
enum class Jacobian { ColorTerm, HybridTerm };

struct OdometryResult {
    bool success = false;
    Eigen::Matrix4d transformation = Eigen::Matrix4d::Identity();  ///< source to target
    Matrix6d information = Matrix6d::Identity();
};

/// @brief The motion taking `source` onto `target`, from `odo_init`. The images are Open3D's odometry input:
/// color a 1-channel float intensity, depth 1-channel float metres, all four the same size.
/// @throws InvalidArgument on other image formats, mismatched sizes, an empty image, a bad intrinsic or option.
/// A frame pair that cannot be aligned (no pixel pair left within depth_diff_max) is not an error: success
/// is false with the identity, as Open3D.
OdometryResult compute_rgbd_odometry(const geometry::RGBDImage& source, const geometry::RGBDImage& target,
                                     const camera::PinholeCameraIntrinsic& intrinsic,
                                     const Eigen::Matrix4d& odo_init, Jacobian jacobian,
                                     const OdometryOption& option);

}  // namespace o3d::odometry
