// SPDX-License-Identifier: MIT
// o3d.geometry.PointCloud tools (Open3D 0.20 names): outlier removal, crop, RANSAC plane, DBSCAN,
// mean/covariance, Mahalanobis distance. Over the point-cloud tools of pointcloud.h; every C call runs
// with the GIL released under the cloud's shared lock.
#include <limits>
#include <random>
#include <vector>

#include "geometry_types.h"

namespace o3dpy {
namespace {

size_t count_of(const o3d_pointcloud_t* pc) {
    size_t n = 0;
    o3d_pointcloud_size(&n, pc);
    return n;
}

/// Kept / inlier indices as a Python list of int (what Open3D returns for std::vector<size_t>).
py::list index_list(const std::vector<int32_t>& idx, size_t n) {
    py::list out(n);
    for (size_t i = 0; i < n; ++i) out[i] = py::int_(idx[i]);
    return out;
}

py::array_t<double> vec_array(const double* v, size_t n) {
    py::array_t<double> out((py::ssize_t)n);
    if (n) std::memcpy(out.mutable_data(), v, n * sizeof(double));
    return out;
}


uint64_t seed_of(py::handle seed) {
    if (seed.is_none()) {  // Open3D: a fresh random draw unless seeded
        std::random_device rd;
        return ((uint64_t)rd() << 32) ^ rd();
    }
    if (!PyLong_Check(seed.ptr()) && !PyIndex_Check(seed.ptr())) invalid("seed: expected an integer or None");
    py::int_ i = py::reinterpret_borrow<py::object>(seed);
    return (uint64_t)PyLong_AsUnsignedLongLongMask(i.ptr());
}

/// Shared body of the two outlier filters: (kept cloud, kept indices).
template <typename F>
py::tuple outlier_filter(const PyPointCloud& self, F&& f) {
    o3d_pointcloud_t* out = nullptr;
    std::vector<int32_t> idx;
    size_t n = 0;
    locked_const(self.h, [&](const o3d_pointcloud_t* pc) {
        idx.resize(count_of(pc));  // the kept count never exceeds the cloud's size
        return f(&out, pc, idx.data(), idx.size(), &n);
    });
    PyPointCloud kept(adopt(out));
    return py::make_tuple(std::move(kept), index_list(idx, n));
}

/// Read (min_bound, max_bound) of an AxisAlignedBoundingBox (or anything with get_min_bound/get_max_bound).
std::pair<std::array<double, 3>, std::array<double, 3>> box_bounds(py::handle box) {
    if (box.is_none() || !py::hasattr(box, "get_min_bound") || !py::hasattr(box, "get_max_bound"))
        throw py::type_error("crop: bounding_box must be an o3d.geometry.AxisAlignedBoundingBox or OrientedBoundingBox, got " +
                             std::string(py::str(py::type::handle_of(box).attr("__name__"))));
    auto lo = as_vec3(box.attr("get_min_bound")(), "bounding_box.min_bound");
    auto hi = as_vec3(box.attr("get_max_bound")(), "bounding_box.max_bound");
    return {lo, hi};
}

}  // namespace

void define_pointcloud_tools(py::module_& m) {
    auto cls = static_cast<py::class_<PyPointCloud>>(m.attr("PointCloud"));
    cls.def(
           "remove_statistical_outlier",
           [](const PyPointCloud& self, int64_t nb_neighbors, double std_ratio, bool /*print_progress*/) {
               const int32_t k = int32_of(nb_neighbors, "nb_neighbors");
               return outlier_filter(self, [&](o3d_pointcloud_t** out, const o3d_pointcloud_t* pc, int32_t* idx,
                                               size_t cap, size_t* n) {
                   return o3d_pointcloud_remove_statistical_outlier(out, idx, cap, n, pc, k, std_ratio);
               });
           },
           py::arg("nb_neighbors"), py::arg("std_ratio"), py::arg("print_progress") = false,
           "Drop points whose mean distance to their nb_neighbors nearest points is above the cloud's mean of "
           "that distance + std_ratio standard deviations. Returns (kept cloud, list of kept indices, ascending). "
           "print_progress is accepted for Open3D compatibility.")
        .def(
            "remove_radius_outlier",
            [](const PyPointCloud& self, int64_t nb_points, double radius, bool /*print_progress*/) {
                const int32_t k = int32_of(nb_points, "nb_points");
                return outlier_filter(self, [&](o3d_pointcloud_t** out, const o3d_pointcloud_t* pc, int32_t* idx,
                                                size_t cap, size_t* n) {
                    return o3d_pointcloud_remove_radius_outlier(out, idx, cap, n, pc, k, radius);
                });
            },
            py::arg("nb_points"), py::arg("radius"), py::arg("print_progress") = false,
            "Keep the points with at least nb_points other points within radius. Returns (kept cloud, list of "
            "kept indices, ascending). print_progress is accepted for Open3D compatibility.")
        .def(
            "crop",
            [](const PyPointCloud& self, py::handle bounding_box, bool invert) {
                o3d_pointcloud_t* out = nullptr;
                if (is_obb(bounding_box)) {
                    o3d_obb_t obb = obb_of(bounding_box);
                    locked_const(self.h, [&](const o3d_pointcloud_t* pc) {
                        return o3d_pointcloud_crop_obb(&out, pc, &obb, invert ? 1 : 0);
                    });
                    return PyPointCloud(adopt(out));
                }
                auto [lo, hi] = box_bounds(bounding_box);
                locked_const(self.h, [&](const o3d_pointcloud_t* pc) {
                    return o3d_pointcloud_crop_aabb(&out, pc, lo.data(), hi.data(), invert ? 1 : 0);
                });
                return PyPointCloud(adopt(out));
            },
            py::arg("bounding_box"), py::arg("invert") = false,
            "New cloud with the points inside the AxisAlignedBoundingBox or OrientedBoundingBox (bounds "
            "inclusive); invert=True keeps "
            "the points outside.")
        .def(
            "segment_plane",
            [](const PyPointCloud& self, double distance_threshold, int64_t ransac_n, int64_t num_iterations,
               double probability, py::handle seed) {
                const int32_t rn = int32_of(ransac_n, "ransac_n");
                const int32_t it = int32_of(num_iterations, "num_iterations");
                const uint64_t s = seed_of(seed);
                std::array<double, 4> plane{};
                std::vector<int32_t> idx;
                size_t n = 0;
                locked_const(self.h, [&](const o3d_pointcloud_t* pc) {
                    idx.resize(count_of(pc));
                    return o3d_pointcloud_segment_plane(plane.data(), idx.data(), idx.size(), &n, pc,
                                                        distance_threshold, rn, it, probability, s);
                });
                return py::make_tuple(vec_array(plane.data(), 4), index_list(idx, n));
            },
            py::arg("distance_threshold"), py::arg("ransac_n") = 3, py::arg("num_iterations") = 100,
            py::arg("probability") = 0.99999999, py::arg("seed") = py::none(),
            "RANSAC plane fit. Returns (plane_model, inliers): plane_model is a (4,) ndarray [a, b, c, d] with "
            "a x + b y + c z + d = 0 and unit (a, b, c); inliers the list of inlier indices (ascending). "
            "seed=None draws a new seed each call (as Open3D); an integer seed gives the same result every time.")
        .def(
            "cluster_dbscan",
            [](const PyPointCloud& self, double eps, int64_t min_points, bool /*print_progress*/) {
                const int32_t mp = int32_of(min_points, "min_points");
                std::vector<int32_t> labels;
                size_t n = 0;
                locked_const(self.h, [&](const o3d_pointcloud_t* pc) {
                    labels.resize(count_of(pc));
                    return o3d_pointcloud_cluster_dbscan(labels.data(), labels.size(), &n, pc, eps, mp);
                });
                py::array_t<int32_t> out((py::ssize_t)n);
                if (n) std::memcpy(out.mutable_data(), labels.data(), n * sizeof(int32_t));
                return out;
            },
            py::arg("eps"), py::arg("min_points"), py::arg("print_progress") = false,
            "DBSCAN clustering: an (N,) int32 array of labels, clusters 0, 1, ... in order of their lowest point "
            "index, -1 for noise. print_progress is accepted for Open3D compatibility.")
        .def(
            "compute_mean_and_covariance",
            [](const PyPointCloud& self) {
                std::array<double, 3> mean{};
                std::array<double, 9> cov{};
                locked_const(self.h, [&](const o3d_pointcloud_t* pc) {
                    return o3d_pointcloud_compute_mean_and_covariance(mean.data(), cov.data(), pc);
                });
                py::array_t<double> c(std::vector<py::ssize_t>{3, 3});
                std::memcpy(c.mutable_data(), cov.data(), sizeof(cov));
                return py::make_tuple(vec_array(mean.data(), 3), std::move(c));
            },
            "(mean (3,), covariance (3, 3)) of the points; the covariance is divided by N "
            "(np.cov(points.T, bias=True)). An empty cloud raises ValueError.")
        .def(
            "compute_mahalanobis_distance",
            [](const PyPointCloud& self) {
                std::vector<double> d;
                size_t n = 0;
                locked_const(self.h, [&](const o3d_pointcloud_t* pc) {
                    d.resize(count_of(pc));
                    return o3d_pointcloud_compute_mahalanobis_distance(d.data(), d.size(), &n, pc);
                });
                return vec_array(d.data(), n);
            },
            "Mahalanobis distance of each point to the cloud's distribution, (N,) float64.");
}

}  // namespace o3dpy
