// SPDX-License-Identifier: MIT
// C API: RGB-D images and the back-projection of depth and RGB-D images (o3d/rgbd.h).
#include <memory>
#include <string>

#include "camera_internal.h"
#include "internal.h"
#include "o3d/geometry/depth_projection.h"
#include "o3d/geometry/rgbd_dataset_formats.h"
#include "o3d/geometry/rgbd_image_ops.h"
#include "o3d/o3d.h"

namespace {

using o3d::capi::require;

constexpr o3d_rgbd_options_t kRgbdDefaults = {sizeof(o3d_rgbd_options_t), 1000.0, 3.0, 1};
constexpr o3d_depth_to_cloud_options_t kDepthToCloudDefaults = {sizeof(o3d_depth_to_cloud_options_t), 1000.0,
                                                                 1000.0, 1, 1};

void emit(o3d_rgbd_image_t** out, o3d::geometry::RGBDImage rgbd) {
    auto handle = std::make_unique<o3d_rgbd_image>();
    handle->rgbd = std::move(rgbd);
    *out = handle.release();
}

void emit(o3d_image_t** out, const o3d::geometry::Image& image) {
    auto handle = std::make_unique<o3d_image>();
    handle->image = image;
    *out = handle.release();
}

void emit(o3d_pointcloud_t** out, o3d::geometry::PointCloud cloud) {
    auto handle = std::make_unique<o3d_pointcloud>();
    handle->cloud = std::move(cloud);
    *out = handle.release();
}

template <typename T>
void clear_out(T** out) {
    require(out, "out");
    *out = nullptr;
}

}  // namespace

extern "C" {

O3D_API o3d_status o3d_rgbd_options_init(o3d_rgbd_options_t* opts, uint32_t struct_size) {
    return o3d::capi::guard(__func__, [&] { o3d::capi::init_options(opts, struct_size, kRgbdDefaults, "opts"); });
}

O3D_API o3d_status o3d_rgbd_image_create_from_color_and_depth(o3d_rgbd_image_t** out, const o3d_image_t* color,
                                                              const o3d_image_t* depth,
                                                              const o3d_rgbd_options_t* opts) {
    return o3d::capi::guard(__func__, [&] {
        clear_out(out);
        require(color, "color");
        require(depth, "depth");
        const o3d_rgbd_options_t o = o3d::capi::read_options(opts, kRgbdDefaults, "opts");
        o3d::geometry::RGBDOptions options;
        options.depth_scale = o.depth_scale;
        options.depth_trunc = o.depth_trunc;
        options.convert_rgb_to_intensity = o.convert_rgb_to_intensity != 0;
        emit(out, o3d::geometry::create_rgbd_from_color_and_depth(color->image, depth->image, options));
    });
}

O3D_API o3d_status o3d_rgbd_image_create_from_dataset_format(o3d_rgbd_image_t** out, int32_t format,
                                                             const o3d_image_t* color, const o3d_image_t* depth,
                                                             int32_t convert_rgb_to_intensity) {
    return o3d::capi::guard(__func__, [&] {
        clear_out(out);
        require(color, "color");
        require(depth, "depth");
        if (format < O3D_RGBD_FORMAT_REDWOOD || format > O3D_RGBD_FORMAT_NYU)
            throw o3d::InvalidArgument("unknown RGB-D dataset format " + std::to_string(format) +
                                       " (O3D_RGBD_FORMAT_REDWOOD, _TUM, _SUN or _NYU)");
        emit(out, o3d::geometry::create_rgbd_from_dataset_format(static_cast<o3d::geometry::RGBDDatasetFormat>(format),
                                                                 color->image, depth->image,
                                                                 convert_rgb_to_intensity != 0));
    });
}

O3D_API void o3d_rgbd_image_destroy(o3d_rgbd_image_t* rgbd) { delete rgbd; }

O3D_API o3d_status o3d_rgbd_image_get_color(o3d_image_t** out, const o3d_rgbd_image_t* rgbd) {
    return o3d::capi::guard(__func__, [&] {
        clear_out(out);
        emit(out, require(rgbd, "rgbd")->rgbd.color);
    });
}

O3D_API o3d_status o3d_rgbd_image_get_depth(o3d_image_t** out, const o3d_rgbd_image_t* rgbd) {
    return o3d::capi::guard(__func__, [&] {
        clear_out(out);
        emit(out, require(rgbd, "rgbd")->rgbd.depth);
    });
}

O3D_API o3d_status o3d_depth_to_cloud_options_init(o3d_depth_to_cloud_options_t* opts, uint32_t struct_size) {
    return o3d::capi::guard(__func__,
                            [&] { o3d::capi::init_options(opts, struct_size, kDepthToCloudDefaults, "opts"); });
}

O3D_API o3d_status o3d_pointcloud_create_from_depth_image(o3d_pointcloud_t** out, const o3d_image_t* depth,
                                                          const o3d_pinhole_intrinsic_t* intrinsic,
                                                          const double extrinsic[16],
                                                          const o3d_depth_to_cloud_options_t* opts) {
    return o3d::capi::guard(__func__, [&] {
        clear_out(out);
        require(depth, "depth");
        require(intrinsic, "intrinsic");
        const o3d_depth_to_cloud_options_t o = o3d::capi::read_options(opts, kDepthToCloudDefaults, "opts");
        o3d::geometry::DepthToCloudOptions options;
        options.depth_scale = o.depth_scale;
        options.depth_trunc = o.depth_trunc;
        options.stride = o.stride;
        options.project_valid_depth_only = o.project_valid_depth_only != 0;
        emit(out, o3d::geometry::create_point_cloud_from_depth_image(depth->image, o3d::capi::to_core(*intrinsic),
                                                                     o3d::capi::matrix_from_row_major(extrinsic),
                                                                     options));
    });
}

O3D_API o3d_status o3d_pointcloud_create_from_rgbd_image(o3d_pointcloud_t** out, const o3d_rgbd_image_t* rgbd,
                                                         const o3d_pinhole_intrinsic_t* intrinsic,
                                                         const double extrinsic[16],
                                                         int32_t project_valid_depth_only) {
    return o3d::capi::guard(__func__, [&] {
        clear_out(out);
        require(rgbd, "rgbd");
        require(intrinsic, "intrinsic");
        emit(out, o3d::geometry::create_point_cloud_from_rgbd_image(rgbd->rgbd, o3d::capi::to_core(*intrinsic),
                                                                    o3d::capi::matrix_from_row_major(extrinsic),
                                                                    project_valid_depth_only != 0));
    });
}

}  // extern "C"
