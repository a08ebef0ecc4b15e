// SPDX-License-Identifier: MIT
// o3d.geometry.HalfEdgeTriangleMesh over o3d_halfedgemesh_t (halfedgemesh.h). A half-edge mesh never changes after
// it is made, so copies share the handle and its arrays come back as read-only numpy copies. Its half_edges (a list
// of o3d.geometry.HalfEdge, pure Python) and bounds are built in o3d/geometry.py from _half_edge_array().
#include "geometry_types.h"

namespace o3dpy {
namespace {

using HalfEdgeMeshHandle = Handle<o3d_halfedgemesh_t, &o3d_halfedgemesh_destroy>;

struct PyHalfEdgeTriangleMesh {
    std::shared_ptr<HalfEdgeMeshHandle> h;
    explicit PyHalfEdgeTriangleMesh(o3d_halfedgemesh_t* raw) : h(std::make_shared<HalfEdgeMeshHandle>(raw)) {}
};

PyHalfEdgeTriangleMesh from_mesh(const PyTriangleMesh& mesh) {
    o3d_halfedgemesh_t* out = nullptr;
    locked_const(mesh.h, [&](const o3d_trianglemesh_t* m) { return o3d_halfedgemesh_create_from_triangle_mesh(&out, m); });
    return PyHalfEdgeTriangleMesh(out);
}

py::array float_rows(const PyHalfEdgeTriangleMesh& self, int32_t which) {
    auto v = read_rows<double>(self.h, 3, 0, [&](double* out, size_t cap, size_t* n, const o3d_halfedgemesh_t* p) {
        return o3d_halfedgemesh_get_array(out, cap, n, p, which);
    });
    return to_numpy(v, {(py::ssize_t)(v.size() / 3), 3}, false);
}

size_t rows_of(const PyHalfEdgeTriangleMesh& self, int32_t which) {
    size_t n = 0;
    locked_const(self.h, [&](const o3d_halfedgemesh_t* p) { return o3d_halfedgemesh_get_array(nullptr, 0, &n, p, which); });
    return n;
}

size_t num_half_edges(const PyHalfEdgeTriangleMesh& self) {
    size_t n = 0;
    locked_const(self.h, [&](const o3d_halfedgemesh_t* p) { return o3d_halfedgemesh_get_half_edges(nullptr, 0, &n, p); });
    return n;
}

template <typename F>
py::list lists_of(const PyHalfEdgeTriangleMesh& self, F&& f) {
    o3d_index_lists_t* raw = nullptr;
    locked_const(self.h, [&](const o3d_halfedgemesh_t* p) { return f(&raw, p); });
    return index_lists_to_python(own_lists(raw), false);
}

template <typename F>
py::array loop_of(const PyHalfEdgeTriangleMesh& self, int64_t vertex_index, F&& f) {
    const int32_t v = int32_of(vertex_index, "vertex_index");
    auto out = read_rows<int32_t>(self.h, 1, 0, [&](int32_t* o, size_t cap, size_t* n, const o3d_halfedgemesh_t* p) {
        return f(o, cap, n, p, v);
    });
    return to_numpy(out, {(py::ssize_t)out.size()});
}

}  // namespace

void declare_halfedgemesh(py::module_& m) {
    py::class_<PyHalfEdgeTriangleMesh>(
        m, "HalfEdgeTriangleMesh",
        "A half-edge triangle mesh: a cleaned, manifold, read-only copy of a TriangleMesh with its half-edges "
        "(half-edge 3t + k is side k of triangle t), for walking one-rings and boundary loops. Its arrays are "
        "read-only numpy copies.");
}

void define_halfedgemesh(py::module_& m) {
    auto cls = static_cast<py::class_<PyHalfEdgeTriangleMesh>>(m.attr("HalfEdgeTriangleMesh"));
    cls.def(py::init([] { return from_mesh(PyTriangleMesh()); }), "An empty half-edge mesh.")
        .def(py::init([](const PyHalfEdgeTriangleMesh& other) { return PyHalfEdgeTriangleMesh(other); }),
             py::arg("mesh"), "A copy (the two share the immutable data).")
        .def("__copy__", [](const PyHalfEdgeTriangleMesh& self) { return PyHalfEdgeTriangleMesh(self); })
        .def("__deepcopy__", [](const PyHalfEdgeTriangleMesh& self, py::handle) { return PyHalfEdgeTriangleMesh(self); })
        .def_static("create_from_triangle_mesh", &from_mesh, py::arg("mesh"),
                    "Open3D's create_from_triangle_mesh: the mesh cleaned (equal vertices merged, duplicated and "
                    "degenerate triangles and unreferenced vertices dropped), normals computed afresh, colors kept. "
                    "A non-manifold mesh raises InvalidArgumentError.")
        .def_property_readonly("vertices", [](const PyHalfEdgeTriangleMesh& s) { return float_rows(s, O3D_HALFEDGEMESH_VERTICES); },
                               "(N, 3) float64, read-only.")
        .def_property_readonly("vertex_normals",
                               [](const PyHalfEdgeTriangleMesh& s) { return float_rows(s, O3D_HALFEDGEMESH_VERTEX_NORMALS); },
                               "(N, 3) float64 unit area-weighted normals, read-only.")
        .def_property_readonly("vertex_colors",
                               [](const PyHalfEdgeTriangleMesh& s) { return float_rows(s, O3D_HALFEDGEMESH_VERTEX_COLORS); },
                               "(N, 3) float64, read-only (empty when the mesh had none).")
        .def_property_readonly("triangle_normals",
                               [](const PyHalfEdgeTriangleMesh& s) { return float_rows(s, O3D_HALFEDGEMESH_TRIANGLE_NORMALS); },
                               "(M, 3) float64 unit normals, read-only.")
        .def_property_readonly(
            "triangles",
            [](const PyHalfEdgeTriangleMesh& s) {
                auto v = read_rows<int32_t>(s.h, 3, 0, [](int32_t* out, size_t cap, size_t* n, const o3d_halfedgemesh_t* p) {
                    return o3d_halfedgemesh_get_triangles(out, cap, n, p);
                });
                return to_numpy(v, {(py::ssize_t)(v.size() / 3), 3}, false);
            },
            "(M, 3) int32 vertex indices, read-only.")
        .def(
            "_half_edge_array",
            [](const PyHalfEdgeTriangleMesh& s) {
                auto v = read_rows<int32_t>(s.h, 5, 0, [](int32_t* out, size_t cap, size_t* n, const o3d_halfedgemesh_t* p) {
                    return o3d_halfedgemesh_get_half_edges(out, cap, n, p);
                });
                return to_numpy(v, {(py::ssize_t)(v.size() / 5), 5}, false);
            },
            "(E, 5) int32, read-only: next, twin (-1 on a boundary), from vertex, to vertex, triangle per half-edge.")
        .def_property_readonly(
            "ordered_half_edge_from_vertex",
            [](const PyHalfEdgeTriangleMesh& s) { return lists_of(s, &o3d_halfedgemesh_get_ordered_half_edge_from_vertex); },
            "Per vertex its outgoing half-edges in fan order (list of int32 arrays), from its boundary half-edge "
            "when it has one.")
        .def(
            "boundary_half_edges_from_vertex",
            [](const PyHalfEdgeTriangleMesh& s, int64_t vertex_index) {
                return loop_of(s, vertex_index, &o3d_halfedgemesh_boundary_half_edges_from_vertex);
            },
            py::arg("vertex_index"),
            "The boundary loop through vertex_index as half-edge indices (int32 array); empty when the vertex is not "
            "on a boundary (Open3D raises there).")
        .def(
            "boundary_vertices_from_vertex",
            [](const PyHalfEdgeTriangleMesh& s, int64_t vertex_index) {
                return loop_of(s, vertex_index, &o3d_halfedgemesh_boundary_vertices_from_vertex);
            },
            py::arg("vertex_index"),
            "The boundary loop through vertex_index as vertex indices starting with it (int32 array); empty when the "
            "vertex is not on a boundary.")
        .def(
            "get_boundaries",
            [](const PyHalfEdgeTriangleMesh& s) { return lists_of(s, &o3d_halfedgemesh_get_boundaries); },
            "Every boundary loop once, as a list of int32 arrays of vertex indices.")
        .def("has_half_edges", [](const PyHalfEdgeTriangleMesh& s) { return num_half_edges(s) > 0; })
        .def("has_vertices", [](const PyHalfEdgeTriangleMesh& s) { return rows_of(s, O3D_HALFEDGEMESH_VERTICES) > 0; })
        .def("has_vertex_normals",
             [](const PyHalfEdgeTriangleMesh& s) {
                 const size_t n = rows_of(s, O3D_HALFEDGEMESH_VERTICES);
                 return n > 0 && rows_of(s, O3D_HALFEDGEMESH_VERTEX_NORMALS) == n;
             })
        .def("has_vertex_colors",
             [](const PyHalfEdgeTriangleMesh& s) {
                 const size_t n = rows_of(s, O3D_HALFEDGEMESH_VERTICES);
                 return n > 0 && rows_of(s, O3D_HALFEDGEMESH_VERTEX_COLORS) == n;
             })
        .def("has_triangle_normals",
             [](const PyHalfEdgeTriangleMesh& s) { return rows_of(s, O3D_HALFEDGEMESH_TRIANGLE_NORMALS) > 0; })
        .def("is_empty", [](const PyHalfEdgeTriangleMesh& s) { return rows_of(s, O3D_HALFEDGEMESH_VERTICES) == 0; })
        .def("__repr__", [](const PyHalfEdgeTriangleMesh& s) {
            return "HalfEdgeTriangleMesh with " + std::to_string(rows_of(s, O3D_HALFEDGEMESH_VERTICES)) +
                   " points and " + std::to_string(num_half_edges(s)) + " half edges.";
        });
}

}  // namespace o3dpy
