// SPDX-License-Identifier: MIT
#pragma once
/// @file rgbd.hpp
/// @brief o3dpp::RgbdImage and the back-projection of depth / RGB-D images to point clouds.
#include <cstdint>

#include "o3d/rgbd.h"
#include "o3dpp/camera.hpp"
#include "o3dpp/error.hpp"
#include "o3dpp/handle.hpp"
#include "o3dpp/image.hpp"
#include "o3dpp/pointcloud.hpp"

namespace o3dpp {

/// @brief RGBDImage.create_from_color_and_depth keyword arguments (Open3D's defaults).
struct RgbdOptions {
    double depth_scale = 1000.0;
    double depth_trunc = 3.0;
    bool convert_rgb_to_intensity = true;

    o3d_rgbd_options_t to_c() const {
        o3d_rgbd_options_t c;
        check(o3d_rgbd_options_init(&c, sizeof c));
        c.depth_scale = depth_scale;
        c.depth_trunc = depth_trunc;
        c.convert_rgb_to_intensity = convert_rgb_to_intensity ? 1 : 0;
        return c;
    }
};

/// @brief The dataset layouts of the Open3D paper.
enum class RgbdFormat : int32_t {
    Redwood = O3D_RGBD_FORMAT_REDWOOD,
    Tum = O3D_RGBD_FORMAT_TUM,
    Sun = O3D_RGBD_FORMAT_SUN,
    Nyu = O3D_RGBD_FORMAT_NYU
};

/// @brief A color (or intensity) image and a float depth image in metres. Move-only.
class RgbdImage {
public:
    explicit RgbdImage(o3d_rgbd_image_t* owned) : h_(owned) {
        if (!owned) throw Error(O3D_ERROR_INVALID_ARGUMENT, "o3dpp::RgbdImage: NULL handle");
    }
    RgbdImage(RgbdImage&&) noexcept = default;
    RgbdImage& operator=(RgbdImage&&) noexcept = default;
    RgbdImage(const RgbdImage&) = delete;
    RgbdImage& operator=(const RgbdImage&) = delete;

    /// @brief Pair a color image with a same-size depth image (depth converted to metres).
    static RgbdImage create_from_color_and_depth(const Image& color, const Image& depth,
                                                 const RgbdOptions& options = {}) {
        const o3d_rgbd_options_t c = options.to_c();
        return adopt([&](o3d_rgbd_image_t** o) {
            return o3d_rgbd_image_create_from_color_and_depth(o, color.get(), depth.get(), &c);
        });
    }
    /// @brief create_from_{redwood,tum,sun,nyu}_format.
    static RgbdImage create_from_dataset_format(RgbdFormat format, const Image& color, const Image& depth,
                                                bool convert_rgb_to_intensity = true) {
        return adopt([&](o3d_rgbd_image_t** o) {
            return o3d_rgbd_image_create_from_dataset_format(o, static_cast<int32_t>(format), color.get(),
                                                             depth.get(), convert_rgb_to_intensity ? 1 : 0);
        });
    }

    o3d_rgbd_image_t* get() const noexcept { return h_.get(); }

    /// @brief Copy of the color (or intensity) image.
    Image color() const { return Image::adopt([&](o3d_image_t** o) { return o3d_rgbd_image_get_color(o, get()); }); }
    /// @brief Copy of the depth image (float metres).
    Image depth() const { return Image::adopt([&](o3d_image_t** o) { return o3d_rgbd_image_get_depth(o, get()); }); }

private:
    template <typename F>
    static RgbdImage adopt(F&& create) {
        o3d_rgbd_image_t* p = nullptr;
        check(create(&p));
        return RgbdImage(p);
    }

    UniqueHandle<o3d_rgbd_image_t, &o3d_rgbd_image_destroy> h_;
};

/// @brief PointCloud.create_from_depth_image keyword arguments (Open3D's defaults).
struct DepthToCloudOptions {
    double depth_scale = 1000.0;
    double depth_trunc = 1000.0;
    int stride = 1;
    bool project_valid_depth_only = true;

    o3d_depth_to_cloud_options_t to_c() const {
        o3d_depth_to_cloud_options_t c;
        check(o3d_depth_to_cloud_options_init(&c, sizeof c));
        c.depth_scale = depth_scale;
        c.depth_trunc = depth_trunc;
        c.stride = stride;
        c.project_valid_depth_only = project_valid_depth_only ? 1 : 0;
        return c;
    }
};

/// @brief Back-project a depth image (uint16 raw or float metres) through `intrinsic`, then to world
/// coordinates with the inverse of the world-to-camera `extrinsic`.
inline PointCloud create_point_cloud_from_depth_image(const Image& depth, const PinholeIntrinsic& intrinsic,
                                                      const Mat4& extrinsic = identity4(),
                                                      const DepthToCloudOptions& options = {}) {
    const o3d_depth_to_cloud_options_t c = options.to_c();
    return PointCloud::adopt([&](o3d_pointcloud_t** o) {
        return o3d_pointcloud_create_from_depth_image(o, depth.get(), &intrinsic, extrinsic.data(), &c);
    });
}

/// @brief As create_point_cloud_from_depth_image for an RGB-D image, with per-point colors.
inline PointCloud create_point_cloud_from_rgbd_image(const RgbdImage& rgbd, const PinholeIntrinsic& intrinsic,
                                                     const Mat4& extrinsic = identity4(),
                                                     bool project_valid_depth_only = true) {
    return PointCloud::adopt([&](o3d_pointcloud_t** o) {
        return o3d_pointcloud_create_from_rgbd_image(o, rgbd.get(), &intrinsic, extrinsic.data(),
                                                     project_valid_depth_only ? 1 : 0);
    });
}

}  // namespace o3dpp
