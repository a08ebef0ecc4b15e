// SPDX-License-Identifier: MIT
// Small conversions shared by the mesh, image, RGB-D, camera and I/O bindings.
#include <limits>
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

std::vector<int32_t> int32_indices(py::handle obj, const char* what) {
    const std::string name(what);
    py::array a = py::array::ensure(obj);
    if (!a) invalid(name + ": expected a sequence of integers");
    if (a.size() == 0) return {};
    char kind = a.dtype().kind();
    if (kind != 'i' && kind != 'u') invalid(name + ": expected integers, got dtype " + std::string(py::str(a.dtype())));
    if (a.ndim() != 1) invalid(name + ": expected a 1-D sequence");
    auto v = py::array_t<int64_t, py::array::c_style | py::array::forcecast>::ensure(a);
    if (!v) throw py::error_already_set();
    std::vector<int32_t> out((size_t)v.size());
    const int64_t* p = v.data();
    for (size_t i = 0; i < out.size(); ++i) {
        if (p[i] < 0 || p[i] > std::numeric_limits<int32_t>::max())
            invalid(name + ": index " + std::to_string(p[i]) + " is out of range");
        out[i] = (int32_t)p[i];
    }
    return out;
}

std::vector<uint8_t> byte_mask(py::handle obj, const char* what) {
    const std::string name(what);
    py::array a = py::array::ensure(obj);
    if (!a) invalid(name + ": expected a sequence of booleans");
    if (a.ndim() != 1 && a.size() != 0) invalid(name + ": expected a 1-D sequence");
    char kind = a.dtype().kind();
    if (a.size() != 0 && kind != 'b' && kind != 'i' && kind != 'u')
        invalid(name + ": expected booleans, got dtype " + std::string(py::str(a.dtype())));
    auto v = py::array_t<bool, py::array::c_style | py::array::forcecast>::ensure(a);
    if (!v) throw py::error_already_set();
    std::vector<uint8_t> out((size_t)v.size());
    for (size_t i = 0; i < out.size(); ++i) out[i] = v.data()[i] ? 1 : 0;
    return out;
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
