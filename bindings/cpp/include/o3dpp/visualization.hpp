// SPDX-License-Identifier: MIT
#pragma once
/// @file visualization.hpp
/// @brief Rendering without a display: o3dpp::RenderOption (o3d.visualization.RenderOption),
/// o3dpp::RenderMaterial (a subset of rendering.MaterialRecord) and o3dpp::OffscreenRenderer
/// (rendering.OffscreenRenderer with its scene's add/remove/has/clear). See o3d/visualization.h for the
/// camera and lighting model.
#include <array>
#include <cstdint>
#include <string>
#include <utility>

#include "o3d/visualization.h"
#include "o3dpp/arrays.hpp"
#include "o3dpp/camera.hpp"
#include "o3dpp/error.hpp"
#include "o3dpp/handle.hpp"
#include "o3dpp/image.hpp"
#include "o3dpp/lineset.hpp"
#include "o3dpp/options.hpp"
#include "o3dpp/pointcloud.hpp"
#include "o3dpp/span.hpp"
#include "o3dpp/trianglemesh.hpp"
#include "o3dpp/voxelgrid.hpp"

namespace o3dpp {

/// @brief Where the renderer's OpenGL context comes from.
enum class RenderBackend : int32_t {
    Auto = O3D_RENDER_BACKEND_AUTO,  ///< EGL when it works, else a hidden GLFW window
    Egl = O3D_RENDER_BACKEND_EGL,    ///< headless EGL only
    Glfw = O3D_RENDER_BACKEND_GLFW   ///< a hidden GLFW window only (needs a display)
};

/// @brief RenderOption.mesh_shade_option.
enum class MeshShadeOption : int32_t { Flat = O3D_MESH_SHADE_FLAT, Smooth = O3D_MESH_SHADE_SMOOTH };

/// @brief RenderOption.point_color_option and mesh_color_option.
enum class ColorOption : int32_t {
    Default = O3D_COLOR_OPTION_DEFAULT,
    Color = O3D_COLOR_OPTION_COLOR,
    XCoordinate = O3D_COLOR_OPTION_X,
    YCoordinate = O3D_COLOR_OPTION_Y,
    ZCoordinate = O3D_COLOR_OPTION_Z,
    Normal = O3D_COLOR_OPTION_NORMAL
};

/// @brief A material's shader.
enum class Shader : int32_t { DefaultLit = O3D_SHADER_DEFAULT_LIT, DefaultUnlit = O3D_SHADER_DEFAULT_UNLIT };

/// @brief o3d.visualization.RenderOption; defaults from o3d_render_option_init (Open3D's).
struct RenderOption : COptions<RenderOption, o3d_render_option_t, &o3d_render_option_init> {
    Vec3 background_color;
    double point_size;
    double line_width;
    bool light_on;
    bool point_show_normal;
    bool mesh_show_wireframe;
    bool mesh_show_back_face;
    MeshShadeOption mesh_shade_option;
    ColorOption point_color_option;
    ColorOption mesh_color_option;
    Vec3 default_mesh_color;
    Vec3 light_ambient_color;
    std::array<double, 12> light_position;  ///< 4 lights x (right, up, front) relative to the scene's box
    std::array<double, 12> light_color;     ///< 4 RGB
    std::array<double, 4> light_diffuse_power;
    std::array<double, 4> light_specular_power;
    std::array<double, 4> light_specular_shininess;

    RenderOption() { load(library_defaults()); }
    static RenderOption from_c(const o3d_render_option_t& c) {
        RenderOption r;
        r.load(c);
        return r;
    }
    /// @brief These options with the fields present in an Open3D RenderOption JSON file replaced.
    RenderOption& load_from_json(const std::string& path) {
        o3d_render_option_t c = to_c();
        check(o3d_render_option_load_json(&c, path.c_str()));
        load(c);
        return *this;
    }
    /// @brief Write in Open3D's RenderOption JSON layout.
    void save_to_json(const std::string& path) const {
        const o3d_render_option_t c = to_c();
        check(o3d_render_option_save_json(path.c_str(), &c));
    }

    template <typename S, typename C, typename F>
    static void fields(S& s, C& c, F f) {
        f(s.background_color, c.background_color);
        f(s.point_size, c.point_size);
        f(s.line_width, c.line_width);
        f(s.light_on, c.light_on);
        f(s.point_show_normal, c.point_show_normal);
        f(s.mesh_show_wireframe, c.mesh_show_wireframe);
        f(s.mesh_show_back_face, c.mesh_show_back_face);
        f(s.mesh_shade_option, c.mesh_shade_option);
        f(s.point_color_option, c.point_color_option);
        f(s.mesh_color_option, c.mesh_color_option);
        f(s.default_mesh_color, c.default_mesh_color);
        f(s.light_ambient_color, c.light_ambient_color);
        f(s.light_position, c.light_position);
        f(s.light_color, c.light_color);
        f(s.light_diffuse_power, c.light_diffuse_power);
        f(s.light_specular_power, c.light_specular_power);
        f(s.light_specular_shininess, c.light_specular_shininess);
    }
};

/// @brief How one geometry is drawn; defaults from o3d_render_material_init (lit, white tint, the
/// RenderOption's point size and line width).
struct RenderMaterial : COptions<RenderMaterial, o3d_render_material_t, &o3d_render_material_init> {
    Shader shader;
    std::array<double, 4> base_color;  ///< multiplies the geometry's colors (RGBA; alpha unused)
    double point_size;                 ///< pixels; 0 = the RenderOption's
    double line_width;                 ///< pixels; 0 = the RenderOption's

    RenderMaterial() { load(library_defaults()); }
    /// @brief The defaults with shader `s` (e.g. RenderMaterial(Shader::DefaultUnlit)).
    explicit RenderMaterial(Shader s) : RenderMaterial() { shader = s; }

    template <typename S, typename C, typename F>
    static void fields(S& s, C& c, F f) {
        f(s.shader, c.shader);
        f(s.base_color, c.base_color);
        f(s.point_size, c.point_size);
        f(s.line_width, c.line_width);
    }
};

/// @brief rendering.OffscreenRenderer: draws copies of geometries into a width x height image without a
/// display. Move-only. Calls on one renderer are serialized by the library, so its queries are not
/// `const` here (as in C).
class OffscreenRenderer
    : public Owner<OffscreenRenderer, o3d_offscreen_renderer_t, &o3d_offscreen_renderer_destroy> {
public:
    /// @brief A renderer of `width` x `height` pixels (Error O3D_ERROR_UNSUPPORTED without OpenGL 3.3).
    OffscreenRenderer(int width, int height, RenderBackend backend = RenderBackend::Auto)
        : Owner(make([&](o3d_offscreen_renderer_t** out) {
              return o3d_offscreen_renderer_create(out, width, height, static_cast<int32_t>(backend));
          })) {}
    /// @brief Take ownership of `owned` (must not be NULL).
    explicit OffscreenRenderer(o3d_offscreen_renderer_t* owned) : Owner(owned) {}

    /// @brief The backend it runs on (Egl or Glfw, never Auto).
    RenderBackend backend() const {
        return static_cast<RenderBackend>(query(&o3d_offscreen_renderer_get_backend));
    }
    /// @brief (width, height) in pixels.
    std::pair<int, int> size() const {
        int32_t w = 0, h = 0;
        check(o3d_offscreen_renderer_get_size(&w, &h, get()));
        return {w, h};
    }

    // ---- the scene: geometries are copied when added ----
    OffscreenRenderer& add(const std::string& name, const PointCloud& cloud, const RenderMaterial& material = {}) {
        const o3d_render_material_t m = material.to_c();
        return done(o3d_offscreen_renderer_add_pointcloud(get(), name.c_str(), cloud.get(), &m));
    }
    OffscreenRenderer& add(const std::string& name, const TriangleMesh& mesh, const RenderMaterial& material = {}) {
        const o3d_render_material_t m = material.to_c();
        return done(o3d_offscreen_renderer_add_trianglemesh(get(), name.c_str(), mesh.get(), &m));
    }
    OffscreenRenderer& add(const std::string& name, const LineSet& lines, const RenderMaterial& material = {}) {
        const o3d_render_material_t m = material.to_c();
        return done(o3d_offscreen_renderer_add_lineset(get(), name.c_str(), lines.get(), &m));
    }
    OffscreenRenderer& add(const std::string& name, const VoxelGrid& grid, const RenderMaterial& material = {}) {
        const o3d_render_material_t m = material.to_c();
        return done(o3d_offscreen_renderer_add_voxelgrid(get(), name.c_str(), grid.get(), &m));
    }
    bool has(const std::string& name) {
        int32_t out = 0;
        check(o3d_offscreen_renderer_has_geometry(&out, get(), name.c_str()));
        return out != 0;
    }
    /// @brief Remove `name` (Error when it is not in the scene).
    OffscreenRenderer& remove(const std::string& name) {
        return done(o3d_offscreen_renderer_remove_geometry(get(), name.c_str()));
    }
    OffscreenRenderer& clear() { return done(o3d_offscreen_renderer_clear_geometries(get())); }

    // ---- style and camera ----
    OffscreenRenderer& set_render_option(const RenderOption& option) {
        const o3d_render_option_t c = option.to_c();
        return done(o3d_offscreen_renderer_set_render_option(get(), &c));
    }
    RenderOption render_option() {
        o3d_render_option_t c = RenderOption::library_defaults();
        check(o3d_offscreen_renderer_get_render_option(&c, get()));
        return RenderOption::from_c(c);
    }
    /// @brief A pinhole camera: intrinsic of the renderer's size, row-major world-to-camera extrinsic.
    OffscreenRenderer& setup_camera(const PinholeIntrinsic& intrinsic, const Mat4& extrinsic) {
        return done(o3d_offscreen_renderer_setup_camera(get(), &intrinsic, extrinsic.data()));
    }
    OffscreenRenderer& setup_camera(const PinholeCameraParameters& parameters) {
        return setup_camera(parameters.intrinsic, parameters.extrinsic);
    }
    /// @brief A perspective camera at `eye` looking at `center`, `up` up, with a vertical field of view.
    OffscreenRenderer& setup_camera(double vertical_fov_deg, const Vec3& center, const Vec3& eye, const Vec3& up) {
        return done(o3d_offscreen_renderer_setup_camera_fov(get(), vertical_fov_deg, center.data(), eye.data(),
                                                            up.data()));
    }
    /// @brief Open3D's ViewControl view (draw_geometries' lookat/front/up/zoom), resolved at each render
    /// against the scene's bounding box.
    OffscreenRenderer& setup_camera_lookat(const Vec3& lookat, const Vec3& front, const Vec3& up, double zoom = 0.7) {
        return done(o3d_offscreen_renderer_setup_camera_lookat(get(), lookat.data(), front.data(), up.data(), zoom));
    }
    /// @brief The camera the next render uses, as pinhole parameters (setup_camera of them reproduces it).
    PinholeCameraParameters camera() {
        PinholeCameraParameters p;
        check(o3d_offscreen_renderer_get_camera(&p.intrinsic, p.extrinsic.data(), get()));
        return p;
    }

    // ---- rendering ----
    /// @brief RGB, 1 byte a channel.
    Image render_to_image() {
        return Image::adopt([&](o3d_image_t** out) { return o3d_offscreen_renderer_render_to_image(out, get()); });
    }
    /// @brief 1-channel float32: with `z_in_view_space` the distance along the camera's axis (0 where
    /// nothing was drawn), else the depth buffer in [0, 1] (1 where nothing was drawn).
    Image render_to_depth_image(bool z_in_view_space = false) {
        return Image::adopt([&](o3d_image_t** out) {
            return o3d_offscreen_renderer_render_to_depth_image(out, get(), z_in_view_space ? 1 : 0);
        });
    }
    /// @brief Render and write a PNG file.
    void render_to_png(const std::string& path) { check(o3d_offscreen_renderer_render_to_png(get(), path.c_str())); }
};

}  // namespace o3dpp
