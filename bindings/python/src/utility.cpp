// SPDX-License-Identifier: MIT
// o3d.utility natives: version, verbosity, log callback (GIL-safe), thread count.
#include "common.h"

namespace o3dpy {
namespace {

// The Python log callable; owned here, swapped only after the library stopped using the old one.
py::object* g_log_callback = nullptr;

void log_trampoline(int32_t level, const char* message, void* user_data) {
    if (!Py_IsInitialized() || !user_data) return;
    py::gil_scoped_acquire gil;  // may run on a library worker thread
    try {
        (*static_cast<py::object*>(user_data))(level, message ? message : "");
    } catch (py::error_already_set& e) {
        e.discard_as_unraisable("o3d log callback");
    } catch (...) {
    }
}

void set_log_callback(py::object callback) {
    if (!callback.is_none() && !PyCallable_Check(callback.ptr())) invalid("set_log_callback: expected a callable or None");
    py::object* fresh = callback.is_none() ? nullptr : new py::object(callback);
    // Without the GIL: the library holds its log lock while calling the trampoline, which takes the GIL.
    o3d_status s = nogil([&] {
        return fresh ? o3d_set_log_callback(&log_trampoline, fresh) : o3d_set_log_callback(nullptr, nullptr);
    });
    if (s != O3D_OK) {
        delete fresh;
        check(s);
    }
    delete g_log_callback;  // no trampoline can still be using it: the swap took the log lock
    g_log_callback = fresh;
}

}  // namespace

void declare_utility(py::module_& m) {
    m.def("_version", []() { return std::string(o3d_version()); }, "Library version string (o3d_version()).");
    m.def("_version_tuple",
          []() { return py::make_tuple(o3d_version_major(), o3d_version_minor(), o3d_version_patch()); },
          "(major, minor, patch) of the loaded libo3d.");
    // The log levels, for o3d.utility.VerbosityLevel.
    m.attr("O3D_LOG_ERROR") = O3D_LOG_ERROR;
    m.attr("O3D_LOG_WARNING") = O3D_LOG_WARNING;
    m.attr("O3D_LOG_INFO") = O3D_LOG_INFO;
    m.attr("O3D_LOG_DEBUG") = O3D_LOG_DEBUG;
}

void define_utility(py::module_& m) {
    m.def(
        "_set_verbosity_level",
        [](int32_t level) { check(nogil([&] { return o3d_set_verbosity_level(level); })); }, py::arg("level"));
    m.def("_get_verbosity_level", []() { return o3d_get_verbosity_level(); });
    m.def("_set_log_callback", &set_log_callback, py::arg("callback"),
          "Route library log lines to callback(level: int, message: str); None restores stderr.");
    m.def(
        "set_num_threads", [](int32_t n) { check(nogil([&] { return o3d_set_num_threads(n); })); },
        py::arg("num_threads"),
        "Default thread count of parallel algorithms (0 restores the OpenMP default, the number of cores).");
    m.def("get_num_threads", []() { return o3d_get_num_threads(); },
          "Thread count used when a call is given num_threads=0.");
}

}  // namespace o3dpy
