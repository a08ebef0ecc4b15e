// SPDX-License-Identifier: MIT
// o3d.geometry.TriangleMesh over o3d_trianglemesh_t (trianglemesh.h): the container, zero-copy array views and
// textures; the methods that are one C call (normals, transforms, bounds, clean-up, topology queries, processing)
// come from generated/trianglemesh_methods.h. The rest of processing and the primitives are in
// trianglemesh_processing.cpp.
#include "generated/trianglemesh_methods.h"

namespace o3dpy {

PyTriangleMesh::PyTriangleMesh() : Geom(nullptr) { check(o3d_trianglemesh_create(&h->p)); }

namespace {

PyTriangleMesh& mesh_of(py::handle self) { return self.cast<PyTriangleMesh&>(); }

size_t count(const PyTriangleMesh& self, bool triangles) {
    size_t n = 0;
    locked_const(self.h, [&](const o3d_trianglemesh_t* m) {
        return triangles ? o3d_trianglemesh_num_triangles(&n, m) : o3d_trianglemesh_num_vertices(&n, m);
    });
    return n;
}

PyTriangleMesh clone_of(const PyTriangleMesh& self) {
    o3d_trianglemesh_t* out = nullptr;
    locked_const(self.h, [&](const o3d_trianglemesh_t* m) { return o3d_trianglemesh_clone(&out, m); });
    PyTriangleMesh copy(out);
    copy.adjacency = self.adjacency;
    return copy;
}

void append_into(const MeshPtr& dst, MeshPtr src) {
    if (src == dst) {  // mesh += mesh: append a snapshot of itself
        o3d_trianglemesh_t* copy = nullptr;
        locked_const(src, [&](const o3d_trianglemesh_t* m) { return o3d_trianglemesh_clone(&copy, m); });
        src = std::make_shared<MeshHandle>(copy);
    }
    o3d_status s;
    {
        py::gil_scoped_release release;
        std::unique_lock<std::shared_mutex> l1(dst->mutex, std::defer_lock);
        std::shared_lock<std::shared_mutex> l2(src->mutex, std::defer_lock);
        std::lock(l1, l2);
        s = o3d_trianglemesh_append(dst->p, src->p);
    }
    check(s);
}

py::list get_textures(const PyTriangleMesh& self) {
    size_t n = 0;
    locked_const(self.h, [&](const o3d_trianglemesh_t* m) { return o3d_trianglemesh_texture_count(&n, m); });
    py::list out;
    for (size_t i = 0; i < n; ++i) {
        o3d_image_t* img = nullptr;
        locked_const(self.h, [&](const o3d_trianglemesh_t* m) { return o3d_trianglemesh_get_texture(&img, m, i); });
        out.append(py::cast(PyImage(img)));
    }
    return out;
}

void set_textures(PyTriangleMesh& self, py::handle images) {
    std::vector<ImagePtr> list;
    for (py::handle item : py::iter(images)) {
        if (!py::isinstance<PyImage>(item)) throw py::type_error("textures: expected a list of o3d.geometry.Image");
        list.push_back(item.cast<PyImage&>().h);
    }
    MeshPtr h = self.for_resize();
    locked_mut(h, [&](o3d_trianglemesh_t* m) {
        o3d_status s = o3d_trianglemesh_clear_textures(m);
        for (size_t i = 0; i < list.size() && s == O3D_OK; ++i) s = o3d_trianglemesh_add_texture(m, list[i]->p);
        return s;
    });
}

}  // namespace

void declare_trianglemesh(py::module_& m) {
    py::class_<PyTriangleMesh>(
        m, "TriangleMesh",
        "A triangle mesh: vertices with optional normals and colors, int32 triangles with optional normals, "
        "UVs, material ids and texture images.\n\n"
        "``np.asarray(mesh.vertices)`` (and the other arrays) are writable zero-copy views of the mesh's "
        "memory. Calls that resize an array first give the mesh a private copy while such views are alive, "
        "so an old view never dangles (it keeps the old data).");
}

void define_trianglemesh(py::module_& m) {
    auto cls = static_cast<py::class_<PyTriangleMesh>>(m.attr("TriangleMesh"));
    cls.def(py::init<>(), "An empty mesh.")
        .def(py::init([](const PyTriangleMesh& other) { return clone_of(other); }), py::arg("mesh"),
             "Deep copy of another mesh (textures included).")
        .def(py::init([](py::handle vertices, py::handle triangles) {
                 PyTriangleMesh mesh;
                 array_set(mesh, O3D_MESH_VERTICES, vertices, "vertices");
                 array_set(mesh, O3D_MESH_TRIANGLES, triangles, "triangles");
                 return mesh;
             }),
             py::arg("vertices"), py::arg("triangles"), "A mesh with these (N, 3) vertices and (M, 3) triangles.")
        .def("__copy__", [](const PyTriangleMesh& self) { return clone_of(self); })
        .def("__deepcopy__", [](const PyTriangleMesh& self, py::handle) { return clone_of(self); })
        .def_property("textures", &get_textures, &set_textures,
                      "List of texture Images (a copy, as Open3D's list; assign a list to replace them).")
        .def("has_triangles", [](const PyTriangleMesh& self) { return count(self, false) > 0 && count(self, true) > 0; })
        .def("has_textures", [](const PyTriangleMesh& self) {
            size_t n = 0;
            locked_const(self.h, [&](const o3d_trianglemesh_t* m) { return o3d_trianglemesh_texture_count(&n, m); });
            return n > 0;
        })
        .def("is_empty", [](const PyTriangleMesh& self) { return count(self, false) == 0; })
        .def("__repr__",
             [](const PyTriangleMesh& self) {
                 return "TriangleMesh with " + std::to_string(count(self, false)) + " points and " +
                        std::to_string(count(self, true)) + " triangles.";
             })
        .def(
            "__iadd__",
            [](py::object self, const PyTriangleMesh& other) {
                MeshPtr src = other.h;
                append_into(mesh_of(self).for_resize(), src);
                return self;
            },
            py::arg("mesh"))
        .def(
            "__add__",
            [](const PyTriangleMesh& self, const PyTriangleMesh& other) {
                PyTriangleMesh out = clone_of(self);
                append_into(out.h, other.h);
                return out;
            },
            py::arg("mesh"))
        .def(
            "cluster_connected_triangles",
            [](const PyTriangleMesh& self) {
                std::vector<int32_t> clusters, sizes;
                std::vector<double> areas;
                size_t nt = 0, nc = 0;
                locked_const(self.h, [&](const o3d_trianglemesh_t* m) {
                    o3d_status s = o3d_trianglemesh_num_triangles(&nt, m);
                    if (s != O3D_OK) return s;
                    clusters.resize(nt);
                    sizes.resize(nt);
                    areas.resize(nt);
                    return o3d_trianglemesh_cluster_connected_triangles(clusters.data(), sizes.data(), areas.data(),
                                                                        nt, &nt, &nc, m);
                });
                py::array_t<int32_t> c((py::ssize_t)nt), n((py::ssize_t)nc);
                py::array_t<double> a((py::ssize_t)nc);
                if (nt) std::memcpy(c.mutable_data(), clusters.data(), nt * sizeof(int32_t));
                if (nc) {
                    std::memcpy(n.mutable_data(), sizes.data(), nc * sizeof(int32_t));
                    std::memcpy(a.mutable_data(), areas.data(), nc * sizeof(double));
                }
                return py::make_tuple(c, n, a);
            },
            "Edge-connected components: (triangle_clusters (M,) int32, cluster_n_triangles (C,) int32, "
            "cluster_area (C,) float64) numpy arrays; clusters numbered by their lowest triangle index.");
    struct {
        const char* name;
        int32_t which;
        const char* doc;
    } arrays[] = {{"vertices", O3D_MESH_VERTICES, "(N, 3) float64 view."},
                  {"vertex_normals", O3D_MESH_VERTEX_NORMALS, "(N, 3) float64 view."},
                  {"vertex_colors", O3D_MESH_VERTEX_COLORS, "(N, 3) float64 view, RGB in [0, 1]."},
                  {"triangle_normals", O3D_MESH_TRIANGLE_NORMALS, "(M, 3) float64 view."},
                  {"triangle_uvs", O3D_MESH_TRIANGLE_UVS, "(3M, 2) float64 view: three UV rows per triangle, in corner order."},
                  {"triangles", O3D_MESH_TRIANGLES, "(M, 3) int32 view of vertex indices."},
                  {"triangle_material_ids", O3D_MESH_TRIANGLE_MATERIAL_IDS, "(M,) int32 view: each triangle's index into textures."}};
    for (const auto& a : arrays) {
        def_array(cls, a.name, a.which, a.doc);
        if (a.which != O3D_MESH_TRIANGLES) def_has(cls, (std::string("has_") + a.name).c_str(), a.which);
    }
    def_array_access(cls);
    def_triangle_mesh_methods(cls);
    def_aabb(cls, &o3d_trianglemesh_get_axis_aligned_bounding_box);
}

}  // namespace o3dpy
