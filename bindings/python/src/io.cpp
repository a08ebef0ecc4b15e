// SPDX-License-Identifier: MIT
// o3d.io point-cloud reading/writing over io.h: files (str or os.PathLike) and in-memory bytes.
#include "common.h"

namespace o3dpy {
namespace {

std::string path_string(py::handle filename) {
    py::object p = py::module_::import("os").attr("fspath")(filename);
    if (py::isinstance<py::bytes>(p)) return p.cast<std::string>();
    return p.cast<std::string>();  // str -> UTF-8
}

std::string format_string(py::handle format) {
    if (format.is_none()) return "auto";
    return format.cast<std::string>();
}

o3d_read_options_t read_opts(bool remove_nan, bool remove_inf) {
    o3d_read_options_t o = init_of(&o3d_read_options_init);
    o.remove_nan_points = remove_nan ? 1 : 0;
    o.remove_infinite_points = remove_inf ? 1 : 0;
    return o;
}

o3d_write_options_t write_opts(bool write_ascii, bool compressed) {
    o3d_write_options_t o = init_of(&o3d_write_options_init);
    o.write_ascii = write_ascii ? 1 : 0;
    o.compressed = compressed ? 1 : 0;
    return o;
}

using BufferPtr = std::shared_ptr<o3d_buffer_t>;

BufferPtr encode(const PyPointCloud& pcd, const std::string& fmt, bool write_ascii, bool compressed) {
    o3d_write_options_t o = write_opts(write_ascii, compressed);
    o3d_buffer_t* buf = nullptr;
    locked_const(pcd.h, [&](const o3d_pointcloud_t* pc) {
        return o3d_io_write_point_cloud_to_memory(&buf, pc, fmt.c_str(), &o);
    });
    return BufferPtr(buf, o3d_buffer_destroy);
}

}  // namespace

void declare_io(py::module_&) {}

void define_io(py::module_& m) {
    const o3d_read_options_t rd = init_of(&o3d_read_options_init);
    const o3d_write_options_t wd = init_of(&o3d_write_options_init);
    m.def(
        "read_point_cloud",
        [](py::handle filename, py::handle format, bool remove_nan_points, bool remove_infinite_points,
           bool /*print_progress*/) {
            std::string path = path_string(filename), fmt = format_string(format);
            o3d_read_options_t o = read_opts(remove_nan_points, remove_infinite_points);
            o3d_pointcloud_t* out = nullptr;
            o3d_status s = nogil([&] { return o3d_io_read_point_cloud(&out, path.c_str(), fmt.c_str(), &o); });
            check(s, path);
            return PyPointCloud(adopt(out));
        },
        py::arg("filename"), py::arg("format") = "auto", py::arg("remove_nan_points") = rd.remove_nan_points != 0,
        py::arg("remove_infinite_points") = rd.remove_infinite_points != 0, py::arg("print_progress") = false,
        "Read a cloud (ply, pcd, xyz, xyzn, xyzrgb, pts; 'auto' = from the extension). Unlike Open3D, a "
        "failure raises (O3DFileNotFoundError, O3DIOError, ParseError, UnsupportedError) instead of returning an "
        "empty cloud.");
    m.def(
        "write_point_cloud",
        [](py::handle filename, const PyPointCloud& pointcloud, py::handle format, bool write_ascii, bool compressed,
           bool /*print_progress*/) {
            std::string path = path_string(filename), fmt = format_string(format);
            o3d_write_options_t o = write_opts(write_ascii, compressed);
            o3d_status s;
            {
                CloudPtr h = pointcloud.h;
                py::gil_scoped_release release;
                std::shared_lock<std::shared_mutex> lock(h->mutex);
                s = o3d_io_write_point_cloud(path.c_str(), h->p, fmt.c_str(), &o);
            }
            check(s, path);
            return true;
        },
        py::arg("filename"), py::arg("pointcloud"), py::arg("format") = "auto",
        py::arg("write_ascii") = wd.write_ascii != 0, py::arg("compressed") = wd.compressed != 0,
        py::arg("print_progress") = false,
        "Write a cloud; returns True (failures raise, e.g. O3DIOError).");
    m.def(
        "read_point_cloud_from_bytes",
        [](py::buffer data, const std::string& format, bool remove_nan_points, bool remove_infinite_points) {
            py::buffer_info info = data.request();
            if (info.ndim > 1 && info.strides.back() != info.itemsize) invalid("data: expected a contiguous bytes-like object");
            size_t size = (size_t)(info.size * info.itemsize);
            o3d_read_options_t o = read_opts(remove_nan_points, remove_infinite_points);
            o3d_pointcloud_t* out = nullptr;
            const uint8_t* p = static_cast<const uint8_t*>(info.ptr);
            check(nogil([&] { return o3d_io_read_point_cloud_from_memory(&out, p, size, format.c_str(), &o); }));
            return PyPointCloud(adopt(out));
        },
        py::arg("data"), py::arg("format"), py::arg("remove_nan_points") = rd.remove_nan_points != 0,
        py::arg("remove_infinite_points") = rd.remove_infinite_points != 0,
        "Decode a cloud from bytes in the given format (required: there is no file extension).");
    m.def(
        "write_point_cloud_to_bytes",
        [](const PyPointCloud& pcd, const std::string& format, bool write_ascii, bool compressed) {
            BufferPtr buf = encode(pcd, format, write_ascii, compressed);
            size_t size = 0;
            o3d_status s = o3d_buffer_get_data(nullptr, 0, &size, buf.get());
            if (s != O3D_OK && s != O3D_ERROR_BUFFER_TOO_SMALL) check(s);
            PyObject* raw = PyBytes_FromStringAndSize(nullptr, (py::ssize_t)size);
            if (!raw) throw py::error_already_set();
            py::bytes out = py::reinterpret_steal<py::bytes>(raw);
            check(o3d_buffer_get_data(reinterpret_cast<uint8_t*>(PyBytes_AS_STRING(raw)), size, &size, buf.get()));
            return out;
        },
        py::arg("pointcloud"), py::arg("format"), py::arg("write_ascii") = wd.write_ascii != 0,
        py::arg("compressed") = wd.compressed != 0,
        "Encode a cloud in the given format into bytes.");
    m.def(
        "write_point_cloud_to_buffer",
        [](const PyPointCloud& pcd, const std::string& format, bool write_ascii, bool compressed) {
            BufferPtr buf = encode(pcd, format, write_ascii, compressed);
            const uint8_t* data = nullptr;
            size_t size = 0;
            check(o3d_buffer_view(&data, &size, buf.get()));
            if (!data || size == 0) return py::array(py::array_t<uint8_t>((py::ssize_t)0));
            py::array a(py::dtype::of<uint8_t>(), std::vector<py::ssize_t>{(py::ssize_t)size},
                        std::vector<py::ssize_t>{1}, data, keepalive(buf));
            a.attr("setflags")(py::arg("write") = false);
            return a;
        },
        py::arg("pointcloud"), py::arg("format"), py::arg("write_ascii") = wd.write_ascii != 0,
        py::arg("compressed") = wd.compressed != 0,
        "As write_point_cloud_to_bytes, as a read-only uint8 array sharing the library's buffer (no copy).");
}

}  // namespace o3dpy
