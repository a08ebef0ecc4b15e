// SPDX-License-Identifier: MIT
// o3d.geometry.VoxelGrid over o3d_voxelgrid_t (voxelgrid.h). get_voxels() (a list of o3d.geometry.Voxel)
// is completed in o3d/geometry.py from _get_voxel_arrays(), create_from_octree (static or in place) from
// _create_from_octree() and _assign(). No numpy view points into a grid (every array is copied out), so the
// editing calls (add_voxel, remove_voxel, carving) just take the handle's exclusive lock.
#include <array>
#include <vector>

#include "generated/voxelgrid_methods.h"

namespace o3dpy {
namespace {

/// A grid index (i, j, k) from any 3 integers (InvalidArgumentError naming `what` otherwise).
std::array<int32_t, 3> index3(py::handle obj, const char* what) {
    auto a = as_int32(as_numeric(obj, what), what);
    if (a.size() != 3) invalid(std::string(what) + ": expected 3 integers, got " + std::to_string(a.size()));
    return {a.data()[0], a.data()[1], a.data()[2]};
}

/// carve_depth_map / carve_silhouette: the image shared-locked, the grid exclusively; returns the grid (Open3D).
py::object carve(py::object self_, const PyImage& image, const PyCameraParameters& camera, bool keep,
                 o3d_status (*fn)(o3d_voxelgrid_t*, const o3d_image_t*, const o3d_pinhole_intrinsic_t*, const double*,
                                  o3d_bool)) {
    auto& self = self_.cast<PyVoxelGrid&>();
    const auto img = image.h;
    const PyCameraParameters cam = camera;
    locked_mut(self.h, [&](o3d_voxelgrid_t* g) {
        std::shared_lock<std::shared_mutex> lock(img->mutex);
        return fn(g, img->p, &cam.intrinsic.v, cam.extrinsic.data(), keep ? 1 : 0);
    });
    return self_;
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
            py::arg("queries"), "For each (N, 3) query point, whether its cell is occupied (list of bool).")
        .def(py::init([] {
                 o3d_voxelgrid_t* raw = nullptr;
                 const double zero[3] = {0, 0, 0};
                 check(o3d_voxelgrid_create_dense(&raw, zero, zero, 1.0, 0, 0, 0));
                 return PyVoxelGrid(raw);
             }),
             "An empty grid (origin (0, 0, 0), voxel_size 1; Open3D's has 0), to fill with add_voxel or "
             "create_from_octree.")
        .def(
            "_assign",
            [](PyVoxelGrid& self, const PyVoxelGrid& other) {
                if (self.h == other.h) return;
                const auto src = other.h;
                locked_mut(self.h, [&](o3d_voxelgrid_t*) {
                    std::unique_lock<std::shared_mutex> lock(src->mutex);
                    std::swap(self.h->p, src->p);
                    return O3D_OK;
                });
            },
            py::arg("other"), "Swap contents with other (create_from_octree in place; other is a fresh result).")
        .def(
            "add_voxel",
            [](PyVoxelGrid& self, py::handle voxel) {
                if (!py::hasattr(voxel, "grid_index") || !py::hasattr(voxel, "color"))
                    throw py::type_error("add_voxel: expected an o3d.geometry.Voxel");
                const auto idx = index3(voxel.attr("grid_index"), "voxel.grid_index");
                const auto color = as_vec3(voxel.attr("color"), "voxel.color");
                locked_mut(self.h, [&](o3d_voxelgrid_t* g) { return o3d_voxelgrid_add_voxel(g, idx.data(), color.data()); });
            },
            py::arg("voxel"), "Add an o3d.geometry.Voxel (grid_index, color), replacing the voxel at its index.")
        .def(
            "remove_voxel",
            [](PyVoxelGrid& self, py::handle idx) {
                const auto i = index3(idx, "idx");
                locked_mut(self.h, [&](o3d_voxelgrid_t* g) { return o3d_voxelgrid_remove_voxel(g, i.data()); });
            },
            py::arg("idx"), "Remove the voxel at grid index idx (nothing when there is none).")
        .def(
            "get_voxel_center_coordinate",
            [](const PyVoxelGrid& self, py::handle idx) {
                const auto i = index3(idx, "idx");
                double out[3];
                locked_const(self.h, [&](const o3d_voxelgrid_t* g) {
                    return o3d_voxelgrid_get_voxel_center_coordinate(out, g, i.data());
                });
                return vec3_to_array(out);
            },
            py::arg("idx"),
            "Centre of cell idx, occupied or not (Open3D answers (0, 0, 0) for an unoccupied one): origin + "
            "(idx + 0.5) * voxel_size.")
        .def(
            "get_voxel_bounding_points",
            [](const PyVoxelGrid& self, py::handle index) {
                const auto i = index3(index, "index");
                double out[24];
                locked_const(self.h, [&](const o3d_voxelgrid_t* g) {
                    return o3d_voxelgrid_get_voxel_bounding_points(out, g, i.data());
                });
                return py::module_::import("o3d.utility").attr("Vector3dVector")(mat_to_array(out, 8, 3));
            },
            py::arg("index"), "The 8 corners of cell index (Vector3dVector), in Open3D's order.")
        .def(
            "carve_depth_map",
            [](py::object self, const PyImage& depth_map, const PyCameraParameters& camera_params, bool keep) {
                return carve(std::move(self), depth_map, camera_params, keep, &o3d_voxelgrid_carve_depth_map);
            },
            py::arg("depth_map"), py::arg("camera_params"), py::arg("keep_voxels_outside_image") = false,
            "Space carving with a 1-channel float32 depth map (metres) seen by camera_params "
            "(PinholeCameraParameters, rigid extrinsic): a voxel stays when a corner projected inside the image "
            "lies on or behind the observed depth, or, with keep_voxels_outside_image, when a corner falls outside "
            "the image. Returns self.")
        .def(
            "carve_silhouette",
            [](py::object self, const PyImage& silhouette_mask, const PyCameraParameters& camera_params, bool keep) {
                return carve(std::move(self), silhouette_mask, camera_params, keep, &o3d_voxelgrid_carve_silhouette);
            },
            py::arg("silhouette_mask"), py::arg("camera_params"), py::arg("keep_voxels_outside_image") = false,
            "Space carving with a 1-channel float32 mask seen by camera_params (PinholeCameraParameters, rigid "
            "extrinsic): a voxel stays when a corner projected inside the image falls on the mask (value > 0), or, "
            "with keep_voxels_outside_image, when a corner falls outside the image. Returns self.");
}

}  // namespace o3dpy
