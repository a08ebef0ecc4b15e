// SPDX-License-Identifier: MIT
// Open3D 0.20's geometry algorithms whose C calls take or give more than plain values (index lists, boxes and
// ellipsoids, buffers of rows, search parameters): TriangleMesh adjacency, non-manifold and self-intersection
// queries, minimal boxes and ellipsoids, ARAP deformation; PointCloud smoothing, planar patches, point covariances
// and traced down-sampling; OrientedBoundingBox.create_from_points_minimal and OrientedBoundingEllipsoid's C half.
// The plain ones (is_intersecting, orient_triangles, filter_sharpen, create_ellipsoid, smooth_laplacian,
// smooth_taubin) are generated. Every C call runs with the GIL released.
#include "geometry_types.h"

namespace o3dpy {

o3d_status read_index_lists(IndexRows& out, const o3d_index_lists_t* lists) {
    size_t n = 0, total = 0, got = 0;
    o3d_status s = o3d_index_lists_num_lists(&n, lists);
    if (s == O3D_OK) s = o3d_index_lists_num_values(&total, lists);
    if (s != O3D_OK) return s;
    out.offsets.assign(n + 1, 0);
    out.values.assign(total, 0);
    s = o3d_index_lists_get_offsets(out.offsets.data(), out.offsets.size(), &got, lists);
    if (s != O3D_OK) return s;
    return o3d_index_lists_get_values(total ? out.values.data() : nullptr, total, &got, lists);
}

py::list index_rows_to_python(const IndexRows& rows, bool as_sets) {
    const size_t n = rows.size();
    py::list out(n);
    for (size_t i = 0; i < n; ++i) {
        const int32_t* v = rows.values.data() + rows.offsets[i];
        const size_t len = (size_t)(rows.offsets[i + 1] - rows.offsets[i]);
        if (as_sets) {
            py::set s;
            for (size_t k = 0; k < len; ++k) s.add(py::int_(v[k]));
            out[i] = std::move(s);
        } else {
            py::array_t<int32_t> a((py::ssize_t)len);
            if (len) std::memcpy(a.mutable_data(), v, len * sizeof(int32_t));
            out[i] = std::move(a);
        }
    }
    return out;
}

py::list index_lists_to_python(const IndexLists& lists, bool as_sets) {
    IndexRows rows;
    check(nogil([&] { return read_index_lists(rows, lists.get()); }));
    return index_rows_to_python(rows, as_sets);
}

namespace {

py::object ellipsoid_class() { return py::module_::import("o3d.geometry").attr("OrientedBoundingEllipsoid"); }

py::tuple obe_tuple(const o3d_obe_t& obe) {
    return py::make_tuple(vec3_to_array(obe.center), mat_to_array(obe.R, 3, 3), vec3_to_array(obe.radii));
}

size_t num_triangles(const PyTriangleMesh& self) {
    size_t n = 0;
    locked_const(self.h, [&](const o3d_trianglemesh_t* m) { return o3d_trianglemesh_num_triangles(&n, m); });
    return n;
}

size_t num_vertices(const PyTriangleMesh& self) {
    size_t n = 0;
    locked_const(self.h, [&](const o3d_trianglemesh_t* m) { return o3d_trianglemesh_num_vertices(&n, m); });
    return n;
}

size_t cloud_size(const PyPointCloud& self) {
    size_t n = 0;
    locked_const(self.h, [&](const o3d_pointcloud_t* pc) { return o3d_pointcloud_size(&n, pc); });
    return n;
}

/// The C search parameter of a KDTreeSearchParam, or NULL (the C call's Open3D default) for None.
struct OptionalSearch {
    o3d_search_param_t p{};
    bool set = false;
    explicit OptionalSearch(py::handle obj) {
        if (!obj.is_none()) {
            p = to_search_param(obj);
            set = true;
        }
    }
    const o3d_search_param_t* get() const { return set ? &p : nullptr; }
};

/// An ellipsoid of (N, 3) points, or one of the geometry's points (`f(out, handle)`).
template <typename G, typename F>
py::object ellipsoid_of(const G& self, F&& f) {
    o3d_obe_t obe{};
    locked_const(self.h, [&](auto p) { return f(&obe, p); });
    return make_obe(obe);
}

std::vector<std::vector<int32_t>> rows_to_vectors(const IndexRows& rows) {
    std::vector<std::vector<int32_t>> out(rows.size());
    for (size_t i = 0; i < rows.size(); ++i)
        out[i].assign(rows.values.begin() + rows.offsets[i], rows.values.begin() + rows.offsets[i + 1]);
    return out;
}

std::vector<std::vector<int32_t>> adjacency_from_python(py::handle value) {
    std::vector<std::vector<int32_t>> out;
    for (py::handle row : py::iter(value)) {
        std::vector<int32_t> r;
        for (py::handle v : py::iter(row)) r.push_back(int32_of(py::cast<int64_t>(v), "adjacency_list"));
        std::sort(r.begin(), r.end());
        r.erase(std::unique(r.begin(), r.end()), r.end());
        out.push_back(std::move(r));
    }
    return out;
}

py::list adjacency_to_python(const std::vector<std::vector<int32_t>>& adjacency) {
    py::list out(adjacency.size());
    for (size_t i = 0; i < adjacency.size(); ++i) {
        py::set s;
        for (int32_t v : adjacency[i]) s.add(py::int_(v));
        out[i] = std::move(s);
    }
    return out;
}

void define_mesh(py::module_& m) {
    auto cls = static_cast<py::class_<PyTriangleMesh>>(m.attr("TriangleMesh"));
    cls.def(
           "compute_adjacency_list",
           [](py::object self) {
               PyTriangleMesh& me = self.cast<PyTriangleMesh&>();
               o3d_index_lists_t* raw = nullptr;
               locked_const(me.h, [&](const o3d_trianglemesh_t* p) {
                   return o3d_trianglemesh_compute_adjacency_list(&raw, p);
               });
               IndexLists lists = own_lists(raw);
               IndexRows rows;
               check(nogil([&] { return read_index_lists(rows, lists.get()); }));
               me.adjacency = rows_to_vectors(rows);
               return self;
           },
           "Fill adjacency_list: per vertex the vertices joined to it by a triangle side. Returns self.")
        .def_property(
            "adjacency_list", [](const PyTriangleMesh& self) { return adjacency_to_python(self.adjacency); },
            [](PyTriangleMesh& self, py::handle value) { self.adjacency = adjacency_from_python(value); },
            "The vertex adjacency list compute_adjacency_list filled: a list (one per vertex) of sets of vertex "
            "indices (a copy, as Open3D's; assign a list to replace it).")
        .def(
            "has_adjacency_list",
            [](const PyTriangleMesh& self) {
                const size_t n = num_vertices(self);
                return n > 0 && self.adjacency.size() == n;
            },
            "Whether adjacency_list has one entry per vertex (of a mesh with vertices).")
        .def(
            "get_non_manifold_edges",
            [](const PyTriangleMesh& self, bool allow_boundary_edges) {
                auto v = read_rows<int32_t>(self.h, 2, 3 * num_triangles(self),
                                            [&](int32_t* out, size_t cap, size_t* n, const o3d_trianglemesh_t* p) {
                                                return o3d_trianglemesh_get_non_manifold_edges(
                                                    out, cap, n, p, allow_boundary_edges ? 1 : 0);
                                            });
                return to_numpy(v, {(py::ssize_t)(v.size() / 2), 2});
            },
            py::arg("allow_boundary_edges") = true,
            "The non-manifold edges as an (E, 2) int32 array of (min, max) vertex indices, ascending: edges of more "
            "than two triangles, and of one when allow_boundary_edges is False.")
        .def(
            "get_non_manifold_vertices",
            [](const PyTriangleMesh& self) {
                auto v = read_rows<int32_t>(self.h, 1, num_vertices(self),
                                            [&](int32_t* out, size_t cap, size_t* n, const o3d_trianglemesh_t* p) {
                                                return o3d_trianglemesh_get_non_manifold_vertices(out, cap, n, p);
                                            });
                return to_numpy(v, {(py::ssize_t)v.size()});
            },
            "The vertices whose triangles do not form one fan, ascending ((K,) int32 array).")
        .def(
            "get_self_intersecting_triangles",
            [](const PyTriangleMesh& self) {
                auto v = read_rows<int32_t>(self.h, 2, num_triangles(self),
                                            [&](int32_t* out, size_t cap, size_t* n, const o3d_trianglemesh_t* p) {
                                                return o3d_trianglemesh_get_self_intersecting_triangles(out, cap, n, p);
                                            });
                return to_numpy(v, {(py::ssize_t)(v.size() / 2), 2});
            },
            "The pairs (i < j) of triangles that share no vertex and intersect, ascending ((K, 2) int32 array).")
        .def(
            "get_minimal_oriented_bounding_box",
            [](const PyTriangleMesh& self, bool robust) {
                o3d_obb_t obb{};
                locked_const(self.h, [&](const o3d_trianglemesh_t* p) {
                    return o3d_trianglemesh_get_minimal_oriented_bounding_box(&obb, p, robust ? 1 : 0);
                });
                return make_obb(obb);
            },
            py::arg("robust") = false,
            "The minimum-volume oriented box of the vertices; robust=True joggles them so flat meshes still give a "
            "box.")
        .def(
            "get_oriented_bounding_ellipsoid",
            [](const PyTriangleMesh& self, bool robust) {
                return ellipsoid_of(self, [&](o3d_obe_t* out, const o3d_trianglemesh_t* p) {
                    return o3d_trianglemesh_get_oriented_bounding_ellipsoid(out, p, robust ? 1 : 0);
                });
            },
            py::arg("robust") = false, "The minimum-volume enclosing ellipsoid of the vertices (Khachiyan).")
        .def_static(
            "create_from_oriented_bounding_box",
            [](py::handle obox, py::handle scale, bool create_uv_map) {
                const o3d_obb_t obb = obb_of(obox);
                const auto sc = as_vec3(scale, "scale");
                o3d_trianglemesh_t* out = nullptr;
                check(nogil([&] {
                    return o3d_trianglemesh_create_from_oriented_bounding_box(&out, &obb, sc.data(),
                                                                             create_uv_map ? 1 : 0);
                }));
                return PyTriangleMesh(out);
            },
            py::arg("obox"), py::arg("scale") = py::make_tuple(1.0, 1.0, 1.0), py::arg("create_uv_map") = false,
            "The box as a closed mesh (8 vertices in get_box_points order, 12 triangles wound outwards), its extent "
            "multiplied by scale about the centre.")
        .def_static(
            "create_from_oriented_bounding_ellipsoid",
            [](py::handle obel, py::handle scale, int64_t resolution, bool create_uv_map) {
                const o3d_obe_t obe = obe_of(obel);
                const auto sc = as_vec3(scale, "scale");
                const int32_t res = int32_of(resolution, "resolution");
                o3d_trianglemesh_t* out = nullptr;
                check(nogil([&] {
                    return o3d_trianglemesh_create_from_oriented_bounding_ellipsoid(&out, &obe, sc.data(), res,
                                                                                   create_uv_map ? 1 : 0);
                }));
                return PyTriangleMesh(out);
            },
            py::arg("obel"), py::arg("scale") = py::make_tuple(1.0, 1.0, 1.0), py::arg("resolution") = 20,
            py::arg("create_uv_map") = false,
            "The ellipsoid as a mesh (create_ellipsoid of its radii times scale, rotated by R and moved to its "
            "centre), painted white.")
        .def(
            "deform_as_rigid_as_possible",
            [](const PyTriangleMesh& self, py::handle constraint_vertex_indices, py::handle constraint_vertex_positions,
               int64_t max_iter, DeformAsRigidAsPossibleEnergy energy, double smoothed_alpha) {
                const std::vector<int32_t> idx = int32_indices(constraint_vertex_indices, "constraint_vertex_indices");
                const auto pos = rows3_f64(constraint_vertex_positions, "constraint_vertex_positions");
                const size_t npos = (size_t)pos.shape(0);
                const int32_t iters = int32_of(max_iter, "max_iter");
                o3d_trianglemesh_t* out = nullptr;
                locked_const(self.h, [&](const o3d_trianglemesh_t* p) {
                    return o3d_trianglemesh_deform_as_rigid_as_possible(
                        &out, p, idx.empty() ? nullptr : idx.data(), idx.size(), npos ? pos.data() : nullptr, npos,
                        iters, (int32_t)energy, smoothed_alpha);
                });
                return PyTriangleMesh(out);
            },
            py::arg("constraint_vertex_indices"), py::arg("constraint_vertex_positions"), py::arg("max_iter"),
            py::arg("energy") = DeformAsRigidAsPossibleEnergy::Spokes, py::arg("smoothed_alpha") = 0.01,
            "As-rigid-as-possible deformation (Sorkine & Alexa 2007): a new mesh (vertices and triangles) whose "
            "constrained vertices sit at constraint_vertex_positions and whose one-rings turn as rigidly as they "
            "can, after max_iter rotation/solve rounds.");
}

void define_cloud(py::module_& m) {
    auto cls = static_cast<py::class_<PyPointCloud>>(m.attr("PointCloud"));
    cls.def(
           "smooth_mls",
           [](const PyPointCloud& self, py::handle search_param) {
               const OptionalSearch sp(search_param);
               o3d_pointcloud_t* out = nullptr;
               locked_const(self.h, [&](const o3d_pointcloud_t* pc) { return o3d_pointcloud_smooth_mls(&out, pc, sp.get()); });
               return PyPointCloud(out);
           },
           py::arg("search_param") = py::none(),
           "A new cloud, each point projected onto the weighted PCA plane of its neighbours (MLS-style). "
           "search_param None: Open3D's KDTreeSearchParamHybrid(radius=0.05, max_nn=30).")
        .def(
            "smooth_bilateral",
            [](const PyPointCloud& self, py::handle search_param, double sigma_s, double sigma_r) {
                const OptionalSearch sp(search_param);
                o3d_pointcloud_t* out = nullptr;
                locked_const(self.h, [&](const o3d_pointcloud_t* pc) {
                    return o3d_pointcloud_smooth_bilateral(&out, pc, sp.get(), sigma_s, sigma_r);
                });
                return PyPointCloud(out);
            },
            py::arg("search_param") = py::none(), py::arg("sigma_s") = 0.05, py::arg("sigma_r") = 0.05,
            "A new cloud, each point the average of its neighbours weighted by distance (sigma_s) and by offset "
            "along its normal (sigma_r). search_param None: KDTreeSearchParamHybrid(radius=0.05, max_nn=30).")
        .def(
            "get_minimal_oriented_bounding_box",
            [](const PyPointCloud& self, bool robust) {
                o3d_obb_t obb{};
                locked_const(self.h, [&](const o3d_pointcloud_t* pc) {
                    return o3d_pointcloud_get_minimal_oriented_bounding_box(&obb, pc, robust ? 1 : 0);
                });
                return make_obb(obb);
            },
            py::arg("robust") = false,
            "The minimum-volume oriented box of the points; robust=True joggles them so flat clouds still give a box.")
        .def(
            "get_oriented_bounding_ellipsoid",
            [](const PyPointCloud& self, bool robust) {
                return ellipsoid_of(self, [&](o3d_obe_t* out, const o3d_pointcloud_t* pc) {
                    return o3d_pointcloud_get_oriented_bounding_ellipsoid(out, pc, robust ? 1 : 0);
                });
            },
            py::arg("robust") = false, "The minimum-volume enclosing ellipsoid of the points (Khachiyan).")
        .def_static(
            "estimate_point_covariances",
            [](const PyPointCloud& input, py::handle search_param, int64_t num_threads) {
                const OptionalSearch sp(search_param);
                const int32_t threads = int32_of(num_threads, "num_threads");
                auto v = read_rows<double>(input.h, 9, cloud_size(input),
                                           [&](double* out, size_t cap, size_t* n, const o3d_pointcloud_t* pc) {
                                               return o3d_pointcloud_estimate_point_covariances(out, cap, n, pc,
                                                                                                sp.get(), threads);
                                           });
                return to_numpy(v, {(py::ssize_t)(v.size() / 9), 3, 3});
            },
            py::arg("input"), py::arg("search_param") = py::none(), py::kw_only(), py::arg("num_threads") = 0,
            "Each point's neighbourhood covariance as an (N, 3, 3) array, without changing the cloud. "
            "search_param None: KDTreeSearchParamKNN(30).");

    const o3d_planar_patch_options_t po = init_of(&o3d_planar_patch_options_init);
    cls.def(
           "detect_planar_patches",
           [](const PyPointCloud& self, double normal_variance_threshold_deg, double coplanarity_deg,
              double outlier_ratio, double min_plane_edge_length, int64_t min_num_points, py::handle search_param,
              int64_t num_threads) {
               o3d_planar_patch_options_t o = init_of(&o3d_planar_patch_options_init);
               o.normal_variance_threshold_deg = normal_variance_threshold_deg;
               o.coplanarity_deg = coplanarity_deg;
               o.outlier_ratio = outlier_ratio;
               o.min_plane_edge_length = min_plane_edge_length;
               o.min_num_points = int32_of(min_num_points, "min_num_points");
               if (!search_param.is_none()) o.search_param = to_search_param(search_param);
               o.num_threads = int32_of(num_threads, "num_threads");
               static_assert(sizeof(o3d_obb_t) == 15 * sizeof(double), "a patch is one o3d_obb_t");
               auto boxes = read_rows<o3d_obb_t>(self.h, 1, 64,
                                                 [&](o3d_obb_t* out, size_t cap, size_t* n, const o3d_pointcloud_t* pc) {
                                                     return o3d_pointcloud_detect_planar_patches(
                                                         reinterpret_cast<double*>(out), cap, n, pc, &o);
                                                 });
               py::list out;
               for (const auto& b : boxes) out.append(make_obb(b));
               return out;
           },
           py::arg("normal_variance_threshold_deg") = po.normal_variance_threshold_deg,
           py::arg("coplanarity_deg") = po.coplanarity_deg, py::arg("outlier_ratio") = po.outlier_ratio,
           py::arg("min_plane_edge_length") = po.min_plane_edge_length, py::arg("min_num_points") = po.min_num_points,
           py::arg("search_param") = py::none(), py::kw_only(), py::arg("num_threads") = po.num_threads,
           "Planar patches (Araujo & Oliveira 2020) as a list of OrientedBoundingBox, largest first (R[:, 2] the "
           "patch normal). The cloud needs normals. search_param None: KDTreeSearchParamKNN(30).")
        .def(
            "voxel_down_sample_and_trace",
            [](const PyPointCloud& self, double voxel_size, py::handle min_bound, py::handle max_bound,
               bool approximate_class) {
                const auto lo = as_vec3(min_bound, "min_bound");
                const auto hi = as_vec3(max_bound, "max_bound");
                o3d_pointcloud_t* out = nullptr;
                o3d_index_lists_t *cubic = nullptr, *orig = nullptr;
                locked_const(self.h, [&](const o3d_pointcloud_t* pc) {
                    return o3d_pointcloud_voxel_down_sample_and_trace(&out, &cubic, &orig, pc, voxel_size, lo.data(),
                                                                      hi.data(), approximate_class ? 1 : 0);
                });
                PyPointCloud cloud(out);
                IndexLists cubic_ids = own_lists(cubic), original = own_lists(orig);
                IndexRows rows;
                check(nogil([&] { return read_index_lists(rows, cubic_ids.get()); }));
                if (rows.values.size() != rows.size() * 8) invalid("voxel_down_sample_and_trace: cubic ids not 8 per point");
                py::array cubic_id = to_numpy(rows.values, {(py::ssize_t)rows.size(), 8});
                return py::make_tuple(std::move(cloud), cubic_id, index_lists_to_python(original, false));
            },
            py::arg("voxel_size"), py::arg("min_bound"), py::arg("max_bound"), py::arg("approximate_class") = false,
            "(down-sampled cloud, cubic_id (N, 8) int32: per octant of each voxel the largest input index in it or "
            "-1, list of (n_i,) int32 arrays: the input indices each output point averages).");
}

}  // namespace

o3d_obe_t obe_of(py::handle ellipsoid) {
    if (!py::isinstance(ellipsoid, ellipsoid_class()))
        throw py::type_error("expected an o3d.geometry.OrientedBoundingEllipsoid, got " +
                             std::string(py::str(py::type::handle_of(ellipsoid).attr("__name__"))));
    o3d_obe_t obe{};
    const auto c = as_vec3(ellipsoid.attr("center"), "OrientedBoundingEllipsoid.center");
    const auto r = as_mat3(ellipsoid.attr("R"), "OrientedBoundingEllipsoid.R");
    const auto e = as_vec3(ellipsoid.attr("radii"), "OrientedBoundingEllipsoid.radii");
    std::memcpy(obe.center, c.data(), sizeof(obe.center));
    std::memcpy(obe.R, r.data(), sizeof(obe.R));
    std::memcpy(obe.radii, e.data(), sizeof(obe.radii));
    return obe;
}

py::object make_obe(const o3d_obe_t& obe) { return ellipsoid_class()(*obe_tuple(obe)); }

void define_geometry_algorithms(py::module_& m) {
    m.def(
        "_obb_create_from_points_minimal",
        [](py::handle points, bool robust) {
            auto xyz = rows3_f64(points, "points");
            const size_t n = (size_t)xyz.shape(0);
            o3d_obb_t obb{};
            check(nogil([&] {
                return o3d_obb_create_from_points_minimal(&obb, n ? xyz.data() : nullptr, n, robust ? 1 : 0);
            }));
            return py::make_tuple(vec3_to_array(obb.center), mat_to_array(obb.R, 3, 3), vec3_to_array(obb.extent));
        },
        py::arg("points"), py::arg("robust") = false, "(center, R, extent) of the minimal oriented box of (N, 3) points.");
    m.def(
        "_obe_create_from_points",
        [](py::handle points, bool robust) {
            auto xyz = rows3_f64(points, "points");
            const size_t n = (size_t)xyz.shape(0);
            o3d_obe_t obe{};
            check(nogil([&] { return o3d_obe_create_from_points(&obe, n ? xyz.data() : nullptr, n, robust ? 1 : 0); }));
            return obe_tuple(obe);
        },
        py::arg("points"), py::arg("robust") = false,
        "(center, R, radii) of the minimum-volume enclosing ellipsoid of (N, 3) points.");
    define_mesh(m);
    define_cloud(m);
}

}  // namespace o3dpy
