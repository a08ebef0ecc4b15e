// SPDX-License-Identifier: MIT
// o3d.geometry.VoxelGrid over o3d_voxelgrid_t (voxelgrid.h). get_voxels() (a list of o3d.geometry.Voxel)
// is completed in o3d/geometry.py from _get_voxel_arrays().
#include <vector>

#include "geometry_types.h"

namespace o3dpy {
namespace {

template <typename F>
PyVoxelGrid make(F&& f) {
    o3d_voxelgrid_t* out = nullptr;
    f(&out);
    return PyVoxelGrid(out);
}

size_t num_voxels(const PyVoxelGrid& self) {
    size_t n = 0;
    locked_const(self.h, [&](const o3d_voxelgrid_t* g) { return o3d_voxelgrid_num_voxels(&n, g); });
    return n;
}

}  // namespace

void declare_voxelgrid(py::module_& m) {
    py::class_<PyVoxelGrid>(m, "VoxelGrid",
                            "Sparse occupied voxels of edge voxel_size on a grid whose cell (0, 0, 0) starts at "
                            "origin. Voxels come sorted by grid index (x, then y, then z).");
}

void define_voxelgrid(py::module_& m) {
    auto cls = static_cast<py::class_<PyVoxelGrid>>(m.attr("VoxelGrid"));
    cls.def_static(
           "create_from_point_cloud",
           [](const PyPointCloud& input, double voxel_size) {
               return make([&](o3d_voxelgrid_t** out) {
                   locked_const(input.h, [&](const o3d_pointcloud_t* pc) {
                       return o3d_voxelgrid_create_from_point_cloud(out, pc, voxel_size);
                   });
               });
           },
           py::arg("input"), py::arg("voxel_size"),
           "Voxels holding at least one point; origin = min bound - voxel_size / 2; colors are the mean point color.")
        .def_static(
            "create_from_point_cloud_within_bounds",
            [](const PyPointCloud& input, double voxel_size, py::handle min_bound, py::handle max_bound) {
                auto lo = as_vec3(min_bound, "min_bound");
                auto hi = as_vec3(max_bound, "max_bound");
                return make([&](o3d_voxelgrid_t** out) {
                    locked_const(input.h, [&](const o3d_pointcloud_t* pc) {
                        return o3d_voxelgrid_create_from_point_cloud_within_bounds(out, pc, voxel_size, lo.data(),
                                                                                   hi.data());
                    });
                });
            },
            py::arg("input"), py::arg("voxel_size"), py::arg("min_bound"), py::arg("max_bound"),
            "As create_from_point_cloud on the grid starting at min_bound; points outside the bounds are ignored.")
        .def_static(
            "create_from_triangle_mesh",
            [](const PyTriangleMesh& input, double voxel_size) {
                return make([&](o3d_voxelgrid_t** out) {
                    locked_const(input.h, [&](const o3d_trianglemesh_t* me) {
                        return o3d_voxelgrid_create_from_triangle_mesh(out, me, voxel_size);
                    });
                });
            },
            py::arg("input"), py::arg("voxel_size"), "Voxels intersecting at least one triangle.")
        .def_property_readonly("voxel_size",
                               [](const PyVoxelGrid& self) {
                                   double v = 0;
                                   locked_const(self.h, [&](const o3d_voxelgrid_t* g) {
                                       return o3d_voxelgrid_get_voxel_size(&v, g);
                                   });
                                   return v;
                               })
        .def_property_readonly("origin",
                               [](const PyVoxelGrid& self) {
                                   double o[3];
                                   locked_const(self.h, [&](const o3d_voxelgrid_t* g) { return o3d_voxelgrid_get_origin(o, g); });
                                   return vec3_to_array(o);
                               })
        .def("has_voxels",
             [](const PyVoxelGrid& self) {
                 int32_t has = 0;
                 locked_const(self.h, [&](const o3d_voxelgrid_t* g) {
                     return o3d_voxelgrid_has_array(&has, g, O3D_VOXELGRID_GRID_INDEX);
                 });
                 return has != 0;
             })
        .def("has_colors", [](const PyVoxelGrid&) { return true; },
             "Always True, as Open3D (every voxel has a color; black when the input had none).")
        .def("is_empty", [](const PyVoxelGrid& self) { return num_voxels(self) == 0; })
        .def("__len__", [](const PyVoxelGrid& self) { return num_voxels(self); })
        .def("__repr__",
             [](const PyVoxelGrid& self) { return "VoxelGrid with " + std::to_string(num_voxels(self)) + " voxels."; })
        .def(
            "_get_voxel_arrays",
            [](const PyVoxelGrid& self) {
                size_t n = 0, cols = 0, got = 0;
                locked_const(self.h, [&](const o3d_voxelgrid_t* g) {
                    return o3d_voxelgrid_array_shape(&n, &cols, g, O3D_VOXELGRID_GRID_INDEX);
                });
                py::array_t<int32_t> gi(std::vector<py::ssize_t>{(py::ssize_t)n, 3});
                py::array_t<double> co(std::vector<py::ssize_t>{(py::ssize_t)n, 3});
                locked_const(self.h, [&](const o3d_voxelgrid_t* g) {
                    o3d_status s = o3d_voxelgrid_get_index_array(gi.mutable_data(), n, &got, g, O3D_VOXELGRID_GRID_INDEX);
                    return s != O3D_OK ? s : o3d_voxelgrid_get_array(co.mutable_data(), n, &got, g, O3D_VOXELGRID_COLORS);
                });
                return py::make_tuple(gi, co);
            },
            "(grid_index (N, 3) int32, colors (N, 3) float64), sorted by grid index.")
        .def(
            "get_voxel",
            [](const PyVoxelGrid& self, py::handle point) {
                auto p = as_vec3(point, "point");
                py::array_t<int32_t> out(3);
                int32_t idx[3];
                locked_const(self.h, [&](const o3d_voxelgrid_t* g) { return o3d_voxelgrid_get_voxel(idx, g, p.data()); });
                std::memcpy(out.mutable_data(), idx, sizeof(idx));
                return out;
            },
            py::arg("point"), "Grid index (int32 (3,)) of the cell containing point, occupied or not.")
        .def(
            "check_if_included",
            [](const PyVoxelGrid& self, py::handle queries) {
                auto xyz = rows3_f64(queries, "queries");
                const size_t n = (size_t)xyz.shape(0);
                std::vector<int32_t> inc(n);
                size_t got = 0;
                locked_const(self.h, [&](const o3d_voxelgrid_t* g) {
                    return o3d_voxelgrid_check_if_included(inc.data(), n, &got, g, n ? xyz.data() : nullptr, n);
                });
                py::list out(n);
                for (size_t i = 0; i < n; ++i) out[i] = py::bool_(inc[i] != 0);
                return out;
            },
            py::arg("queries"), "For each (N, 3) query point, whether its cell is occupied (list of bool).");
}

}  // namespace o3dpy
