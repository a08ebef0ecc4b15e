// SPDX-License-Identifier: MIT
#include "o3d/visualization/visualizer.h"

#include <Eigen/Geometry>
#include <cmath>
#include <type_traits>
#include <limits>

#include "o3d/geometry/line_set.h"
#include "o3d/geometry/point_cloud.h"
#include "o3d/geometry/triangle_mesh.h"
#include "o3d/geometry/voxel_grid.h"
#include "o3d/utility/error.h"
#include "o3d/visualization/glfw_window.h"

namespace o3d::visualization {
namespace {

/// @brief Counts nested user callbacks, so that destroy_window cannot pull the scene from under one.
struct CallbackScope {
    explicit CallbackScope(int& depth) : depth_(depth) { ++depth_; }
    ~CallbackScope() { --depth_; }
    int& depth_;
};

const std::vector<Eigen::Vector3d>* vertices_of(const geometry::PointCloud& g) { return &g.points; }
const std::vector<Eigen::Vector3d>* vertices_of(const geometry::TriangleMesh& g) { return &g.vertices; }
const std::vector<Eigen::Vector3d>* vertices_of(const geometry::LineSet& g) { return &g.points; }
const std::vector<Eigen::Vector3d>* vertices_of(const geometry::VoxelGrid&) { return nullptr; }
const std::vector<Eigen::Vector3d>* vertices_of(const geometry::Image&) { return nullptr; }

}  // namespace

Visualizer::Visualizer(bool editing) : editing_(editing) {}

Visualizer::~Visualizer() {
    try {
        destroy_window();
    } catch (...) {  // only a callback in progress can refuse; a destructor has to go on
    }
}

void Visualizer::require_window(const char* what) const {
    if (!renderer_) throw InvalidArgument(std::string(what) + " needs a window: call create_window first");
}

void Visualizer::create_window(const std::string& title, int width, int height, int left, int top, bool visible) {
    if (renderer_) throw InvalidArgument("this visualizer already has a window");
    if (width < 1 || width > 16384 || height < 1 || height > 16384)
        throw InvalidArgument("window size must be 1..16384 pixels each way, got " + std::to_string(width) + " x " +
                              std::to_string(height));
    std::unique_ptr<GLContext> context;
    GlfwWindow* window = nullptr;
    if (visible) {
        std::string why;
        auto created = GlfwWindow::create(title, width, height, left, top, true, &why);
        if (!created) throw Unsupported("cannot open a window (a visible Visualizer needs an X display): " + why);
        window = created.get();
        context = std::move(created);
    } else {
        context = create_gl_context(Backend::Auto);
    }
    renderer_ = std::make_unique<OffscreenRenderer>(width, height, std::move(context));
    view_ = std::make_unique<ViewControl>(width, height);
    window_ = window;
    visible_ = visible;
    closed_ = false;
    redraw_ = true;
    if (window_) {
        glfw().set_window_user_pointer(window_->handle(), this);
        install_input(*window_);
    }
}

void Visualizer::destroy_window() {
    if (callback_depth_ > 0) throw InvalidArgument("destroy_window cannot run inside a callback: call close()");
    renderer_.reset();  // the window goes with its context
    window_ = nullptr;
    view_.reset();
    visible_ = false;
    forget_editing();
}

template <typename Geometry>
void Visualizer::add_geometry(const std::string& name, const Geometry& geometry, bool reset_bounding_box) {
    require_window("add_geometry");
    renderer_->add(name, geometry, Material{}, true);  // an update keeps the old one if the new one fails
    if (editing_ && (editing_name_.empty() || editing_name_ == name)) remember_editing(name, geometry);
    if (reset_bounding_box) {
        SceneBox box = view_->bounding_box();
        box.add(renderer_->geometry_bounds(name));
        view_->set_bounding_box(box);
        view_->reset();
    }
    redraw_ = true;
}

template void Visualizer::add_geometry(const std::string&, const geometry::PointCloud&, bool);
template void Visualizer::add_geometry(const std::string&, const geometry::TriangleMesh&, bool);
template void Visualizer::add_geometry(const std::string&, const geometry::LineSet&, bool);
template void Visualizer::add_geometry(const std::string&, const geometry::VoxelGrid&, bool);
template void Visualizer::add_geometry(const std::string&, const geometry::Image&, bool);

void Visualizer::remove_geometry(const std::string& name, bool reset_bounding_box) {
    require_window("remove_geometry");
    renderer_->remove(name);
    if (name == editing_name_) {
        forget_editing();
    }
    if (reset_bounding_box) reset_view_point();
    redraw_ = true;
}

void Visualizer::clear_geometries() {
    require_window("clear_geometries");
    renderer_->clear();
    forget_editing();
    redraw_ = true;
}

bool Visualizer::has_geometry(const std::string& name) { return renderer_ && renderer_->has(name); }

RenderOption Visualizer::render_option() {
    require_window("get_render_option");
    return renderer_->render_option();
}

void Visualizer::set_render_option(const RenderOption& option) {
    require_window("set_render_option");
    renderer_->set_render_option(option);
    redraw_ = true;
}

ViewControl& Visualizer::view_control() {
    require_window("get_view_control");
    redraw_ = true;  // the caller may move the view: the window shows it at the next poll
    return *view_;
}

void Visualizer::reset_view_point() {
    require_window("reset_view_point");
    view_->set_bounding_box(renderer_->scene_bounds());
    view_->reset();
    redraw_ = true;
}

void Visualizer::aim_camera() {
    const camera::PinholeCameraParameters camera = view_->to_pinhole();
    renderer_->setup_camera(camera.intrinsic, camera.extrinsic);
}

void Visualizer::forget_editing() {
    editing_name_.clear();
    editing_points_.clear();
    editing_cloud_.reset();
    editing_mesh_.reset();
    picked_.clear();
}

template <typename Geometry>
void Visualizer::remember_editing(const std::string& name, const Geometry& geometry) {
    const auto* vertices = vertices_of(geometry);
    if (!vertices) return;
    editing_name_ = name;
    editing_points_ = *vertices;
    editing_cloud_.reset();
    editing_mesh_.reset();
    if constexpr (std::is_same_v<Geometry, geometry::PointCloud>) editing_cloud_ = geometry;
    if constexpr (std::is_same_v<Geometry, geometry::TriangleMesh>) editing_mesh_ = geometry;
}

void Visualizer::draw_if_needed() {
    if (!redraw_ || !renderer_) return;
    redraw_ = false;
    if (!window_) return;  // a hidden context draws when something is captured
    aim_camera();
    renderer_->render_to_window([this] { glfw().swap_buffers(window_->handle()); });
}

bool Visualizer::poll_events() {
    if (!renderer_ || closed_) return false;
    draw_if_needed();
    if (window_) {
        glfw().poll_events();
        if (pending_) std::rethrow_exception(std::exchange(pending_, nullptr));
        if (glfw().window_should_close(window_->handle())) closed_ = true;
        draw_if_needed();
    }
    return !closed_;
}

void Visualizer::run() {
    require_window("run");
    redraw_ = true;
    if (!window_ && !animation_) {  // nothing could ever close it
        poll_events();
        return;
    }
    while (poll_events()) {
        if (animation_) {
            const AnimationCallback callback = animation_;  // a copy: the callback may replace itself
            CallbackScope scope(callback_depth_);
            if (callback(*this)) redraw_ = true;
        } else {
            glfw().wait_events_timeout(0.1);
        }
    }
}

void Visualizer::close() {
    closed_ = true;
    if (window_) glfw().set_window_should_close(window_->handle(), GLFW_TRUE);
}

void Visualizer::register_key_callback(int key, KeyCallback callback, bool every_action) {
    if (callback) key_callbacks_[key] = {std::move(callback), every_action};
    else key_callbacks_.erase(key);
}

void Visualizer::key_event(int key, int action, int mods) {
    const auto it = key_callbacks_.find(key);
    if (it != key_callbacks_.end()) {
        if (!it->second.second && action == keys::kRelease) return;
        const KeyCallback callback = it->second.first;  // a copy: the callback may register another
        CallbackScope scope(callback_depth_);
        if (callback(*this, action, mods)) redraw_ = true;
        return;
    }
    if (action == keys::kRelease) return;
    default_key_action(key, mods);
}

void Visualizer::mouse_move(double x, double y) {
    const double dx = x - mouse_x_, dy = y - mouse_y_;
    mouse_x_ = x;
    mouse_y_ = y;
    if (!view_ || select_with_mouse_move() || buttons_down_ == 0) return;
    const bool left = buttons_down_ & (1 << keys::kMouseLeft);
    const bool middle = buttons_down_ & (1 << keys::kMouseMiddle);
    if (middle || (left && (mods_down_ & keys::kModControl))) view_->translate(dx, dy);
    else if (left && !(mods_down_ & keys::kModShift)) view_->rotate(dx, dy);
    redraw_ = true;
}

void Visualizer::mouse_button(int button, int action, int mods) {
    if (button < 0 || button > 7) return;
    if (select_with_mouse_button(button, action, mods)) return;
    if (action == keys::kPress) {
        buttons_down_ |= 1 << button;
        mods_down_ = mods;
        return;
    }
    buttons_down_ &= ~(1 << button);
    if (!editing_ || !(mods & keys::kModShift) || !renderer_) return;
    if (button == keys::kMouseLeft) {
        const int index = pick_point(mouse_x_, mouse_y_);
        if (index >= 0) picked_.push_back(index);
    } else if (button == keys::kMouseRight && !picked_.empty()) {
        picked_.pop_back();
    }
}

void Visualizer::scroll(double, double dy) {
    if (!view_) return;
    view_->scale(dy);
    redraw_ = true;
}

// A capture reads the frame the window shows, drawing it first when it is due (as Open3D's do_render), and
// never draws one frame twice: the renderer redraws only when the view, the scene or the option changed.
geometry::Image Visualizer::capture_screen() {
    require_window("capture_screen");
    draw_if_needed();
    aim_camera();
    return renderer_->render_to_image(OffscreenRenderer::Frame::ReuseIfCurrent);
}

geometry::Image Visualizer::capture_depth() {
    require_window("capture_depth");
    draw_if_needed();
    aim_camera();
    return renderer_->render_to_depth_image(true, OffscreenRenderer::Frame::ReuseIfCurrent);
}

void Visualizer::update_renderer() {
    redraw_ = true;
    if (renderer_) renderer_->invalidate();  // the caller says the frame is stale, so it is drawn again
}

int Visualizer::pick_point(double x, double y) {
    require_window("pick_point");
    if (editing_points_.empty() || !std::isfinite(x) || !std::isfinite(y)) return -1;
    const geometry::Image depth = capture_depth();
    const auto camera = view_->to_pinhole();
    const auto& k = camera.intrinsic;
    const double radius = std::max(3.0, renderer_->render_option().point_size);
    const double extent = view_->bounding_box().max_extent();
    int best = -1;
    double best_distance = std::numeric_limits<double>::infinity();
    for (size_t i = 0; i < editing_points_.size(); ++i) {
        const Eigen::Vector4d p = camera.extrinsic * editing_points_[i].homogeneous();
        if (!(p.z() > 0)) continue;
        const double u = k.fx * p.x() / p.z() + k.cx, v = k.fy * p.y() / p.z() + k.cy;
        const double d = std::hypot(u - x, v - y);
        if (!(d <= radius) || d >= best_distance) continue;
        const int pu = int(std::lround(u)), pv = int(std::lround(v));
        if (pu < 0 || pv < 0 || pu >= depth.width || pv >= depth.height) continue;
        const float seen = *depth.pixel<float>(pu, pv);
        // Hidden behind something else drawn at that pixel: not pickable.
        if (seen > 0 && p.z() > seen + 0.01 * extent) continue;
        best = int(i);
        best_distance = d;
    }
    return best;
}

std::string Visualizer::view_status_json() const {
    require_window("view_status_json");
    ViewTrajectory t;
    t.views.push_back(view_->status());
    return view_trajectory_to_json(t);
}

void Visualizer::set_view_status_json(const std::string& json) {
    require_window("set_view_status_json");
    const ViewTrajectory t = view_trajectory_from_json(json);
    view_->set_status(t.views.front());
    redraw_ = true;
}

}  // namespace o3d::visualization
