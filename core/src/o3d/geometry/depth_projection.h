// SPDX-License-Identifier: MIT
#pragma once
/// @file depth_projection.h
/// @brief Back-projection of depth and RGB-D images to point clouds
/// (PointCloud.create_from_depth_image / create_from_rgbd_image).
///
/// Pixel (u, v) with depth z > 0 becomes the camera point ((u - cx) z / fx, (v - cy) z / fy, z), then the
/// world point inverse(extrinsic) * p. Points are in row-major pixel order over every stride-th row and
/// column. With project_valid_depth_only = false the cloud is organised: one point per visited pixel, NaN
/// (and color 0) where the depth is invalid. Results do not depend on the thread count.
#include <Eigen/Core>

#include "o3d/camera/pinhole_camera.h"
#include "o3d/geometry/point_cloud.h"
#include "o3d/geometry/rgbd_image.h"

namespace o3d::geometry {

struct DepthToCloudOptions {
    double depth_scale = 1000.0;  ///< raw units per metre of a uint16 depth image
    double depth_trunc = 1000.0;  ///< depths at or beyond this (metres) are invalid
    int stride = 1;               ///< visit every stride-th pixel in x and y
    bool project_valid_depth_only = true;
    int num_threads = 0;          ///< 0: the library default
};

/// @brief `depth` is 1-channel uint16 (raw, divided by depth_scale) or float32 (metres, used as is; unlike
/// Open3D, which divides float depth by depth_scale too). Non-finite depths are invalid.
/// `extrinsic` is world-to-camera with last row (0, 0, 0, 1). Bad input throws o3d::InvalidArgument.
PointCloud create_point_cloud_from_depth_image(const Image& depth, const camera::PinholeCameraIntrinsic& intrinsic,
                                               const Eigen::Matrix4d& extrinsic,
                                               const DepthToCloudOptions& options = {});

/// @brief As above for an RGB-D image (float32 depth in metres, no truncation), with per-point colors:
/// 8-bit colors divided by 255, a gray or float intensity repeated in R, G and B.
PointCloud create_point_cloud_from_rgbd_image(const RGBDImage& rgbd, const camera::PinholeCameraIntrinsic& intrinsic,
                                              const Eigen::Matrix4d& extrinsic, bool project_valid_depth_only = true,
                                              int num_threads = 0);

}  // namespace o3d::geometry
