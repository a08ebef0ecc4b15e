// SPDX-License-Identifier: MIT
#pragma once
/// @file visualizer.hpp
/// @brief o3dpp::Visualizer: the viewer (o3d.visualization.Visualizer, VisualizerWithKeyCallback,
/// VisualizerWithEditing and its ViewControl) over o3d/visualizer.h. A hidden window (`visible` false)
/// renders through EGL, so it captures images and takes keys and mouse events on a headless machine.
/// Callbacks are std::function; one that throws stops the loop, and run() (or the poll or send call that
/// ran it) rethrows the original exception.
#include <cstdint>
#include <exception>
#include <functional>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "o3d/visualizer.h"
#include "o3dpp/generated/visualizer.hpp"
#include "o3dpp/visualization.hpp"

namespace o3dpp {

/// @brief ViewControl's view: the eye looks at `lookat` from the direction `front`, `zoom` (in [0.02, 2])
/// times the view box's largest extent away in units of the field of view.
struct View {
    Vec3 front{0, 0, 1}, lookat{0, 0, 0}, up{0, 1, 0};
    double zoom = 0.7;
};

/// @brief o3d.visualization.Visualizer. Move-only; belongs to the thread that created its window.
/// The methods that pass their arguments to one C function are generated (detail::VisualizerCalls).
class Visualizer : public Owner<Visualizer, o3d_visualizer_t, &o3d_visualizer_destroy>,
                   public detail::VisualizerCalls<Visualizer> {
    friend class detail::VisualizerCalls<Visualizer>;  // checks its calls with done / ran

public:
    /// @brief Returns true when the geometry or the view changed.
    using AnimationCallback = std::function<bool(Visualizer&)>;
    /// @brief (visualizer, action, O3D_KEY_MOD_* bits); returns true when the geometry or the view changed.
    using KeyCallback = std::function<bool(Visualizer&, KeyAction, int mods)>;

    /// @brief A visualizer without a window; `editing`: VisualizerWithEditing (Shift + click picks).
    explicit Visualizer(bool editing = false)
        : Owner(make([&](o3d_visualizer_t** out) { return o3d_visualizer_create(out, editing ? 1 : 0); })),
          state_(std::make_unique<State>()) {
        state_->owner = this;
    }
    // The callbacks reach the owner through state_->owner, which follows the object when it moves.
    Visualizer(Visualizer&& other) noexcept : Owner(std::move(other)), state_(std::move(other.state_)) {
        if (state_) state_->owner = this;
    }
    Visualizer& operator=(Visualizer&& other) noexcept {
        Owner::operator=(std::move(other));
        state_ = std::move(other.state_);
        if (state_) state_->owner = this;
        return *this;
    }
    ~Visualizer() = default;

    // ---- the scene: geometries are copied; adding under a taken name replaces it (update_geometry) ----
    RenderOption render_option() {
        o3d_render_option_t c = RenderOption::library_defaults();
        check(o3d_visualizer_get_render_option(&c, get()));
        return RenderOption::from_c(c);
    }
    Visualizer& set_render_option(const RenderOption& option) {
        const o3d_render_option_t c = option.to_c();
        return done(o3d_visualizer_set_render_option(get(), &c));
    }

    // ---- the loop and callbacks ----
    /// @brief Called once per loop of run (replaces the previous one; empty removes it).
    Visualizer& register_animation_callback(AnimationCallback callback) {
        auto next = callback ? std::make_shared<AnimationCallback>(std::move(callback)) : nullptr;
        done(o3d_visualizer_register_animation_callback(get(), next ? &animation_trampoline : nullptr, state_.get()));
        state_->animation = std::move(next);
        return *this;
    }
    /// @brief Called on press and repeat of `key` (GLFW's number: 'K', O3D_KEY_*) instead of its binding.
    Visualizer& register_key_callback(int key, KeyCallback callback) {
        return register_key(key, std::move(callback), &o3d_visualizer_register_key_callback);
    }
    /// @brief As register_key_callback, and also on release.
    Visualizer& register_key_action_callback(int key, KeyCallback callback) {
        return register_key(key, std::move(callback), &o3d_visualizer_register_key_action_callback);
    }

    // ---- editing (the captures, a frame drawn for each, are generated) ----
    /// @brief Editing: vertex indices of the first geometry added, in pick order.
    std::vector<int32_t> picked_points() const { return copy_out<int32_t>(&o3d_visualizer_get_picked_points); }
    /// @brief Editing: a copy of the last crop (key C) when it was of a point cloud, else nothing.
    std::optional<PointCloud> cropped_point_cloud() const {
        return cropped<PointCloud>(&o3d_visualizer_get_cropped_pointcloud);
    }
    /// @brief Editing: a copy of the last crop when it was of a triangle mesh, else nothing.
    std::optional<TriangleMesh> cropped_triangle_mesh() const {
        return cropped<TriangleMesh>(&o3d_visualizer_get_cropped_trianglemesh);
    }

    // ---- ViewControl ----
    View view() {
        View v;
        check(o3d_visualizer_view_get(v.front.data(), v.lookat.data(), v.up.data(), &v.zoom, get()));
        return v;
    }
    /// @brief set_front / set_lookat / set_up / set_zoom at once (on error the view is unchanged).
    Visualizer& set_view(const View& v) {
        return done(o3d_visualizer_view_set(get(), v.front.data(), v.lookat.data(), v.up.data(), v.zoom));
    }
    PinholeCameraParameters to_pinhole() {
        PinholeCameraParameters p;
        check(o3d_visualizer_view_to_pinhole(&p.intrinsic, p.extrinsic.data(), get()));
        return p;
    }
    /// @brief The same camera gives the same image (window size, centred principal point, fx = fy).
    Visualizer& from_pinhole(const PinholeCameraParameters& p) {
        return done(o3d_visualizer_view_from_pinhole(get(), &p.intrinsic, p.extrinsic.data()));
    }
    /// @brief The view as Open3D's ViewTrajectory JSON (what Ctrl+C copies).
    std::string view_status() {
        return Buffer::adopt([&](o3d_buffer_t** o) { return o3d_visualizer_get_view_status(o, get()); }).to_string();
    }
    /// @brief Play a ViewTrajectory JSON file, writing image_%06d.png (and depth_%06d.png) into
    /// `capture_dir` unless it is empty; `progress` after each frame may return false to stop.
    Visualizer& play_view_trajectory(const std::string& path, const std::string& capture_dir = "",
                                     bool capture_depth = false, const ProgressCallback& progress = {}) {
        detail::ProgressContext ctx{progress ? &progress : nullptr, nullptr};
        const o3d_status status = o3d_visualizer_play_view_trajectory(
            get(), path.c_str(), capture_dir.empty() ? nullptr : capture_dir.c_str(), capture_depth ? 1 : 0,
            progress ? &detail::progress_trampoline : nullptr, &ctx);
        if (ctx.error) std::rethrow_exception(ctx.error);
        return done(status);
    }

private:
    // The C getter writes NULL when the last crop was of the other kind or nothing was cropped.
    template <typename G, typename H>
    std::optional<G> cropped(o3d_status (*fn)(H**, const o3d_visualizer_t*)) const {
        H* out = nullptr;
        check(fn(&out, get()));
        if (!out) return std::nullopt;
        return G(out);
    }
    struct State;
    // A registered callback: shared, so that one replaced while it runs lives until it returns.
    template <typename F>
    struct Slot {
        State* state = nullptr;
        std::shared_ptr<F> fn;
    };
    // Heap state the trampolines reach through user_data: stays put when the Visualizer moves.
    struct State {
        Visualizer* owner = nullptr;
        std::exception_ptr error;  // what a callback threw, rethrown when the C call returns
        std::shared_ptr<AnimationCallback> animation;
        std::map<int, Slot<KeyCallback>> keys;  // map nodes stay put: their address is the key's user_data
    };

    // Run a callback: an exception is kept for the caller and reported to the loop, which then stops.
    template <typename Call>
    static int32_t invoke(o3d_visualizer_t* vis, State* state, Call&& call) noexcept {
        try {
            return call(*state->owner) ? 1 : 0;
        } catch (const std::exception& e) {
            return failed(vis, state, e.what());
        } catch (...) {
            return failed(vis, state, "a callback threw");
        }
    }
    static int32_t failed(o3d_visualizer_t* vis, State* state, const char* what) noexcept {
        state->error = std::current_exception();  // called from a handler: the exception being handled
        o3d_visualizer_set_callback_error(vis, what);
        return 0;
    }
    static int32_t animation_trampoline(o3d_visualizer_t* vis, void* user_data) noexcept {
        auto* state = static_cast<State*>(user_data);
        const std::shared_ptr<AnimationCallback> fn = state->animation;
        return invoke(vis, state, [&](Visualizer& v) { return (*fn)(v); });
    }
    static int32_t key_trampoline(o3d_visualizer_t* vis, int32_t action, int32_t mods, void* user_data) noexcept {
        auto* slot = static_cast<Slot<KeyCallback>*>(user_data);
        const std::shared_ptr<KeyCallback> fn = slot->fn;
        return invoke(vis, slot->state, [&](Visualizer& v) { return (*fn)(v, static_cast<KeyAction>(action), mods); });
    }
    template <typename Register>
    Visualizer& register_key(int key, KeyCallback callback, Register reg) {
        auto next = callback ? std::make_shared<KeyCallback>(std::move(callback)) : nullptr;
        Slot<KeyCallback>& slot = state_->keys[key];
        slot.state = state_.get();
        done(reg(get(), key, next ? &key_trampoline : nullptr, &slot));
        slot.fn = std::move(next);
        return *this;
    }
    // Check a call that may have run callbacks: a callback's exception first (the status is then
    // O3D_ERROR_CANCELLED), else the status.
    Visualizer& ran(o3d_status status) {
        if (state_ && state_->error) std::rethrow_exception(std::exchange(state_->error, nullptr));
        return done(status);
    }

    std::unique_ptr<State> state_;
};

}  // namespace o3dpp
