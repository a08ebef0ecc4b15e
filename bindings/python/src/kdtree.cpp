// SPDX-License-Identifier: MIT
// o3d.geometry.KDTreeFlann and KDTreeSearchParam* over o3d_kdtree_t (kdtree.h).
#include "common.h"

namespace o3dpy {
namespace {

struct SearchParam {
    o3d_search_param_t p{};
    SearchParam() { check(o3d_search_param_init(&p, sizeof(p))); }
};
struct SearchParamKNN : SearchParam {};
struct SearchParamRadius : SearchParam {};
struct SearchParamHybrid : SearchParam {};

using TreePtr = std::shared_ptr<o3d_kdtree_t>;
using ResultPtr = std::shared_ptr<o3d_search_result_t>;

struct KDTree {
    TreePtr tree;
};

TreePtr tree_from_cloud(const PyPointCloud& pc) {
    o3d_kdtree_t* t = nullptr;
    with_const(pc.h, [&](const o3d_pointcloud_t* c) { return o3d_kdtree_create_from_pointcloud(&t, c); });
    return TreePtr(t, o3d_kdtree_destroy);
}

TreePtr tree_from_data(py::handle data) {
    if (py::isinstance<PyPointCloud>(data)) return tree_from_cloud(data.cast<const PyPointCloud&>());
    Rows3 r = as_rows3(data, "data");
    py::array_t<double, py::array::c_style | py::array::forcecast> d = r.arr;  // float32 -> one conversion
    o3d_kdtree_t* t = nullptr;
    check(nogil([&] { return o3d_kdtree_create_from_points(&t, r.n ? d.data() : nullptr, r.n); }));
    return TreePtr(t, o3d_kdtree_destroy);
}

const TreePtr& need(const KDTree& k) {
    if (!k.tree) invalid("KDTreeFlann has no data: pass a PointCloud or an (N, 3) array, or call set_geometry()");
    return k.tree;
}

ResultPtr run_search(const TreePtr& tree, const Rows3& q, const o3d_search_param_t& p, int32_t num_threads) {
    o3d_search_result_t* res = nullptr;
    check(nogil([&] {
        return q.f32 ? o3d_kdtree_search_f32(tree.get(), static_cast<const float*>(q.data()), q.n, &p, num_threads, &res)
                     : o3d_kdtree_search(tree.get(), static_cast<const double*>(q.data()), q.n, &p, num_threads, &res);
    }));
    return ResultPtr(res, o3d_search_result_destroy);
}

template <typename T>
py::array flat_view(const T* data, size_t n, const py::object& owner) {
    if (!data || n == 0) return py::array_t<T>((py::ssize_t)0);
    py::array a(py::dtype::of<T>(), std::vector<py::ssize_t>{(py::ssize_t)n}, std::vector<py::ssize_t>{(py::ssize_t)sizeof(T)},
                data, owner);
    a.attr("setflags")(py::arg("write") = false);
    return a;
}

// Batch search: (offsets int64 (Q+1,), indices int32 (total,), distances2 float64 (total,)), zero-copy
// read-only views on the C result, which they keep alive.
py::tuple batch(const KDTree& self, py::handle queries, const o3d_search_param_t& p, int32_t num_threads) {
    Rows3 q = as_rows3(queries, "queries");
    ResultPtr r = run_search(need(self), q, p, num_threads);
    size_t nq = 0, total = 0;
    check(o3d_search_result_counts(r.get(), &nq, &total));
    const int64_t* off = nullptr;
    const int32_t* idx = nullptr;
    const double* d2 = nullptr;
    check(o3d_search_result_view(r.get(), &off, &idx, &d2));
    py::object owner = keepalive(r);
    py::array offsets = off ? flat_view(off, nq + 1, owner) : py::array(py::array_t<int64_t>(std::vector<py::ssize_t>{(py::ssize_t)nq + 1}));
    if (!off) std::fill_n(static_cast<int64_t*>(offsets.mutable_data()), nq + 1, int64_t(0));
    return py::make_tuple(offsets, flat_view(idx, total, owner), flat_view(d2, total, owner));
}

// One query, Open3D style: (k, indices, distances2), copied out with o3d_search_result_get_*.
py::tuple single(const KDTree& self, py::handle query, const o3d_search_param_t& p) {
    auto v = as_vec3(query, "query");
    Rows3 q;
    q.arr = py::array_t<double>(std::vector<py::ssize_t>{1, 3}, v.data());
    q.n = 1;
    ResultPtr r = run_search(need(self), q, p, 1);
    size_t nq = 0, total = 0;
    check(o3d_search_result_counts(r.get(), &nq, &total));
    int64_t offsets[2] = {0, 0};
    check(o3d_search_result_get_offsets(r.get(), offsets, 2));
    py::array_t<int32_t> idx((py::ssize_t)total);
    py::array_t<double> d2((py::ssize_t)total);
    check(o3d_search_result_get_indices(r.get(), idx.mutable_data(), total));
    check(o3d_search_result_get_distances2(r.get(), d2.mutable_data(), total));
    return py::make_tuple((int)(offsets[1] - offsets[0]), idx, d2);
}

o3d_search_param_t knn_param(int32_t knn) {
    SearchParam s;
    s.p.kind = O3D_SEARCH_KNN;
    s.p.knn = knn;
    return s.p;
}
o3d_search_param_t radius_param(double radius) {
    SearchParam s;
    s.p.kind = O3D_SEARCH_RADIUS;
    s.p.radius = radius;
    return s.p;
}
o3d_search_param_t hybrid_param(double radius, int32_t max_nn) {
    SearchParam s;
    s.p.kind = O3D_SEARCH_HYBRID;
    s.p.radius = radius;
    s.p.knn = max_nn;
    return s.p;
}

}  // namespace

o3d_search_param_t to_search_param(py::handle obj) {
    if (obj.is_none()) return SearchParam().p;
    if (!py::isinstance<SearchParam>(obj))
        invalid("search_param: expected KDTreeSearchParamKNN, KDTreeSearchParamRadius or KDTreeSearchParamHybrid");
    return obj.cast<const SearchParam&>().p;
}

void declare_kdtree(py::module_& m) {
    py::class_<SearchParam>(m, "KDTreeSearchParam", "Base of the KD-tree search parameters.");
    py::class_<SearchParamKNN, SearchParam>(m, "KDTreeSearchParamKNN", "The knn nearest neighbours.");
    py::class_<SearchParamRadius, SearchParam>(m, "KDTreeSearchParamRadius", "All neighbours within radius.");
    py::class_<SearchParamHybrid, SearchParam>(m, "KDTreeSearchParamHybrid", "At most max_nn nearest neighbours within radius.");
    py::class_<KDTree>(m, "KDTreeFlann", "KD-tree over 3-D points. It copies the points: later edits of the cloud are not seen.");
}

void define_kdtree(py::module_& m) {
    static_cast<py::class_<SearchParam>>(m.attr("KDTreeSearchParam"))
        .def("__repr__", [](const SearchParam& s) {
            return "KDTreeSearchParam(kind=" + std::to_string(s.p.kind) + ", knn=" + std::to_string(s.p.knn) +
                   ", radius=" + std::to_string(s.p.radius) + ")";
        });
    static_cast<py::class_<SearchParamKNN, SearchParam>>(m.attr("KDTreeSearchParamKNN"))
        .def(py::init([](int32_t knn) {
                 SearchParamKNN s;
                 s.p = knn_param(knn);
                 return s;
             }),
             py::arg("knn") = 30)
        .def_property(
            "knn", [](const SearchParamKNN& s) { return s.p.knn; }, [](SearchParamKNN& s, int32_t v) { s.p.knn = v; })
        .def("__repr__", [](const SearchParamKNN& s) { return "KDTreeSearchParamKNN(knn=" + std::to_string(s.p.knn) + ")"; });
    static_cast<py::class_<SearchParamRadius, SearchParam>>(m.attr("KDTreeSearchParamRadius"))
        .def(py::init([](double radius) {
                 SearchParamRadius s;
                 s.p = radius_param(radius);
                 return s;
             }),
             py::arg("radius"))
        .def_property(
            "radius", [](const SearchParamRadius& s) { return s.p.radius; },
            [](SearchParamRadius& s, double v) { s.p.radius = v; })
        .def("__repr__",
             [](const SearchParamRadius& s) { return "KDTreeSearchParamRadius(radius=" + std::to_string(s.p.radius) + ")"; });
    static_cast<py::class_<SearchParamHybrid, SearchParam>>(m.attr("KDTreeSearchParamHybrid"))
        .def(py::init([](double radius, int32_t max_nn) {
                 SearchParamHybrid s;
                 s.p = hybrid_param(radius, max_nn);
                 return s;
             }),
             py::arg("radius"), py::arg("max_nn"))
        .def_property(
            "radius", [](const SearchParamHybrid& s) { return s.p.radius; },
            [](SearchParamHybrid& s, double v) { s.p.radius = v; })
        .def_property(
            "max_nn", [](const SearchParamHybrid& s) { return s.p.knn; }, [](SearchParamHybrid& s, int32_t v) { s.p.knn = v; })
        .def("__repr__", [](const SearchParamHybrid& s) {
            return "KDTreeSearchParamHybrid(radius=" + std::to_string(s.p.radius) + ", max_nn=" + std::to_string(s.p.knn) + ")";
        });

    static_cast<py::class_<KDTree>>(m.attr("KDTreeFlann"))
        .def(py::init<>(), "An empty tree; call set_geometry() before searching.")
        .def(py::init([](py::handle data) { return KDTree{tree_from_data(data)}; }), py::arg("data"),
             "A tree over a PointCloud's points or an (N, 3) float64/float32 array.")
        .def(
            "set_geometry",
            [](KDTree& self, const PyPointCloud& geometry) {
                self.tree = tree_from_cloud(geometry);
                return true;
            },
            py::arg("geometry"))
        .def(
            "set_matrix_data",
            [](KDTree& self, py::handle data) {
                self.tree = tree_from_data(data);
                return true;
            },
            py::arg("data"), "Index an (N, 3) array.")
        .def("size",
             [](const KDTree& self) {
                 size_t n = 0;
                 if (self.tree) check(o3d_kdtree_size(self.tree.get(), &n));
                 return n;
             })
        .def("__len__",
             [](const KDTree& self) {
                 size_t n = 0;
                 if (self.tree) check(o3d_kdtree_size(self.tree.get(), &n));
                 return n;
             })
        .def(
            "search_vector_3d",
            [](const KDTree& self, py::handle query, py::handle search_param) {
                return single(self, query, to_search_param(search_param));
            },
            py::arg("query"), py::arg("search_param"))
        .def(
            "search_knn_vector_3d",
            [](const KDTree& self, py::handle query, int32_t knn) { return single(self, query, knn_param(knn)); },
            py::arg("query"), py::arg("knn"),
            "(k, indices, distances2) of the knn nearest points, nearest first (squared distances).")
        .def(
            "search_radius_vector_3d",
            [](const KDTree& self, py::handle query, double radius) { return single(self, query, radius_param(radius)); },
            py::arg("query"), py::arg("radius"))
        .def(
            "search_hybrid_vector_3d",
            [](const KDTree& self, py::handle query, double radius, int32_t max_nn) {
                return single(self, query, hybrid_param(radius, max_nn));
            },
            py::arg("query"), py::arg("radius"), py::arg("max_nn"))
        .def(
            "search",
            [](const KDTree& self, py::handle queries, py::handle search_param, int32_t num_threads) {
                return batch(self, queries, to_search_param(search_param), num_threads);
            },
            py::arg("queries"), py::arg("search_param"), py::arg("num_threads") = 0,
            "Batch search of (Q, 3) queries: (offsets, indices, distances2); the neighbours of query i are "
            "indices[offsets[i]:offsets[i+1]].")
        .def(
            "search_knn",
            [](const KDTree& self, py::handle queries, int32_t knn, int32_t num_threads) {
                return batch(self, queries, knn_param(knn), num_threads);
            },
            py::arg("queries"), py::arg("knn"), py::arg("num_threads") = 0)
        .def(
            "search_radius",
            [](const KDTree& self, py::handle queries, double radius, int32_t num_threads) {
                return batch(self, queries, radius_param(radius), num_threads);
            },
            py::arg("queries"), py::arg("radius"), py::arg("num_threads") = 0)
        .def(
            "search_hybrid",
            [](const KDTree& self, py::handle queries, double radius, int32_t max_nn, int32_t num_threads) {
                return batch(self, queries, hybrid_param(radius, max_nn), num_threads);
            },
            py::arg("queries"), py::arg("radius"), py::arg("max_nn"), py::arg("num_threads") = 0);
}

}  // namespace o3dpy
