// SPDX-License-Identifier: MIT
// o3d.geometry.Octree over o3d_octree_t (octree.h). locate_leaf_node builds its Open3D result objects
// (OctreePointColorLeafNode, OctreeNodeInfo) in o3d/geometry.py from _locate_leaf_node().
#include <limits>
#include <vector>

#include "generated/octree_methods.h"

namespace o3dpy {
namespace {

void root(const PyOctree& self, double* origin, double* size, int32_t* depth) {
    locked_const(self.h, [&](const o3d_octree_t* o) { return o3d_octree_get_root(origin, size, depth, o); });
}

}  // namespace

void declare_octree(py::module_& m) {
    py::class_<PyOctree>(m, "Octree",
                         "Octree over a point cloud: a cube of edge size at origin split to max_depth; each leaf "
                         "keeps the indices of its points and their mean color.");
}

void define_octree(py::module_& m) {
    auto cls = static_cast<py::class_<PyOctree>>(m.attr("Octree"));
    cls.def(py::init([](int64_t max_depth) {
                if (max_depth < 1 || max_depth > std::numeric_limits<int32_t>::max())
                    invalid("Octree: max_depth must be >= 1, got " + std::to_string(max_depth));
                o3d_octree_t* raw = nullptr;
                check(o3d_octree_create(&raw, (int32_t)max_depth));
                return PyOctree(raw);
            }),
            py::arg("max_depth"), "An empty octree of max_depth >= 1.")
        .def_property_readonly("max_depth",
                               [](const PyOctree& self) {
                                   int32_t d = 0;
                                   root(self, nullptr, nullptr, &d);
                                   return d;
                               })
        .def_property_readonly("origin",
                               [](const PyOctree& self) {
                                   double o[3];
                                   root(self, o, nullptr, nullptr);
                                   return vec3_to_array(o);
                               })
        .def_property_readonly("size",
                               [](const PyOctree& self) {
                                   double s = 0;
                                   root(self, nullptr, &s, nullptr);
                                   return s;
                               })
        .def("is_empty",
             [](const PyOctree& self) {
                 size_t n = 0;
                 locked_const(self.h, [&](const o3d_octree_t* o) { return o3d_octree_num_leaf_nodes(&n, o); });
                 return n == 0;
             })
        .def(
            "_locate_leaf_node",
            [](const PyOctree& self, py::handle point) -> py::object {
                auto p = as_vec3(point, "point");
                int32_t found = 0;
                o3d_octree_node_info_t info{};
                double color[3] = {0, 0, 0};
                std::vector<int32_t> idx;
                size_t n = 0;
                locked_const(self.h, [&](const o3d_octree_t* o) {
                    o3d_status s = o3d_octree_locate_leaf_node(&found, &info, color, nullptr, 0, &n, o, p.data());
                    if (s != O3D_OK && s != O3D_ERROR_BUFFER_TOO_SMALL) return s;
                    if (!found) return O3D_OK;
                    idx.resize(n);
                    return o3d_octree_locate_leaf_node(&found, &info, color, idx.data(), idx.size(), &n, o, p.data());
                });
                if (!found) return py::none();
                return py::make_tuple(int_list(idx.data(), std::min(n, idx.size())), vec3_to_array(color),
                                      vec3_to_array(info.origin), info.size, info.depth, info.child_index);
            },
            py::arg("point"), "None, or (indices, color, origin, size, depth, child_index) of the leaf holding point.")
        .def_static(
            "is_point_in_bound",
            [](py::handle point, py::handle origin, double size) {
                const auto p = as_vec3(point, "point");
                const auto o = as_vec3(origin, "origin");
                int32_t in = 0;
                check(o3d_octree_is_point_in_bound(&in, p.data(), o.data(), size));
                return in != 0;
            },
            py::arg("point"), py::arg("origin"), py::arg("size"),
            "Whether point lies in the half-open cube [origin, origin + size)^3.");
    def_octree_methods(cls);
}

}  // namespace o3dpy
