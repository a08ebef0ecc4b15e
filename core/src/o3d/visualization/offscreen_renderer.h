// SPDX-License-Identifier: MIT
#pragma once
/// @file offscreen_renderer.h
/// @brief Renders a scene of named geometries into an offscreen framebuffer (Open3D's OffscreenRenderer,
/// drawn in the style of its legacy Visualizer), and reads back colour and depth.
#include <map>
#include <memory>
#include <cstdint>
#include <mutex>
#include <string>
#include <utility>

#include "o3d/camera/pinhole_camera.h"
#include "o3d/geometry/image.h"
#include "o3d/visualization/gl_context.h"
#include "o3d/visualization/gpu_geometry.h"
#include "o3d/visualization/render_option.h"
#include "o3d/visualization/shader_program.h"
#include "o3d/visualization/view_camera.h"

namespace o3d::visualization {

struct FrameUniforms;

class OffscreenRenderer {
public:
    /// @brief Throws InvalidArgument (size), Unsupported (no context, or the shader does not build).
    OffscreenRenderer(int width, int height, Backend backend);
    /// @brief Renders with `context` (e.g. a visible window's), which must stay alive as long as this.
    OffscreenRenderer(int width, int height, std::unique_ptr<GLContext> context);
    ~OffscreenRenderer();
    OffscreenRenderer(const OffscreenRenderer&) = delete;
    OffscreenRenderer& operator=(const OffscreenRenderer&) = delete;

    int width() const { return width_; }
    int height() const { return height_; }
    Backend backend() const { return backend_; }

    // Scene. Names are unique; add throws InvalidArgument for an empty or taken name.
    /// `replace`: a geometry of that name is swapped for the new one once it is uploaded (kept on failure).
    template <typename Geometry>
    void add(const std::string& name, const Geometry& geometry, const Material& material, bool replace = false);
    bool has(const std::string& name);
    void remove(const std::string& name);  ///< throws InvalidArgument when absent
    void clear();

    void set_render_option(const RenderOption& option);  ///< checked
    RenderOption render_option();

    // Camera (see visualization.h for the three forms); each throws InvalidArgument on bad values.
    void setup_camera(const camera::PinholeCameraIntrinsic& intrinsic, const Eigen::Matrix4d& extrinsic);
    void setup_camera_lookat(const Eigen::Vector3d& lookat, const Eigen::Vector3d& front, const Eigen::Vector3d& up,
                             double zoom);
    void setup_camera_fov(double vertical_fov_deg, const Eigen::Vector3d& center, const Eigen::Vector3d& eye,
                          const Eigen::Vector3d& up);
    /// @brief The pinhole parameters the next render uses.
    camera::PinholeCameraParameters camera();

    /// @brief The box around every geometry in the scene, or around the one named (throws when absent).
    SceneBox scene_bounds();
    SceneBox geometry_bounds(const std::string& name);
    /// @brief The context this renders with.
    GLContext& context() { return *context_; }

    /// @brief Whether a read may return the frame last drawn: only when nothing that shapes it (geometry,
    /// render option, camera; see invalidate) changed since. A viewer that has just drawn its window reads
    /// that frame instead of drawing it again.
    enum class Frame { Redraw, ReuseIfCurrent };
    geometry::Image render_to_image(Frame frame = Frame::Redraw);  ///< RGB, 1 byte per channel
    geometry::Image render_to_depth_image(bool z_in_view_space, Frame frame = Frame::Redraw);  ///< float32
    /// @brief A closed outline through window pixels, drawn over the scene in `color` (not part of the scene:
    /// no name, no box); fewer than 2 pixels removes it.
    void set_outline(const std::vector<Eigen::Vector2d>& pixels, const Eigen::Vector3d& color);
    /// @brief The next ReuseIfCurrent read draws (a viewer's update_renderer: the caller says something changed).
    void invalidate();
    /// @brief Render, copy the frame to the context's default framebuffer (a window) and call `swap`
    /// while the context is still current.
    template <typename Swap>
    void render_to_window(Swap&& swap) {
        std::lock_guard<std::mutex> lock(mutex_);
        CurrentContext current(*context_);
        draw_scene();
        blit_to_default_framebuffer();
        swap();
    }

private:
    struct CameraSetting;
    void add_uploaded(const std::string& name, GpuGeometry&& geometry);
    SceneBox scene_box() const;
    camera::PinholeCameraParameters resolve_camera(const SceneBox& box) const;
    /// @brief One frame into the framebuffer; returns the near and far planes it used.
    std::pair<double, double> draw_scene();
    /// @brief draw_scene, unless `frame` allows the one drawn last and it is current.
    std::pair<double, double> frame(Frame frame);
    void draw_geometry(const GpuGeometry& g, const FrameUniforms& frame);
    void blit_to_default_framebuffer();

    int width_, height_;
    Backend backend_;
    std::mutex mutex_;  // one call at a time: the context is bound for the duration of each
    std::unique_ptr<GLContext> context_;
    ShaderPrograms programs_;
    GLuint framebuffer_ = 0, color_buffer_ = 0, depth_buffer_ = 0;
    std::map<std::string, GpuGeometry> scene_;
    GpuGeometry outline_;
    Eigen::Vector3d outline_color_ = Eigen::Vector3d::Zero();
    RenderOption option_;
    std::unique_ptr<CameraSetting> camera_;
    uint64_t changes_ = 1, drawn_ = 0;  // changes_ counts what shapes a frame; drawn_ is its value at the last draw
    std::pair<double, double> drawn_near_far_{0.0, 0.0};
};

}  // namespace o3d::visualization
