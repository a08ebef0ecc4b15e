// SPDX-License-Identifier: MIT
// C API: camera.h (intrinsic presets, trajectories) and the camera part of io.h.
#include <memory>
#include <string>

#include "camera_internal.h"
#include "internal.h"
#include "o3d/camera.h"
#include "o3d/camera/camera_checks.h"
#include "o3d/camera/camera_io.h"
#include "o3d/camera/intrinsic_presets.h"
#include "o3d/io.h"

namespace {

using o3d::capi::require;

std::string format_arg(const char* format) { return format ? format : "auto"; }

}  // namespace

extern "C" {

O3D_API o3d_status o3d_pinhole_intrinsic_set_preset(o3d_pinhole_intrinsic_t* out, int32_t preset) {
    return o3d::capi::guard(__func__, [&] {
        require(out, "out");
        if (preset < O3D_INTRINSIC_PRIMESENSE_DEFAULT || preset > O3D_INTRINSIC_KINECT2_COLOR_DEFAULT)
            throw o3d::InvalidArgument("unknown preset " + std::to_string(preset));
        *out = o3d::capi::to_c(o3d::camera::intrinsic_preset(static_cast<o3d::camera::IntrinsicPreset>(preset)));
    });
}

O3D_API o3d_status o3d_camera_trajectory_create(o3d_camera_trajectory_t** out) {
    return o3d::capi::guard(__func__, [&] {
        require(out, "out");
        *out = nullptr;
        *out = new o3d_camera_trajectory();
    });
}

O3D_API void o3d_camera_trajectory_destroy(o3d_camera_trajectory_t* trajectory) { delete trajectory; }

O3D_API o3d_status o3d_camera_trajectory_size(size_t* out_n, const o3d_camera_trajectory_t* trajectory) {
    return o3d::capi::guard(__func__, [&] {
        require(trajectory, "trajectory");
        require(out_n, "out_n");
        *out_n = trajectory->trajectory.parameters.size();
    });
}

O3D_API o3d_status o3d_camera_trajectory_get(o3d_pinhole_intrinsic_t* out_intrinsic, double out_extrinsic[16],
                                             const o3d_camera_trajectory_t* trajectory, size_t index) {
    return o3d::capi::guard(__func__, [&] {
        require(trajectory, "trajectory");
        const auto& list = trajectory->trajectory.parameters;
        if (index >= list.size())
            throw o3d::InvalidArgument("index " + std::to_string(index) + " is out of range (size " +
                                       std::to_string(list.size()) + ")");
        if (out_intrinsic) *out_intrinsic = o3d::capi::to_c(list[index].intrinsic);
        if (out_extrinsic) o3d::capi::matrix_to_row_major(list[index].extrinsic, out_extrinsic);
    });
}

O3D_API o3d_status o3d_camera_trajectory_append(o3d_camera_trajectory_t* trajectory,
                                                const o3d_pinhole_intrinsic_t* intrinsic,
                                                const double extrinsic[16]) {
    return o3d::capi::guard(__func__, [&] {
        require(trajectory, "trajectory");
        require(intrinsic, "intrinsic");
        require(extrinsic, "extrinsic");
        o3d::camera::PinholeCameraParameters p;
        p.intrinsic = o3d::capi::to_core(*intrinsic);
        p.extrinsic = o3d::capi::matrix_from_row_major(extrinsic);
        o3d::camera::require_finite_intrinsic(p.intrinsic, "intrinsic");
        o3d::camera::require_rigid_layout(p.extrinsic, "extrinsic");
        trajectory->trajectory.parameters.push_back(p);
    });
}

O3D_API o3d_status o3d_camera_trajectory_clear(o3d_camera_trajectory_t* trajectory) {
    return o3d::capi::guard(__func__, [&] {
        require(trajectory, "trajectory");
        trajectory->trajectory.parameters.clear();
    });
}

O3D_API o3d_status o3d_io_read_pinhole_camera_intrinsic(o3d_pinhole_intrinsic_t* out, const char* path) {
    return o3d::capi::guard(__func__, [&] {
        require(path, "path");
        require(out, "out");
        *out = o3d::capi::to_c(o3d::camera::read_pinhole_camera_intrinsic(path));
    });
}

O3D_API o3d_status o3d_io_write_pinhole_camera_intrinsic(const char* path, const o3d_pinhole_intrinsic_t* intrinsic) {
    return o3d::capi::guard(__func__, [&] {
        require(path, "path");
        require(intrinsic, "intrinsic");
        o3d::camera::write_pinhole_camera_intrinsic(path, o3d::capi::to_core(*intrinsic));
    });
}

O3D_API o3d_status o3d_io_read_pinhole_camera_parameters(o3d_pinhole_intrinsic_t* out_intrinsic,
                                                         double out_extrinsic[16], const char* path) {
    return o3d::capi::guard(__func__, [&] {
        require(path, "path");
        const o3d::camera::PinholeCameraParameters p = o3d::camera::read_pinhole_camera_parameters(path);
        if (out_intrinsic) *out_intrinsic = o3d::capi::to_c(p.intrinsic);
        if (out_extrinsic) o3d::capi::matrix_to_row_major(p.extrinsic, out_extrinsic);
    });
}

O3D_API o3d_status o3d_io_write_pinhole_camera_parameters(const char* path, const o3d_pinhole_intrinsic_t* intrinsic,
                                                          const double extrinsic[16]) {
    return o3d::capi::guard(__func__, [&] {
        require(path, "path");
        require(intrinsic, "intrinsic");
        require(extrinsic, "extrinsic");
        o3d::camera::PinholeCameraParameters p;
        p.intrinsic = o3d::capi::to_core(*intrinsic);
        p.extrinsic = o3d::capi::matrix_from_row_major(extrinsic);
        o3d::camera::write_pinhole_camera_parameters(path, p);
    });
}

O3D_API o3d_status o3d_io_read_pinhole_camera_trajectory(o3d_camera_trajectory_t** out, const char* path,
                                                         const char* format) {
    return o3d::capi::guard(__func__, [&] {
        require(out, "out");
        *out = nullptr;
        require(path, "path");
        auto t = std::make_unique<o3d_camera_trajectory>();
        t->trajectory = o3d::camera::read_pinhole_camera_trajectory(path, format_arg(format));
        *out = t.release();
    });
}

O3D_API o3d_status o3d_io_write_pinhole_camera_trajectory(const char* path,
                                                          const o3d_camera_trajectory_t* trajectory,
                                                          const char* format) {
    return o3d::capi::guard(__func__, [&] {
        require(path, "path");
        require(trajectory, "trajectory");
        o3d::camera::write_pinhole_camera_trajectory(path, trajectory->trajectory, format_arg(format));
    });
}

}  // extern "C"
