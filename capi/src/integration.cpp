// SPDX-License-Identifier: MIT
// C API of TSDF integration (integration.h): one handle over either core volume.
#include "o3d/integration.h"

#include <memory>

#include "camera_internal.h"
#include "internal.h"
#include "o3d/integration/scalable_tsdf_volume.h"
#include "o3d/integration/uniform_tsdf_volume.h"

struct o3d_tsdf_volume {
    std::unique_ptr<o3d::integration::TSDFVolume> volume;
    o3d::integration::UniformTSDFVolume* uniform = nullptr;    // the same object when uniform, else null
    o3d::integration::ScalableTSDFVolume* scalable = nullptr;  // the same object when scalable, else null
};

namespace {

using o3d::capi::guard;
using o3d::capi::require;
using o3d::integration::ColorType;

ColorType to_color_type(o3d_tsdf_volume_color_type type) {
    switch (type) {
        case O3D_TSDF_VOLUME_COLOR_TYPE_NO_COLOR: return ColorType::None;
        case O3D_TSDF_VOLUME_COLOR_TYPE_RGB8: return ColorType::RGB8;
        case O3D_TSDF_VOLUME_COLOR_TYPE_GRAY32: return ColorType::Gray32;
        default: throw o3d::InvalidArgument("color_type must be O3D_TSDF_VOLUME_COLOR_TYPE_NO_COLOR, _RGB8 or _GRAY32");
    }
}

const o3d::integration::TSDFVolume& of(const o3d_tsdf_volume_t* v) { return *require(v, "volume")->volume; }

const o3d::integration::UniformTSDFVolume& uniform_of(const o3d_tsdf_volume_t* v) {
    if (!require(v, "volume")->uniform) throw o3d::InvalidArgument("volume is scalable; this needs a uniform volume");
    return *v->uniform;
}

const o3d::integration::ScalableTSDFVolume& scalable_of(const o3d_tsdf_volume_t* v) {
    if (!require(v, "volume")->scalable) throw o3d::InvalidArgument("volume is uniform; this needs a scalable volume");
    return *v->scalable;
}

template <typename Handle, typename Geometry>
void give(Handle** out, Geometry geometry) {
    *out = new Handle{std::move(geometry)};
}

template <typename Handle>
Handle** require_out(Handle** out) {
    require(out, "out");
    *out = nullptr;
    return out;
}

}  // namespace

O3D_API o3d_status o3d_tsdf_volume_create_uniform(o3d_tsdf_volume_t** out, double length, int32_t resolution,
                                                  double sdf_trunc, o3d_tsdf_volume_color_type color_type,
                                                  const double origin[3]) {
    return guard(__func__, [&] {
        require_out(out);
        const Eigen::Vector3d corner = origin ? o3d::capi::vec3(origin, "origin") : Eigen::Vector3d::Zero();
        auto volume = std::make_unique<o3d::integration::UniformTSDFVolume>(length, resolution, sdf_trunc,
                                                                           to_color_type(color_type), corner);
        auto handle = std::make_unique<o3d_tsdf_volume>();
        handle->uniform = volume.get();
        handle->volume = std::move(volume);
        *out = handle.release();
    });
}

O3D_API o3d_status o3d_tsdf_volume_create_scalable(o3d_tsdf_volume_t** out, double voxel_length, double sdf_trunc,
                                                   o3d_tsdf_volume_color_type color_type,
                                                   int32_t volume_unit_resolution, int32_t depth_sampling_stride) {
    return guard(__func__, [&] {
        require_out(out);
        auto volume = std::make_unique<o3d::integration::ScalableTSDFVolume>(
            voxel_length, sdf_trunc, to_color_type(color_type), volume_unit_resolution, depth_sampling_stride);
        auto handle = std::make_unique<o3d_tsdf_volume>();
        handle->scalable = volume.get();
        handle->volume = std::move(volume);
        *out = handle.release();
    });
}

O3D_API void o3d_tsdf_volume_destroy(o3d_tsdf_volume_t* volume) { delete volume; }

O3D_API o3d_status o3d_tsdf_volume_integrate(o3d_tsdf_volume_t* volume, const o3d_rgbd_image_t* image,
                                             const o3d_pinhole_intrinsic_t* intrinsic, const double extrinsic[16]) {
    return guard(__func__, [&] {
        require(volume, "volume");
        require(image, "image");
        require(intrinsic, "intrinsic");
        require(extrinsic, "extrinsic");
        volume->volume->integrate(image->rgbd, o3d::capi::to_core(*intrinsic),
                                  o3d::capi::matrix_from_row_major(extrinsic));
    });
}

O3D_API o3d_status o3d_tsdf_volume_reset(o3d_tsdf_volume_t* volume) {
    return guard(__func__, [&] { require(volume, "volume")->volume->reset(); });
}

O3D_API o3d_status o3d_tsdf_volume_extract_triangle_mesh(o3d_trianglemesh_t** out, const o3d_tsdf_volume_t* volume) {
    return guard(__func__, [&] {
        require_out(out);
        give(out, of(volume).extract_triangle_mesh());
    });
}

O3D_API o3d_status o3d_tsdf_volume_extract_point_cloud(o3d_pointcloud_t** out, const o3d_tsdf_volume_t* volume) {
    return guard(__func__, [&] {
        require_out(out);
        give(out, of(volume).extract_point_cloud());
    });
}

O3D_API o3d_status o3d_tsdf_volume_extract_voxel_point_cloud(o3d_pointcloud_t** out, const o3d_tsdf_volume_t* volume) {
    return guard(__func__, [&] {
        require_out(out);
        give(out, of(volume).extract_voxel_point_cloud());
    });
}

O3D_API o3d_status o3d_tsdf_volume_extract_voxel_grid(o3d_voxelgrid_t** out, const o3d_tsdf_volume_t* volume) {
    return guard(__func__, [&] {
        require_out(out);
        give(out, of(volume).extract_voxel_grid());
    });
}

O3D_API o3d_status o3d_tsdf_volume_extract_volume_tsdf(float* out, size_t capacity, size_t* out_rows,
                                                       const o3d_tsdf_volume_t* volume) {
    return guard(__func__, [&] {
        require(out_rows, "out_rows");
        const auto& uniform = uniform_of(volume);
        const size_t rows = size_t(uniform.resolution()) * size_t(uniform.resolution()) * size_t(uniform.resolution());
        if (!out || capacity < rows) return o3d::capi::copy_out<float>(nullptr, rows, out, capacity, out_rows, 2);
        const std::vector<float> values = uniform.extract_volume_tsdf();
        o3d::capi::copy_out(values.data(), rows, out, capacity, out_rows, 2);
    });
}

O3D_API o3d_status o3d_tsdf_volume_extract_volume_color(float* out, size_t capacity, size_t* out_rows,
                                                        const o3d_tsdf_volume_t* volume) {
    return guard(__func__, [&] {
        require(out_rows, "out_rows");
        const auto& uniform = uniform_of(volume);
        const size_t rows = size_t(uniform.resolution()) * size_t(uniform.resolution()) * size_t(uniform.resolution());
        if (!out || capacity < rows) return o3d::capi::copy_out<float>(nullptr, rows, out, capacity, out_rows, 3);
        const std::vector<float> values = uniform.extract_volume_color();
        o3d::capi::copy_out(values.data(), rows, out, capacity, out_rows, 3);
    });
}

O3D_API o3d_status o3d_tsdf_volume_is_scalable(o3d_bool* out, const o3d_tsdf_volume_t* volume) {
    return guard(__func__, [&] { *require(out, "out") = require(volume, "volume")->scalable ? 1 : 0; });
}

O3D_API o3d_status o3d_tsdf_volume_get_voxel_length(double* out, const o3d_tsdf_volume_t* volume) {
    return guard(__func__, [&] { *require(out, "out") = of(volume).voxel_length(); });
}

O3D_API o3d_status o3d_tsdf_volume_get_sdf_trunc(double* out, const o3d_tsdf_volume_t* volume) {
    return guard(__func__, [&] { *require(out, "out") = of(volume).sdf_trunc(); });
}

O3D_API o3d_status o3d_tsdf_volume_get_color_type(o3d_tsdf_volume_color_type* out, const o3d_tsdf_volume_t* volume) {
    return guard(__func__, [&] { *require(out, "out") = o3d_tsdf_volume_color_type(of(volume).color_type()); });
}

O3D_API o3d_status o3d_tsdf_volume_block_count(size_t* out_n, const o3d_tsdf_volume_t* volume) {
    return guard(__func__, [&] {
        require(out_n, "out_n");
        *out_n = require(volume, "volume")->scalable ? volume->scalable->block_count() : 1;
    });
}

O3D_API o3d_status o3d_tsdf_volume_get_length(double* out, const o3d_tsdf_volume_t* volume) {
    return guard(__func__, [&] { *require(out, "out") = uniform_of(volume).length(); });
}

O3D_API o3d_status o3d_tsdf_volume_get_resolution(int32_t* out, const o3d_tsdf_volume_t* volume) {
    return guard(__func__, [&] { *require(out, "out") = uniform_of(volume).resolution(); });
}

O3D_API o3d_status o3d_tsdf_volume_get_origin(double out[3], const o3d_tsdf_volume_t* volume) {
    return guard(__func__, [&] { o3d::capi::write3(out, "out", uniform_of(volume).origin()); });
}

O3D_API o3d_status o3d_tsdf_volume_get_volume_unit_resolution(int32_t* out, const o3d_tsdf_volume_t* volume) {
    return guard(__func__, [&] { *require(out, "out") = scalable_of(volume).volume_unit_resolution(); });
}

O3D_API o3d_status o3d_tsdf_volume_get_depth_sampling_stride(int32_t* out, const o3d_tsdf_volume_t* volume) {
    return guard(__func__, [&] { *require(out, "out") = scalable_of(volume).depth_sampling_stride(); });
}
