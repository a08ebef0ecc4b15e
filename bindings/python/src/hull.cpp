// SPDX-License-Identifier: MIT
// Convex hulls and hidden-point removal (hull.h): each returns (TriangleMesh, list of the input point
// index of every mesh vertex), as Open3D's compute_convex_hull / hidden_point_removal.
#include <vector>

#include "geometry_types.h"

namespace o3dpy {
namespace {

/// Run a hull-like C call whose index output never exceeds `capacity_of(input)` values.
template <typename F>
py::tuple mesh_and_indices(size_t capacity, F&& f) {
    o3d_trianglemesh_t* out = nullptr;
    std::vector<int32_t> idx(capacity);
    size_t n = 0;
    f(&out, idx.data(), idx.size(), &n);
    PyTriangleMesh mesh(out);
    return py::make_tuple(std::move(mesh), int_list(idx.data(), std::min(n, idx.size())));
}

}  // namespace

void define_hull(py::module_& m) {
    auto pcd = static_cast<py::class_<PyPointCloud>>(m.attr("PointCloud"));
    pcd.def(
           "compute_convex_hull",
           [](const PyPointCloud& self, bool joggle_inputs) {
               return mesh_and_indices(self.size(), [&](o3d_trianglemesh_t** out, int32_t* idx, size_t cap, size_t* n) {
                   locked_const(self.h, [&](const o3d_pointcloud_t* pc) {
                       return o3d_pointcloud_compute_convex_hull(out, idx, cap, n, pc, joggle_inputs ? 1 : 0);
                   });
               });
           },
           py::arg("joggle_inputs") = false,
           "Convex hull (Qhull): (TriangleMesh with outward triangles, list of the point index of each hull "
           "vertex). joggle_inputs=True perturbs the input so degenerate (e.g. planar) sets still give a hull.")
        .def(
            "hidden_point_removal",
            [](const PyPointCloud& self, py::handle camera_location, double radius) {
                auto cam = as_vec3(camera_location, "camera_location");
                return mesh_and_indices(self.size(), [&](o3d_trianglemesh_t** out, int32_t* idx, size_t cap, size_t* n) {
                    locked_const(self.h, [&](const o3d_pointcloud_t* pc) {
                        return o3d_pointcloud_hidden_point_removal(out, idx, cap, n, pc, cam.data(), radius);
                    });
                });
            },
            py::arg("camera_location"), py::arg("radius"),
            "Points visible from camera_location (Katz et al. 2007; larger radius keeps more): (TriangleMesh, "
            "list of visible point indices).");

    auto mesh = static_cast<py::class_<PyTriangleMesh>>(m.attr("TriangleMesh"));
    mesh.def(
        "compute_convex_hull",
        [](const PyTriangleMesh& self, bool joggle_inputs) {
            size_t nv = 0;
            locked_const(self.h, [&](const o3d_trianglemesh_t* me) { return o3d_trianglemesh_num_vertices(&nv, me); });
            return mesh_and_indices(nv, [&](o3d_trianglemesh_t** out, int32_t* idx, size_t cap, size_t* n) {
                locked_const(self.h, [&](const o3d_trianglemesh_t* me) {
                    return o3d_trianglemesh_compute_convex_hull(out, idx, cap, n, me, joggle_inputs ? 1 : 0);
                });
            });
        },
        py::arg("joggle_inputs") = false,
        "Convex hull of the vertices: (TriangleMesh, list of the vertex index of each hull vertex).");
}

}  // namespace o3dpy
