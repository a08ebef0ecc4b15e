// SPDX-License-Identifier: MIT
// Small conversions shared by the mesh, image, RGB-D, camera and I/O bindings.
#include <random>

#include "geometry_types.h"

namespace o3dpy {

std::string path_of(py::handle filename) {
    py::object p = py::module_::import("os").attr("fspath")(filename);
    return p.cast<std::string>();  // str -> UTF-8; bytes as they are
}

uint64_t seed_or_random(py::handle seed) {
    if (seed.is_none()) {  // Open3D: a fresh random draw unless seeded
        std::random_device rd;
        return ((uint64_t)rd() << 32) ^ rd();
    }
    if (!PyLong_Check(seed.ptr()) && !PyIndex_Check(seed.ptr())) invalid("seed: expected an integer or None");
    py::int_ i = py::reinterpret_borrow<py::object>(seed);
    return (uint64_t)PyLong_AsUnsignedLongLongMask(i.ptr());
}

py::array vec3_to_array(const double* v) { return mat_to_array(v, 3, 0); }

py::array mat_to_array(const double* v, size_t rows, size_t cols) {
    // cols == 0: a 1-D array of `rows` values
    std::vector<py::ssize_t> shape = cols ? std::vector<py::ssize_t>{(py::ssize_t)rows, (py::ssize_t)cols}
                                          : std::vector<py::ssize_t>{(py::ssize_t)rows};
    py::array_t<double> out(shape);
    std::memcpy(out.mutable_data(), v, rows * (cols ? cols : 1) * sizeof(double));
    return std::move(out);
}

std::pair<std::array<double, 3>, std::array<double, 3>> aabb_bounds(py::handle box) {
    if (box.is_none() || !py::hasattr(box, "get_min_bound") || !py::hasattr(box, "get_max_bound"))
        throw py::type_error("crop: bounding_box must be an o3d.geometry.AxisAlignedBoundingBox or OrientedBoundingBox, got " +
                             std::string(py::str(py::type::handle_of(box).attr("__name__"))));
    auto lo = as_vec3(box.attr("get_min_bound")(), "bounding_box.min_bound");
    auto hi = as_vec3(box.attr("get_max_bound")(), "bounding_box.max_bound");
    return {lo, hi};
}

py::object make_aabb(const double* lo, const double* hi) {
    py::object cls = py::module_::import("o3d.geometry").attr("AxisAlignedBoundingBox");
    return cls(vec3_to_array(lo), vec3_to_array(hi));
}

}  // namespace o3dpy
