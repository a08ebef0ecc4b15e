// SPDX-License-Identifier: MIT
// The exception hierarchy. Every failed C call raises a subclass of o3d.O3DError (a RuntimeError)
// carrying the C message (str(e)), the status code (e.status) and its name (e.status_name):
//   O3DError(RuntimeError)
//   +- InvalidArgumentError(O3DError, ValueError)   O3D_ERROR_INVALID_ARGUMENT
//   +- O3DMemoryError(O3DError, MemoryError)        O3D_ERROR_OUT_OF_MEMORY
//   +- O3DIOError(O3DError, OSError)                O3D_ERROR_IO
//   |  +- O3DFileNotFoundError(O3DIOError, FileNotFoundError)   ... when the file does not exist
//   +- ParseError(O3DError)                         O3D_ERROR_PARSE
//   +- UnsupportedError(O3DError, NotImplementedError)  O3D_ERROR_UNSUPPORTED
//   +- NotConvergedError(O3DError)                  O3D_ERROR_NOT_CONVERGED
//   +- CancelledError(O3DError)                     O3D_ERROR_CANCELLED
//   +- InternalError(O3DError)                      O3D_ERROR_INTERNAL, O3D_ERROR_BUFFER_TOO_SMALL
#include <cerrno>
#include <filesystem>

#include "common.h"

namespace o3dpy {
namespace {

struct Classes {
    PyObject* base = nullptr;
    PyObject* invalid = nullptr;
    PyObject* memory = nullptr;
    PyObject* io = nullptr;
    PyObject* not_found = nullptr;
    PyObject* parse = nullptr;
    PyObject* unsupported = nullptr;
    PyObject* not_converged = nullptr;
    PyObject* cancelled = nullptr;
    PyObject* internal = nullptr;
};
Classes g;  // strong references, never released (the module lives until exit)

PyObject* make(py::module_& m, const char* name, std::initializer_list<PyObject*> bases, const char* doc) {
    std::string qual = std::string("o3d.") + name;
    py::tuple b(bases.size());
    size_t i = 0;
    for (PyObject* p : bases) b[i++] = py::reinterpret_borrow<py::object>(p);
    PyObject* cls = PyErr_NewExceptionWithDoc(qual.c_str(), doc, b.ptr(), nullptr);
    if (!cls) throw py::error_already_set();
    m.add_object(name, py::reinterpret_borrow<py::object>(cls));
    return cls;  // the new reference is kept in `g`
}

PyObject* class_for(o3d_status s) {
    switch (s) {
        case O3D_ERROR_INVALID_ARGUMENT: return g.invalid;
        case O3D_ERROR_OUT_OF_MEMORY: return g.memory;
        case O3D_ERROR_IO: return g.io;
        case O3D_ERROR_PARSE: return g.parse;
        case O3D_ERROR_UNSUPPORTED: return g.unsupported;
        case O3D_ERROR_NOT_CONVERGED: return g.not_converged;
        case O3D_ERROR_CANCELLED: return g.cancelled;
        default: return g.internal;
    }
}

void raise_status(const StatusError& e) {
    PyObject* cls = class_for(e.status);
    bool missing = false;
    if (e.status == O3D_ERROR_IO && !e.filename.empty()) {
        std::error_code ec;
        missing = !std::filesystem::exists(std::filesystem::u8path(e.filename), ec);
        if (missing) cls = g.not_found;
    }
    py::object exc = py::reinterpret_borrow<py::object>(cls)(e.message);
    exc.attr("status") = e.status;
    exc.attr("status_name") = std::string(o3d_status_string(e.status));
    if (!e.filename.empty() && e.status == O3D_ERROR_IO) {
        exc.attr("filename") = e.filename;
        if (missing) exc.attr("errno") = ENOENT;
    }
    PyErr_SetObject(cls, exc.ptr());
}

}  // namespace

[[noreturn]] void invalid(const std::string& message) {
    throw StatusError{O3D_ERROR_INVALID_ARGUMENT, message, std::string()};
}

void declare_errors(py::module_& m) {
    g.base = make(m, "O3DError", {PyExc_RuntimeError},
                  "Base of every o3d error. str(e) is the library's message; e.status is the C status code "
                  "and e.status_name its name.");
    g.invalid = make(m, "InvalidArgumentError", {g.base, PyExc_ValueError}, "Bad argument (O3D_ERROR_INVALID_ARGUMENT).");
    g.memory = make(m, "O3DMemoryError", {g.base, PyExc_MemoryError}, "Out of memory (O3D_ERROR_OUT_OF_MEMORY).");
    g.io = make(m, "O3DIOError", {g.base, PyExc_OSError}, "A file could not be opened, read or written (O3D_ERROR_IO).");
    g.not_found = make(m, "O3DFileNotFoundError", {g.io, PyExc_FileNotFoundError}, "The file does not exist.");
    g.parse = make(m, "ParseError", {g.base}, "Malformed, truncated or inconsistent data (O3D_ERROR_PARSE).");
    g.unsupported = make(m, "UnsupportedError", {g.base, PyExc_NotImplementedError},
                         "Unknown format or unavailable feature (O3D_ERROR_UNSUPPORTED).");
    g.not_converged = make(m, "NotConvergedError", {g.base}, "An iterative method did not converge.");
    g.cancelled = make(m, "CancelledError", {g.base}, "A progress callback cancelled the call (O3D_ERROR_CANCELLED).");
    g.internal = make(m, "InternalError", {g.base}, "Internal library error (a bug; please report).");

    py::register_exception_translator([](std::exception_ptr p) {
        if (!p) return;
        try {
            std::rethrow_exception(p);
        } catch (const StatusError& e) {
            raise_status(e);
        }
    });

    m.def("_status_string", [](int32_t s) { return std::string(o3d_status_string(s)); },
          "Name of a C status code, e.g. _status_string(-3) == 'O3D_ERROR_IO'.");
    m.def("_last_error", []() {
        // The thread-local C error state (normally already cleared after a raise).
        return py::make_tuple(o3d_last_error_code(), std::string(o3d_last_error_message()));
    });
    m.def("_clear_error", []() { o3d_clear_error(); });
}

}  // namespace o3dpy
