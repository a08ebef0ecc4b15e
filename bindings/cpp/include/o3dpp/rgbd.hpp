// SPDX-License-Identifier: MIT
#pragma once
/// @file rgbd.hpp
/// @brief o3dpp::RgbdImage and the back-projection of depth / RGB-D images to point clouds.
#include <cstdint>

#include "o3d/rgbd.h"
#include "o3dpp/camera.hpp"
#include "o3dpp/error.hpp"
#include "o3dpp/generated/options.hpp"
#include "o3dpp/generated/rgbd.hpp"
#include "o3dpp/handle.hpp"
#include "o3dpp/image.hpp"
#include "o3dpp/pointcloud.hpp"

namespace o3dpp {

/// @brief A color (or intensity) image and a float depth image in metres. Move-only. The dataset readers and the
/// image copies are generated (detail::RgbdImageCalls).
class RgbdImage : public Owner<RgbdImage, o3d_rgbd_image_t, &o3d_rgbd_image_destroy>,
                  public detail::RgbdImageCalls<RgbdImage> {
public:
    explicit RgbdImage(o3d_rgbd_image_t* owned) : Owner(owned) {}

    /// @brief Pair a color image with a same-size depth image (depth converted to metres).
    static RgbdImage create_from_color_and_depth(const Image& color, const Image& depth,
                                                 const RgbdOptions& options = {}) {
        const o3d_rgbd_options_t c = options.to_c();
        return create(&o3d_rgbd_image_create_from_color_and_depth, color.get(), depth.get(), &c);
    }
};

/// @brief Back-project a depth image (uint16 raw or float metres) through `intrinsic`, then to world
/// coordinates with the inverse of the world-to-camera `extrinsic`.
inline PointCloud create_point_cloud_from_depth_image(const Image& depth, const PinholeIntrinsic& intrinsic,
                                                      const Mat4& extrinsic = identity4(),
                                                      const DepthToCloudOptions& options = {}) {
    const o3d_depth_to_cloud_options_t c = options.to_c();
    return PointCloud::create(&o3d_pointcloud_create_from_depth_image, depth.get(), &intrinsic, extrinsic.data(), &c);
}

/// @brief As create_point_cloud_from_depth_image for an RGB-D image, with per-point colors.
inline PointCloud create_point_cloud_from_rgbd_image(const RgbdImage& rgbd, const PinholeIntrinsic& intrinsic,
                                                     const Mat4& extrinsic = identity4(),
                                                     bool project_valid_depth_only = true) {
    return PointCloud::create(&o3d_pointcloud_create_from_rgbd_image, rgbd.get(), &intrinsic, extrinsic.data(),
                              project_valid_depth_only ? 1 : 0);
}

}  // namespace o3dpp
