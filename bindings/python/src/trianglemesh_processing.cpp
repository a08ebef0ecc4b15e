// SPDX-License-Identifier: MIT
// o3d.geometry.TriangleMesh processing and primitives that take more than the C call's arguments (Poisson-disk
// sampling, crop, the create_* primitives with Open3D's UV flags, create_mobius), with Open3D 0.20's names and
// keyword defaults; the rest (uniform sampling, simplification, smoothing, subdivision) is generated
// (def_triangle_mesh_methods). Each C call runs with the GIL released and writes a new mesh or cloud.
#include "geometry_types.h"

namespace o3dpy {
namespace {

template <typename F>
PyTriangleMesh derive_mesh(const PyTriangleMesh& self, F&& f) {
    o3d_trianglemesh_t* out = nullptr;
    locked_const(self.h, [&](const o3d_trianglemesh_t* m) { return f(&out, m); });
    return PyTriangleMesh(out);
}

template <typename F>
PyPointCloud derive_cloud(const PyTriangleMesh& self, F&& f) {
    o3d_pointcloud_t* out = nullptr;
    locked_const(self.h, [&](const o3d_trianglemesh_t* m) { return f(&out, m); });
    return PyPointCloud(adopt(out));
}

template <typename F>
PyTriangleMesh primitive(F&& f) {
    o3d_trianglemesh_t* out = nullptr;
    check(nogil([&] { return f(&out); }));
    return PyTriangleMesh(out);
}

/// Open3D's create_uv_map / map_texture_to_each_face: the C primitives make no UVs, so asking for them
/// raises rather than silently returning a mesh without them.
void no_uv_map(bool create_uv_map, const char* fn) {
    if (create_uv_map)
        throw StatusError{O3D_ERROR_UNSUPPORTED, std::string(fn) + ": create_uv_map=True is not supported", ""};
}

}  // namespace

void declare_trianglemesh_enums(py::module_& m) {
    def_enum<SimplificationContraction>(m);
    def_enum<FilterScope>(m);
}

void define_trianglemesh_processing(py::module_& m) {
    auto cls = static_cast<py::class_<PyTriangleMesh>>(m.attr("TriangleMesh"));
    cls.def(
            "sample_points_poisson_disk",
            [](const PyTriangleMesh& self, int64_t number_of_points, double init_factor, py::handle pcl,
               bool use_triangle_normal, py::handle seed) {
                if (!pcl.is_none())
                    throw StatusError{O3D_ERROR_UNSUPPORTED,
                                      "sample_points_poisson_disk: an initial point cloud (pcl) is not supported", ""};
                const size_t n = non_negative(number_of_points, "number_of_points");
                const uint64_t s = seed_or_random(seed);
                return derive_cloud(self, [&](o3d_pointcloud_t** out, const o3d_trianglemesh_t* m) {
                    return o3d_trianglemesh_sample_points_poisson_disk(out, m, n, init_factor, use_triangle_normal ? 1 : 0, s);
                });
            },
            py::arg("number_of_points"), py::arg("init_factor") = 5.0, py::arg("pcl") = py::none(),
            py::arg("use_triangle_normal") = false, py::arg("seed") = py::none(),
            "Poisson-disk samples by sample elimination from init_factor * number_of_points uniform samples. "
            "pcl (Open3D's initial cloud) must be None.")
        .def(
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

    cls.def_static(
           "create_box",
           [](double width, double height, double depth, bool create_uv_map, bool map_texture_to_each_face) {
               no_uv_map(create_uv_map || map_texture_to_each_face, "create_box");
               return primitive([&](o3d_trianglemesh_t** out) { return o3d_trianglemesh_create_box(out, width, height, depth); });
           },
           py::arg("width") = 1.0, py::arg("height") = 1.0, py::arg("depth") = 1.0, py::arg("create_uv_map") = false,
           py::arg("map_texture_to_each_face") = false, "Box [0,width] x [0,height] x [0,depth].")
        .def_static(
            "create_sphere",
            [](double radius, int64_t resolution, bool create_uv_map) {
                no_uv_map(create_uv_map, "create_sphere");
                const int32_t r = int32_of(resolution, "resolution");
                return primitive([&](o3d_trianglemesh_t** out) { return o3d_trianglemesh_create_sphere(out, radius, r); });
            },
            py::arg("radius") = 1.0, py::arg("resolution") = 20, py::arg("create_uv_map") = false)
        .def_static(
            "create_cylinder",
            [](double radius, double height, int64_t resolution, int64_t split, bool create_uv_map) {
                no_uv_map(create_uv_map, "create_cylinder");
                const int32_t r = int32_of(resolution, "resolution"), s = int32_of(split, "split");
                return primitive(
                    [&](o3d_trianglemesh_t** out) { return o3d_trianglemesh_create_cylinder(out, radius, height, r, s); });
            },
            py::arg("radius") = 1.0, py::arg("height") = 2.0, py::arg("resolution") = 20, py::arg("split") = 4,
            py::arg("create_uv_map") = false)
        .def_static(
            "create_cone",
            [](double radius, double height, int64_t resolution, int64_t split, bool create_uv_map) {
                no_uv_map(create_uv_map, "create_cone");
                const int32_t r = int32_of(resolution, "resolution"), s = int32_of(split, "split");
                return primitive(
                    [&](o3d_trianglemesh_t** out) { return o3d_trianglemesh_create_cone(out, radius, height, r, s); });
            },
            py::arg("radius") = 1.0, py::arg("height") = 2.0, py::arg("resolution") = 20, py::arg("split") = 1,
            py::arg("create_uv_map") = false)
        .def_static(
            "create_tetrahedron",
            [](double radius, bool create_uv_map) {
                no_uv_map(create_uv_map, "create_tetrahedron");
                return primitive([&](o3d_trianglemesh_t** out) { return o3d_trianglemesh_create_tetrahedron(out, radius); });
            },
            py::arg("radius") = 1.0, py::arg("create_uv_map") = false)
        .def_static(
            "create_octahedron",
            [](double radius, bool create_uv_map) {
                no_uv_map(create_uv_map, "create_octahedron");
                return primitive([&](o3d_trianglemesh_t** out) { return o3d_trianglemesh_create_octahedron(out, radius); });
            },
            py::arg("radius") = 1.0, py::arg("create_uv_map") = false)
        .def_static(
            "create_icosahedron",
            [](double radius, bool create_uv_map) {
                no_uv_map(create_uv_map, "create_icosahedron");
                return primitive([&](o3d_trianglemesh_t** out) { return o3d_trianglemesh_create_icosahedron(out, radius); });
            },
            py::arg("radius") = 1.0, py::arg("create_uv_map") = false);
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
