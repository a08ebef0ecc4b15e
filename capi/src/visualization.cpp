// SPDX-License-Identifier: MIT
// C API of the offscreen renderer and its options (visualization.h).
#include "o3d/visualization.h"

#include <memory>

#include "camera_internal.h"
#include "internal.h"
#include "render_option_internal.h"
#include "o3d/io/image_io.h"
#include "o3d/visualization/offscreen_renderer.h"

struct o3d_offscreen_renderer {
    std::unique_ptr<o3d::visualization::OffscreenRenderer> renderer;
};

namespace {

using o3d::capi::guard;
using o3d::capi::require;
namespace vis = o3d::visualization;

o3d_render_option_t default_option_c();

using o3d::capi::vec3;
using o3d::capi::write3;

o3d_render_option_t to_c(const vis::RenderOption& o) {
    o3d_render_option_t c{};
    c.struct_size = sizeof c;
    write3(c.background_color, "background_color", o.background_color);
    c.point_size = o.point_size;
    c.line_width = o.line_width;
    c.light_on = o.light_on;
    c.point_show_normal = o.point_show_normal;
    c.mesh_show_wireframe = o.mesh_show_wireframe;
    c.mesh_show_back_face = o.mesh_show_back_face;
    c.mesh_shade_option = int32_t(o.mesh_shade);
    c.point_color_option = int32_t(o.point_color);
    c.mesh_color_option = int32_t(o.mesh_color);
    write3(c.default_mesh_color, "default_mesh_color", o.default_mesh_color);
    write3(c.light_ambient_color, "light_ambient_color", o.light_ambient_color);
    for (int i = 0; i < 4; ++i) {
        write3(c.light_position + 3 * i, "light_position", o.lights[i].position);
        write3(c.light_color + 3 * i, "light_color", o.lights[i].color);
        c.light_diffuse_power[i] = o.lights[i].diffuse_power;
        c.light_specular_power[i] = o.lights[i].specular_power;
        c.light_specular_shininess[i] = o.lights[i].specular_shininess;
    }
    return c;
}

/// @brief The core option for a C one (NULL: defaults), checked: flags must be 0 or 1, enums known.
vis::RenderOption to_core(const o3d_render_option_t* user) {
    const o3d_render_option_t c = o3d::capi::read_options(user, default_option_c(), "opts");
    auto flag = [](int32_t v, const char* name) {
        if (v != 0 && v != 1) throw o3d::InvalidArgument(std::string(name) + " must be 0 or 1");
        return v == 1;
    };
    vis::RenderOption o;
    o.background_color = vec3(c.background_color, "background_color");
    o.point_size = c.point_size;
    o.line_width = c.line_width;
    o.light_on = flag(c.light_on, "light_on");
    o.point_show_normal = flag(c.point_show_normal, "point_show_normal");
    o.mesh_show_wireframe = flag(c.mesh_show_wireframe, "mesh_show_wireframe");
    o.mesh_show_back_face = flag(c.mesh_show_back_face, "mesh_show_back_face");
    if (c.mesh_shade_option != O3D_MESH_SHADE_FLAT && c.mesh_shade_option != O3D_MESH_SHADE_SMOOTH)
        throw o3d::InvalidArgument("mesh_shade_option must be O3D_MESH_SHADE_FLAT or O3D_MESH_SHADE_SMOOTH");
    if (!vis::is_color_option(c.point_color_option) || !vis::is_color_option(c.mesh_color_option))
        throw o3d::InvalidArgument("point_color_option and mesh_color_option must be O3D_COLOR_OPTION_*");
    o.mesh_shade = vis::MeshShade(c.mesh_shade_option);
    o.point_color = vis::ColorOption(c.point_color_option);
    o.mesh_color = vis::ColorOption(c.mesh_color_option);
    o.default_mesh_color = vec3(c.default_mesh_color, "default_mesh_color");
    o.light_ambient_color = vec3(c.light_ambient_color, "light_ambient_color");
    for (int i = 0; i < 4; ++i) {
        o.lights[i].position = vec3(c.light_position + 3 * i, "light_position");
        o.lights[i].color = vec3(c.light_color + 3 * i, "light_color");
        o.lights[i].diffuse_power = c.light_diffuse_power[i];
        o.lights[i].specular_power = c.light_specular_power[i];
        o.lights[i].specular_shininess = c.light_specular_shininess[i];
    }
    vis::check_render_option(o);
    return o;
}

o3d_render_option_t default_option_c() { return to_c(vis::RenderOption()); }

o3d_render_material_t default_material_c() {
    o3d_render_material_t m{};
    m.struct_size = sizeof m;
    m.shader = O3D_SHADER_DEFAULT_LIT;
    for (double& c : m.base_color) c = 1.0;
    return m;
}

vis::Material to_core(const o3d_render_material_t* user) {
    const o3d_render_material_t c = o3d::capi::read_options(user, default_material_c(), "material");
    vis::Material m;
    m.shader = vis::Shader(c.shader);
    m.base_color = Eigen::Vector4d(c.base_color[0], c.base_color[1], c.base_color[2], c.base_color[3]);
    m.point_size = c.point_size;
    m.line_width = c.line_width;
    vis::check_material(m);
    return m;
}

vis::OffscreenRenderer& renderer_of(o3d_offscreen_renderer_t* r) { return *require(r, "renderer")->renderer; }

const char* name_of(const char* name) { return require(name, "name"); }

template <typename Handle, typename Member>
o3d_status add_geometry(const char* function, o3d_offscreen_renderer_t* r, const char* name, const Handle* handle,
                        Member member, const o3d_render_material_t* material) {
    return guard(function, [&] {
        auto& renderer = renderer_of(r);
        require(handle, "geometry");
        renderer.add(name_of(name), handle->*member, to_core(material));
    });
}

}  // namespace

namespace o3d::capi {

visualization::RenderOption render_option_to_core(const o3d_render_option_t* user) { return ::to_core(user); }

void write_render_option(o3d_render_option_t* out, const visualization::RenderOption& option) {
    require(out, "out");
    read_options(out, default_option_c(), "out");  // validates out->struct_size
    const o3d_render_option_t c = ::to_c(option);
    std::memcpy(reinterpret_cast<char*>(out) + sizeof(uint32_t), reinterpret_cast<const char*>(&c) + sizeof(uint32_t),
                out->struct_size - sizeof(uint32_t));  // only the fields the caller's struct has
}

o3d_image_t* new_image(geometry::Image&& image) {
    auto handle = std::make_unique<o3d_image>();
    handle->image = std::move(image);
    return handle.release();
}

}  // namespace o3d::capi

using o3d::capi::new_image;

extern "C" {

O3D_API o3d_status o3d_render_option_init(o3d_render_option_t* opts, uint32_t struct_size) {
    return guard(__func__, [&] { o3d::capi::init_options(opts, struct_size, default_option_c(), "opts"); });
}

O3D_API o3d_status o3d_render_option_load_json(o3d_render_option_t* out, const char* path) {
    return guard(__func__, [&] {
        require(out, "out");
        vis::RenderOption option = to_core(out);
        vis::load_render_option_json(require(path, "path"), option);
        const o3d_render_option_t c = to_c(option);
        std::memcpy(reinterpret_cast<char*>(out) + sizeof(uint32_t), reinterpret_cast<const char*>(&c) + sizeof(uint32_t),
                    out->struct_size - sizeof(uint32_t));  // only the fields the caller's struct has
    });
}

O3D_API o3d_status o3d_render_option_save_json(const char* path, const o3d_render_option_t* opts) {
    return guard(__func__, [&] { vis::save_render_option_json(require(path, "path"), to_core(opts)); });
}

O3D_API o3d_status o3d_render_material_init(o3d_render_material_t* material, uint32_t struct_size) {
    return guard(__func__, [&] { o3d::capi::init_options(material, struct_size, default_material_c(), "material"); });
}

O3D_API o3d_status o3d_offscreen_renderer_create(o3d_offscreen_renderer_t** out, int32_t width, int32_t height,
                                                 int32_t backend) {
    return guard(__func__, [&] {
        require(out, "out");
        *out = nullptr;
        if (backend != O3D_RENDER_BACKEND_AUTO && backend != O3D_RENDER_BACKEND_EGL &&
            backend != O3D_RENDER_BACKEND_GLFW)
            throw o3d::InvalidArgument("backend must be O3D_RENDER_BACKEND_AUTO, _EGL or _GLFW");
        auto handle = std::make_unique<o3d_offscreen_renderer>();
        handle->renderer = std::make_unique<vis::OffscreenRenderer>(width, height, vis::Backend(backend));
        *out = handle.release();
    });
}

O3D_API void o3d_offscreen_renderer_destroy(o3d_offscreen_renderer_t* renderer) {
    // A destructor that fails (a lost context) must not throw across the C boundary.
    guard(__func__, [&] { delete renderer; });
}

O3D_API o3d_status o3d_offscreen_renderer_get_backend(int32_t* out, const o3d_offscreen_renderer_t* renderer) {
    return guard(__func__, [&] {
        *require(out, "out") = int32_t(require(renderer, "renderer")->renderer->backend());
    });
}

O3D_API o3d_status o3d_offscreen_renderer_get_size(int32_t* out_width, int32_t* out_height,
                                                   const o3d_offscreen_renderer_t* renderer) {
    return guard(__func__, [&] {
        require(out_width, "out_width");
        require(out_height, "out_height");
        const auto& r = *require(renderer, "renderer")->renderer;
        *out_width = r.width();
        *out_height = r.height();
    });
}

O3D_API o3d_status o3d_offscreen_renderer_add_pointcloud(o3d_offscreen_renderer_t* renderer, const char* name,
                                                         const o3d_pointcloud_t* pc,
                                                         const o3d_render_material_t* material) {
    return add_geometry(__func__, renderer, name, pc, &o3d_pointcloud::cloud, material);
}

O3D_API o3d_status o3d_offscreen_renderer_add_trianglemesh(o3d_offscreen_renderer_t* renderer, const char* name,
                                                           const o3d_trianglemesh_t* mesh,
                                                           const o3d_render_material_t* material) {
    return add_geometry(__func__, renderer, name, mesh, &o3d_trianglemesh::mesh, material);
}

O3D_API o3d_status o3d_offscreen_renderer_add_lineset(o3d_offscreen_renderer_t* renderer, const char* name,
                                                      const o3d_lineset_t* lineset,
                                                      const o3d_render_material_t* material) {
    return add_geometry(__func__, renderer, name, lineset, &o3d_lineset::lineset, material);
}

O3D_API o3d_status o3d_offscreen_renderer_add_voxelgrid(o3d_offscreen_renderer_t* renderer, const char* name,
                                                        const o3d_voxelgrid_t* grid,
                                                        const o3d_render_material_t* material) {
    return add_geometry(__func__, renderer, name, grid, &o3d_voxelgrid::grid, material);
}

O3D_API o3d_status o3d_offscreen_renderer_has_geometry(int32_t* out, o3d_offscreen_renderer_t* renderer,
                                                       const char* name) {
    return guard(__func__, [&] {
        require(out, "out");
        *out = renderer_of(renderer).has(name_of(name)) ? 1 : 0;
    });
}

O3D_API o3d_status o3d_offscreen_renderer_remove_geometry(o3d_offscreen_renderer_t* renderer, const char* name) {
    return guard(__func__, [&] { renderer_of(renderer).remove(name_of(name)); });
}

O3D_API o3d_status o3d_offscreen_renderer_clear_geometries(o3d_offscreen_renderer_t* renderer) {
    return guard(__func__, [&] { renderer_of(renderer).clear(); });
}

O3D_API o3d_status o3d_offscreen_renderer_set_render_option(o3d_offscreen_renderer_t* renderer,
                                                            const o3d_render_option_t* opts) {
    return guard(__func__, [&] {
        auto& r = renderer_of(renderer);
        r.set_render_option(to_core(opts));
    });
}

O3D_API o3d_status o3d_offscreen_renderer_get_render_option(o3d_render_option_t* out,
                                                            o3d_offscreen_renderer_t* renderer) {
    return guard(__func__, [&] {
        require(out, "out");
        o3d::capi::write_render_option(out, renderer_of(renderer).render_option());
    });
}

O3D_API o3d_status o3d_offscreen_renderer_setup_camera(o3d_offscreen_renderer_t* renderer,
                                                       const o3d_pinhole_intrinsic_t* intrinsic,
                                                       const double extrinsic[16]) {
    return guard(__func__, [&] {
        auto& r = renderer_of(renderer);
        require(intrinsic, "intrinsic");
        require(extrinsic, "extrinsic");
        r.setup_camera(o3d::capi::to_core(*intrinsic), o3d::capi::matrix_from_row_major(extrinsic));
    });
}

O3D_API o3d_status o3d_offscreen_renderer_setup_camera_lookat(o3d_offscreen_renderer_t* renderer,
                                                              const double lookat[3], const double front[3],
                                                              const double up[3], double zoom) {
    return guard(__func__, [&] {
        auto& r = renderer_of(renderer);
        r.setup_camera_lookat(vec3(lookat, "lookat"), vec3(front, "front"), vec3(up, "up"), zoom);
    });
}

O3D_API o3d_status o3d_offscreen_renderer_setup_camera_fov(o3d_offscreen_renderer_t* renderer,
                                                           double vertical_fov_deg, const double center[3],
                                                           const double eye[3], const double up[3]) {
    return guard(__func__, [&] {
        auto& r = renderer_of(renderer);
        r.setup_camera_fov(vertical_fov_deg, vec3(center, "center"), vec3(eye, "eye"), vec3(up, "up"));
    });
}

O3D_API o3d_status o3d_offscreen_renderer_get_camera(o3d_pinhole_intrinsic_t* out_intrinsic,
                                                     double out_extrinsic[16],
                                                     o3d_offscreen_renderer_t* renderer) {
    return guard(__func__, [&] {
        const o3d::camera::PinholeCameraParameters p = renderer_of(renderer).camera();
        if (out_intrinsic) *out_intrinsic = o3d::capi::to_c(p.intrinsic);
        if (out_extrinsic) o3d::capi::matrix_to_row_major(p.extrinsic, out_extrinsic);
    });
}

O3D_API o3d_status o3d_offscreen_renderer_render_to_image(o3d_image_t** out, o3d_offscreen_renderer_t* renderer) {
    return guard(__func__, [&] {
        require(out, "out");
        *out = nullptr;
        *out = new_image(renderer_of(renderer).render_to_image());
    });
}

O3D_API o3d_status o3d_offscreen_renderer_render_to_depth_image(o3d_image_t** out,
                                                                o3d_offscreen_renderer_t* renderer,
                                                                int32_t z_in_view_space) {
    return guard(__func__, [&] {
        require(out, "out");
        *out = nullptr;
        *out = new_image(renderer_of(renderer).render_to_depth_image(z_in_view_space != 0));
    });
}

O3D_API o3d_status o3d_offscreen_renderer_render_to_png(o3d_offscreen_renderer_t* renderer, const char* path) {
    return guard(__func__, [&] {
        require(path, "path");
        o3d::io::write_image(path, renderer_of(renderer).render_to_image(), "png");
    });
}

}  // extern "C"
