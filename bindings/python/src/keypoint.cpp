// SPDX-License-Identifier: MIT
// o3d.geometry.keypoint.compute_iss_keypoints over o3d_pointcloud_compute_iss_keypoints (pointcloud.h), with
// Open3D 0.20's keywords; the defaults come from o3d_iss_options_init. o3d/geometry.py shows it in the
// o3d.geometry.keypoint module.
#include <vector>

#include "geometry_types.h"

namespace o3dpy {

void define_keypoint(py::module_& m) {
    const o3d_iss_options_t d = init_of(&o3d_iss_options_init);
    m.def(
        "compute_iss_keypoints",
        [](const PyPointCloud& input, double salient_radius, double non_max_radius, double gamma_21, double gamma_32,
           int64_t min_neighbors, int64_t num_threads) {
            o3d_iss_options_t o = init_of(&o3d_iss_options_init);
            o.salient_radius = salient_radius;
            o.non_max_radius = non_max_radius;
            o.gamma_21 = gamma_21;
            o.gamma_32 = gamma_32;
            o.min_neighbors = int32_of(min_neighbors, "min_neighbors");
            o.num_threads = int32_of(num_threads, "num_threads");
            o3d_pointcloud_t* out = nullptr;
            size_t n = 0;
            locked_const(input.h, [&](const o3d_pointcloud_t* pc) {
                // Open3D returns only the cloud: the index buffer is skipped (NULL).
                return o3d_pointcloud_compute_iss_keypoints(&out, nullptr, 0, &n, pc, &o);
            });
            return PyPointCloud(adopt(out));
        },
        py::arg("input"), py::arg("salient_radius") = d.salient_radius, py::arg("non_max_radius") = d.non_max_radius,
        py::arg("gamma_21") = d.gamma_21, py::arg("gamma_32") = d.gamma_32, py::arg("min_neighbors") = d.min_neighbors,
        py::kw_only(), py::arg("num_threads") = d.num_threads,
        "Intrinsic Shape Signature keypoints (Zhong 2009) of `input`, as a PointCloud (with their normals and "
        "colors). A radius of 0 is derived from the cloud's resolution (salient 6x, non-max 4x). o3d extra "
        "(keyword-only): num_threads (0 = default; never changes the result).");
}

}  // namespace o3dpy
