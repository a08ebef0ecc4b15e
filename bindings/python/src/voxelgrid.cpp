// SPDX-License-Identifier: MIT
// o3d.geometry.VoxelGrid over o3d_voxelgrid_t (voxelgrid.h). get_voxels() (a list of o3d.geometry.Voxel)
// is completed in o3d/geometry.py from _get_voxel_arrays().
#include <vector>

#include "generated/voxelgrid_methods.h"

namespace o3dpy {
namespace {

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
    def_voxel_grid_methods(cls);
    cls.def("has_voxels",
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
