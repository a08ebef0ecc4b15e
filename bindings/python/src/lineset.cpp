// SPDX-License-Identifier: MIT
// o3d.geometry.LineSet over o3d_lineset_t (lineset.h). points / colors / lines are read-only zero-copy
// views (the C API has no writable view); assigning a new array replaces them.
#include <limits>
#include <vector>

#include "generated/lineset_methods.h"

namespace o3dpy {

PyLineSet::PyLineSet() : Geom(nullptr) { check(o3d_lineset_create(&h->p)); }

namespace {

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

size_t count(const PyLineSet& self, o3d_status (*fn)(size_t*, const o3d_lineset_t*)) {
    size_t n = 0;
    locked_const(self.h, [&](const o3d_lineset_t* ls) { return fn(&n, ls); });
    return n;
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
                 array_set(ls, O3D_LINESET_POINTS, points, "points");
                 array_set(ls, O3D_LINESET_LINES, lines, "lines");
                 return ls;
             }),
             py::arg("points"), py::arg("lines"), "A line set with these points and lines.")
        .def(py::init([](const PyLineSet& other) { return clone(other); }), py::arg("cpp_line_set"), "Deep copy.")
        .def("__copy__", [](const PyLineSet& self) { return clone(self); })
        .def("__deepcopy__", [](const PyLineSet& self, py::handle) { return clone(self); })
        .def("has_points", [](const PyLineSet& self) { return count(self, &o3d_lineset_num_points) > 0; })
        .def("has_lines",
             [](const PyLineSet& self) {
                 return count(self, &o3d_lineset_num_points) > 0 && count(self, &o3d_lineset_num_lines) > 0;
             })
        .def("is_empty", [](const PyLineSet& self) { return count(self, &o3d_lineset_num_points) == 0; })
        .def("__repr__",
             [](const PyLineSet& self) {
                 return "LineSet with " + std::to_string(count(self, &o3d_lineset_num_lines)) + " lines.";
             })
        .def_static(
            "create_from_point_cloud_correspondences",
            [](const PyPointCloud& cloud0, const PyPointCloud& cloud1, py::handle correspondences) {
                std::vector<int32_t> pairs = pairs_of(correspondences, "correspondences");
                CloudPtr a = cloud0.h, b = cloud1.h;
                return make([&](o3d_lineset_t** out) {
                    std::shared_lock<std::shared_mutex> la(a->mutex);
                    std::shared_lock<std::shared_mutex> lb(b->mutex, std::defer_lock);
                    if (b != a) lb.lock();
                    return o3d_lineset_create_from_point_cloud_correspondences(out, a->p, b->p, pairs.data(),
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
            py::arg("box"), "The 12 edges of an AxisAlignedBoundingBox.");
    def_array(cls, "points", O3D_LINESET_POINTS, "(N, 3) float64 points (read-only view; assign to replace).", true);
    def_array(cls, "colors", O3D_LINESET_COLORS, "(M, 3) float64 line colors in [0, 1] (read-only view).", true);
    def_array(cls, "lines", O3D_LINESET_LINES, "(M, 2) int32 point indices (read-only view).", true);
    def_has(cls, "has_colors", O3D_LINESET_COLORS);
    def_array_access(cls);
    def_line_set_methods(cls);
}

}  // namespace o3dpy
