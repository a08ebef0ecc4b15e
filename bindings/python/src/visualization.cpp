// SPDX-License-Identifier: MIT
// o3d.visualization.RenderOption (with MeshShadeOption, PointColorOption, MeshColorOption) and
// o3d.visualization.rendering.MaterialRecord / OffscreenRenderer / Open3DScene over visualization.h.
// Defaults come from o3d_render_option_init and o3d_render_material_init; every check on a value is the
// C library's, so a bad option raises where the C call rejects it.

#include "generated/visualization_methods.h"

namespace o3dpy {
namespace {

using RendererHandle = Handle<o3d_offscreen_renderer_t, &o3d_offscreen_renderer_destroy>;
using RendererPtr = std::shared_ptr<RendererHandle>;

/// Run `f(renderer)` under the renderer's lock with the GIL released; the status is the caller's to check
/// (so I/O calls can pass their path to check()).
template <typename F>
o3d_status with_renderer(const RendererPtr& r, F&& f) {
    py::gil_scoped_release release;
    std::unique_lock<std::shared_mutex> lock(r->mutex);
    return f(r->p);
}

/// A RenderOption: a plain value, or (renderer.render_option) a live view of one renderer's option, so
/// that `renderer.render_option.point_size = 3` changes the renderer, as Open3D's
/// `vis.get_render_option().point_size = 3` does.
struct PyRenderOption {
    o3d_render_option_t v = init_of(&o3d_render_option_init);
    OptionEdit bound;  // the owner of a live option (a renderer or a Visualizer); empty for a plain value
};

/// renderer.render_option's owner: the renderer, under its lock.
OptionEdit renderer_options(const RendererPtr& r) {
    return [r](const OptionChange& change, bool write) {
        return with_renderer(r, [&](o3d_offscreen_renderer_t* p) {
            return edit_option(p, &o3d_offscreen_renderer_get_render_option, &o3d_offscreen_renderer_set_render_option,
                               change, write);
        });
    };
}

o3d_render_option_t current(const PyRenderOption& o) {
    if (!o.bound) return o.v;
    o3d_render_option_t out{};
    check(o.bound([&](o3d_render_option_t& x) { return out = x, O3D_OK; }, false));
    return out;
}

/// Apply `change` (plain C++, no Python: it runs without the GIL) to the option; a bound option is read,
/// changed and written back under one lock, so the renderer validates the new value at once.
template <typename F>
void update(PyRenderOption& o, F&& change) {
    if (!o.bound) {
        change(o.v);
        return;
    }
    check(o.bound([&](o3d_render_option_t& x) { return change(x), O3D_OK; }, true));
}

/// A field shown to Python as `Py` (bool, double or an enum; a C array as a (3,) float64 array, a copy: assign
/// to change it), stored as the C field's type.
template <typename Py, typename C>
void def_field(py::class_<PyRenderOption>& cls, const char* name, C o3d_render_option_t::*field, const char* doc) {
    if constexpr (std::is_array_v<C>) {
        static_assert(std::extent_v<C> == 3, "RenderOption shows RGB arrays only");
        cls.def_property(
            name, [field](const PyRenderOption& o) { return vec3_to_array(current(o).*field); },
            [field, name](PyRenderOption& o, py::handle value) {
                auto rgb = as_vec3(value, name);
                update(o, [&](o3d_render_option_t& x) { std::memcpy(x.*field, rgb.data(), sizeof(rgb)); });
            },
            doc);
    } else {
        cls.def_property(
            name, [field](const PyRenderOption& o) { return static_cast<Py>(current(o).*field); },
            [field](PyRenderOption& o, Py value) { update(o, [&](o3d_render_option_t& x) { x.*field = static_cast<C>(value); }); },
            doc);
    }
}

/// o3d.visualization.rendering.MaterialRecord: the subset the C material has. `shader` is kept as
/// written and checked when the material is used.
struct PyMaterial {
    std::string shader;
    std::array<double, 4> base_color{};
    double point_size = 0.0;
    double line_width = 0.0;
    PyMaterial() {
        const o3d_render_material_t d = init_of(&o3d_render_material_init);
        shader = d.shader == O3D_SHADER_DEFAULT_UNLIT ? "defaultUnlit" : "defaultLit";
        std::memcpy(base_color.data(), d.base_color, sizeof(d.base_color));
        point_size = d.point_size;
        line_width = d.line_width;
    }
};

o3d_render_material_t to_c(const PyMaterial& m) {
    o3d_render_material_t c = init_of(&o3d_render_material_init);
    if (m.shader == "defaultLit")
        c.shader = O3D_SHADER_DEFAULT_LIT;
    else if (m.shader == "defaultUnlit" || m.shader == "unlitLine")  // Open3D's tutorials draw line sets with "unlitLine"
        c.shader = O3D_SHADER_DEFAULT_UNLIT;
    else
        invalid("MaterialRecord.shader: \"" + m.shader +
                "\" is not supported (use \"defaultLit\", \"defaultUnlit\" or \"unlitLine\")");
    std::memcpy(c.base_color, m.base_color.data(), sizeof(c.base_color));
    c.point_size = m.point_size;
    c.line_width = m.line_width;
    return c;
}

/// A color of 3 (RGB) or 4 (RGBA) numbers as RGBA (alpha 1 when not given).
std::array<double, 4> as_rgba(py::handle value, const char* what) {
    py::array a = as_numeric(value, what);
    auto d = py::array_t<double, py::array::c_style | py::array::forcecast>::ensure(a);
    if (!d) throw py::error_already_set();
    if (d.ndim() != 1 || (d.size() != 3 && d.size() != 4))
        invalid(std::string(what) + ": expected 3 or 4 numbers, got shape " + shape_string(a));
    std::array<double, 4> out{0, 0, 0, 1};
    std::memcpy(out.data(), d.data(), (size_t)d.size() * sizeof(double));
    return out;
}

struct PyRenderer {
    RendererPtr h;
};
/// renderer.scene: the renderer's geometries and background (Open3D's Open3DScene).
struct PyScene {
    RendererPtr h;
};

/// Add a geometry held by a Python object: its lock (shared) is taken before the renderer's, the only
/// order in which both are ever held, so two threads cannot deadlock.
template <typename GH, typename T>
void add_locked(const RendererPtr& r, const std::string& name, const std::shared_ptr<GH>& g,
                o3d_status (*add)(o3d_offscreen_renderer_t*, const char*, const T*, const o3d_render_material_t*),
                const o3d_render_material_t* material) {
    o3d_status s;
    {
        py::gil_scoped_release release;
        std::shared_lock<std::shared_mutex> geometry_lock(g->mutex);
        std::unique_lock<std::shared_mutex> renderer_lock(r->mutex);
        s = add(r->p, name.c_str(), g->p, material);
    }
    check(s);
}

/// A bounding box is drawn as its 12 edges in its `color`, as Open3D draws one.
void add_box(const RendererPtr& r, const std::string& name, py::handle box, const o3d_render_material_t* material) {
    o3d_lineset_t* raw = nullptr;
    if (is_obb(box)) {
        o3d_obb_t obb = obb_of(box);
        check(o3d_lineset_create_from_oriented_bounding_box(&raw, &obb));
    } else {
        auto [lo, hi] = aabb_bounds(box);
        check(o3d_lineset_create_from_axis_aligned_bounding_box(&raw, lo.data(), hi.data()));
    }
    std::unique_ptr<o3d_lineset_t, void (*)(o3d_lineset_t*)> lines(raw, &o3d_lineset_destroy);
    if (py::hasattr(box, "color")) {
        auto rgb = as_vec3(box.attr("color"), "bounding box color");
        check(o3d_lineset_paint_uniform_color(lines.get(), rgb.data()));
    }
    check(with_renderer(r, [&](o3d_offscreen_renderer_t* p) {
        return o3d_offscreen_renderer_add_lineset(p, name.c_str(), lines.get(), material);
    }));
}

void add_geometry(const PyScene& scene, const std::string& name, py::handle geometry, py::handle material) {
    o3d_render_material_t m{};
    const o3d_render_material_t* mp = nullptr;  // NULL: the C defaults, which MaterialRecord() also has
    if (!material.is_none()) {
        if (!py::isinstance<PyMaterial>(material))
            throw py::type_error("add_geometry: material must be an o3d.visualization.rendering.MaterialRecord");
        m = to_c(material.cast<const PyMaterial&>());
        mp = &m;
    }
    const RendererPtr& r = scene.h;
    py::module_ geometry_module = py::module_::import("o3d.geometry");
    if (py::isinstance<PyPointCloud>(geometry))
        add_locked(r, name, geometry.cast<const PyPointCloud&>().h, &o3d_offscreen_renderer_add_pointcloud, mp);
    else if (py::isinstance<PyTriangleMesh>(geometry))
        add_locked(r, name, geometry.cast<const PyTriangleMesh&>().h, &o3d_offscreen_renderer_add_trianglemesh, mp);
    else if (py::isinstance<PyLineSet>(geometry))
        add_locked(r, name, geometry.cast<const PyLineSet&>().h, &o3d_offscreen_renderer_add_lineset, mp);
    else if (py::isinstance<PyVoxelGrid>(geometry))
        add_locked(r, name, geometry.cast<const PyVoxelGrid&>().h, &o3d_offscreen_renderer_add_voxelgrid, mp);
    else if (is_obb(geometry) || py::isinstance(geometry, geometry_module.attr("AxisAlignedBoundingBox")))
        add_box(r, name, geometry, mp);
    else
        throw py::type_error("add_geometry: expected a PointCloud, TriangleMesh, LineSet, VoxelGrid, "
                             "AxisAlignedBoundingBox or OrientedBoundingBox, got " +
                             std::string(py::str(py::type::handle_of(geometry).attr("__name__"))));
}

int32_t backend_of(const std::string& name) {
    if (name == "auto") return O3D_RENDER_BACKEND_AUTO;
    if (name == "egl") return O3D_RENDER_BACKEND_EGL;
    if (name == "glfw") return O3D_RENDER_BACKEND_GLFW;
    invalid("backend: expected \"auto\", \"egl\" or \"glfw\", got \"" + name + "\"");
}

PyRenderer make_renderer(int64_t width, int64_t height, const std::string& /*resource_path*/, const std::string& backend) {
    const int32_t w = int32_of(width, "width"), h = int32_of(height, "height"), b = backend_of(backend);
    o3d_offscreen_renderer_t* raw = nullptr;
    check(nogil([&] { return o3d_offscreen_renderer_create(&raw, w, h, b); }));  // EGL start-up takes a while
    return PyRenderer{std::make_shared<RendererHandle>(raw)};
}

void setup_pinhole(const PyRenderer& self, const o3d_pinhole_intrinsic_t& intrinsic, py::handle extrinsic) {
    auto e = as_mat4(extrinsic, "extrinsic_matrix");
    check(with_renderer(self.h, [&](o3d_offscreen_renderer_t* r) {
        return o3d_offscreen_renderer_setup_camera(r, &intrinsic, e.data());
    }));
}

PyImage render(const PyRenderer& self, bool depth, bool z_in_view_space) {
    o3d_image_t* out = nullptr;
    check(with_renderer(self.h, [&](o3d_offscreen_renderer_t* r) {
        return depth ? o3d_offscreen_renderer_render_to_depth_image(&out, r, z_in_view_space ? 1 : 0)
                     : o3d_offscreen_renderer_render_to_image(&out, r);
    }));
    return PyImage(out);
}

void define_render_option(py::module_& m) {
    auto cls = static_cast<py::class_<PyRenderOption>>(m.attr("RenderOption"));
    cls.def(py::init<>(), "Open3D's defaults (white background, point_size 5, light_on, ...).")
        .def(py::init([](const PyRenderOption& other) { return PyRenderOption{current(other), nullptr}; }),
             py::arg("other"), "A copy (a plain value, even of renderer.render_option).")
        .def("__copy__", [](const PyRenderOption& self) { return PyRenderOption{current(self), nullptr}; })
        .def("__deepcopy__", [](const PyRenderOption& self, py::handle) { return PyRenderOption{current(self), nullptr}; })
        .def(
            "load_from_json",
            [](PyRenderOption& self, py::handle filename) {
                const std::string path = path_of(filename);
                o3d_status s;
                if (self.bound) {
                    s = self.bound([&](o3d_render_option_t& x) { return o3d_render_option_load_json(&x, path.c_str()); }, true);
                } else {
                    s = nogil([&] { return o3d_render_option_load_json(&self.v, path.c_str()); });
                }
                check(s, path);
                return true;
            },
            py::arg("filename"),
            "Read Open3D's RenderOption JSON: fields in the file replace these, others stay. Returns True; a "
            "missing or malformed file raises (the option is then unchanged).")
        .def(
            "save_to_json",
            [](const PyRenderOption& self, py::handle filename) {
                const std::string path = path_of(filename);
                const o3d_render_option_t o = current(self);
                check(nogil([&] { return o3d_render_option_save_json(path.c_str(), &o); }), path);
                return true;
            },
            py::arg("filename"), "Write the option as Open3D's RenderOption JSON. Returns True.")
        .def("__repr__", [](const PyRenderOption& self) {
            const o3d_render_option_t o = current(self);
            return py::str("RenderOption(point_size={}, line_width={}, light_on={}, point_color_option={}, "
                           "mesh_color_option={})")
                .format(o.point_size, o.line_width, o.light_on != 0,
                        py::cast(static_cast<PointColorOption>(o.point_color_option)),
                        py::cast(static_cast<MeshColorOption>(o.mesh_color_option)));
        });
    Fields<o3d_render_option_t>::each([&](const char* name, auto field, auto as, const char* doc) {
        def_field<typename decltype(as)::type>(cls, name, field, doc);
    });
}

void define_material(py::module_& m) {
    auto cls = static_cast<py::class_<PyMaterial>>(m.attr("MaterialRecord"));
    cls.def(py::init<>(), "shader \"defaultLit\", base_color (1, 1, 1, 1), point_size and line_width 0 (= the "
                          "RenderOption's).")
        .def_readwrite("shader", &PyMaterial::shader,
                       "\"defaultLit\" (the RenderOption's lights) or \"defaultUnlit\" (colors as they are); other "
                       "names raise when the material is used.")
        .def_property(
            "base_color",
            [](const PyMaterial& self) {
                py::array_t<double> out(4);
                std::memcpy(out.mutable_data(), self.base_color.data(), sizeof(self.base_color));
                return out;
            },
            [](PyMaterial& self, py::handle v) { self.base_color = as_rgba(v, "base_color"); },
            "(4,) RGBA tint multiplying the geometry's colors (alpha unused).")
        .def_readwrite("point_size", &PyMaterial::point_size, "Point size in pixels (0: the RenderOption's).")
        .def_readwrite("line_width", &PyMaterial::line_width, "Line width in pixels (0: the RenderOption's).")
        .def("__repr__", [](const PyMaterial& self) { return "MaterialRecord(shader=\"" + self.shader + "\")"; });
}

void define_scene(py::module_& m) {
    auto cls = static_cast<py::class_<PyScene>>(m.attr("Open3DScene"));
    cls.def("add_geometry",
            [](const PyScene& self, const std::string& name, py::handle geometry, py::handle material, bool) {
                add_geometry(self, name, geometry, material);
            },
            py::arg("name"), py::arg("geometry"), py::arg("material") = py::none(),
            py::arg("add_downsampled_copy_for_fast_rendering") = true,
            "Add a copy of a PointCloud, TriangleMesh, LineSet, VoxelGrid or bounding box (drawn as its edges) "
            "under a new name. material: a MaterialRecord (None: MaterialRecord()). The last argument is "
            "accepted for Open3D's signature and ignored. A taken or empty name raises.")
        .def(
            "set_background",
            [](const PyScene& self, py::handle color, py::handle image) {
                if (!image.is_none())
                    throw StatusError{O3D_ERROR_UNSUPPORTED, "set_background: a background image is not supported", ""};
                auto rgba = as_rgba(color, "color");
                PyRenderOption live{init_of(&o3d_render_option_init), renderer_options(self.h)};
                update(live, [&](o3d_render_option_t& x) { std::memcpy(x.background_color, rgba.data(), 3 * sizeof(double)); });
            },
            py::arg("color"), py::arg("image") = py::none(),
            "Background color [r, g, b, a] in [0, 1] (alpha ignored: images are RGB); sets render_option.background_color.");
    def_open3d_scene_methods(cls);
}

void define_renderer(py::module_& m) {
    auto cls = static_cast<py::class_<PyRenderer>>(m.attr("OffscreenRenderer"));
    cls.def(py::init(&make_renderer), py::arg("width"), py::arg("height"), py::arg("resource_path") = "", py::kw_only(),
            py::arg("backend") = "auto",
            "A renderer of width x height pixels (1..16384). resource_path is accepted for Open3D's signature and "
            "ignored. backend (o3d extra): \"auto\" (EGL, else a hidden GLFW window), \"egl\" (headless) or \"glfw\" "
            "(needs a display). Raises UnsupportedError when no OpenGL 3.3 context can be made.")
        .def_property_readonly("scene", [](const PyRenderer& self) { return PyScene{self.h}; },
                               "The Open3DScene: add_geometry, remove_geometry, has_geometry, clear_geometry, "
                               "set_background.")
        .def_property_readonly("backend",
                               [](const PyRenderer& self) {
                                   int32_t b = 0;
                                   check(with_renderer(self.h, [&](o3d_offscreen_renderer_t* r) {
                                       return o3d_offscreen_renderer_get_backend(&b, r);
                                   }));
                                   return std::string(b == O3D_RENDER_BACKEND_GLFW ? "glfw" : "egl");
                               },
                               "\"egl\" or \"glfw\": where the OpenGL context came from (o3d extra).")
        .def_property_readonly("size",
                               [](const PyRenderer& self) {
                                   int32_t w = 0, h = 0;
                                   check(with_renderer(self.h, [&](o3d_offscreen_renderer_t* r) {
                                       return o3d_offscreen_renderer_get_size(&w, &h, r);
                                   }));
                                   return py::make_tuple(w, h);
                               },
                               "(width, height) in pixels (o3d extra).")
        .def_property(
            "render_option",
            [](const PyRenderer& self) { return PyRenderOption{init_of(&o3d_render_option_init), renderer_options(self.h)}; },
            [](const PyRenderer& self, const PyRenderOption& o) {
                const o3d_render_option_t v = current(o);
                check(with_renderer(self.h, [&](o3d_offscreen_renderer_t* r) { return o3d_offscreen_renderer_set_render_option(r, &v); }));
            },
            "The RenderOption (o3d extra): a live view (setting a field changes the renderer at once); assign a "
            "RenderOption to replace it all. Bad values raise.");
    def_offscreen_renderer_methods(cls);  // setup_camera(vertical_field_of_view, ...) first, as Open3D lists it
    cls.def(
            "setup_camera",
            [](const PyRenderer& self, const PyIntrinsic& intrinsics, py::handle extrinsic) {
                setup_pinhole(self, intrinsics.v, extrinsic);
            },
            py::arg("intrinsics"), py::arg("extrinsic_matrix"),
            "A pinhole camera: a PinholeCameraIntrinsic of the renderer's size and a 4x4 world-to-camera extrinsic.")
        .def(
            "setup_camera",
            [](const PyRenderer& self, py::handle intrinsic_matrix, py::handle extrinsic, int64_t width, int64_t height) {
                auto k = as_mat3(intrinsic_matrix, "intrinsic_matrix");
                if (k[1] != 0.0) invalid("intrinsic_matrix: a non-zero skew (K[0, 1]) is not supported");
                o3d_pinhole_intrinsic_t in{};
                in.width = int32_of(width, "intrinsic_width_px");
                in.height = int32_of(height, "intrinsic_height_px");
                in.fx = k[0];
                in.fy = k[4];
                in.cx = k[2];
                in.cy = k[5];
                setup_pinhole(self, in, extrinsic);
            },
            py::arg("intrinsic_matrix"), py::arg("extrinsic_matrix"), py::arg("intrinsic_width_px"),
            py::arg("intrinsic_height_px"), "A pinhole camera from a 3x3 K, a 4x4 extrinsic and the image size.")
        .def(
            "get_camera",
            [](const PyRenderer& self) {
                PyCameraParameters p;
                check(with_renderer(self.h, [&](o3d_offscreen_renderer_t* r) {
                    return o3d_offscreen_renderer_get_camera(&p.intrinsic.v, p.extrinsic.data(), r);
                }));
                return p;
            },
            "o3d extra: the camera of the next render as PinholeCameraParameters; setup_camera(p.intrinsic, "
            "p.extrinsic) reproduces the image.")
        .def("render_to_image", [](const PyRenderer& self) { return render(self, false, false); },
             "Render to an RGB uint8 o3d.geometry.Image (the GIL is released meanwhile).")
        .def("render_to_depth_image",
             [](const PyRenderer& self, bool z_in_view_space) { return render(self, true, z_in_view_space); },
             py::arg("z_in_view_space") = false,
             "Render the depth to a float32 Image: the depth buffer in [0, 1] (1 where empty), or with "
             "z_in_view_space=True the distance along the camera axis (0 where empty).");
}

}  // namespace

py::object live_render_option(OptionEdit edit) {
    return py::cast(PyRenderOption{init_of(&o3d_render_option_init), std::move(edit)});
}

void declare_visualization(py::module_& m) {
    def_enum<MeshShadeOption>(m);
    def_enum<PointColorOption>(m);
    def_enum<MeshColorOption>(m);
    py::class_<PyRenderOption>(m, "RenderOption", "How geometries are drawn: background, sizes, lights, color options.");
    py::class_<PyMaterial>(m, "MaterialRecord", "A geometry's material: shader, base_color, point_size, line_width.");
    py::class_<PyScene>(m, "Open3DScene", "The geometries of an OffscreenRenderer (renderer.scene).");
    py::class_<PyRenderer>(m, "OffscreenRenderer", "Renders geometries to images without a display (EGL or GLFW).");
}

void define_visualization(py::module_& m) {
    define_render_option(m);
    define_material(m);
    define_scene(m);
    define_renderer(m);
}

}  // namespace o3dpy
