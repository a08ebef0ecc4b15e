// SPDX-License-Identifier: MIT
// o3d.geometry.PointCloud over o3d_pointcloud_t (pointcloud.h).
#include <limits>

#include "generated/pointcloud_methods.h"

namespace o3dpy {

PyPointCloud::PyPointCloud() : Geom(nullptr) { check(o3d_pointcloud_create(&h->p)); }

size_t PyPointCloud::size() const {
    size_t n = 0;
    locked_const(h, [&](const o3d_pointcloud_t* pc) { return o3d_pointcloud_size(&n, pc); });
    return n;
}

namespace {

template <typename F>
PyPointCloud derive(const CloudPtr& h, F&& f) {
    o3d_pointcloud_t* out = nullptr;
    locked_const(h, [&](const o3d_pointcloud_t* pc) { return f(&out, pc); });
    return PyPointCloud(adopt(out));
}

PyPointCloud& cloud(py::handle self) { return self.cast<PyPointCloud&>(); }

template <typename F>
py::array distances(const CloudPtr& h, F&& f) {
    std::vector<double> out;
    locked_const(h, [&](const o3d_pointcloud_t* pc) {
        size_t n = 0;
        o3d_status s = o3d_pointcloud_size(&n, pc);
        if (s != O3D_OK) return s;
        out.resize(n);
        size_t got = 0;
        s = f(pc, out.data(), out.size(), &got);
        out.resize(std::min(got, out.size()));
        return s;
    });
    py::array_t<double> arr((py::ssize_t)out.size());
    if (!out.empty()) std::memcpy(arr.mutable_data(), out.data(), out.size() * sizeof(double));
    return std::move(arr);
}

}  // namespace

void declare_pointcloud(py::module_& m) {
    py::class_<PyPointCloud>(m, "PointCloud",
                             "A point cloud: points, optional normals and colors ((N, 3) float64, colors in [0, 1]).\n\n"
                             "``np.asarray(pcd.points)`` is a writable zero-copy view of the cloud's memory. Calls "
                             "that resize an array (setting points, clear, +=, remove_non_finite_points, "
                             "estimate_normals, paint_uniform_color) first give the cloud a private copy when such "
                             "views are alive, so an old view never dangles (it keeps the old data).");
}

void define_pointcloud(py::module_& m) {
    auto cls = static_cast<py::class_<PyPointCloud>>(m.attr("PointCloud"));
    cls.def(py::init<>(), "An empty cloud.")
        .def(py::init([](const PyPointCloud& other) {
                 return derive(other.h, [](o3d_pointcloud_t** out, const o3d_pointcloud_t* pc) {
                     return o3d_pointcloud_clone(out, pc);
                 });
             }),
             py::arg("cloud"), "Deep copy of another cloud.")
        .def(py::init([](py::handle points) {
                 PyPointCloud pc;
                 array_set(pc, O3D_POINTCLOUD_POINTS, points, "points");
                 return pc;
             }),
             py::arg("points"), "A cloud with these (N, 3) points (float64 or float32).")
        .def("__copy__", [](const PyPointCloud& self) {
            return derive(self.h, [](o3d_pointcloud_t** out, const o3d_pointcloud_t* pc) { return o3d_pointcloud_clone(out, pc); });
        })
        .def("__deepcopy__", [](const PyPointCloud& self, py::handle) {
            return derive(self.h, [](o3d_pointcloud_t** out, const o3d_pointcloud_t* pc) { return o3d_pointcloud_clone(out, pc); });
        })
        .def("is_empty", [](const PyPointCloud& self) { return !array_has<o3d_pointcloud_t>(self.h, O3D_POINTCLOUD_POINTS); })
        .def("__len__", &PyPointCloud::size)
        .def("__repr__", [](const PyPointCloud& self) {
            return "PointCloud with " + std::to_string(self.size()) + " points.";
        })
        .def(
            "__iadd__",
            [](py::object self, const PyPointCloud& other) {
                CloudPtr src = other.h;
                PyPointCloud& me = cloud(self);
                if (src == me.h) {  // pcd += pcd: append a snapshot of itself
                    o3d_pointcloud_t* copy = nullptr;
                    locked_const(src, [&](const o3d_pointcloud_t* pc) { return o3d_pointcloud_clone(&copy, pc); });
                    src = adopt(copy);
                }
                CloudPtr dst = me.for_resize();
                o3d_status s;
                {
                    py::gil_scoped_release release;
                    std::unique_lock<std::shared_mutex> l1(dst->mutex, std::defer_lock);
                    std::shared_lock<std::shared_mutex> l2(src->mutex, std::defer_lock);
                    std::lock(l1, l2);
                    s = o3d_pointcloud_append(dst->p, src->p);
                }
                check(s);
                return self;
            },
            py::arg("cloud"))
        .def(
            "__add__",
            [](const PyPointCloud& self, const PyPointCloud& other) {
                PyPointCloud out = derive(self.h, [](o3d_pointcloud_t** o, const o3d_pointcloud_t* pc) {
                    return o3d_pointcloud_clone(o, pc);
                });
                CloudPtr src = other.h;
                o3d_status s;
                {
                    py::gil_scoped_release release;
                    std::shared_lock<std::shared_mutex> l2(src->mutex);
                    s = o3d_pointcloud_append(out.h->p, src->p);
                }
                check(s);
                return out;
            },
            py::arg("cloud"))
        .def(
            "select_by_index",
            [](const PyPointCloud& self, py::handle indices, bool invert) {
                std::vector<int32_t> idx = int32_indices(indices, "indices");
                return derive(self.h, [&](o3d_pointcloud_t** out, const o3d_pointcloud_t* pc) {
                    return o3d_pointcloud_select_by_index(out, pc, idx.data(), idx.size(), invert ? 1 : 0);
                });
            },
            py::arg("indices"), py::arg("invert") = false,
            "New cloud with the points at indices (invert=True: all the others). Out-of-range indices raise ValueError.")
        .def(
            "estimate_normals",
            [](py::object self, py::handle search_param, bool /*fast_normal_computation*/, int32_t num_threads) {
                o3d_search_param_t p = to_search_param(search_param);
                locked_mut(cloud(self).for_resize(),
                         [&](o3d_pointcloud_t* pc) { return o3d_pointcloud_estimate_normals(pc, &p, num_threads); });
            },
            py::arg("search_param") = py::none(), py::arg("fast_normal_computation") = true, py::arg("num_threads") = 0,
            "PCA normals over each point's neighbourhood (default KDTreeSearchParamKNN(30)). Existing normals "
            "orient the new ones. fast_normal_computation is accepted for Open3D compatibility.")
        .def(
            "compute_nearest_neighbor_distance",
            [](const PyPointCloud& self, int32_t num_threads) {
                return distances(self.h, [&](const o3d_pointcloud_t* pc, double* out, size_t cap, size_t* n) {
                    return o3d_pointcloud_compute_nearest_neighbor_distance(out, cap, n, pc, num_threads);
                });
            },
            py::arg("num_threads") = 0, "Distance from each point to its nearest other point, (N,) float64.")
        .def(
            "compute_point_cloud_distance",
            [](const PyPointCloud& self, const PyPointCloud& target, int32_t num_threads) {
                CloudPtr t = target.h;
                return distances(self.h, [&](const o3d_pointcloud_t* pc, double* out, size_t cap, size_t* n) {
                    std::shared_lock<std::shared_mutex> lock(t->mutex, std::defer_lock);
                    if (t != self.h) lock.lock();
                    return o3d_pointcloud_compute_point_cloud_distance(out, cap, n, pc, t->p, num_threads);
                });
            },
            py::arg("target"), py::arg("num_threads") = 0,
            "For each point, the distance to the closest point of target, (N,) float64.");
    def_array(cls, "points", O3D_POINTCLOUD_POINTS,
              "(N, 3) float64 writable view; assign any (N, 3) float64/float32 array or Vector3dVector.");
    def_array(cls, "normals", O3D_POINTCLOUD_NORMALS, "(N, 3) normals (view).");
    def_array(cls, "colors", O3D_POINTCLOUD_COLORS, "(N, 3) RGB colors in [0, 1] (view).");
    def_array(cls, "covariances", O3D_POINTCLOUD_COVARIANCES,
              "(N, 3, 3) float64 per-point covariances: a read-only zero-copy view; assign an (N, 3, 3) array or "
              "Matrix3dVector to replace them (each must be symmetric).", true);
    def_has(cls, "has_points", O3D_POINTCLOUD_POINTS);
    def_has(cls, "has_normals", O3D_POINTCLOUD_NORMALS);
    def_has(cls, "has_colors", O3D_POINTCLOUD_COLORS);
    def_has(cls, "has_covariances", O3D_POINTCLOUD_COVARIANCES);
    def_array_access(cls);
    def_point_cloud_methods(cls);
    def_aabb(cls, &o3d_pointcloud_get_axis_aligned_bounding_box);
    cls.def(
        "estimate_covariances",
        [](PyPointCloud& self, py::handle search_param) {
            o3d_search_param_t p = to_search_param(search_param);
            locked_mut(self.for_resize(), [&](o3d_pointcloud_t* pc) { return o3d_pointcloud_estimate_covariances(pc, &p); });
        },
        py::arg("search_param") = py::none(), "Covariance of each point's neighbourhood (default KDTreeSearchParamKNN(30)).");
}

}  // namespace o3dpy
