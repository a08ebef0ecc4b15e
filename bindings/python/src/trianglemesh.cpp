// SPDX-License-Identifier: MIT
// o3d.geometry.TriangleMesh over o3d_trianglemesh_t (trianglemesh.h): the container, zero-copy array
// views, normals, transforms, bounds, clean-up and topology queries. Processing and primitives are in
// trianglemesh_processing.cpp.
#include <limits>

#include "geometry_types.h"

namespace o3dpy {

PyTriangleMesh::PyTriangleMesh() {
    o3d_trianglemesh_t* raw = nullptr;
    check(o3d_trianglemesh_create(&raw));
    h = std::make_shared<MeshHandle>(raw);
}

MeshPtr PyTriangleMesh::for_resize() {
    if (h.use_count() > 1) {
        // numpy views (or another thread's call) share this handle: give this mesh a private copy so
        // the old arrays stay valid for them.
        o3d_trianglemesh_t* copy = nullptr;
        MeshPtr old = h;
        locked_const(old, [&](const o3d_trianglemesh_t* m) { return o3d_trianglemesh_clone(&copy, m); });
        h = std::make_shared<MeshHandle>(copy);
    }
    return h;
}

namespace {

struct FloatAttr {
    int32_t which;
    size_t cols;
    const char* name;
};
constexpr FloatAttr kVertices{O3D_MESH_VERTICES, 3, "vertices"};
constexpr FloatAttr kVertexNormals{O3D_MESH_VERTEX_NORMALS, 3, "vertex_normals"};
constexpr FloatAttr kVertexColors{O3D_MESH_VERTEX_COLORS, 3, "vertex_colors"};
constexpr FloatAttr kTriangleNormals{O3D_MESH_TRIANGLE_NORMALS, 3, "triangle_normals"};
constexpr FloatAttr kTriangleUvs{O3D_MESH_TRIANGLE_UVS, 2, "triangle_uvs"};

PyTriangleMesh& mesh_of(py::handle self) { return self.cast<PyTriangleMesh&>(); }

/// An (N, cols) numeric input as a C-contiguous float64 array (no copy when it already is one).
py::array_t<double> rows_f64(py::handle obj, size_t cols, const char* what) {
    if (obj.is_none()) invalid(std::string(what) + ": expected an array, got None");
    py::array a = py::array::ensure(obj);
    if (!a) invalid(std::string(what) + ": expected an array-like of numbers");
    char kind = a.dtype().kind();
    if (kind != 'f' && kind != 'i' && kind != 'u' && kind != 'b')
        invalid(std::string(what) + ": expected numbers, got dtype " + std::string(py::str(a.dtype())));
    if (a.size() == 0) return py::array_t<double>(std::vector<py::ssize_t>{0, (py::ssize_t)cols});
    if (a.ndim() != 2 || a.shape(1) != (py::ssize_t)cols)
        invalid(std::string(what) + ": expected an (N, " + std::to_string(cols) + ") array, got " +
                std::to_string(a.ndim()) + "-D input of " + std::to_string(a.size()) + " values");
    auto d = py::array_t<double, py::array::c_style | py::array::forcecast>::ensure(a);
    if (!d) throw py::error_already_set();
    return d;
}

/// An integer input of `cols` columns (cols == 1: 1-D) as C-contiguous int32, each value checked.
py::array_t<int32_t> rows_i32(py::handle obj, size_t cols, const char* what) {
    if (obj.is_none()) invalid(std::string(what) + ": expected an array, got None");
    py::array a = py::array::ensure(obj);
    if (!a) invalid(std::string(what) + ": expected an array-like of integers");
    std::vector<py::ssize_t> empty_shape = cols == 1 ? std::vector<py::ssize_t>{0}
                                                     : std::vector<py::ssize_t>{0, (py::ssize_t)cols};
    if (a.size() == 0) return py::array_t<int32_t>(empty_shape);
    char kind = a.dtype().kind();
    if (kind != 'i' && kind != 'u')
        invalid(std::string(what) + ": expected integers, got dtype " + std::string(py::str(a.dtype())));
    bool ok = cols == 1 ? a.ndim() == 1 || (a.ndim() == 2 && a.shape(1) == 1)
                        : a.ndim() == 2 && a.shape(1) == (py::ssize_t)cols;
    if (!ok) invalid(std::string(what) + ": expected " + (cols == 1 ? "a 1-D sequence" : "an (N, 3) array"));
    if (a.dtype().is(py::dtype::of<int32_t>())) {
        auto d = py::array_t<int32_t, py::array::c_style>::ensure(a);
        if (!d) throw py::error_already_set();
        return d;
    }
    auto wide = py::array_t<int64_t, py::array::c_style | py::array::forcecast>::ensure(a);
    if (!wide) throw py::error_already_set();
    py::array_t<int32_t> out(cols == 1 ? std::vector<py::ssize_t>{wide.size()}
                                       : std::vector<py::ssize_t>{wide.size() / (py::ssize_t)cols, (py::ssize_t)cols});
    const int64_t* src = wide.data();
    int32_t* dst = out.mutable_data();
    for (py::ssize_t i = 0; i < wide.size(); ++i) {
        if (src[i] < std::numeric_limits<int32_t>::min() || src[i] > std::numeric_limits<int32_t>::max())
            invalid(std::string(what) + ": value " + std::to_string(src[i]) + " does not fit in int32");
        dst[i] = (int32_t)src[i];
    }
    return out;
}

py::array get_float(PyTriangleMesh& self, const FloatAttr& a) {
    MeshPtr h = self.h;
    double* data = nullptr;
    size_t n = 0;
    locked_mut(h, [&](o3d_trianglemesh_t* m) { return o3d_trianglemesh_array_mutable_view(&data, &n, m, a.which); });
    return view_array(data, n, a.cols, keepalive(h), true);
}

void set_float(PyTriangleMesh& self, const FloatAttr& a, py::handle value) {
    py::array_t<double> rows = rows_f64(value, a.cols, a.name);
    const size_t n = (size_t)rows.shape(0);
    const double* p = n ? rows.data() : nullptr;
    locked_mut(self.for_resize(), [&](o3d_trianglemesh_t* m) { return o3d_trianglemesh_set_array(m, a.which, p, n); });
}

/// Zero-copy int32 view: (n, 3) for triangles, (n,) for material ids.
py::array int_view(int32_t* data, size_t n, bool triangles, py::object owner, bool writable) {
    std::vector<py::ssize_t> shape = triangles ? std::vector<py::ssize_t>{(py::ssize_t)n, 3}
                                               : std::vector<py::ssize_t>{(py::ssize_t)n};
    if (!data || n == 0) return py::array_t<int32_t>(shape);
    std::vector<py::ssize_t> strides = triangles ? std::vector<py::ssize_t>{3 * sizeof(int32_t), sizeof(int32_t)}
                                                 : std::vector<py::ssize_t>{sizeof(int32_t)};
    py::array a(py::dtype::of<int32_t>(), shape, strides, data, owner);
    if (!writable) a.attr("setflags")(py::arg("write") = false);
    return a;
}

py::array get_index(PyTriangleMesh& self, int32_t which) {
    MeshPtr h = self.h;
    int32_t* data = nullptr;
    size_t n = 0;
    locked_mut(h, [&](o3d_trianglemesh_t* m) { return o3d_trianglemesh_index_array_mutable_view(&data, &n, m, which); });
    return int_view(data, n, which == O3D_MESH_TRIANGLES, keepalive(h), true);
}

void set_index(PyTriangleMesh& self, int32_t which, py::handle value) {
    const bool tri = which == O3D_MESH_TRIANGLES;
    py::array_t<int32_t> rows = rows_i32(value, tri ? 3 : 1, tri ? "triangles" : "triangle_material_ids");
    const size_t n = (size_t)rows.shape(0);
    const int32_t* p = n ? rows.data() : nullptr;
    locked_mut(self.for_resize(), [&](o3d_trianglemesh_t* m) { return o3d_trianglemesh_set_index_array(m, which, p, n); });
}

bool has(const PyTriangleMesh& self, int32_t which) {
    int32_t v = 0;
    locked_const(self.h, [&](const o3d_trianglemesh_t* m) { return o3d_trianglemesh_has_array(&v, m, which); });
    return v != 0;
}

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
    return PyTriangleMesh(out);
}

bool query_flag(const PyTriangleMesh& self, o3d_status (*fn)(const o3d_trianglemesh_t*, int32_t*)) {
    int32_t v = 0;
    locked_const(self.h, [&](const o3d_trianglemesh_t* m) { return fn(m, &v); });
    return v != 0;
}

/// Clean-up calls: in place (may shrink arrays, so copy-on-write first), returning self.
py::object cleanup(py::object self, o3d_status (*fn)(o3d_trianglemesh_t*)) {
    locked_mut(mesh_of(self).for_resize(), [&](o3d_trianglemesh_t* m) { return fn(m); });
    return self;
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

py::array bound(const PyTriangleMesh& self, o3d_status (*fn)(const o3d_trianglemesh_t*, double*)) {
    std::array<double, 3> v{};
    locked_const(self.h, [&](const o3d_trianglemesh_t* m) { return fn(m, v.data()); });
    return vec3_to_array(v.data());
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
                 set_float(mesh, kVertices, vertices);
                 set_index(mesh, O3D_MESH_TRIANGLES, triangles);
                 return mesh;
             }),
             py::arg("vertices"), py::arg("triangles"), "A mesh with these (N, 3) vertices and (M, 3) triangles.")
        .def("__copy__", [](const PyTriangleMesh& self) { return clone_of(self); })
        .def("__deepcopy__", [](const PyTriangleMesh& self, py::handle) { return clone_of(self); })
        .def_property(
            "vertices", [](PyTriangleMesh& self) { return get_float(self, kVertices); },
            [](PyTriangleMesh& self, py::handle v) { set_float(self, kVertices, v); }, "(N, 3) float64 view.")
        .def_property(
            "vertex_normals", [](PyTriangleMesh& self) { return get_float(self, kVertexNormals); },
            [](PyTriangleMesh& self, py::handle v) { set_float(self, kVertexNormals, v); }, "(N, 3) float64 view.")
        .def_property(
            "vertex_colors", [](PyTriangleMesh& self) { return get_float(self, kVertexColors); },
            [](PyTriangleMesh& self, py::handle v) { set_float(self, kVertexColors, v); },
            "(N, 3) float64 view, RGB in [0, 1].")
        .def_property(
            "triangle_normals", [](PyTriangleMesh& self) { return get_float(self, kTriangleNormals); },
            [](PyTriangleMesh& self, py::handle v) { set_float(self, kTriangleNormals, v); }, "(M, 3) float64 view.")
        .def_property(
            "triangle_uvs", [](PyTriangleMesh& self) { return get_float(self, kTriangleUvs); },
            [](PyTriangleMesh& self, py::handle v) { set_float(self, kTriangleUvs, v); },
            "(3M, 2) float64 view: three UV rows per triangle, in corner order.")
        .def_property(
            "triangles", [](PyTriangleMesh& self) { return get_index(self, O3D_MESH_TRIANGLES); },
            [](PyTriangleMesh& self, py::handle v) { set_index(self, O3D_MESH_TRIANGLES, v); },
            "(M, 3) int32 view of vertex indices.")
        .def_property(
            "triangle_material_ids", [](PyTriangleMesh& self) { return get_index(self, O3D_MESH_TRIANGLE_MATERIAL_IDS); },
            [](PyTriangleMesh& self, py::handle v) { set_index(self, O3D_MESH_TRIANGLE_MATERIAL_IDS, v); },
            "(M,) int32 view: each triangle's index into textures.")
        .def_property("textures", &get_textures, &set_textures,
                      "List of texture Images (a copy, as Open3D's list; assign a list to replace them).")
        .def("has_vertices", [](const PyTriangleMesh& self) { return has(self, O3D_MESH_VERTICES); })
        .def("has_vertex_normals", [](const PyTriangleMesh& self) { return has(self, O3D_MESH_VERTEX_NORMALS); })
        .def("has_vertex_colors", [](const PyTriangleMesh& self) { return has(self, O3D_MESH_VERTEX_COLORS); })
        .def("has_triangles", [](const PyTriangleMesh& self) { return count(self, false) > 0 && count(self, true) > 0; })
        .def("has_triangle_normals", [](const PyTriangleMesh& self) { return has(self, O3D_MESH_TRIANGLE_NORMALS); })
        .def("has_triangle_uvs", [](const PyTriangleMesh& self) { return has(self, O3D_MESH_TRIANGLE_UVS); })
        .def("has_triangle_material_ids",
             [](const PyTriangleMesh& self) { return has(self, O3D_MESH_TRIANGLE_MATERIAL_IDS); })
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
            "clear", [](py::object self) { return cleanup(self, &o3d_trianglemesh_clear); },
            "Remove every array and texture. Returns self.")
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
            "compute_vertex_normals",
            [](py::object self, bool normalized) {
                locked_mut(mesh_of(self).for_resize(), [&](o3d_trianglemesh_t* m) {
                    return o3d_trianglemesh_compute_vertex_normals(m, normalized ? 1 : 0);
                });
                return self;
            },
            py::arg("normalized") = true, "Area-weighted vertex normals (also computes triangle normals). Returns self.")
        .def(
            "compute_triangle_normals",
            [](py::object self, bool normalized) {
                locked_mut(mesh_of(self).for_resize(), [&](o3d_trianglemesh_t* m) {
                    return o3d_trianglemesh_compute_triangle_normals(m, normalized ? 1 : 0);
                });
                return self;
            },
            py::arg("normalized") = true, "Triangle normals (b - a) x (c - a). Returns self.")
        .def(
            "normalize_normals",
            [](py::object self) {
                locked_mut(mesh_of(self).h, [](o3d_trianglemesh_t* m) { return o3d_trianglemesh_normalize_normals(m); });
                return self;
            },
            "Scale vertex and triangle normals to unit length. Returns self.")
        .def(
            "paint_uniform_color",
            [](py::object self, py::handle color) {
                auto c = as_vec3(color, "color");
                locked_mut(mesh_of(self).for_resize(),
                           [&](o3d_trianglemesh_t* m) { return o3d_trianglemesh_paint_uniform_color(m, c.data()); });
                return self;
            },
            py::arg("color"), "Set every vertex color to the RGB color. Returns self.")
        .def(
            "transform",
            [](py::object self, py::handle T) {
                auto t = as_mat4(T, "transformation");
                locked_mut(mesh_of(self).h, [&](o3d_trianglemesh_t* m) { return o3d_trianglemesh_transform(m, t.data()); });
                return self;
            },
            py::arg("transformation"), "Apply a 4x4 transform (vertices; normals rotated). Returns self.")
        .def(
            "translate",
            [](py::object self, py::handle t, bool relative) {
                auto v = as_vec3(t, "translation");
                locked_mut(mesh_of(self).h, [&](o3d_trianglemesh_t* m) {
                    return o3d_trianglemesh_translate(m, v.data(), relative ? 1 : 0);
                });
                return self;
            },
            py::arg("translation"), py::arg("relative") = true,
            "relative=True: add translation; False: move the center to it. Returns self.")
        .def(
            "rotate",
            [](py::object self, py::handle R, py::handle center) {
                auto r = as_mat3(R, "R");
                std::array<double, 3> c{};
                const bool has_center = !center.is_none();
                if (has_center) c = as_vec3(center, "center");
                locked_mut(mesh_of(self).h, [&](o3d_trianglemesh_t* m) {
                    return o3d_trianglemesh_rotate(m, r.data(), has_center ? c.data() : nullptr);
                });
                return self;
            },
            py::arg("R"), py::arg("center") = py::none(), "Rotate about center (None: the mesh's center). Returns self.")
        .def(
            "scale",
            [](py::object self, double scale, py::handle center) {
                std::array<double, 3> c{};
                const bool has_center = !center.is_none();
                if (has_center) c = as_vec3(center, "center");
                locked_mut(mesh_of(self).h, [&](o3d_trianglemesh_t* m) {
                    return o3d_trianglemesh_scale(m, scale, has_center ? c.data() : nullptr);
                });
                return self;
            },
            py::arg("scale"), py::arg("center") = py::none(), "Scale about center (None: the mesh's center). Returns self.")
        .def("get_min_bound", [](const PyTriangleMesh& self) { return bound(self, &o3d_trianglemesh_get_min_bound); })
        .def("get_max_bound", [](const PyTriangleMesh& self) { return bound(self, &o3d_trianglemesh_get_max_bound); })
        .def("get_center", [](const PyTriangleMesh& self) { return bound(self, &o3d_trianglemesh_get_center); })
        .def(
            "get_axis_aligned_bounding_box",
            [](const PyTriangleMesh& self) {
                std::array<double, 3> lo{}, hi{};
                locked_const(self.h, [&](const o3d_trianglemesh_t* m) {
                    return o3d_trianglemesh_get_axis_aligned_bounding_box(lo.data(), hi.data(), m);
                });
                return make_aabb(lo.data(), hi.data());
            },
            "The axis-aligned bounding box (o3d.geometry.AxisAlignedBoundingBox).")
        .def(
            "remove_duplicated_vertices", [](py::object self) { return cleanup(self, &o3d_trianglemesh_remove_duplicated_vertices); },
            "Merge vertices with equal coordinates. Returns self.")
        .def(
            "remove_duplicated_triangles",
            [](py::object self) { return cleanup(self, &o3d_trianglemesh_remove_duplicated_triangles); },
            "Remove triangles with the same three vertices (any order). Returns self.")
        .def(
            "remove_degenerate_triangles",
            [](py::object self) { return cleanup(self, &o3d_trianglemesh_remove_degenerate_triangles); },
            "Remove triangles that repeat a vertex index. Returns self.")
        .def(
            "remove_unreferenced_vertices",
            [](py::object self) { return cleanup(self, &o3d_trianglemesh_remove_unreferenced_vertices); },
            "Remove vertices no triangle uses. Returns self.")
        .def(
            "remove_non_manifold_edges", [](py::object self) { return cleanup(self, &o3d_trianglemesh_remove_non_manifold_edges); },
            "Remove the smallest triangles on edges shared by more than two. Returns self.")
        .def(
            "merge_close_vertices",
            [](py::object self, double eps) {
                locked_mut(mesh_of(self).for_resize(),
                           [&](o3d_trianglemesh_t* m) { return o3d_trianglemesh_merge_close_vertices(m, eps); });
                return self;
            },
            py::arg("eps"), "Merge vertices closer than eps into their mean. Returns self.")
        .def("get_surface_area",
             [](const PyTriangleMesh& self) {
                 double v = 0;
                 locked_const(self.h, [&](const o3d_trianglemesh_t* m) { return o3d_trianglemesh_get_surface_area(&v, m); });
                 return v;
             })
        .def(
            "get_volume",
            [](const PyTriangleMesh& self) {
                double v = 0;
                locked_const(self.h, [&](const o3d_trianglemesh_t* m) { return o3d_trianglemesh_get_volume(&v, m); });
                return v;
            },
            "Enclosed volume; raises ValueError (InvalidArgumentError) unless watertight and orientable.")
        .def("is_watertight", [](const PyTriangleMesh& self) { return query_flag(self, &o3d_trianglemesh_is_watertight); })
        .def(
            "is_edge_manifold",
            [](const PyTriangleMesh& self, bool allow_boundary_edges) {
                int32_t v = 0;
                locked_const(self.h, [&](const o3d_trianglemesh_t* m) {
                    return o3d_trianglemesh_is_edge_manifold(&v, m, allow_boundary_edges ? 1 : 0);
                });
                return v != 0;
            },
            py::arg("allow_boundary_edges") = true)
        .def("is_vertex_manifold",
             [](const PyTriangleMesh& self) { return query_flag(self, &o3d_trianglemesh_is_vertex_manifold); })
        .def("is_self_intersecting",
             [](const PyTriangleMesh& self) { return query_flag(self, &o3d_trianglemesh_is_self_intersecting); })
        .def("is_orientable", [](const PyTriangleMesh& self) { return query_flag(self, &o3d_trianglemesh_is_orientable); })
        .def("euler_poincare_characteristic",
             [](const PyTriangleMesh& self) {
                 int64_t v = 0;
                 locked_const(self.h, [&](const o3d_trianglemesh_t* m) {
                     return o3d_trianglemesh_euler_poincare_characteristic(&v, m);
                 });
                 return v;
             })
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
            "cluster_area (C,) float64) numpy arrays; clusters numbered by their lowest triangle index.")
        .def(
            "_array_copy",
            [](const PyTriangleMesh& self, int32_t which) -> py::array {
                // Copy-out path (get_array / get_index_array): a snapshot independent of the mesh.
                const bool is_index = which >= O3D_MESH_TRIANGLES;
                const size_t cols = which == O3D_MESH_TRIANGLE_UVS ? 2 : which == O3D_MESH_TRIANGLE_MATERIAL_IDS ? 1 : 3;
                std::vector<double> f;
                std::vector<int32_t> i;
                size_t n = 0;
                locked_const(self.h, [&](const o3d_trianglemesh_t* m) {
                    o3d_status s = is_index ? o3d_trianglemesh_get_index_array(nullptr, 0, &n, m, which)
                                            : o3d_trianglemesh_get_array(nullptr, 0, &n, m, which);
                    if (s != O3D_OK && s != O3D_ERROR_BUFFER_TOO_SMALL) return s;
                    if (is_index) {
                        i.resize(n * cols);
                        return o3d_trianglemesh_get_index_array(i.data(), n, &n, m, which);
                    }
                    f.resize(n * cols);
                    return o3d_trianglemesh_get_array(f.data(), n, &n, m, which);
                });
                if (is_index) {
                    py::array_t<int32_t> out(cols == 1 ? std::vector<py::ssize_t>{(py::ssize_t)n}
                                                       : std::vector<py::ssize_t>{(py::ssize_t)n, (py::ssize_t)cols});
                    if (n) std::memcpy(out.mutable_data(), i.data(), n * cols * sizeof(int32_t));
                    return std::move(out);
                }
                py::array_t<double> out(std::vector<py::ssize_t>{(py::ssize_t)n, (py::ssize_t)cols});
                if (n) std::memcpy(out.mutable_data(), f.data(), n * cols * sizeof(double));
                return std::move(out);
            },
            py::arg("which"), "Copy of the array O3D_MESH_* `which` (0-4 float64, 100-101 int32), not a view.")
        .def(
            "_readonly_view",
            [](const PyTriangleMesh& self, int32_t which) -> py::array {
                MeshPtr h = self.h;
                if (which >= O3D_MESH_TRIANGLES) {
                    const int32_t* data = nullptr;
                    size_t n = 0;
                    locked_const(h, [&](const o3d_trianglemesh_t* m) {
                        return o3d_trianglemesh_index_array_view(&data, &n, m, which);
                    });
                    return int_view(const_cast<int32_t*>(data), n, which == O3D_MESH_TRIANGLES, keepalive(h), false);
                }
                const double* data = nullptr;
                size_t n = 0;
                locked_const(h, [&](const o3d_trianglemesh_t* m) { return o3d_trianglemesh_array_view(&data, &n, m, which); });
                return view_array(data, n, which == O3D_MESH_TRIANGLE_UVS ? 2 : 3, keepalive(h), false);
            },
            py::arg("which"), "Read-only zero-copy view of the array O3D_MESH_* `which`.");
}

}  // namespace o3dpy
