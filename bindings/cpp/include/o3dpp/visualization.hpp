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
#include "o3dpp/generated/options.hpp"
#include "o3dpp/generated/visualization.hpp"
#include "o3dpp/handle.hpp"
#include "o3dpp/image.hpp"
#include "o3dpp/lineset.hpp"
#include "o3dpp/pointcloud.hpp"
#include "o3dpp/span.hpp"
#include "o3dpp/trianglemesh.hpp"
#include "o3dpp/voxelgrid.hpp"

namespace o3dpp {

/// @brief o3d.visualization.RenderOption; defaults from o3d_render_option_init (Open3D's).
struct RenderOption : detail::RenderOptionBase {
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
};

/// @brief How one geometry is drawn; defaults from o3d_render_material_init (lit, white tint, the
/// RenderOption's point size and line width).
struct RenderMaterial : detail::RenderMaterialBase {
    RenderMaterial() = default;
    /// @brief The defaults with shader `s` (e.g. RenderMaterial(Shader::DefaultUnlit)).
    explicit RenderMaterial(Shader s) { shader = s; }
};

/// @brief rendering.OffscreenRenderer: draws copies of geometries into a width x height image without a
/// display. Move-only. Calls on one renderer are serialized by the library, so its queries are not
/// `const` here (as in C).
/// The methods that pass their arguments to one C function are generated (detail::OffscreenRendererCalls).
class OffscreenRenderer
    : public Owner<OffscreenRenderer, o3d_offscreen_renderer_t, &o3d_offscreen_renderer_destroy>,
      public detail::OffscreenRendererCalls<OffscreenRenderer> {
    friend class detail::OffscreenRendererCalls<OffscreenRenderer>;  // checks its calls with done

public:
    using detail::OffscreenRendererCalls<OffscreenRenderer>::setup_camera;  // and the overloads below

    /// @brief A renderer of `width` x `height` pixels (Error O3D_ERROR_UNSUPPORTED without OpenGL 3.3).
    OffscreenRenderer(int width, int height, RenderBackend backend = RenderBackend::Auto)
        : Owner(make([&](o3d_offscreen_renderer_t** out) {
              return o3d_offscreen_renderer_create(out, width, height, static_cast<int32_t>(backend));
          })) {}
    /// @brief Take ownership of `owned` (must not be NULL).
    explicit OffscreenRenderer(o3d_offscreen_renderer_t* owned) : Owner(owned) {}

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
    /// @brief The camera the next render uses, as pinhole parameters (setup_camera of them reproduces it).
    PinholeCameraParameters camera() {
        PinholeCameraParameters p;
        check(o3d_offscreen_renderer_get_camera(&p.intrinsic, p.extrinsic.data(), get()));
        return p;
    }
};

}  // namespace o3dpp
