// SPDX-License-Identifier: MIT
// o3d.geometry.LineSet over o3d_lineset_t (lineset.h). points / colors / lines are read-only zero-copy
// views (the C API has no writable view); assigning a new array replaces them.
#include <limits>
#include <vector>

#include "geometry_types.h"

namespace o3dpy {

PyLineSet::PyLineSet() {
    o3d_lineset_t* raw = nullptr;
    check(o3d_lineset_create(&raw));
    h = std::make_shared<LineSetHandle>(raw);
}

LineSetPtr PyLineSet::for_resize() {
    if (h.use_count() > 1) {  // views share the current arrays: keep them valid with a private copy
        o3d_lineset_t* copy = nullptr;
        LineSetPtr old = h;
        locked_const(old, [&](const o3d_lineset_t* ls) { return o3d_lineset_clone(&copy, ls); });
        h = std::make_shared<LineSetHandle>(copy);
    }
    return h;
}

namespace {

py::array float_view(const PyLineSet& self, int32_t which) {
    LineSetPtr h = self.h;
    const double* data = nullptr;
    size_t n = 0;
    locked_const(h, [&](const o3d_lineset_t* ls) { return o3d_lineset_array_view(&data, &n, ls, which); });
    return view_array(data, n, 3, keepalive(h), false);
}

void set_float(PyLineSet& self, int32_t which, py::handle value) {
    auto a = rows3_f64(value, which == O3D_LINESET_POINTS ? "points" : "colors");
    const size_t n = (size_t)a.shape(0);
    locked_mut(self.for_resize(),
               [&](o3d_lineset_t* ls) { return o3d_lineset_set_array(ls, which, n ? a.data() : nullptr, n); });
}

py::array lines_view(const PyLineSet& self) {
    LineSetPtr h = self.h;
    const int32_t* data = nullptr;
    size_t n = 0;
    locked_const(h, [&](const o3d_lineset_t* ls) { return o3d_lineset_index_array_view(&data, &n, ls, O3D_LINESET_LINES); });
    if (!data || n == 0) return py::array_t<int32_t>(std::vector<py::ssize_t>{0, 2});
    py::array a(py::dtype::of<int32_t>(), {(py::ssize_t)n, (py::ssize_t)2},
                {(py::ssize_t)(2 * sizeof(int32_t)), (py::ssize_t)sizeof(int32_t)}, data, keepalive(h));
    a.attr("setflags")(py::arg("write") = false);
    return a;
}

/// An (M, 2) array of integers as int32 (values outside int32 raise; negative ones are caught by the C
/// calls that follow the lines).
std::vector<int32_t> pairs_of(py::handle value, const char* what) {
    if (value.is_none()) invalid(std::string(what) + ": expected an (M, 2) array of integers, got None");
    py::array a = py::array::ensure(value);
    if (!a) invalid(std::string(what) + ": expected an (M, 2) array of integers");
    if (a.size() == 0) return {};
    char kind = a.dtype().kind();
    if (kind != 'i' && kind != 'u') invalid(std::string(what) + ": expected integers, got dtype " + std::string(py::str(a.dtype())));
    if (a.ndim() != 2 || a.shape(1) != 2) invalid(std::string(what) + ": expected an (M, 2) array");
    auto v = py::array_t<int64_t, py::array::c_style | py::array::forcecast>::ensure(a);
    if (!v) throw py::error_already_set();
    std::vector<int32_t> out((size_t)v.size());
    const int64_t* p = v.data();
    for (size_t i = 0; i < out.size(); ++i) {
        if (p[i] < std::numeric_limits<int32_t>::min() || p[i] > std::numeric_limits<int32_t>::max())
            invalid(std::string(what) + ": index " + std::to_string(p[i]) + " is out of range");
        out[i] = (int32_t)p[i];
    }
    return out;
}

void set_lines(PyLineSet& self, py::handle value) {
    std::vector<int32_t> l = pairs_of(value, "lines");
    locked_mut(self.for_resize(), [&](o3d_lineset_t* ls) { return o3d_lineset_set_index_array(ls, O3D_LINESET_LINES, l.data(), l.size() / 2); });
}

size_t count(const PyLineSet& self, o3d_status (*fn)(const o3d_lineset_t*, size_t*)) {
    size_t n = 0;
    locked_const(self.h, [&](const o3d_lineset_t* ls) { return fn(ls, &n); });
    return n;
}

bool has_colors(const PyLineSet& self) {
    const double* data = nullptr;
    size_t n = 0;
    locked_const(self.h, [&](const o3d_lineset_t* ls) { return o3d_lineset_array_view(&data, &n, ls, O3D_LINESET_COLORS); });
    return n > 0 && n == count(self, &o3d_lineset_num_lines);
}

template <typename F>
PyLineSet make(F&& f) {
    o3d_lineset_t* out = nullptr;
    check(nogil([&] { return f(&out); }));
    return PyLineSet(out);
}

PyLineSet clone(const PyLineSet& self) {
    o3d_lineset_t* out = nullptr;
    locked_const(self.h, [&](const o3d_lineset_t* ls) { return o3d_lineset_clone(&out, ls); });
    return PyLineSet(out);
}

}  // namespace

void declare_lineset(py::module_& m) {
    py::class_<PyLineSet>(m, "LineSet",
                          "Lines between points: points (N, 3) float64, lines (M, 2) int32, colors (M, 3) one per "
                          "line. The arrays read as read-only zero-copy views; assign a new array to change them.");
}

void define_lineset(py::module_& m) {
    auto cls = static_cast<py::class_<PyLineSet>>(m.attr("LineSet"));
    cls.def(py::init<>(), "An empty line set.")
        .def(py::init([](py::handle points, py::handle lines) {
                 PyLineSet ls;
                 set_float(ls, O3D_LINESET_POINTS, points);
                 set_lines(ls, lines);
                 return ls;
             }),
             py::arg("points"), py::arg("lines"), "A line set with these points and lines.")
        .def(py::init([](const PyLineSet& other) { return clone(other); }), py::arg("cpp_line_set"), "Deep copy.")
        .def("__copy__", [](const PyLineSet& self) { return clone(self); })
        .def("__deepcopy__", [](const PyLineSet& self, py::handle) { return clone(self); })
        .def_property(
            "points", [](const PyLineSet& self) { return float_view(self, O3D_LINESET_POINTS); },
            [](PyLineSet& self, py::handle v) { set_float(self, O3D_LINESET_POINTS, v); }, "(N, 3) float64 points.")
        .def_property(
            "colors", [](const PyLineSet& self) { return float_view(self, O3D_LINESET_COLORS); },
            [](PyLineSet& self, py::handle v) { set_float(self, O3D_LINESET_COLORS, v); },
            "(M, 3) float64 line colors in [0, 1].")
        .def_property(
            "lines", [](const PyLineSet& self) { return lines_view(self); },
            [](PyLineSet& self, py::handle v) { set_lines(self, v); }, "(M, 2) int32 point indices.")
        .def("has_points", [](const PyLineSet& self) { return count(self, &o3d_lineset_num_points) > 0; })
        .def("has_lines",
             [](const PyLineSet& self) {
                 return count(self, &o3d_lineset_num_points) > 0 && count(self, &o3d_lineset_num_lines) > 0;
             })
        .def("has_colors", [](const PyLineSet& self) { return has_colors(self); })
        .def("is_empty", [](const PyLineSet& self) { return count(self, &o3d_lineset_num_points) == 0; })
        .def("__repr__",
             [](const PyLineSet& self) {
                 return "LineSet with " + std::to_string(count(self, &o3d_lineset_num_lines)) + " lines.";
             })
        .def(
            "paint_uniform_color",
            [](py::object self, py::handle color) {
                auto c = as_vec3(color, "color");
                locked_mut(self.cast<PyLineSet&>().for_resize(),
                           [&](o3d_lineset_t* ls) { return o3d_lineset_paint_uniform_color(ls, c.data()); });
                return self;
            },
            py::arg("color"), "Set every line color. Returns self.")
        .def(
            "transform",
            [](py::object self, py::handle T) {
                auto t = as_mat4(T, "transformation");
                locked_mut(self.cast<PyLineSet&>().h, [&](o3d_lineset_t* ls) { return o3d_lineset_transform(ls, t.data()); });
                return self;
            },
            py::arg("transformation"), "Apply a 4x4 homogeneous transform to the points. Returns self.")
        .def(
            "_copy_arrays",
            [](const PyLineSet& self) {
                // Copy-out path (o3d_lineset_get_*): snapshots independent of the line set.
                std::vector<double> pts, cols;
                std::vector<int32_t> lines;
                size_t np = 0, nc = 0, nl = 0;
                locked_const(self.h, [&](const o3d_lineset_t* ls) {
                    o3d_status s = o3d_lineset_get_array(nullptr, 0, &np, ls, O3D_LINESET_POINTS);
                    if (s != O3D_OK && s != O3D_ERROR_BUFFER_TOO_SMALL) return s;
                    pts.resize(np * 3);
                    if ((s = o3d_lineset_get_array(pts.data(), np, &np, ls, O3D_LINESET_POINTS)) != O3D_OK) return s;
                    s = o3d_lineset_get_array(nullptr, 0, &nc, ls, O3D_LINESET_COLORS);
                    if (s != O3D_OK && s != O3D_ERROR_BUFFER_TOO_SMALL) return s;
                    cols.resize(nc * 3);
                    if ((s = o3d_lineset_get_array(cols.data(), nc, &nc, ls, O3D_LINESET_COLORS)) != O3D_OK) return s;
                    s = o3d_lineset_get_index_array(nullptr, 0, &nl, ls, O3D_LINESET_LINES);
                    if (s != O3D_OK && s != O3D_ERROR_BUFFER_TOO_SMALL) return s;
                    lines.resize(nl * 2);
                    return o3d_lineset_get_index_array(lines.data(), nl, &nl, ls, O3D_LINESET_LINES);
                });
                py::array_t<int32_t> l(std::vector<py::ssize_t>{(py::ssize_t)nl, 2});
                if (nl) std::memcpy(l.mutable_data(), lines.data(), nl * 2 * sizeof(int32_t));
                py::array p = np ? mat_to_array(pts.data(), np, 3) : py::array_t<double>(std::vector<py::ssize_t>{0, 3});
                py::array c = nc ? mat_to_array(cols.data(), nc, 3) : py::array_t<double>(std::vector<py::ssize_t>{0, 3});
                return py::make_tuple(p, l, c);
            },
            "Copies (points, lines, colors), not views.")
        .def_static(
            "create_from_point_cloud_correspondences",
            [](const PyPointCloud& cloud0, const PyPointCloud& cloud1, py::handle correspondences) {
                std::vector<int32_t> pairs = pairs_of(correspondences, "correspondences");
                CloudPtr a = cloud0.h, b = cloud1.h;
                return make([&](o3d_lineset_t** out) {
                    std::shared_lock<std::shared_mutex> la(a->mutex);
                    std::shared_lock<std::shared_mutex> lb(b->mutex, std::defer_lock);
                    if (b != a) lb.lock();
                    return o3d_lineset_create_from_point_cloud_correspondences(out, a->pc, b->pc, pairs.data(),
                                                                                pairs.size() / 2);
                });
            },
            py::arg("cloud0"), py::arg("cloud1"), py::arg("correspondences"),
            "Points of cloud0 then cloud1, one line per (i, j) correspondence (cloud0 index, cloud1 index).")
        .def_static(
            "create_from_oriented_bounding_box",
            [](py::handle box) {
                o3d_obb_t obb = obb_of(box);
                return make([&](o3d_lineset_t** out) { return o3d_lineset_create_from_oriented_bounding_box(out, &obb); });
            },
            py::arg("box"), "The 12 edges of an OrientedBoundingBox.")
        .def_static(
            "create_from_axis_aligned_bounding_box",
            [](py::handle box) {
                auto [lo, hi] = aabb_bounds(box);
                return make([&](o3d_lineset_t** out) {
                    return o3d_lineset_create_from_axis_aligned_bounding_box(out, lo.data(), hi.data());
                });
            },
            py::arg("box"), "The 12 edges of an AxisAlignedBoundingBox.")
        .def_static(
            "create_from_triangle_mesh",
            [](const PyTriangleMesh& mesh) {
                o3d_lineset_t* out = nullptr;
                locked_const(mesh.h, [&](const o3d_trianglemesh_t* me) { return o3d_lineset_create_from_triangle_mesh(&out, me); });
                return PyLineSet(out);
            },
            py::arg("mesh"), "The mesh's unique edges, each once, on its vertices.");
}

}  // namespace o3dpy
