// SPDX-License-Identifier: MIT
// Shared helpers of the Python extension: status -> exception, GIL-free calls, handle wrappers,
// array conversion. Everything here sits on the public C API only (capi/include/o3d/*.h).
#pragma once

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

#include <array>
#include <cstring>
#include <memory>
#include <mutex>
#include <shared_mutex>
#include <string>
#include <utility>

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

/// Run a C call with the GIL released (the library may log through a Python callback, which
/// takes the GIL while holding the library's log lock: calls that may log must not hold the GIL).
template <typename F>
o3d_status nogil(F&& f) {
    py::gil_scoped_release release;
    return f();
}

/// A point-cloud handle plus a reader/writer lock, so that two Python threads using the same
/// cloud with the GIL released never break the C API's "const calls only" threading rule.
struct CloudHandle {
    o3d_pointcloud_t* pc = nullptr;
    mutable std::shared_mutex mutex;
    explicit CloudHandle(o3d_pointcloud_t* p) : pc(p) {}
    CloudHandle(const CloudHandle&) = delete;
    CloudHandle& operator=(const CloudHandle&) = delete;
    ~CloudHandle() { o3d_pointcloud_destroy(pc); }
};
using CloudPtr = std::shared_ptr<CloudHandle>;

/// Take ownership of a freshly created handle.
inline CloudPtr adopt(o3d_pointcloud_t* pc) { return std::make_shared<CloudHandle>(pc); }

/// o3d.geometry.PointCloud. `h` may be replaced by a private copy before a call that can
/// reallocate the cloud's arrays while numpy views on the old arrays are alive (copy-on-write):
/// those views keep the old handle alive, so they never dangle.
struct PyPointCloud {
    CloudPtr h;
    PyPointCloud();
    explicit PyPointCloud(CloudPtr p) : h(std::move(p)) {}
    /// Handle for a call that may reallocate arrays: cloned first when views or in-flight calls
    /// share the current one.
    CloudPtr for_resize();
    /// Handle for an in-place call (arrays keep their addresses; views see the change).
    CloudPtr for_inplace() const { return h; }
    const o3d_pointcloud_t* cpc() const { return h->pc; }
    size_t size() const;
};

/// Run `f(pc)` on the handle with a shared (const) lock, the GIL released.
template <typename F>
void with_const(const CloudPtr& h, F&& f) {
    o3d_status s;
    {
        py::gil_scoped_release release;
        std::shared_lock<std::shared_mutex> lock(h->mutex);
        s = f(static_cast<const o3d_pointcloud_t*>(h->pc));
    }
    check(s);
}

/// Run `f(pc)` on the handle with an exclusive lock, the GIL released.
template <typename F>
void with_mut(const CloudPtr& h, F&& f) {
    o3d_status s;
    {
        py::gil_scoped_release release;
        std::unique_lock<std::shared_mutex> lock(h->mutex);
        s = f(h->pc);
    }
    check(s);
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

/// Raise o3d.InvalidArgumentError (a ValueError) from the binding itself.
[[noreturn]] void invalid(const std::string& message);

/// Read-only or writable zero-copy (n,cols) array on `data`, whose base object keeps `owner` alive.
py::array view_array(const double* data, size_t n, size_t cols, py::object owner, bool writable);

/// A Python object that owns a shared_ptr (the base of numpy views).
py::object keepalive(std::shared_ptr<void> p);

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
