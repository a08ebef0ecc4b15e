// SPDX-License-Identifier: MIT
// C API of the viewer (visualizer.h): the core Visualizer behind a handle, with C callbacks.
#include "o3d/visualizer.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <memory>
#include <optional>

#include "camera_internal.h"
#include "internal.h"
#include "o3d/io/file_bytes.h"
#include "o3d/io/image_io.h"
#include "o3d/visualization/visualizer.h"
#include "render_option_internal.h"

struct o3d_visualizer {
    explicit o3d_visualizer(bool editing) : vis(editing) {}
    o3d::visualization::Visualizer vis;
    std::optional<std::string> callback_error;  // set by a binding's failing callback
};

namespace {

using o3d::capi::guard;
using o3d::capi::require;
using o3d::capi::vec3;
namespace vis = o3d::visualization;

vis::Visualizer& of(o3d_visualizer_t* v) { return require(v, "vis")->vis; }

/// @brief After a C callback returned: the error a binding reported from it ends the loop as Cancelled.
void rethrow_callback_error(o3d_visualizer_t* v) {
    if (!v->callback_error) return;
    const std::string message = *v->callback_error;
    v->callback_error.reset();
    throw o3d::Cancelled(message);
}

template <typename Handle, typename Member>
o3d_status add_geometry(const char* function, o3d_visualizer_t* v, const char* name, const Handle* handle,
                        Member member, int32_t reset_bounding_box) {
    return guard(function, [&] {
        auto& visualizer = of(v);
        require(handle, "geometry");
        // An empty name is refused by the renderer's add, with the same message.
        visualizer.add_geometry(require(name, "name"), handle->*member, reset_bounding_box != 0);
    });
}

void check_action(int32_t action) {
    if (action != O3D_KEY_ACTION_RELEASE && action != O3D_KEY_ACTION_PRESS && action != O3D_KEY_ACTION_REPEAT)
        throw o3d::InvalidArgument("action must be O3D_KEY_ACTION_RELEASE, _PRESS or _REPEAT");
}

void check_finite(double a, double b, const char* what) {
    if (!std::isfinite(a) || !std::isfinite(b)) throw o3d::InvalidArgument(std::string(what) + " must be finite");
}

o3d_status register_key(const char* function, o3d_visualizer_t* v, int32_t key, o3d_visualizer_key_callback callback,
                        void* user_data, bool every_action) {
    return guard(function, [&] {
        auto& visualizer = of(v);
        if (key < 0) throw o3d::InvalidArgument("key must be >= 0");
        vis::Visualizer::KeyCallback wrapped;
        if (callback)
            wrapped = [v, callback, user_data](vis::Visualizer&, int action, int mods) {
                const bool changed = callback(v, action, mods, user_data) != 0;
                rethrow_callback_error(v);
                return changed;
            };
        visualizer.register_key_callback(key, std::move(wrapped), every_action);
    });
}

}  // namespace

extern "C" {

O3D_API o3d_status o3d_visualizer_create(o3d_visualizer_t** out, int32_t editing) {
    return guard(__func__, [&] {
        require(out, "out");
        *out = new o3d_visualizer(editing != 0);
    });
}

O3D_API void o3d_visualizer_destroy(o3d_visualizer_t* v) {
    guard(__func__, [&] { delete v; });
}

O3D_API o3d_status o3d_visualizer_create_window(o3d_visualizer_t* v, const char* window_name, int32_t width,
                                                int32_t height, int32_t left, int32_t top, int32_t visible) {
    return guard(__func__, [&] {
        of(v).create_window(window_name ? window_name : "o3d", width, height, left, top, visible != 0);
    });
}

O3D_API o3d_status o3d_visualizer_destroy_window(o3d_visualizer_t* v) {
    return guard(__func__, [&] { of(v).destroy_window(); });
}

O3D_API o3d_status o3d_visualizer_add_pointcloud(o3d_visualizer_t* v, const char* name, const o3d_pointcloud_t* pc,
                                                 int32_t reset_bounding_box) {
    return add_geometry(__func__, v, name, pc, &o3d_pointcloud::cloud, reset_bounding_box);
}

O3D_API o3d_status o3d_visualizer_add_trianglemesh(o3d_visualizer_t* v, const char* name,
                                                   const o3d_trianglemesh_t* mesh, int32_t reset_bounding_box) {
    return add_geometry(__func__, v, name, mesh, &o3d_trianglemesh::mesh, reset_bounding_box);
}

O3D_API o3d_status o3d_visualizer_add_lineset(o3d_visualizer_t* v, const char* name, const o3d_lineset_t* lineset,
                                              int32_t reset_bounding_box) {
    return add_geometry(__func__, v, name, lineset, &o3d_lineset::lineset, reset_bounding_box);
}

O3D_API o3d_status o3d_visualizer_add_voxelgrid(o3d_visualizer_t* v, const char* name, const o3d_voxelgrid_t* grid,
                                                int32_t reset_bounding_box) {
    return add_geometry(__func__, v, name, grid, &o3d_voxelgrid::grid, reset_bounding_box);
}

O3D_API o3d_status o3d_visualizer_add_image(o3d_visualizer_t* v, const char* name, const o3d_image_t* image,
                                            int32_t reset_bounding_box) {
    return add_geometry(__func__, v, name, image, &o3d_image::image, reset_bounding_box);
}

O3D_API o3d_status o3d_visualizer_remove_geometry(o3d_visualizer_t* v, const char* name, int32_t reset_bounding_box) {
    return guard(__func__, [&] { of(v).remove_geometry(require(name, "name"), reset_bounding_box != 0); });
}

O3D_API o3d_status o3d_visualizer_clear_geometries(o3d_visualizer_t* v) {
    return guard(__func__, [&] { of(v).clear_geometries(); });
}

O3D_API o3d_status o3d_visualizer_has_geometry(int32_t* out, o3d_visualizer_t* v, const char* name) {
    return guard(__func__, [&] {
        require(out, "out");
        *out = of(v).has_geometry(require(name, "name")) ? 1 : 0;
    });
}

O3D_API o3d_status o3d_visualizer_get_render_option(o3d_render_option_t* out, o3d_visualizer_t* v) {
    return guard(__func__, [&] {
        require(out, "out");
        o3d::capi::write_render_option(out, of(v).render_option());
    });
}

O3D_API o3d_status o3d_visualizer_set_render_option(o3d_visualizer_t* v, const o3d_render_option_t* opts) {
    return guard(__func__, [&] {
        auto& visualizer = of(v);
        visualizer.set_render_option(o3d::capi::render_option_to_core(require(opts, "opts")));
    });
}

O3D_API o3d_status o3d_visualizer_poll_events(int32_t* out_open, o3d_visualizer_t* v) {
    return guard(__func__, [&] {
        const bool open = of(v).poll_events();
        if (out_open) *out_open = open ? 1 : 0;
    });
}

O3D_API o3d_status o3d_visualizer_update_renderer(o3d_visualizer_t* v) {
    return guard(__func__, [&] { of(v).update_renderer(); });
}

O3D_API o3d_status o3d_visualizer_run(o3d_visualizer_t* v) {
    return guard(__func__, [&] { of(v).run(); });
}

O3D_API o3d_status o3d_visualizer_close(o3d_visualizer_t* v) {
    return guard(__func__, [&] { of(v).close(); });
}

O3D_API o3d_status o3d_visualizer_set_callback_error(o3d_visualizer_t* v, const char* message) {
    return guard(__func__, [&] {
        require(v, "vis")->callback_error = message ? message : "a callback failed";
    });
}

O3D_API o3d_status o3d_visualizer_register_animation_callback(o3d_visualizer_t* v,
                                                              o3d_visualizer_animation_callback callback,
                                                              void* user_data) {
    return guard(__func__, [&] {
        auto& visualizer = of(v);
        vis::Visualizer::AnimationCallback wrapped;
        if (callback)
            wrapped = [v, callback, user_data](vis::Visualizer&) {
                const bool changed = callback(v, user_data) != 0;
                rethrow_callback_error(v);
                return changed;
            };
        visualizer.register_animation_callback(std::move(wrapped));
    });
}

O3D_API o3d_status o3d_visualizer_register_key_callback(o3d_visualizer_t* v, int32_t key,
                                                        o3d_visualizer_key_callback callback, void* user_data) {
    return register_key(__func__, v, key, callback, user_data, false);
}

O3D_API o3d_status o3d_visualizer_register_key_action_callback(o3d_visualizer_t* v, int32_t key,
                                                               o3d_visualizer_key_callback callback, void* user_data) {
    return register_key(__func__, v, key, callback, user_data, true);
}

O3D_API o3d_status o3d_visualizer_send_key(o3d_visualizer_t* v, int32_t key, int32_t action, int32_t mods) {
    return guard(__func__, [&] {
        auto& visualizer = of(v);
        check_action(action);
        visualizer.key_event(key, action, mods);
    });
}

O3D_API o3d_status o3d_visualizer_send_mouse_move(o3d_visualizer_t* v, double x, double y) {
    return guard(__func__, [&] {
        auto& visualizer = of(v);
        check_finite(x, y, "the cursor position");
        visualizer.mouse_move(x, y);
    });
}

O3D_API o3d_status o3d_visualizer_send_mouse_button(o3d_visualizer_t* v, int32_t button, int32_t action,
                                                    int32_t mods) {
    return guard(__func__, [&] {
        auto& visualizer = of(v);
        if (button < 0 || button > 7) throw o3d::InvalidArgument("button must be 0..7");
        if (action != O3D_KEY_ACTION_RELEASE && action != O3D_KEY_ACTION_PRESS)
            throw o3d::InvalidArgument("a mouse button action must be O3D_KEY_ACTION_PRESS or _RELEASE");
        visualizer.mouse_button(button, action, mods);
    });
}

O3D_API o3d_status o3d_visualizer_send_scroll(o3d_visualizer_t* v, double dx, double dy) {
    return guard(__func__, [&] {
        auto& visualizer = of(v);
        check_finite(dx, dy, "the scroll offsets");
        visualizer.scroll(dx, dy);
    });
}

O3D_API o3d_status o3d_visualizer_capture_screen_float_buffer(o3d_image_t** out, o3d_visualizer_t* v, int32_t) {
    return guard(__func__, [&] {
        require(out, "out");
        *out = nullptr;
        const o3d::geometry::Image rgb = of(v).capture_screen();
        o3d::geometry::Image image;
        image.width = rgb.width;
        image.height = rgb.height;
        image.num_channels = 3;
        image.bytes_per_channel = 4;
        image.data.resize(image.byte_size());
        float* dst = image.pixel<float>(0, 0);
        for (size_t i = 0; i < rgb.data.size(); ++i) dst[i] = float(rgb.data[i]) / 255.0f;
        *out = o3d::capi::new_image(std::move(image));
    });
}

O3D_API o3d_status o3d_visualizer_capture_screen_image(o3d_visualizer_t* v, const char* path, int32_t) {
    return guard(__func__, [&] {
        auto& visualizer = of(v);
        o3d::io::write_image(require(path, "path"), visualizer.capture_screen());
    });
}

O3D_API o3d_status o3d_visualizer_capture_depth_float_buffer(o3d_image_t** out, o3d_visualizer_t* v, int32_t) {
    return guard(__func__, [&] {
        require(out, "out");
        *out = nullptr;
        *out = o3d::capi::new_image(of(v).capture_depth());
    });
}

O3D_API o3d_status o3d_visualizer_capture_depth_image(o3d_visualizer_t* v, const char* path, int32_t,
                                                      double depth_scale) {
    return guard(__func__, [&] {
        auto& visualizer = of(v);
        require(path, "path");
        if (!(depth_scale > 0) || !std::isfinite(depth_scale))
            throw o3d::InvalidArgument("depth_scale must be finite and > 0");
        o3d::io::write_image(path, vis::Visualizer::depth_to_uint16(visualizer.capture_depth(), depth_scale), "png");
    });
}

O3D_API o3d_status o3d_visualizer_get_picked_points(int32_t* out, size_t capacity, size_t* out_count,
                                                    const o3d_visualizer_t* v) {
    return guard(__func__, [&] {
        require(out_count, "out_count");
        const std::vector<int>& picked = require(v, "vis")->vis.picked_points();
        static_assert(sizeof(int) == sizeof(int32_t), "indices are copied as int32");
        o3d::capi::copy_out(reinterpret_cast<const int32_t*>(picked.data()), picked.size(), out, capacity, out_count);
    });
}

O3D_API o3d_status o3d_visualizer_view_rotate(o3d_visualizer_t* v, double x, double y) {
    return guard(__func__, [&] {
        of(v).view_control().rotate(x, y);
        of(v).update_renderer();
    });
}

O3D_API o3d_status o3d_visualizer_view_translate(o3d_visualizer_t* v, double x, double y) {
    return guard(__func__, [&] {
        of(v).view_control().translate(x, y);
        of(v).update_renderer();
    });
}

O3D_API o3d_status o3d_visualizer_view_scale(o3d_visualizer_t* v, double scale) {
    return guard(__func__, [&] {
        of(v).view_control().scale(scale);
        of(v).update_renderer();
    });
}

O3D_API o3d_status o3d_visualizer_view_change_field_of_view(o3d_visualizer_t* v, double step) {
    return guard(__func__, [&] {
        of(v).view_control().change_field_of_view(step);
        of(v).update_renderer();
    });
}

O3D_API o3d_status o3d_visualizer_view_get_field_of_view(double* out, o3d_visualizer_t* v) {
    return guard(__func__, [&] {
        require(out, "out");
        *out = of(v).view_control().status().field_of_view;
    });
}

O3D_API o3d_status o3d_visualizer_view_set(o3d_visualizer_t* v, const double front[3], const double lookat[3],
                                           const double up[3], double zoom) {
    return guard(__func__, [&] {
        vis::ViewControl& view = of(v).view_control();
        vis::ViewStatus s = view.status();
        if (front) s.front = vec3(front, "front");
        if (lookat) s.lookat = vec3(lookat, "lookat");
        if (up) s.up = vec3(up, "up");
        if (std::isnan(zoom)) throw o3d::InvalidArgument("zoom must not be NaN");
        if (zoom >= 0) s.zoom = std::clamp(zoom, vis::kMinZoom, vis::kMaxZoom);
        view.set_status(s);  // checked as a whole: up must not end parallel to front
        of(v).update_renderer();
    });
}

O3D_API o3d_status o3d_visualizer_view_get(double out_front[3], double out_lookat[3], double out_up[3],
                                           double* out_zoom, o3d_visualizer_t* v) {
    return guard(__func__, [&] {
        const vis::ViewStatus& s = of(v).view_control().status();
        if (out_front) o3d::capi::write3(out_front, "out_front", s.front);
        if (out_lookat) o3d::capi::write3(out_lookat, "out_lookat", s.lookat);
        if (out_up) o3d::capi::write3(out_up, "out_up", s.up);
        if (out_zoom) *out_zoom = s.zoom;
    });
}

O3D_API o3d_status o3d_visualizer_view_reset(o3d_visualizer_t* v) {
    return guard(__func__, [&] { of(v).reset_view_point(); });
}

O3D_API o3d_status o3d_visualizer_view_to_pinhole(o3d_pinhole_intrinsic_t* out_intrinsic, double out_extrinsic[16],
                                                  o3d_visualizer_t* v) {
    return guard(__func__, [&] {
        const o3d::camera::PinholeCameraParameters p = of(v).view_control().to_pinhole();
        if (out_intrinsic) *out_intrinsic = o3d::capi::to_c(p.intrinsic);
        if (out_extrinsic) o3d::capi::matrix_to_row_major(p.extrinsic, out_extrinsic);
    });
}

O3D_API o3d_status o3d_visualizer_view_from_pinhole(o3d_visualizer_t* v, const o3d_pinhole_intrinsic_t* intrinsic,
                                                    const double extrinsic[16]) {
    return guard(__func__, [&] {
        auto& visualizer = of(v);
        o3d::camera::PinholeCameraParameters p;
        p.intrinsic = o3d::capi::to_core(*require(intrinsic, "intrinsic"));
        p.extrinsic = o3d::capi::matrix_from_row_major(require(extrinsic, "extrinsic"));
        visualizer.view_control().from_pinhole(p);
        visualizer.update_renderer();
    });
}

O3D_API o3d_status o3d_visualizer_get_view_status(o3d_buffer_t** out, o3d_visualizer_t* v) {
    return guard(__func__, [&] {
        require(out, "out");
        *out = nullptr;
        const std::string json = of(v).view_status_json();
        auto buffer = std::make_unique<o3d_buffer>();
        buffer->bytes.assign(json.begin(), json.end());
        *out = buffer.release();
    });
}

O3D_API o3d_status o3d_visualizer_set_view_status(o3d_visualizer_t* v, const char* json) {
    return guard(__func__, [&] {
        auto& visualizer = of(v);
        visualizer.set_view_status_json(require(json, "json"));
    });
}

O3D_API o3d_status o3d_visualizer_play_view_trajectory(o3d_visualizer_t* v, const char* trajectory_path,
                                                       const char* capture_dir, int32_t capture_depth,
                                                       o3d_progress_callback progress, void* user_data) {
    return guard(__func__, [&] {
        auto& visualizer = of(v);
        const o3d::io::detail::FileBytes bytes(require(trajectory_path, "trajectory_path"));
        const vis::ViewTrajectory trajectory = vis::view_trajectory_from_json(
            std::string(reinterpret_cast<const char*>(bytes.data()), bytes.size()));
        std::function<bool(double)> report;
        if (progress) report = [progress, user_data](double f) { return progress(f, user_data) == 0; };
        visualizer.play_view_trajectory(trajectory, capture_dir ? capture_dir : "", capture_depth != 0, report);
    });
}

}  // extern "C"

O3D_API o3d_status o3d_visualizer_is_selecting(o3d_bool* out, const o3d_visualizer_t* v) {
    return guard(__func__, [&] { *require(out, "out") = require(v, "vis")->vis.selecting() ? 1 : 0; });
}

O3D_API o3d_status o3d_visualizer_crop_to_selection(o3d_visualizer_t* v) {
    return guard(__func__, [&] { of(v).crop_to_selection(); });
}

O3D_API o3d_status o3d_visualizer_get_cropped_pointcloud(o3d_pointcloud_t** out, const o3d_visualizer_t* v) {
    return guard(__func__, [&] {
        require(out, "out");
        *out = nullptr;
        const auto& cropped = require(v, "vis")->vis.cropped_point_cloud();
        if (cropped) *out = new o3d_pointcloud{*cropped};
    });
}

O3D_API o3d_status o3d_visualizer_get_cropped_trianglemesh(o3d_trianglemesh_t** out, const o3d_visualizer_t* v) {
    return guard(__func__, [&] {
        require(out, "out");
        *out = nullptr;
        const auto& cropped = require(v, "vis")->vis.cropped_triangle_mesh();
        if (cropped) *out = new o3d_trianglemesh{*cropped};
    });
}

O3D_API o3d_status o3d_visualizer_set_crop_directory(o3d_visualizer_t* v, const char* directory) {
    return guard(__func__, [&] { of(v).set_crop_directory(directory ? directory : ""); });
}
