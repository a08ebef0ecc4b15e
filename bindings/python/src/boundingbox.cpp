// SPDX-License-Identifier: MIT
// Oriented bounding boxes (boundingbox.h). The box itself is the pure-Python
// o3d.geometry.OrientedBoundingBox (a value: center, R, extent); this file converts it to and from
// o3d_obb_t and binds the C calls that compute or use one.
#include "geometry_types.h"

namespace o3dpy {

bool is_obb(py::handle box) {
    py::object cls = py::module_::import("o3d.geometry").attr("OrientedBoundingBox");
    return py::isinstance(box, cls);
}

o3d_obb_t obb_of(py::handle box) {
    if (!is_obb(box))
        throw py::type_error("expected an o3d.geometry.OrientedBoundingBox, got " +
                             std::string(py::str(py::type::handle_of(box).attr("__name__"))));
    o3d_obb_t obb{};
    auto c = as_vec3(box.attr("center"), "OrientedBoundingBox.center");
    auto r = as_mat3(box.attr("R"), "OrientedBoundingBox.R");
    auto e = as_vec3(box.attr("extent"), "OrientedBoundingBox.extent");
    std::memcpy(obb.center, c.data(), sizeof(obb.center));
    std::memcpy(obb.R, r.data(), sizeof(obb.R));
    std::memcpy(obb.extent, e.data(), sizeof(obb.extent));
    return obb;
}

py::object make_obb(const o3d_obb_t& obb) {
    py::object cls = py::module_::import("o3d.geometry").attr("OrientedBoundingBox");
    return cls(vec3_to_array(obb.center), mat_to_array(obb.R, 3, 3), vec3_to_array(obb.extent));
}

py::array_t<double> rows3_f64(py::handle obj, const char* what) {
    Rows3 r = as_rows3(obj, what);
    auto a = py::array_t<double, py::array::c_style | py::array::forcecast>::ensure(r.arr);
    if (!a) throw py::error_already_set();
    return a;
}

py::list int_list(const int32_t* v, size_t n) {
    py::list out(n);
    for (size_t i = 0; i < n; ++i) out[i] = py::int_(v[i]);
    return out;
}

namespace {

py::tuple obb_tuple(const o3d_obb_t& obb) {
    return py::make_tuple(vec3_to_array(obb.center), mat_to_array(obb.R, 3, 3), vec3_to_array(obb.extent));
}

}  // namespace

void define_boundingbox(py::module_& m) {
    m.def(
        "_obb_create_from_points",
        [](py::handle points, bool robust) {
            auto xyz = rows3_f64(points, "points");
            const size_t n = (size_t)xyz.shape(0);
            o3d_obb_t obb{};
            check(nogil([&] { return o3d_obb_create_from_points(&obb, n ? xyz.data() : nullptr, n, robust ? 1 : 0); }));
            return obb_tuple(obb);
        },
        py::arg("points"), py::arg("robust") = false, "(center, R, extent) of the oriented box of (N, 3) points.");
    m.def(
        "_obb_create_from_axis_aligned_bounding_box",
        [](py::handle min_bound, py::handle max_bound) {
            auto lo = as_vec3(min_bound, "min_bound");
            auto hi = as_vec3(max_bound, "max_bound");
            o3d_obb_t obb{};
            check(o3d_obb_create_from_axis_aligned_bounding_box(&obb, lo.data(), hi.data()));
            return obb_tuple(obb);
        },
        py::arg("min_bound"), py::arg("max_bound"), "(center, R, extent) of the box equal to an axis-aligned one.");
    m.def(
        "_obb_get_box_points",
        [](py::handle box) {
            o3d_obb_t obb = obb_of(box);
            double pts[24];
            check(o3d_obb_get_box_points(pts, &obb));
            return mat_to_array(pts, 8, 3);
        },
        py::arg("box"), "The 8 corners (8, 3) of an OrientedBoundingBox.");
    m.def(
        "_obb_get_point_indices_within",
        [](py::handle box, py::handle points) {
            o3d_obb_t obb = obb_of(box);
            auto xyz = rows3_f64(points, "points");
            const size_t n = (size_t)xyz.shape(0);
            std::vector<int32_t> idx(n);
            size_t got = 0;
            check(nogil([&] {
                return o3d_obb_get_point_indices_within(idx.data(), idx.size(), &got, &obb, n ? xyz.data() : nullptr,
                                                        n);
            }));
            return int_list(idx.data(), std::min(got, idx.size()));
        },
        py::arg("box"), py::arg("points"), "Indices (ascending) of the points inside the box, boundary included.");

    auto pcd = static_cast<py::class_<PyPointCloud>>(m.attr("PointCloud"));
    pcd.def(
        "get_oriented_bounding_box",
        [](const PyPointCloud& self, bool robust) {
            o3d_obb_t obb{};
            locked_const(self.h, [&](const o3d_pointcloud_t* pc) {
                return o3d_pointcloud_get_oriented_bounding_box(&obb, pc, robust ? 1 : 0);
            });
            return make_obb(obb);
        },
        py::arg("robust") = false,
        "Oriented bounding box (PCA of the convex hull); robust=True also handles degenerate (e.g. planar) clouds.");

    auto mesh = static_cast<py::class_<PyTriangleMesh>>(m.attr("TriangleMesh"));
    mesh.def(
        "get_oriented_bounding_box",
        [](const PyTriangleMesh& self, bool robust) {
            o3d_obb_t obb{};
            locked_const(self.h, [&](const o3d_trianglemesh_t* me) {
                return o3d_trianglemesh_get_oriented_bounding_box(&obb, me, robust ? 1 : 0);
            });
            return make_obb(obb);
        },
        py::arg("robust") = false, "Oriented bounding box of the vertices.");
}

}  // namespace o3dpy
