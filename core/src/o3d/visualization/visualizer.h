// SPDX-License-Identifier: MIT
#pragma once
/// @file visualizer.h
/// @brief Open3D's legacy Visualizer (with its key-callback and editing variants): a window, a scene of
/// named geometries, a ViewControl moved by mouse and keys, animation and key callbacks, and captures.
///
/// A visible window is a GLFW window (an X display is needed); a hidden one is any context the offscreen
/// renderer can get (EGL first), so a hidden Visualizer works on a headless server. Frames are drawn into
/// the renderer's framebuffer and copied to the window. Not thread-safe: use one from one thread.
#include <exception>
#include <functional>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "o3d/geometry/image.h"
#include "o3d/visualization/offscreen_renderer.h"
#include "o3d/visualization/view_control.h"

namespace o3d::visualization {

class GlfwWindow;

/// @brief GLFW's key, action and modifier numbers (the C API's O3D_KEY_* equal them).
namespace keys {
constexpr int kRelease = 0, kPress = 1, kRepeat = 2;
constexpr int kModShift = 1, kModControl = 2;
constexpr int kMouseLeft = 0, kMouseRight = 1, kMouseMiddle = 2;
}  // namespace keys

class Visualizer {
public:
    /// @brief Returns true when the geometry or the view changed (the frame is drawn again).
    using AnimationCallback = std::function<bool(Visualizer&)>;
    using KeyCallback = std::function<bool(Visualizer&, int action, int mods)>;

    /// @brief `editing`: VisualizerWithEditing (Shift + left click picks the nearest visible point).
    explicit Visualizer(bool editing = false);
    ~Visualizer();
    Visualizer(const Visualizer&) = delete;
    Visualizer& operator=(const Visualizer&) = delete;

    /// @brief Throws InvalidArgument (size, a window already open), Unsupported (no display or context).
    void create_window(const std::string& title, int width, int height, int left, int top, bool visible);
    /// @brief Closes the window and forgets the scene; no-op without one. Not from inside a callback.
    void destroy_window();
    bool has_window() const { return renderer_ != nullptr; }
    bool visible() const { return visible_; }

    /// @brief Adds, or replaces the geometry of that name (update_geometry). reset_bounding_box: the view's
    /// box grows to take it in and the view is reset (Open3D's add_geometry).
    template <typename Geometry>
    void add_geometry(const std::string& name, const Geometry& geometry, bool reset_bounding_box);
    void remove_geometry(const std::string& name, bool reset_bounding_box);
    void clear_geometries();
    bool has_geometry(const std::string& name);

    RenderOption render_option();
    void set_render_option(const RenderOption& option);
    ViewControl& view_control();
    /// @brief The view box again from the scene, then ViewControl::reset (key R).
    void reset_view_point();

    /// @brief Process window events and draw when needed; false once the window was closed.
    bool poll_events();
    /// @brief Draw at the next poll_events.
    void update_renderer();
    /// @brief Until the window is closed: events, the animation callback, frames. A hidden window with no
    /// animation callback cannot be closed by anyone, so then run draws one frame and returns.
    void run();
    /// @brief Ask the window to close (run and poll_events end).
    void close();

    void register_animation_callback(AnimationCallback callback) { animation_ = std::move(callback); }
    /// @brief `every_action`: called for press, repeat and release with (action, mods) (register_key_action_callback);
    /// else for press and repeat only. A user callback replaces o3d's own binding of that key.
    void register_key_callback(int key, KeyCallback callback, bool every_action);

    // Input as the window delivers it; tests and scripts drive the viewer through these.
    void key_event(int key, int action, int mods);
    void mouse_move(double x, double y);
    void mouse_button(int button, int action, int mods);
    void scroll(double dx, double dy);

    /// @brief RGB, 8 bits (capture_screen_float_buffer converts) and depth in metres along the optical
    /// axis, 0 where nothing was drawn. A frame is rendered for each.
    geometry::Image capture_screen();
    geometry::Image capture_depth();

    /// @brief Indices picked (VisualizerWithEditing) into the vertices of the first geometry added.
    const std::vector<int>& picked_points() const { return picked_; }
    /// @brief Pick the point nearest to window pixel (x, y) among those visible within a few pixels; -1 if none.
    int pick_point(double x, double y);

    // Cropping (VisualizerWithEditing), as Open3D's: K locks the view for selecting; a left drag selects a
    // rectangle, Ctrl + left clicks add polygon corners; C keeps the part of the first geometry (a cloud or a
    // mesh) whose points fall inside the selection on screen, shows it in place of the whole, and writes it
    // to the crop directory when one is set. K again leaves selection without cropping.
    bool selecting() const { return selecting_; }
    /// @brief Crop the editing geometry to the selection now (key C); throws InvalidArgument without an
    /// editing geometry or a selection of at least 3 corners.
    void crop_to_selection();
    /// @brief The last crop's result, if the editing geometry was a cloud (a mesh).
    const std::optional<geometry::PointCloud>& cropped_point_cloud() const { return cropped_cloud_; }
    const std::optional<geometry::TriangleMesh>& cropped_triangle_mesh() const { return cropped_mesh_; }
    /// @brief Where each crop is written as cropped_<n>.ply ("" : not written).
    void set_crop_directory(const std::string& directory) { crop_directory_ = directory; }

    /// @brief The view as Open3D's ViewTrajectory JSON with one view (key Ctrl+C), and back (throws ParseError).
    std::string view_status_json() const;
    void set_view_status_json(const std::string& json);

    /// @brief Show each frame of `trajectory`; with `capture_dir`, write image_%06d.png (and depth_%06d.png,
    /// 16-bit millimetres, when `capture_depth`) there. `progress(fraction)` returning false stops it
    /// (Cancelled).
    void play_view_trajectory(const ViewTrajectory& trajectory, const std::string& capture_dir, bool capture_depth,
                              const std::function<bool(double)>& progress);
    /// @brief capture_depth_image's pixels: depth * scale rounded to uint16 (clamped), 0 stays 0.
    static geometry::Image depth_to_uint16(const geometry::Image& depth, double scale);

    /// @brief Help text of the key and mouse bindings (key H prints it).
    static std::string help_text();

private:
    void require_window(const char* what) const;
    void default_key_action(int key, int mods);
    void draw_if_needed();
    /// @brief The renderer's camera from the view control (before each frame and capture).
    void aim_camera();
    /// @brief Drop the editing geometry's points and the picks into it.
    void forget_editing();
    template <typename Geometry>
    void remember_editing(const std::string& name, const Geometry& geometry);
    void toggle_selecting();
    /// @brief Mouse input while selecting; true when it was used.
    bool select_with_mouse_button(int button, int action, int mods);
    bool select_with_mouse_move();
    void show_selection();
    template <typename F>
    void from_window(F&& f);  // runs an input handler from a GLFW callback, keeping its exception for later
    static void install_input(GlfwWindow& window);

    bool editing_;
    bool visible_ = false;
    bool closed_ = false;
    bool redraw_ = true;
    int callback_depth_ = 0;
    GlfwWindow* window_ = nullptr;  // owned by renderer_ when visible
    std::unique_ptr<OffscreenRenderer> renderer_;
    std::unique_ptr<ViewControl> view_;
    AnimationCallback animation_;
    std::map<int, std::pair<KeyCallback, bool>> key_callbacks_;
    // Mouse state for drags.
    double mouse_x_ = 0, mouse_y_ = 0;
    int buttons_down_ = 0, mods_down_ = 0;
    // Editing: the first geometry's vertices, and what was picked.
    std::string editing_name_;
    std::vector<Eigen::Vector3d> editing_points_;
    std::vector<int> picked_;
    std::optional<geometry::PointCloud> editing_cloud_, cropped_cloud_;
    std::optional<geometry::TriangleMesh> editing_mesh_, cropped_mesh_;
    bool selecting_ = false, dragging_rectangle_ = false, selection_is_rectangle_ = false;
    Eigen::Vector2d rectangle_start_ = Eigen::Vector2d::Zero();
    std::vector<Eigen::Vector2d> selection_;  // window pixels
    std::string crop_directory_;
    int crops_ = 0;
    std::exception_ptr pending_;  // thrown inside a GLFW callback, rethrown after the event loop
};

}  // namespace o3d::visualization
