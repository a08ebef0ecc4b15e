// SPDX-License-Identifier: MIT
// Shared helpers of the Python extension: status -> exception, GIL-free calls, handle wrappers,
// array conversion. Everything here sits on the public C API only (capi/include/o3d/*.h).
#pragma once

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

#include <algorithm>
#include <array>
#include <initializer_list>
#include <cstdint>
#include <cstring>
#include <memory>
#include <mutex>
#include <shared_mutex>
#include <string>
#include <string_view>
#include <type_traits>
#include <utility>
#include <vector>

#include "generated/tables.h"  // enums and options fields, from the C headers
#include "o3d/o3d.h"

namespace o3dpy {
namespace py = pybind11;

/// Thrown (with the GIL held or not) after a failed C call; translated into the o3d exception
/// hierarchy by the translator registered in errors.cpp. Carries the status and the C message.
struct StatusError {
    o3d_status status;
    std::string message;
    std::string filename;  // set for I/O calls, so a missing file can become FileNotFoundError
};

/// Raise StatusError when `s` is not O3D_OK. The message is read on the failing thread, at once.
inline void check(o3d_status s, const std::string& filename = std::string()) {
    if (s == O3D_OK) return;
    std::string msg = o3d_last_error_message();
    if (msg.empty()) msg = o3d_status_string(s);
    o3d_clear_error();
    throw StatusError{s, std::move(msg), filename};
}

/// Field names of a C struct that one Open3D class shows (Open3D splits some C structs over several classes).
using FieldNames = std::initializer_list<std::string_view>;

/// Read-write properties over the fields of the C options `o` a Python class holds: those in `names` (default: all
/// that Fields has), shown as Fields says (bool, number or enum, with the header's doc).
template <typename T>
void def_fields(py::class_<T>& cls, FieldNames names = {}) {
    using C = decltype(T::o);
    Fields<C>::each([&](const char* name, auto field, auto as, const char* doc) {
        using Py = typename decltype(as)::type;
        using F = std::remove_reference_t<decltype(std::declval<C&>().*field)>;
        if constexpr (!std::is_array_v<F>) {
            if (names.size() && std::find(names.begin(), names.end(), name) == names.end()) return;
            cls.def_property(
                name, [field](const T& self) { return static_cast<Py>(self.o.*field); },
                [field](T& self, Py v) { self.o.*field = static_cast<F>(v); }, doc);
        }
    });
}

/// A constructor over def_fields' properties: positional arguments fill the fields in the header's order, keywords
/// by name (the Open3D option classes whose constructor lists exactly their fields); the rest keep `init`'s defaults.
template <typename T>
void def_fields_init(py::class_<T>& cls, const char* doc) {
    cls.def(py::init([](py::args args, py::kwargs kwargs) {
                T t;
                py::object self = py::cast(&t, py::return_value_policy::reference);
                std::vector<std::string> names;
                Fields<decltype(T::o)>::each([&](const char* name, auto, auto, const char*) { names.push_back(name); });
                if (args.size() > names.size()) throw py::type_error("too many positional arguments");
                for (size_t i = 0; i < args.size(); ++i) py::setattr(self, names[i].c_str(), args[i]);
                for (auto kv : kwargs) {
                    const std::string name = py::str(kv.first);
                    if (std::find(names.begin(), names.end(), name) == names.end())
                        throw py::type_error("unexpected keyword argument '" + name + "'");
                    py::setattr(self, name.c_str(), kv.second);
                }
                return t;
            }),
            doc);
}

/// Copy the fields `names` of `from` into `to`.
template <typename C>
void copy_fields(C& to, const C& from, FieldNames names) {
    Fields<C>::each([&](const char* name, auto field, auto, const char*) {
        if (std::find(names.begin(), names.end(), name) != names.end()) std::memcpy(&(to.*field), &(from.*field), sizeof(to.*field));
    });
}

/// A C options struct filled by its *_init (the library's defaults).
template <typename S>
S init_of(o3d_status (*init)(S*, uint32_t)) {
    S s{};
    check(init(&s, (uint32_t)sizeof(S)));
    return s;
}

/// Run a C call with the GIL released (the library may log through a Python callback, which
/// takes the GIL while holding the library's log lock: calls that may log must not hold the GIL).
template <typename F>
o3d_status nogil(F&& f) {
    py::gil_scoped_release release;
    return f();
}

/// A C handle plus a reader/writer lock (the C API allows concurrent const calls only), so that two
/// Python threads using the same handle with the GIL released never break that rule.
template <typename T, void (*Destroy)(T*)>
struct Handle {
    T* p = nullptr;
    mutable std::shared_mutex mutex;
    explicit Handle(T* raw) : p(raw) {}
    Handle(const Handle&) = delete;
    Handle& operator=(const Handle&) = delete;
    ~Handle() { Destroy(p); }
};

/// Run `f(const T*)` under a shared lock with the GIL released; raise on failure (naming `filename`, if any).
template <typename H, typename F>
void locked_const(const std::shared_ptr<H>& h, F&& f, const std::string& filename = std::string()) {
    o3d_status s;
    {
        py::gil_scoped_release release;
        std::shared_lock<std::shared_mutex> lock(h->mutex);
        s = f(static_cast<const std::remove_pointer_t<decltype(h->p)>*>(h->p));
    }
    check(s, filename);
}

/// Run `f(T*)` under an exclusive lock with the GIL released; raise on failure (naming `filename`, if any).
template <typename H, typename F>
void locked_mut(const std::shared_ptr<H>& h, F&& f, const std::string& filename = std::string()) {
    o3d_status s;
    {
        py::gil_scoped_release release;
        std::unique_lock<std::shared_mutex> lock(h->mutex);
        s = f(h->p);
    }
    check(s, filename);
}

/// The array family (o3d_<noun>_*_array) and clone of a geometry, by C handle type.
template <typename T>
struct Api;
#define O3DPY_ARRAY_API(noun, index_arrays, matrix_which)                                                  \
    template <>                                                                                           \
    struct Api<o3d_##noun##_t> {                                                                          \
        static constexpr auto destroy = &o3d_##noun##_destroy;                                           \
        static constexpr auto clone = &o3d_##noun##_clone;                                               \
        static constexpr auto has = &o3d_##noun##_has_array;                                             \
        static constexpr auto shape = &o3d_##noun##_array_shape;                                         \
        static constexpr auto set = &o3d_##noun##_set_array;                                             \
        static constexpr auto set_f32 = &o3d_##noun##_set_array_f32;                                     \
        static constexpr auto get = &o3d_##noun##_get_array;                                             \
        static constexpr auto view = &o3d_##noun##_array_view;                                           \
        static constexpr auto mutable_view = &o3d_##noun##_array_mutable_view;                           \
        static constexpr bool indexed = index_arrays;                                                    \
        static constexpr int32_t matrix = matrix_which; /* an N x 9 array shown as (N, 3, 3) */           \
    }
#define O3DPY_INDEX_API(noun)                                                                             \
    template <>                                                                                           \
    struct IndexApi<o3d_##noun##_t> {                                                                     \
        static constexpr auto set = &o3d_##noun##_set_index_array;                                       \
        static constexpr auto get = &o3d_##noun##_get_index_array;                                       \
        static constexpr auto view = &o3d_##noun##_index_array_view;                                     \
        static constexpr auto mutable_view = &o3d_##noun##_index_array_mutable_view;                     \
    }
O3DPY_ARRAY_API(pointcloud, false, O3D_POINTCLOUD_COVARIANCES);
O3DPY_ARRAY_API(trianglemesh, true, -1);
O3DPY_ARRAY_API(lineset, true, -1);
O3DPY_ARRAY_API(feature, false, -1);
template <typename T>
struct IndexApi;
O3DPY_INDEX_API(trianglemesh);
O3DPY_INDEX_API(lineset);

/// A Python-side geometry: its handle, shared with the numpy views on its arrays. `h` is replaced by a
/// private copy before a call that can reallocate arrays while such views are alive (copy-on-write):
/// the views keep the old handle alive, so they never dangle.
template <typename T>
struct Geom {
    using C = T;
    using H = Handle<T, Api<T>::destroy>;
    std::shared_ptr<H> h;
    explicit Geom(T* raw) : h(std::make_shared<H>(raw)) {}
    explicit Geom(std::shared_ptr<H> p) : h(std::move(p)) {}
    /// Handle for a call that may reallocate arrays: a private clone while views or calls share it.
    std::shared_ptr<H> for_resize() {
        if (h.use_count() > 1) {
            T* copy = nullptr;
            std::shared_ptr<H> old = h;
            locked_const(old, [&](const T* p) { return Api<T>::clone(&copy, p); });
            h = std::make_shared<H>(copy);
        }
        return h;
    }
};

using CloudHandle = Geom<o3d_pointcloud_t>::H;
using CloudPtr = std::shared_ptr<CloudHandle>;

/// Take ownership of a freshly created handle.
inline CloudPtr adopt(o3d_pointcloud_t* pc) { return std::make_shared<CloudHandle>(pc); }

/// o3d.geometry.PointCloud.
struct PyPointCloud : Geom<o3d_pointcloud_t> {
    using Geom::Geom;
    PyPointCloud();
    size_t size() const;
};

/// A Python object that owns a shared_ptr (the base of numpy views).
py::object keepalive(std::shared_ptr<void> p);
/// Raise o3d.InvalidArgumentError (a ValueError) from the binding itself.
[[noreturn]] void invalid(const std::string& message);
/// A Python int narrowed to a C int32 (InvalidArgumentError naming `what` when it does not fit; the C call
/// then checks the range it accepts).
inline int32_t int32_of(int64_t v, const char* what) {
    if (v < INT32_MIN || v > INT32_MAX) invalid(std::string(what) + " is out of range: " + std::to_string(v));
    return (int32_t)v;
}
/// A Python int as a C count (InvalidArgumentError naming `what` when negative).
inline size_t non_negative(int64_t v, const char* what) {
    if (v < 0) invalid(std::string(what) + " must be >= 0, got " + std::to_string(v));
    return (size_t)v;
}

/// A numeric array-like as an ndarray (None, non-arrays and non-numbers raise InvalidArgumentError).
py::array as_numeric(py::handle obj, const char* what);
/// "(2, 3)": an array's shape as Python prints it.
std::string shape_string(const py::array& a);
/// An integer ndarray as C-contiguous int32, each value checked against the int32 range.
py::array_t<int32_t> as_int32(const py::array& a, const char* what);

/// Python shape of `rows` rows of array `which` of `cols` values each: (rows,) for one column,
/// (rows, 3, 3) for the geometry's matrix array, else (rows, cols).
template <typename T>
std::vector<py::ssize_t> py_shape(size_t rows, size_t cols, int32_t which) {
    if (which == Api<T>::matrix) return {(py::ssize_t)rows, 3, 3};
    if (cols == 1) return {(py::ssize_t)rows};
    return {(py::ssize_t)rows, (py::ssize_t)cols};
}

inline py::dtype array_dtype(int32_t which) {
    return which >= O3D_INDEX_ARRAY_FIRST ? py::dtype::of<int32_t>() : py::dtype::of<double>();
}

/// Zero-copy view of array `which` (writable or read-only); its base keeps the handle `h` alive.
template <typename T, typename H>
py::array array_view(const std::shared_ptr<H>& h, int32_t which, bool writable) {
    void* data = nullptr;
    size_t rows = 0, cols = 0;
    auto get = [&](T* p) -> o3d_status {
        o3d_status s = Api<T>::shape(&rows, &cols, p, which);
        if (s != O3D_OK) return s;
        if constexpr (Api<T>::indexed) {
            if (which >= O3D_INDEX_ARRAY_FIRST)
                return writable ? IndexApi<T>::mutable_view(reinterpret_cast<int32_t**>(&data), &rows, p, which)
                                : IndexApi<T>::view(const_cast<const int32_t**>(reinterpret_cast<int32_t**>(&data)),
                                                    &rows, p, which);
        }
        return writable ? Api<T>::mutable_view(reinterpret_cast<double**>(&data), &rows, p, which)
                        : Api<T>::view(const_cast<const double**>(reinterpret_cast<double**>(&data)), &rows, p, which);
    };
    if (writable)
        locked_mut(h, get);
    else
        locked_const(h, [&](const T* p) { return get(const_cast<T*>(p)); });
    auto shape = py_shape<T>(rows, cols, which);
    if (!data || rows == 0) return py::array(array_dtype(which), shape);
    py::array a(array_dtype(which), shape, data, keepalive(h));
    if (!writable) a.attr("setflags")(py::arg("write") = false);
    return a;
}

/// A copy of array `which` (o3d_<noun>_get_array / get_index_array), independent of the geometry.
template <typename T, typename H>
py::array array_copy(const std::shared_ptr<H>& h, int32_t which) {
    std::vector<char> buf;
    size_t rows = 0, cols = 0;
    const bool idx = which >= O3D_INDEX_ARRAY_FIRST;
    locked_const(h, [&](const T* p) {
        o3d_status s = Api<T>::shape(&rows, &cols, p, which);
        if (s != O3D_OK) return s;
        buf.resize(rows * cols * (idx ? sizeof(int32_t) : sizeof(double)));
        if constexpr (Api<T>::indexed) {
            if (idx) return IndexApi<T>::get(reinterpret_cast<int32_t*>(buf.data()), rows, &rows, p, which);
        }
        return Api<T>::get(reinterpret_cast<double*>(buf.data()), rows, &rows, p, which);
    });
    py::array out(array_dtype(which), py_shape<T>(rows, cols, which));
    if (!buf.empty()) std::memcpy(out.mutable_data(), buf.data(), buf.size());
    return out;
}

/// Whether array `which` counts (o3d_<noun>_has_array).
template <typename T, typename H>
bool array_has(const std::shared_ptr<H>& h, int32_t which) {
    int32_t v = 0;
    locked_const(h, [&](const T* p) { return Api<T>::has(&v, p, which); });
    return v != 0;
}

/// Replace array `which` of a geometry with an array-like of its shape (float32 taken as is, integers
/// range-checked); copy-on-write first, so live views keep the old data.
template <typename G>
void array_set(G& self, int32_t which, py::handle value, const char* what) {
    using T = typename G::C;
    size_t rows = 0, cols = 0;
    locked_const(self.h, [&](const T* p) { return Api<T>::shape(&rows, &cols, p, which); });
    auto want = py_shape<T>(0, cols, which);
    py::array a = as_numeric(value, what);
    size_t n = 0;
    if (a.size() != 0) {
        bool ok = a.ndim() == (py::ssize_t)want.size();
        for (size_t i = 1; ok && i < want.size(); ++i) ok = a.shape((py::ssize_t)i) == want[i];
        if (!ok) {
            std::string w = "(N";
            for (size_t i = 1; i < want.size(); ++i) w += ", " + std::to_string(want[i]);
            invalid(std::string(what) + ": expected an " + w + (want.size() == 1 ? ",)" : ")") + " array, got shape " +
                    shape_string(a));
        }
        n = (size_t)a.shape(0);
    }
    if (which >= O3D_INDEX_ARRAY_FIRST) {
        if constexpr (Api<T>::indexed) {
            py::array_t<int32_t> v = as_int32(a, what);
            locked_mut(self.for_resize(), [&](T* p) { return IndexApi<T>::set(p, which, n ? v.data() : nullptr, n); });
        }
        return;
    }
    if (a.dtype().is(py::dtype::of<float>())) {
        auto f = py::array_t<float, py::array::c_style>::ensure(a);  // copies only if strided
        if (!f) throw py::error_already_set();
        locked_mut(self.for_resize(), [&](T* p) { return Api<T>::set_f32(p, which, n ? f.data() : nullptr, n); });
        return;
    }
    auto d = py::array_t<double, py::array::c_style | py::array::forcecast>::ensure(a);
    if (!d) throw py::error_already_set();
    locked_mut(self.for_resize(), [&](T* p) { return Api<T>::set(p, which, n ? d.data() : nullptr, n); });
}

/// A geometry property over array `which`: a zero-copy view (writable unless `readonly`); assigning
/// replaces the array.
template <typename G>
void def_array(py::class_<G>& cls, const char* name, int32_t which, const char* doc, bool readonly = false) {
    cls.def_property(
        name, [which, readonly](G& self) { return array_view<typename G::C>(self.h, which, !readonly); },
        [which, name](G& self, py::handle v) { array_set(self, which, v, name); }, doc);
}

/// has_<name>() over o3d_<noun>_has_array.
template <typename G>
void def_has(py::class_<G>& cls, const char* name, int32_t which) {
    cls.def(name, [which](const G& self) { return array_has<typename G::C>(self.h, which); });
}

/// _array_copy, _readonly_view, _has_array and _set_array(which, ...): every path of the array family, by
/// the C constant `which`, for any geometry (the named properties above are built on the same helpers).
template <typename G>
void def_array_access(py::class_<G>& cls) {
    cls.def("_has_array", [](const G& self, int32_t which) { return array_has<typename G::C>(self.h, which); },
            py::arg("which"), "Whether array `which` counts (o3d_<noun>_has_array).")
        .def("_set_array", [](G& self, int32_t which, py::handle v) { array_set(self, which, v, "_set_array"); },
             py::arg("which"), py::arg("data"), "Replace array `which` (float32 input is converted in the one copy).")
        .def("_array_copy", [](const G& self, int32_t which) { return array_copy<typename G::C>(self.h, which); },
            py::arg("which"), "Copy of array `which` (the C constant), not a view.")
        .def("_readonly_view", [](const G& self, int32_t which) { return array_view<typename G::C>(self.h, which, false); },
             py::arg("which"), "Read-only zero-copy view of array `which` (the C constant).");
}

/// An (N,3) input buffer, float64 or float32, C-contiguous (converted only when it must be).
struct Rows3 {
    py::array arr;
    bool f32 = false;
    size_t n = 0;
    const void* data() const { return arr.size() ? arr.data() : nullptr; }
};
/// Accept any (N,3) array-like (ndarray, Vector3dVector, list of triples). An empty input of any
/// shape with 0 elements is 0 rows. Wrong shapes raise ValueError (InvalidArgumentError).
Rows3 as_rows3(py::handle obj, const char* what);
/// A length-3 vector of doubles.
std::array<double, 3> as_vec3(py::handle obj, const char* what);
/// A (4,4) matrix, row-major doubles.
std::array<double, 16> as_mat4(py::handle obj, const char* what);
/// A (3,3) matrix, row-major doubles.
std::array<double, 9> as_mat3(py::handle obj, const char* what);

/// o3d_search_param_t from a KDTreeSearchParam* object (None: the C default, KNN 30).
o3d_search_param_t to_search_param(py::handle obj);

/// Read-only or writable zero-copy (n,cols) array on `data`, whose base object keeps `owner` alive.
py::array view_array(const double* data, size_t n, size_t cols, py::object owner, bool writable);


// Registration passes (declarations first, then definitions; see module.cpp).
void declare_errors(py::module_& m);
void declare_arrays(py::module_& m);
void declare_utility(py::module_& m);
void declare_pointcloud(py::module_& m);
void declare_kdtree(py::module_& m);
void declare_io(py::module_& m);
void declare_registration(py::module_& m);
void define_utility(py::module_& m);
void define_pointcloud(py::module_& m);
void define_pointcloud_tools(py::module_& m);
void define_kdtree(py::module_& m);
void define_io(py::module_& m);
void define_registration(py::module_& m);

}  // namespace o3dpy
