// SPDX-License-Identifier: MIT
// numpy <-> C buffers: (N,3) inputs taken as float64 or float32 without conversion in Python,
// zero-copy output views whose base object keeps the owning handle alive.
#include "common.h"

namespace o3dpy {
namespace {

struct KeepAlive {
    std::shared_ptr<void> p;
};

}  // namespace

std::string shape_string(const py::array& a) {
    std::string s = "(";
    for (py::ssize_t i = 0; i < a.ndim(); ++i) s += (i ? ", " : "") + std::to_string(a.shape(i));
    if (a.ndim() == 1) s += ",";
    return s + ")";
}

py::array as_numeric(py::handle obj, const char* what) {
    if (obj.is_none()) invalid(std::string(what) + ": expected an array, got None");
    py::array a = py::array::ensure(obj);
    if (!a) invalid(std::string(what) + ": expected an array-like of numbers");
    char kind = a.dtype().kind();
    if (kind != 'f' && kind != 'i' && kind != 'u' && kind != 'b')
        invalid(std::string(what) + ": expected numbers, got dtype " + std::string(py::str(a.dtype())));
    return a;
}

py::array_t<int32_t> as_int32(const py::array& a, const char* what) {
    if (a.size() == 0) return py::array_t<int32_t>(0);
    char kind = a.dtype().kind();
    if (kind != 'i' && kind != 'u')
        invalid(std::string(what) + ": expected integers, got dtype " + std::string(py::str(a.dtype())));
    if (a.dtype().is(py::dtype::of<int32_t>())) {
        auto d = py::array_t<int32_t, py::array::c_style>::ensure(a);
        if (!d) throw py::error_already_set();
        return d;
    }
    auto wide = py::array_t<int64_t, py::array::c_style | py::array::forcecast>::ensure(a);
    if (!wide) throw py::error_already_set();
    py::array_t<int32_t> out(wide.size());
    const int64_t* src = wide.data();
    int32_t* dst = out.mutable_data();
    for (py::ssize_t i = 0; i < wide.size(); ++i) {
        if (src[i] < INT32_MIN || src[i] > INT32_MAX)
            invalid(std::string(what) + ": index " + std::to_string(src[i]) + " is out of range");
        dst[i] = (int32_t)src[i];
    }
    return out;
}

namespace {

template <size_t N>
std::array<double, N> fixed(py::handle obj, const char* what, py::ssize_t rows, py::ssize_t cols) {
    py::array a = as_numeric(obj, what);
    auto d = py::array_t<double, py::array::c_style | py::array::forcecast>::ensure(a);
    if (!d) throw py::error_already_set();
    bool ok = (size_t)d.size() == N &&
              ((rows == 1 && d.ndim() == 1) || (d.ndim() == 2 && d.shape(0) == rows && d.shape(1) == cols) ||
               (rows == 1 && d.ndim() == 2 && ((d.shape(0) == 1) || d.shape(1) == 1)));
    if (!ok) {
        std::string want = rows == 1 ? "(" + std::to_string(cols) + ",)"
                                     : "(" + std::to_string(rows) + ", " + std::to_string(cols) + ")";
        invalid(std::string(what) + ": expected shape " + want + ", got " + shape_string(a));
    }
    std::array<double, N> out{};
    std::memcpy(out.data(), d.data(), N * sizeof(double));
    return out;
}

}  // namespace

Rows3 as_rows3(py::handle obj, const char* what) {
    py::array a = as_numeric(obj, what);
    Rows3 r;
    if (a.size() == 0) {
        r.arr = py::array_t<double>(std::vector<py::ssize_t>{0, 3});
        return r;
    }
    if (a.ndim() != 2 || a.shape(1) != 3)
        invalid(std::string(what) + ": expected an (N, 3) array, got shape " + shape_string(a));
    if (a.dtype().is(py::dtype::of<float>())) {
        r.arr = py::array_t<float, py::array::c_style>::ensure(a);  // copies only if strided
        r.f32 = true;
    } else {
        r.arr = py::array_t<double, py::array::c_style | py::array::forcecast>::ensure(a);
    }
    if (!r.arr) throw py::error_already_set();
    r.n = (size_t)a.shape(0);
    return r;
}

std::array<double, 3> as_vec3(py::handle obj, const char* what) { return fixed<3>(obj, what, 1, 3); }
std::array<double, 16> as_mat4(py::handle obj, const char* what) { return fixed<16>(obj, what, 4, 4); }
std::array<double, 9> as_mat3(py::handle obj, const char* what) { return fixed<9>(obj, what, 3, 3); }

py::object keepalive(std::shared_ptr<void> p) { return py::cast(KeepAlive{std::move(p)}); }

py::array view_array(const double* data, size_t n, size_t cols, py::object owner, bool writable) {
    if (!data || n == 0) {
        py::array_t<double> empty(std::vector<py::ssize_t>{0, (py::ssize_t)cols});
        return std::move(empty);
    }
    std::vector<py::ssize_t> shape{(py::ssize_t)n, (py::ssize_t)cols};
    std::vector<py::ssize_t> strides{(py::ssize_t)(cols * sizeof(double)), (py::ssize_t)sizeof(double)};
    py::array a(py::dtype::of<double>(), shape, strides, data, owner);
    if (!writable) a.attr("setflags")(py::arg("write") = false);
    return a;
}

void declare_arrays(py::module_& m) {
    py::class_<KeepAlive>(m, "_KeepAlive", "Owner of library memory shared by numpy views (the views' base).");
}

}  // namespace o3dpy
