// SPDX-License-Identifier: MIT
// o3d.geometry.TetraMesh over o3d_tetramesh_t (tetramesh.h): vertices and tetras as writable zero-copy views,
// the Delaunay tetrahedralization of a cloud and iso-surfaces of per-vertex values, with Open3D 0.20's names.
#include <limits>
#include <vector>

#include "tetramesh_types.h"

namespace o3dpy {

PyTetraMesh::PyTetraMesh() : Geom(nullptr) { check(o3d_tetramesh_create(&h->p)); }

std::vector<int32_t> int32_values(py::handle obj, const char* what) {
    py::array a = as_numeric(obj, what);
    if (a.size() == 0) return {};
    if (a.ndim() != 1) invalid(std::string(what) + ": expected a 1-D sequence, got shape " + shape_string(a));
    py::array_t<int32_t> v = as_int32(a, what);  // rejects floats and values outside int32
    return std::vector<int32_t>(v.data(), v.data() + v.size());
}

py::array_t<double> double_values(py::handle obj, const char* what) {
    py::array a = as_numeric(obj, what);
    if (a.size() != 0 && a.ndim() != 1)
        invalid(std::string(what) + ": expected a 1-D sequence, got shape " + shape_string(a));
    auto d = py::array_t<double, py::array::c_style | py::array::forcecast>::ensure(a);
    if (!d) throw py::error_already_set();
    return d;
}

namespace {

size_t count(const PyTetraMesh& self, o3d_status (*fn)(size_t*, const o3d_tetramesh_t*)) {
    size_t n = 0;
    locked_const(self.h, [&](const o3d_tetramesh_t* t) { return fn(&n, t); });
    return n;
}

PyTetraMesh clone_of(const PyTetraMesh& self) {
    o3d_tetramesh_t* out = nullptr;
    locked_const(self.h, [&](const o3d_tetramesh_t* t) { return o3d_tetramesh_clone(&out, t); });
    return PyTetraMesh(out);
}

/// (TetraMesh, list of the input point index of each vertex), as Open3D's create_from_point_cloud.
py::tuple from_point_cloud(const PyPointCloud& cloud) {
    o3d_tetramesh_t* out = nullptr;
    std::vector<int32_t> map(cloud.size());  // one vertex per distinct input point at most
    size_t n = 0;
    locked_const(cloud.h, [&](const o3d_pointcloud_t* pc) {
        return o3d_tetramesh_create_from_point_cloud(&out, map.data(), map.size(), &n, pc);
    });
    PyTetraMesh mesh(out);
    return py::make_tuple(std::move(mesh), int_list(map.data(), std::min(n, map.size())));
}

PyTriangleMesh extract_triangle_mesh(const PyTetraMesh& self, py::handle values, double level) {
    py::array_t<double> v = double_values(values, "values");
    o3d_trianglemesh_t* out = nullptr;
    locked_const(self.h, [&](const o3d_tetramesh_t* t) {
        return o3d_tetramesh_extract_triangle_mesh(&out, t, v.size() ? v.data() : nullptr, (size_t)v.size(), level);
    });
    return PyTriangleMesh(out);
}

}  // namespace

void declare_tetramesh(py::module_& m) {
    py::class_<PyTetraMesh>(m, "TetraMesh",
                            "A tetrahedral mesh: vertices (N, 3) float64 and tetras (M, 4) int32 vertex indices.\n\n"
                            "``np.asarray(mesh.vertices)`` and ``mesh.tetras`` are writable zero-copy views; "
                            "assigning an array replaces them (live views keep the old data).");
}

void define_tetramesh(py::module_& m) {
    auto cls = static_cast<py::class_<PyTetraMesh>>(m.attr("TetraMesh"));
    cls.def(py::init<>(), "An empty tetra mesh.")
        .def(py::init([](const PyTetraMesh& other) { return clone_of(other); }), py::arg("mesh"), "Deep copy.")
        .def(py::init([](py::handle vertices, py::handle tetras) {
                 PyTetraMesh mesh;
                 array_set(mesh, O3D_TETRAMESH_VERTICES, vertices, "vertices");
                 array_set(mesh, O3D_TETRAMESH_TETRAS, tetras, "tetras");
                 return mesh;
             }),
             py::arg("vertices"), py::arg("tetras"), "A tetra mesh with these (N, 3) vertices and (M, 4) tetras.")
        .def("__copy__", [](const PyTetraMesh& self) { return clone_of(self); })
        .def("__deepcopy__", [](const PyTetraMesh& self, py::handle) { return clone_of(self); })
        .def("has_vertices", [](const PyTetraMesh& self) { return count(self, &o3d_tetramesh_num_vertices) > 0; })
        .def("has_tetras",
             [](const PyTetraMesh& self) {
                 return count(self, &o3d_tetramesh_num_vertices) > 0 && count(self, &o3d_tetramesh_num_tetras) > 0;
             })
        .def("is_empty", [](const PyTetraMesh& self) { return count(self, &o3d_tetramesh_num_vertices) == 0; })
        .def(
            "clear",
            [](py::object self) {
                // No C clear: emptying both arrays is the same (copy-on-write keeps live views valid).
                auto& mesh = self.cast<PyTetraMesh&>();
                array_set(mesh, O3D_TETRAMESH_TETRAS, py::array_t<int32_t>(std::vector<py::ssize_t>{0, 4}), "tetras");
                array_set(mesh, O3D_TETRAMESH_VERTICES, py::array_t<double>(std::vector<py::ssize_t>{0, 3}), "vertices");
                return self;
            },
            "Remove the vertices and tetras. Returns self.")
        .def("__repr__",
             [](const PyTetraMesh& self) {
                 return "TetraMesh with " + std::to_string(count(self, &o3d_tetramesh_num_vertices)) + " points and " +
                        std::to_string(count(self, &o3d_tetramesh_num_tetras)) + " tetrahedra.";
             })
        .def_static("create_from_point_cloud", &from_point_cloud, py::arg("point_cloud"),
                    "The Delaunay tetrahedralization of the cloud's points (Qhull): (TetraMesh, list of the input "
                    "point index of each vertex). Raises on fewer than 4 points or a flat set.")
        .def("extract_triangle_mesh", &extract_triangle_mesh, py::arg("values"), py::arg("level"),
             "The triangle mesh of the iso-surface values == level of one value per vertex (DoubleVector, list or "
             "array), linear on each tetrahedron (marching tetrahedra).");
    def_array(cls, "vertices", O3D_TETRAMESH_VERTICES, "(N, 3) float64 view.");
    def_array(cls, "tetras", O3D_TETRAMESH_TETRAS, "(M, 4) int32 view of vertex indices.");
    def_array_access(cls);
}

}  // namespace o3dpy
