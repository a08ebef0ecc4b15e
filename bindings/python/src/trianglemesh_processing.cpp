// SPDX-License-Identifier: MIT
// o3d.geometry.TriangleMesh processing that takes more than the C call's arguments (crop, create_mobius), with
// Open3D 0.20's names and keyword defaults; the rest (sampling, simplification, smoothing, subdivision, the other
// create_* primitives with Open3D's UV flags) is generated (def_triangle_mesh_methods). Each C call runs with the
// GIL released and writes a new mesh.
#include "geometry_types.h"

namespace o3dpy {
namespace {

template <typename F>
PyTriangleMesh derive_mesh(const PyTriangleMesh& self, F&& f) {
    o3d_trianglemesh_t* out = nullptr;
    locked_const(self.h, [&](const o3d_trianglemesh_t* m) { return f(&out, m); });
    return PyTriangleMesh(out);
}

/// An in-place removal by indices or mask: the mesh's arrays change size, so live views are detached first.
template <typename Arg, typename Call>
void remove_in_place(PyTriangleMesh& self, const std::vector<Arg>& arg, Call call) {
    locked_mut(self.for_resize(), [&](o3d_trianglemesh_t* m) { return call(m, arg.data(), arg.size()); });
}

template <typename F>
PyTriangleMesh primitive(F&& f) {
    o3d_trianglemesh_t* out = nullptr;
    check(nogil([&] { return f(&out); }));
    return PyTriangleMesh(out);
}

}  // namespace

void declare_trianglemesh_enums(py::module_& m) {
    def_enum<SimplificationContraction>(m);
    def_enum<FilterScope>(m);
    def_enum<DeformAsRigidAsPossibleEnergy>(m);
}

void define_trianglemesh_processing(py::module_& m) {
    auto cls = static_cast<py::class_<PyTriangleMesh>>(m.attr("TriangleMesh"));
    cls.def(
            "crop",
            [](const PyTriangleMesh& self, py::handle bounding_box) {
                if (is_obb(bounding_box)) {
                    o3d_obb_t obb = obb_of(bounding_box);
                    return derive_mesh(self, [&](o3d_trianglemesh_t** out, const o3d_trianglemesh_t* m) {
                        return o3d_trianglemesh_crop_obb(out, m, &obb);
                    });
                }
                auto [lo, hi] = aabb_bounds(bounding_box);
                return derive_mesh(self, [&](o3d_trianglemesh_t** out, const o3d_trianglemesh_t* m) {
                    return o3d_trianglemesh_crop_aabb(out, m, lo.data(), hi.data());
                });
            },
            py::arg("bounding_box"), "New mesh of the triangles whose three vertices lie in the AxisAlignedBoundingBox or "
                                   "OrientedBoundingBox.");

    cls.def(
           "remove_vertices_by_index",
           [](PyTriangleMesh& self, py::handle vertex_indices) {
               remove_in_place(self, int32_indices(vertex_indices, "vertex_indices"),
                               &o3d_trianglemesh_remove_vertices_by_index);
           },
           py::arg("vertex_indices"), "Remove the vertices at vertex_indices and every triangle that uses one of them.")
        .def(
            "remove_vertices_by_mask",
            [](PyTriangleMesh& self, py::handle vertex_mask) {
                remove_in_place(self, byte_mask(vertex_mask, "vertex_mask"), &o3d_trianglemesh_remove_vertices_by_mask);
            },
            py::arg("vertex_mask"),
            "Remove the vertices whose mask entry is True (one per vertex) and every triangle that uses one of them, "
            "e.g. a Poisson surface trimmed by its densities.")
        .def(
            "remove_triangles_by_index",
            [](PyTriangleMesh& self, py::handle triangle_indices) {
                remove_in_place(self, int32_indices(triangle_indices, "triangle_indices"),
                                &o3d_trianglemesh_remove_triangles_by_index);
            },
            py::arg("triangle_indices"), "Remove the triangles at triangle_indices; every vertex stays.")
        .def(
            "remove_triangles_by_mask",
            [](PyTriangleMesh& self, py::handle triangle_mask) {
                remove_in_place(self, byte_mask(triangle_mask, "triangle_mask"),
                                &o3d_trianglemesh_remove_triangles_by_mask);
            },
            py::arg("triangle_mask"), "Remove the triangles whose mask entry is True (one per triangle); every vertex "
                                      "stays.");

    const o3d_mobius_options_t mo = init_of(&o3d_mobius_options_init);
    cls.def_static(
        "create_mobius",
        [](int64_t length_split, int64_t width_split, int64_t twists, double raidus, double flatness, double width,
           double scale) {
            o3d_mobius_options_t o = init_of(&o3d_mobius_options_init);
            o.length_split = int32_of(length_split, "length_split");
            o.width_split = int32_of(width_split, "width_split");
            o.twists = int32_of(twists, "twists");
            o.radius = raidus;
            o.flatness = flatness;
            o.width = width;
            o.scale = scale;
            return primitive([&](o3d_trianglemesh_t** out) { return o3d_trianglemesh_create_mobius(out, &o); });
        },
        py::arg("length_split") = mo.length_split, py::arg("width_split") = mo.width_split,
        py::arg("twists") = mo.twists, py::arg("raidus") = mo.radius, py::arg("flatness") = mo.flatness,
        py::arg("width") = mo.width, py::arg("scale") = mo.scale,
        "A twisted band about the z axis: length_split columns of width_split vertices; an odd number of twists "
        "makes a one-sided Moebius strip. ``raidus`` (sic, Open3D's keyword) is the radius of the band's centre "
        "circle.");
}

}  // namespace o3dpy
