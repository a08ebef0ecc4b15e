// SPDX-License-Identifier: MIT
// o3d.visualization.Visualizer, VisualizerWithKeyCallback, VisualizerWithEditing and ViewControl over
// visualizer.h. Python callbacks reach the C loop through trampolines whose user_data is a Callback: run,
// poll_events, the send_* calls and playback release the GIL and the trampoline takes it back. An exception
// raised in a callback stops the loop (o3d_visualizer_set_callback_error) and the call re-raises that same
// exception object. The C API names geometries while Python identifies them by object: each added object
// gets a name and is kept alive while it is in the scene.

#include <map>
#include <optional>
#include <thread>
#include <unordered_map>

#include "generated/visualizer_methods.h"

namespace o3dpy {
namespace {

struct PyVis;
/// A registered Python callback (a trampoline's user_data).
struct Callback {
    PyVis* owner;
    py::handle vis;  // the Python visualizer passed to `fn`; borrowed, since it owns this Callback
    py::object fn;
};

struct PyVis {
    o3d_visualizer_t* p = nullptr;
    std::thread::id thread;  // set by create_window: the visualizer then belongs to that thread
    std::string window_name;
    std::unique_ptr<Callback> animation;
    std::map<int32_t, std::unique_ptr<Callback>> keys;
    std::unordered_map<PyObject*, std::pair<py::object, std::string>> geometries;  // object -> (kept, its name)
    uint64_t added = 0;                          // geometry names are geometry_<n>, never reused
    std::optional<py::error_already_set> error;  // what a callback raised, re-raised when the loop returns
    explicit PyVis(bool editing) { check(o3d_visualizer_create(&p, editing ? 1 : 0)); }
    PyVis(const PyVis&) = delete;
    ~PyVis() {  // the C visualizer goes first: no callback can run once the Callbacks are freed
        py::gil_scoped_release release;
        o3d_visualizer_destroy(p);
    }
    /// The handle, refused on other threads than the window's (its OpenGL context is current there only).
    o3d_visualizer_t* get() const {
        if (thread != std::thread::id() && thread != std::this_thread::get_id())
            invalid("Visualizer: used from another thread than the one that created its window");
        return p;
    }
};
struct PyVisKey : PyVis { PyVisKey() : PyVis(false) {} };
struct PyVisEdit : PyVis { PyVisEdit() : PyVis(true) {} };
struct PyViewControl {
    py::object vis;  // keeps the visualizer alive
    PyVis& v() const { return vis.cast<PyVis&>(); }
};

/// Raise what a callback raised during the last call (the original exception), else the call's status.
void finish(PyVis& v, o3d_status s, const std::string& path = std::string()) {
    if (v.error) {
        o3d_clear_error();
        py::error_already_set e = std::move(*v.error);
        v.error.reset();
        throw e;
    }
    check(s, path);
}

/// A C call on the visualizer, from its thread, with the GIL released (callbacks it runs take it back).
template <typename F>
void call(PyVis& v, F&& f, const std::string& path = std::string()) {
    o3d_visualizer_t* p = v.get();
    finish(v, nogil([&] { return f(p); }), path);
}

/// The trampoline: the callback's truth value is the C result ("redraw"); an exception is kept for the
/// caller and stops the loop.
template <typename... A>
int32_t invoke(void* user_data, A... args) {
    const auto* c = static_cast<const Callback*>(user_data);
    PyVis* owner = c->owner;  // `c` itself is freed if the callback registers another one for its slot
    std::string failed;
    {
        py::gil_scoped_acquire gil;
        try {
            py::object fn = c->fn;
            return py::bool_(fn(c->vis, args...)) ? 1 : 0;
        } catch (py::error_already_set& e) {
            failed = e.what();
            if (!owner->error) owner->error = std::move(e);
        }
    }
    o3d_visualizer_set_callback_error(owner->p, failed.c_str());
    return 0;
}
int32_t on_frame(o3d_visualizer_t*, void* c) { return invoke(c); }
int32_t on_key(o3d_visualizer_t*, int32_t, int32_t, void* c) { return invoke(c); }
int32_t on_key_action(o3d_visualizer_t*, int32_t action, int32_t mods, void* c) { return invoke(c, action, mods); }

/// Keep `fn` in `slot` (None removes it) once the C API took `register_(p, callback or NULL)`; the old
/// Callback is freed only after the C side stopped pointing at it.
template <typename R>
void set_callback(py::object self, std::unique_ptr<Callback>& slot, py::object fn, R&& register_) {
    if (!fn.is_none() && !PyCallable_Check(fn.ptr())) throw py::type_error("callback_func must be callable or None");
    PyVis& v = self.cast<PyVis&>();
    std::unique_ptr<Callback> next(fn.is_none() ? nullptr : new Callback{&v, self, fn});
    call(v, [&](o3d_visualizer_t* p) { return register_(p, next.get()); });
    slot = std::move(next);
}

/// The C call adding a geometry held by a Python object, under the object's lock (shared).
template <typename G, typename T>
o3d_status add_as(o3d_visualizer_t* p, const std::string& name, py::handle g, int32_t reset,
                  o3d_status (*add)(o3d_visualizer_t*, const char*, const T*, int32_t)) {
    auto h = g.cast<const G&>().h;
    py::gil_scoped_release release;
    std::shared_lock<std::shared_mutex> lock(h->mutex);
    return add(p, name.c_str(), h->p, reset);
}

/// add_geometry, and update_geometry (`update`: the object must be in the scene; same name, view kept).
bool add_geometry(PyVis& v, py::handle geometry, bool reset, bool update) {
    auto known = v.geometries.find(geometry.ptr());
    const bool is_new = known == v.geometries.end();
    if (update && is_new) invalid("update_geometry: that geometry is not in the scene (add_geometry it first)");
    const std::string name = is_new ? "geometry_" + std::to_string(v.added++) : known->second.second;
    py::module_ gm = py::module_::import("o3d.geometry");
    py::object g = py::reinterpret_borrow<py::object>(geometry);
    if (is_obb(g) || py::isinstance(g, gm.attr("AxisAlignedBoundingBox"))) {  // drawn as its edges, as Open3D does
        g = gm.attr("LineSet").attr(is_obb(g) ? "create_from_oriented_bounding_box"
                                              : "create_from_axis_aligned_bounding_box")(geometry);
        if (py::hasattr(geometry, "color")) g.attr("paint_uniform_color")(geometry.attr("color"));
    }
    o3d_visualizer_t* p = v.get();
    const int32_t r = reset ? 1 : 0;
    if (py::isinstance<PyPointCloud>(g))
        check(add_as<PyPointCloud>(p, name, g, r, &o3d_visualizer_add_pointcloud));
    else if (py::isinstance<PyTriangleMesh>(g))
        check(add_as<PyTriangleMesh>(p, name, g, r, &o3d_visualizer_add_trianglemesh));
    else if (py::isinstance<PyLineSet>(g))
        check(add_as<PyLineSet>(p, name, g, r, &o3d_visualizer_add_lineset));
    else if (py::isinstance<PyVoxelGrid>(g))
        check(add_as<PyVoxelGrid>(p, name, g, r, &o3d_visualizer_add_voxelgrid));
    else if (py::isinstance<PyImage>(g))  // drawn flat, scaled to fit, under the 3D geometry
        check(add_as<PyImage>(p, name, g, r, &o3d_visualizer_add_image));
    else
        throw py::type_error("add_geometry: expected a PointCloud, TriangleMesh, LineSet, VoxelGrid, Image or bounding box, got " +
                             std::string(py::str(py::type::handle_of(geometry).attr("__name__"))));
    if (is_new) v.geometries.emplace(geometry.ptr(), std::make_pair(py::reinterpret_borrow<py::object>(geometry), name));
    return true;
}

PyImage capture(PyVis& v, bool depth) {
    o3d_image_t* out = nullptr;
    call(v, [&](o3d_visualizer_t* p) {
        return depth ? o3d_visualizer_capture_depth_float_buffer(&out, p, 1) : o3d_visualizer_capture_screen_float_buffer(&out, p, 1);
    });
    return PyImage(out);
}

/// ViewControl.set_view (o3d extra; set_front, set_lookat, set_up and set_zoom are one value of it): the
/// values given, in one step, so that a front and an up that are parallel only to the old values can be set.
void set_view(const PyViewControl& self, py::handle front, py::handle lookat, py::handle up, py::handle zoom) {
    std::array<double, 3> v[3];
    const double* given[3] = {nullptr, nullptr, nullptr};
    const char* names[3] = {"front", "lookat", "up"};
    py::handle values[3] = {front, lookat, up};
    for (int i = 0; i < 3; ++i)
        if (!values[i].is_none()) given[i] = (v[i] = as_vec3(values[i], names[i])).data();
    // The C call keeps the zoom when negative; Open3D clamps it into [0.02, 2] as the C call does 0.
    const double z = zoom.is_none() ? -1.0 : std::max(zoom.cast<double>(), 0.0);
    call(self.v(), [&](o3d_visualizer_t* p) { return o3d_visualizer_view_set(p, given[0], given[1], given[2], z); });
}

PyVis& vis_of(PyVis& v) { return v; }
PyVis& vis_of(const PyViewControl& c) { return c.v(); }
/// A method (of a Visualizer or a ViewControl) that is one C call taking the method's arguments.
template <typename Self, typename... A>
auto on(o3d_status (*f)(o3d_visualizer_t*, A...)) {
    return [f](Self& self, A... a) { call(vis_of(self), [&](o3d_visualizer_t* p) { return f(p, a...); }); };
}
using View = const PyViewControl;
/// A method that is one C call on a file (the path is named in an I/O error).
template <typename... A, typename... B>
void on_file(PyVis& v, o3d_status (*f)(o3d_visualizer_t*, const char*, A...), py::handle filename, B... b) {
    const std::string path = path_of(filename);
    call(v, [&](o3d_visualizer_t* p) { return f(p, path.c_str(), b...); }, path);
}

void define_view_control(py::module_& m) {
    auto cls = static_cast<py::class_<PyViewControl>>(m.attr("ViewControl"));
    def_view_control_methods(cls);
    cls.def("rotate", [](const PyViewControl& s, double x, double y, double, double) { on<View>(&o3d_visualizer_view_rotate)(s, x, y); },
            py::arg("x"), py::arg("y"), py::arg("xo") = 0.0, py::arg("yo") = 0.0,
            "Rotate as a left-button drag of (x, y) pixels (0.003 rad a pixel); xo, yo are accepted and unused.")
        .def("translate",
             [](const PyViewControl& s, double x, double y, double, double) { on<View>(&o3d_visualizer_view_translate)(s, x, y); },
             py::arg("x"), py::arg("y"), py::arg("xo") = 0.0, py::arg("yo") = 0.0, "Translate as a Ctrl + left drag.")
        .def("set_view", &set_view, py::arg("front") = py::none(), py::arg("lookat") = py::none(),
             py::arg("up") = py::none(), py::arg("zoom") = py::none(),
             "o3d extra: set the values given (None keeps one) in one step; the view is unchanged if one is bad.")
        .def("convert_to_pinhole_camera_parameters",
             [](View& self) {
                 PyCameraParameters out;
                 call(self.v(), [&](o3d_visualizer_t* p) { return o3d_visualizer_view_to_pinhole(&out.intrinsic.v, out.extrinsic.data(), p); });
                 return out;
             })
        .def("convert_from_pinhole_camera_parameters",
             [](View& self, const PyCameraParameters& c, bool) {
                 on<View>(&o3d_visualizer_view_from_pinhole)(self, &c.intrinsic.v, c.extrinsic.data());
                 return true;
             },
             py::arg("parameter"), py::arg("allow_arbitrary") = false,
             "Returns True; raises on a camera the view cannot take (intrinsic not the window's size with a centred "
             "principal point and fx = fy, field of view outside [5, 90] degrees), whatever allow_arbitrary says.")
        .def("get_view_status",
             [](View& self) {
                 o3d_buffer_t* raw = nullptr;
                 call(self.v(), [&](o3d_visualizer_t* p) { return o3d_visualizer_get_view_status(&raw, p); });
                 std::unique_ptr<o3d_buffer_t, void (*)(o3d_buffer_t*)> buf(raw, &o3d_buffer_destroy);
                 const uint8_t* text = nullptr;
                 size_t size = 0;
                 check(o3d_buffer_view(&text, &size, buf.get()));
                 return std::string(reinterpret_cast<const char*>(text), size);
             },
             "o3d extra: the view as Open3D's ViewTrajectory JSON (what Ctrl+C copies).");
    const char* values[] = {"front", "lookat", "up", "zoom"};
    for (int i = 0; i < 4; ++i) {  // set_front, set_lookat, set_up, set_zoom: one value of set_view
        cls.def(("set_" + std::string(values[i])).c_str(), [i](View& self, py::handle x) {
            py::handle a[4] = {py::none(), py::none(), py::none(), py::none()};
            a[i] = x;
            set_view(self, a[0], a[1], a[2], a[3]);
        }, py::arg(values[i]));
        cls.def(("get_" + std::string(values[i])).c_str(), [i](View& self) -> py::object {  // o3d extras
            std::array<double, 3> v[3];
            double zoom = 0;
            call(self.v(), [&](o3d_visualizer_t* p) { return o3d_visualizer_view_get(v[0].data(), v[1].data(), v[2].data(), &zoom, p); });
            return i == 3 ? py::float_(zoom) : py::object(vec3_to_array(v[i].data()));
        });
    }
}

void define_visualizer_class(py::module_& m) {
    auto cls = static_cast<py::class_<PyVis>>(m.attr("Visualizer"));
    def_visualizer_methods(cls);
    cls.def(py::init([] { return std::make_unique<PyVis>(false); }))
        .def("create_window",
             [](PyVis& v, const std::string& name, int64_t w, int64_t h, int64_t left, int64_t top, bool visible) {
                 const int32_t w32 = int32_of(w, "width"), h32 = int32_of(h, "height");
                 const int32_t l32 = int32_of(left, "left"), t32 = int32_of(top, "top");
                 call(v, [&](o3d_visualizer_t* p) { return o3d_visualizer_create_window(p, name.c_str(), w32, h32, l32, t32, visible); });
                 v.thread = std::this_thread::get_id();
                 v.window_name = name;
                 return true;
             },
             py::arg("window_name") = "Open3D", py::arg("width") = 1920, py::arg("height") = 1080, py::arg("left") = 50,
             py::arg("top") = 50, py::arg("visible") = true,
             "Open the window (visible=False: hidden, rendered through EGL, no display needed). Returns True; raises "
             "UnsupportedError when no window can be had (Open3D returns False).")
        .def("destroy_window", [](PyVis& v) { call(v, &o3d_visualizer_destroy_window), v.geometries.clear(), v.thread = {}; })
        .def("add_geometry", [](PyVis& v, py::handle g, bool reset) { return add_geometry(v, g, reset, false); },
             py::arg("geometry"), py::arg("reset_bounding_box") = true,
             "Draw a copy of a PointCloud, TriangleMesh, LineSet, VoxelGrid, bounding box or Image (flat, scaled to "
             "fit, under the rest). Returns True.")
        .def("update_geometry", [](PyVis& v, py::handle g) { return add_geometry(v, g, false, true); }, py::arg("geometry"),
             "Draw the geometry's current state (it must have been added); the view is kept. Returns True.")
        .def("remove_geometry",
             [](PyVis& v, py::handle g, bool reset) {
                 auto known = v.geometries.find(g.ptr());
                 if (known == v.geometries.end()) invalid("remove_geometry: that geometry is not in the scene");
                 call(v, [&](o3d_visualizer_t* p) { return o3d_visualizer_remove_geometry(p, known->second.second.c_str(), reset); });
                 v.geometries.erase(known);
                 return true;
             },
             py::arg("geometry"), py::arg("reset_bounding_box") = true)
        .def("has_geometry",
             [](PyVis& v, py::handle g) {
                 auto known = v.geometries.find(g.ptr());
                 int32_t has = 0;
                 if (known != v.geometries.end())
                     call(v, [&](o3d_visualizer_t* p) { return o3d_visualizer_has_geometry(&has, p, known->second.second.c_str()); });
                 return has != 0;
             },
             py::arg("geometry"), "o3d extra: whether the object is in the scene.")
        .def("clear_geometries", [](PyVis& v) { return call(v, &o3d_visualizer_clear_geometries), v.geometries.clear(), true; })
        .def("get_render_option",
             [](py::object self) {
                 return live_render_option([self](const OptionChange& change, bool write) {
                     o3d_visualizer_t* p = self.cast<PyVis&>().get();
                     return nogil([&] {
                         return edit_option(p, &o3d_visualizer_get_render_option, &o3d_visualizer_set_render_option, change, write);
                     });
                 });
             },
             "The RenderOption, live: setting a field changes the viewer at once.")
        .def("get_view_control", [](py::object self) { return PyViewControl{self}; })
        .def("register_animation_callback",
             [](py::object self, py::object fn) {
                 set_callback(self, self.cast<PyVis&>().animation, fn, [](o3d_visualizer_t* p, Callback* c) {
                     return o3d_visualizer_register_animation_callback(p, c ? &on_frame : nullptr, c);
                 });
             },
             py::arg("callback_func"), "callback_func(vis) -> bool (redraw), called each frame of run; None removes it.")
        .def("capture_screen_float_buffer", [](PyVis& v, bool) { return capture(v, false); }, py::arg("do_render") = false,
             "The frame as an RGB float32 Image in [0, 1] (a frame is always drawn for it).")
        .def("capture_depth_float_buffer", [](PyVis& v, bool) { return capture(v, true); }, py::arg("do_render") = false,
             "Depth in metres along the optical axis as a float32 Image, 0 where nothing was drawn.")
        .def("capture_screen_image",
             [](PyVis& v, py::handle filename, bool) { on_file(v, &o3d_visualizer_capture_screen_image, filename, 1); },
             py::arg("filename"), py::arg("do_render") = false, "Write the frame as PNG or JPEG (by extension).")
        .def("capture_depth_image",
             [](PyVis& v, py::handle filename, bool, double scale) { on_file(v, &o3d_visualizer_capture_depth_image, filename, 1, scale); },
             py::arg("filename"), py::arg("do_render") = false, py::arg("depth_scale") = 1000.0,
             "Write depth * depth_scale as a 16-bit PNG (default: millimetres).")
        .def("reset_view_point", [](PyVis& v, bool) { on<PyVis>(&o3d_visualizer_view_reset)(v); },
             py::arg("reset_bounding_box") = false, "Open3D's default view of the scene (its box is always recomputed).")
        .def("get_window_name", [](const PyVis& v) { return v.window_name; })
        .def("send_key_event", on<PyVis>(&o3d_visualizer_send_key), py::arg("key"), py::arg("action") = 1, py::arg("mods") = 0,
             "o3d extra: deliver a key as the window does (GLFW key numbers: ord('R'); action 0 release, 1 press, "
             "2 repeat; mods 1 Shift, 2 Ctrl, 4 Alt).")
        .def("send_mouse_button", on<PyVis>(&o3d_visualizer_send_mouse_button), py::arg("button"), py::arg("action"), py::arg("mods") = 0,
             "o3d extra: a mouse button (0 left, 1 right, 2 middle) goes down (1) or up (0) at the cursor.")
        .def("play_view_trajectory",
             [](PyVis& v, py::handle path, py::handle capture_dir, bool depth) {
                 const std::string file = path_of(path), dir = capture_dir.is_none() ? "" : path_of(capture_dir);
                 call(v, [&](o3d_visualizer_t* p) {
                     return o3d_visualizer_play_view_trajectory(p, file.c_str(), dir.empty() ? nullptr : dir.c_str(), depth, nullptr, nullptr);
                 }, file);
             },
             py::arg("path"), py::arg("capture_dir") = py::none(), py::arg("capture_depth") = false,
             "o3d extra: show each frame of a ViewTrajectory JSON file, writing image_%06d.png (and depth_%06d.png) "
             "into capture_dir when given.");
}

/// register_key_callback / register_key_action_callback (one slot per key, as in the C API).
void def_key_callback(py::class_<PyVisKey, PyVis>& cls, const char* name, decltype(&o3d_visualizer_register_key_callback) reg,
                      decltype(&on_key) trampoline, const char* doc) {
    cls.def(
        name,
        [reg, trampoline](py::object self, int32_t key, py::object fn) {
            set_callback(self, self.cast<PyVis&>().keys[key], fn, [&](o3d_visualizer_t* p, Callback* c) {
                return reg(p, key, c ? trampoline : nullptr, c);
            });
        },
        py::arg("key"), py::arg("callback_func"), doc);
}

}  // namespace

void declare_visualizer(py::module_& m) {
    py::class_<PyVis>(m, "Visualizer", "Open3D's legacy viewer: a window (or a hidden one) showing geometries.");
    py::class_<PyVisKey, PyVis>(m, "VisualizerWithKeyCallback", "A Visualizer with key callbacks.");
    py::class_<PyVisEdit, PyVis>(m, "VisualizerWithEditing",
                                 "A Visualizer picking points (Shift + left click) and cropping (K, then C).");
    py::class_<PyViewControl>(m, "ViewControl", "The view of a Visualizer (vis.get_view_control()).");
}

void define_visualizer(py::module_& m) {
    define_visualizer_class(m);
    define_view_control(m);
    auto key = static_cast<py::class_<PyVisKey, PyVis>>(m.attr("VisualizerWithKeyCallback"));
    key.def(py::init<>());
    def_key_callback(key, "register_key_callback", &o3d_visualizer_register_key_callback, &on_key,
                     "callback_func(vis) -> bool, on press and repeat of key (GLFW numbers: ord('K')), instead of "
                     "o3d's own binding of the key; None removes it.");
    def_key_callback(key, "register_key_action_callback", &o3d_visualizer_register_key_action_callback, &on_key_action,
                     "callback_func(vis, action, mods) -> bool, on press (1), repeat (2) and release (0) of key.");
    auto edit = static_cast<py::class_<PyVisEdit, PyVis>>(m.attr("VisualizerWithEditing"));
    def_visualizer_with_editing_methods(edit);
    edit.def(py::init([](double, bool, const std::string& directory) {
                 auto v = std::make_unique<PyVisEdit>();
                 check(o3d_visualizer_set_crop_directory(v->get(), directory.c_str()));
                 return v;
             }),
             py::arg("voxel_size") = -1.0, py::arg("use_dialog") = true, py::arg("directory") = "",
             "K locks the view for selecting (left drag: a rectangle; Ctrl + left clicks: a polygon), C crops the "
             "first geometry to it; each crop is written to `directory` as cropped_<n>.ply when it is given. "
             "voxel_size and use_dialog are accepted for Open3D's signature and unused (no file dialog).")
        .def("get_cropped_geometry", [](PyVis& v) -> py::object {
            o3d_pointcloud_t* cloud = nullptr;
            o3d_trianglemesh_t* mesh = nullptr;
            call(v, [&](o3d_visualizer_t* p) { return o3d_visualizer_get_cropped_pointcloud(&cloud, p); });
            if (cloud) return py::cast(PyPointCloud(cloud));
            call(v, [&](o3d_visualizer_t* p) { return o3d_visualizer_get_cropped_trianglemesh(&mesh, p); });
            if (mesh) return py::cast(PyTriangleMesh(mesh));
            return py::none();
        }, "The last crop (a PointCloud or a TriangleMesh), or None before any.")
        .def("get_picked_points", [](PyVis& v) {
            size_t n = 0;
            call(v, [&](o3d_visualizer_t* p) { return o3d_visualizer_get_picked_points(nullptr, 0, &n, p); });
            std::vector<int32_t> out(n);
            call(v, [&](o3d_visualizer_t* p) { return o3d_visualizer_get_picked_points(out.data(), n, &n, p); });
            return int_list(out.data(), n);
        }, "Vertex indices of the first geometry added, in pick order.");
}

}  // namespace o3dpy
