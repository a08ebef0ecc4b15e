// SPDX-License-Identifier: MIT
// Per-point covariances of a PointCloud (the covariance functions of pointcloud.h):
// pcd.covariances is an (N, 3, 3) read-only zero-copy view (the C API has no writable one); assign a
// new (N, 3, 3) array (or Matrix3dVector) to change them.
#include <vector>

#include "geometry_types.h"

namespace o3dpy {
namespace {

py::array_t<double> covariance_copy(const PyPointCloud& self) {
    std::vector<double> buf;
    size_t n = 0;
    with_const(self.h, [&](const o3d_pointcloud_t* pc) {
        o3d_status s = o3d_pointcloud_get_array(nullptr, 0, &n, pc, O3D_POINTCLOUD_COVARIANCES);
        if (s != O3D_OK && s != O3D_ERROR_BUFFER_TOO_SMALL) return s;
        buf.resize(n * 9);
        return o3d_pointcloud_get_array(buf.data(), n, &n, pc, O3D_POINTCLOUD_COVARIANCES);
    });
    py::array_t<double> out(std::vector<py::ssize_t>{(py::ssize_t)n, 3, 3});
    if (n) std::memcpy(out.mutable_data(), buf.data(), n * 9 * sizeof(double));
    return out;
}

py::array covariance_view(const PyPointCloud& self) {
    CloudPtr h = self.h;
    const double* data = nullptr;
    size_t n = 0;
    o3d_status s;
    {
        py::gil_scoped_release release;
        std::shared_lock<std::shared_mutex> lock(h->mutex);
        s = o3d_pointcloud_array_view(&data, &n, h->pc, O3D_POINTCLOUD_COVARIANCES);
    }
    if (s == O3D_ERROR_INVALID_ARGUMENT) {
        // The view exists only while every matrix is symmetric (the storage is column-major): otherwise
        // hand out a read-only copy, so reading pcd.covariances never fails.
        o3d_clear_error();
        py::array_t<double> copy = covariance_copy(self);
        copy.attr("setflags")(py::arg("write") = false);
        return std::move(copy);
    }
    check(s);
    if (!data || n == 0) return py::array_t<double>(std::vector<py::ssize_t>{0, 3, 3});
    const py::ssize_t d = sizeof(double);
    py::array a(py::dtype::of<double>(), {(py::ssize_t)n, (py::ssize_t)3, (py::ssize_t)3}, {9 * d, 3 * d, d}, data,
                keepalive(h));
    a.attr("setflags")(py::arg("write") = false);
    return a;
}

void set_covariances(PyPointCloud& self, py::handle value) {
    if (value.is_none()) invalid("covariances: expected an (N, 3, 3) array, got None");
    py::array a = py::array::ensure(value);
    if (!a || (a.dtype().kind() != 'f' && a.dtype().kind() != 'i' && a.dtype().kind() != 'u'))
        invalid("covariances: expected an (N, 3, 3) array of numbers");
    auto d = py::array_t<double, py::array::c_style | py::array::forcecast>::ensure(a);
    if (!d) throw py::error_already_set();
    size_t n = 0;
    if (d.size() != 0) {
        if (d.ndim() != 3 || d.shape(1) != 3 || d.shape(2) != 3)
            invalid("covariances: expected an (N, 3, 3) array");
        n = (size_t)d.shape(0);
    }
    CloudPtr h = self.for_resize();
    with_mut(h, [&](o3d_pointcloud_t* pc) { return o3d_pointcloud_set_array(pc, O3D_POINTCLOUD_COVARIANCES, n ? d.data() : nullptr, n); });
}

}  // namespace

void define_covariances(py::module_& m) {
    auto cls = static_cast<py::class_<PyPointCloud>>(m.attr("PointCloud"));
    cls.def_property(
           "covariances", [](const PyPointCloud& self) { return covariance_view(self); },
           [](PyPointCloud& self, py::handle v) { set_covariances(self, v); },
           "(N, 3, 3) float64 per-point covariances: a read-only zero-copy view (a read-only copy when some "
           "matrix is not symmetric); assign an (N, 3, 3) array or Matrix3dVector to replace them.")
        .def("has_covariances",
             [](const PyPointCloud& self) {
                 int32_t v = 0;
                 with_const(self.h, [&](const o3d_pointcloud_t* pc) { return o3d_pointcloud_has_array(&v, pc, O3D_POINTCLOUD_COVARIANCES); });
                 return v != 0;
             })
        .def(
            "estimate_covariances",
            [](py::object self, py::handle search_param) {
                o3d_search_param_t p = to_search_param(search_param);
                with_mut(self.cast<PyPointCloud&>().for_resize(),
                         [&](o3d_pointcloud_t* pc) { return o3d_pointcloud_estimate_covariances(pc, &p); });
            },
            py::arg("search_param") = py::none(),
            "Covariance of each point's neighbourhood (default KDTreeSearchParamKNN(30)).")
        .def("_covariances_copy", [](const PyPointCloud& self) { return covariance_copy(self); },
            "Copy of the covariances (N, 3, 3), not a view.");
}

}  // namespace o3dpy
