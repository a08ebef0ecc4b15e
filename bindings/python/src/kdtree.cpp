// SPDX-License-Identifier: MIT
// o3d.geometry.KDTreeFlann and KDTreeSearchParam* over o3d_kdtree_t (kdtree.h; trees over features and
// points of any dimension from feature.h).
#include "registration_types.h"

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
    locked_const(pc.h, [&](const o3d_pointcloud_t* c) { return o3d_kdtree_create_from_pointcloud(&t, c); });
    return TreePtr(t, o3d_kdtree_destroy);
}

TreePtr tree_from_feature(const PyFeature& feature) {
    o3d_kdtree_t* t = nullptr;
    locked_const(feature.h, [&](const o3d_feature_t* f) { return o3d_kdtree_create_from_feature(&t, f); });
    return TreePtr(t, o3d_kdtree_destroy);
}

/// (N, d) float64 rows of any d >= 1 (one point per row, as the 3-D trees).
py::array_t<double, py::array::c_style> rows_xd(py::handle obj, const char* what) {
    py::array a = py::array::ensure(obj);
    if (!a) invalid(std::string(what) + ": expected an (N, d) array of numbers");
    char kind = a.dtype().kind();
    if (kind != 'f' && kind != 'i' && kind != 'u') invalid(std::string(what) + ": expected numbers, got dtype " + std::string(py::str(a.dtype())));
    if (a.ndim() != 2) invalid(std::string(what) + ": expected an (N, d) array");
    auto d = py::array_t<double, py::array::c_style | py::array::forcecast>::ensure(a);
    if (!d) throw py::error_already_set();
    return d;
}

bool is_xd_matrix(py::handle data) {
    py::array a = py::array::ensure(data);
    if (!a) {
        PyErr_Clear();
        return false;
    }
    return a.ndim() == 2 && a.shape(1) != 3 && a.size() > 0;
}

TreePtr tree_from_data(py::handle data) {
    if (py::isinstance<PyPointCloud>(data)) return tree_from_cloud(data.cast<const PyPointCloud&>());
    if (py::isinstance<PyFeature>(data)) return tree_from_feature(data.cast<const PyFeature&>());
    if (is_xd_matrix(data)) {  // (N, d), d != 3: a tree over N points of dimension d
        auto d = rows_xd(data, "data");
        o3d_kdtree_t* t = nullptr;
        size_t n = (size_t)d.shape(0), dim = (size_t)d.shape(1);
        check(nogil([&] { return o3d_kdtree_create_from_points_xd(&t, d.data(), dim, n); }));
        return TreePtr(t, o3d_kdtree_destroy);
    }
    Rows3 r = as_rows3(data, "data");
    py::array_t<double, py::array::c_style | py::array::forcecast> d = r.arr;  // float32 -> one conversion
    o3d_kdtree_t* t = nullptr;
    check(nogil([&] { return o3d_kdtree_create_from_points(&t, r.n ? d.data() : nullptr, r.n); }));
    return TreePtr(t, o3d_kdtree_destroy);
}

const TreePtr& need(const KDTree& k) {
    if (!k.tree) invalid("KDTreeFlann has no data: pass a PointCloud, a Feature or an (N, d) array, or call set_geometry()");
    return k.tree;
}

size_t tree_dimension(const TreePtr& tree) {
    size_t d = 0;
    check(o3d_kdtree_dimension(&d, tree.get()));
    return d;
}

ResultPtr run_search_xd(const TreePtr& tree, const double* q, size_t nq, size_t dim, const o3d_search_param_t& p,
                        int32_t num_threads) {
    o3d_search_result_t* res = nullptr;
    check(nogil([&] { return o3d_kdtree_search_xd(&res, tree.get(), q, nq, dim, &p, num_threads); }));
    return ResultPtr(res, o3d_search_result_destroy);
}

ResultPtr run_search(const TreePtr& tree, const Rows3& q, const o3d_search_param_t& p, int32_t num_threads) {
    o3d_search_result_t* res = nullptr;
    check(nogil([&] {
        return q.f32 ? o3d_kdtree_search_f32(&res, tree.get(), static_cast<const float*>(q.data()), q.n, &p, num_threads)
                     : o3d_kdtree_search(&res, tree.get(), static_cast<const double*>(q.data()), q.n, &p, num_threads);
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
    const TreePtr& tree = need(self);
    ResultPtr r(nullptr, o3d_search_result_destroy);
    if (tree_dimension(tree) != 3) {  // (Q, d) queries of the tree's dimension
        auto q = rows_xd(queries, "queries");
        r = run_search_xd(tree, q.size() ? q.data() : nullptr, (size_t)q.shape(0), (size_t)q.shape(1), p, num_threads);
    } else {
        r = run_search(tree, as_rows3(queries, "queries"), p, num_threads);
    }
    size_t nq = 0, total = 0;
    check(o3d_search_result_counts(&nq, &total, r.get()));
    const int64_t* off = nullptr;
    const int32_t* idx = nullptr;
    const double* d2 = nullptr;
    check(o3d_search_result_view(&off, &idx, &d2, r.get()));
    py::object owner = keepalive(r);
    py::array offsets = off ? flat_view(off, nq + 1, owner) : py::array(py::array_t<int64_t>(std::vector<py::ssize_t>{(py::ssize_t)nq + 1}));
    if (!off) std::fill_n(static_cast<int64_t*>(offsets.mutable_data()), nq + 1, int64_t(0));
    return py::make_tuple(offsets, flat_view(idx, total, owner), flat_view(d2, total, owner));
}

/// (k, indices, distances2) of a one-query result, copied out with o3d_search_result_get_*.
py::tuple copy_single(const ResultPtr& r) {
    size_t nq = 0, total = 0, n = 0;
    check(o3d_search_result_counts(&nq, &total, r.get()));
    int64_t offsets[2] = {0, 0};  // one query: its neighbours are offsets[0] .. offsets[1] - 1
    check(o3d_search_result_get_offsets(offsets, 2, &n, r.get()));
    if (n != 2 || offsets[1] - offsets[0] != (int64_t)total) invalid("search result: inconsistent offsets");
    py::array_t<int32_t> idx((py::ssize_t)total);
    py::array_t<double> d2((py::ssize_t)total);
    check(o3d_search_result_get_indices(idx.mutable_data(), total, &n, r.get()));
    check(o3d_search_result_get_distances2(d2.mutable_data(), total, &n, r.get()));
    return py::make_tuple((int)total, idx, d2);
}

// One query, Open3D style: (k, indices, distances2).
py::tuple single(const KDTree& self, py::handle query, const o3d_search_param_t& p) {
    auto v = as_vec3(query, "query");
    Rows3 q;
    q.arr = py::array_t<double>(std::vector<py::ssize_t>{1, 3}, v.data());
    q.n = 1;
    return copy_single(run_search(need(self), q, p, 1));
}

// One query of the tree's dimension (Open3D's search_*_vector_xd): (k, indices, distances2).
py::tuple single_xd(const KDTree& self, py::handle query, const o3d_search_param_t& p) {
    const TreePtr& tree = need(self);
    py::array a = as_numeric(query, "query");
    if (!(a.ndim() == 1 || (a.ndim() == 2 && (a.shape(0) == 1 || a.shape(1) == 1)))) invalid("query: expected a vector");
    auto q = py::array_t<double, py::array::c_style | py::array::forcecast>::ensure(a);
    if (!q) throw py::error_already_set();
    return copy_single(run_search_xd(tree, q.data(), 1, (size_t)q.size(), p, 1));
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

size_t tree_size(const KDTree& self) {
    size_t n = 0;
    if (self.tree) check(o3d_kdtree_size(&n, self.tree.get()));
    return n;
}

/// One query, four ways (Open3D's search_{,knn_,radius_,hybrid_}vector_<3d|xd>): `run(self, query, param)`
/// under a KDTreeSearchParam*, knn, radius, or radius and max_nn.
template <typename Run>
void def_single_searches(py::class_<KDTree>& cls, const std::string& suffix, Run run, const char* knn_doc) {
    cls.def(("search_vector_" + suffix).c_str(),
            [run](const KDTree& self, py::handle query, py::handle search_param) {
                return run(self, query, to_search_param(search_param));
            },
            py::arg("query"), py::arg("search_param"))
        .def(("search_knn_vector_" + suffix).c_str(),
             [run](const KDTree& self, py::handle query, int32_t knn) { return run(self, query, knn_param(knn)); },
             py::arg("query"), py::arg("knn"), knn_doc)
        .def(("search_radius_vector_" + suffix).c_str(),
             [run](const KDTree& self, py::handle query, double radius) { return run(self, query, radius_param(radius)); },
             py::arg("query"), py::arg("radius"))
        .def(("search_hybrid_vector_" + suffix).c_str(),
             [run](const KDTree& self, py::handle query, double radius, int32_t max_nn) {
                 return run(self, query, hybrid_param(radius, max_nn));
             },
             py::arg("query"), py::arg("radius"), py::arg("max_nn"));
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
    py::class_<KDTree>(m, "KDTreeFlann",
                       "KD-tree over 3-D points (a PointCloud, an (N, 3) array), the descriptors of a Feature, or an "
                       "(N, d) array of points of any dimension (one point per row). It copies the data: later edits "
                       "are not seen.");
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
             py::arg("knn") = init_of(&o3d_search_param_init).knn)
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

    auto tree = static_cast<py::class_<KDTree>>(m.attr("KDTreeFlann"));
    def_single_searches(tree, "3d", &single,
                        "(k, indices, distances2) of the knn nearest points, nearest first (squared distances).");
    def_single_searches(tree, "xd", &single_xd,
                        "(k, indices, distances2) of the knn nearest points to a query of the tree's dimension, "
                        "nearest first.");
    tree.def(py::init<>(), "An empty tree; call set_geometry() before searching.")
        .def(py::init([](py::handle data) { return KDTree{tree_from_data(data)}; }), py::arg("data"),
             "A tree over a PointCloud's points, a Feature's descriptors, or an (N, d) array (float32 kept for d = 3).")
        .def(
            "set_geometry",
            [](KDTree& self, const PyPointCloud& geometry) {
                self.tree = tree_from_cloud(geometry);
                return true;
            },
            py::arg("geometry"))
        .def(
            "set_feature",
            [](KDTree& self, const PyFeature& feature) {
                self.tree = tree_from_feature(feature);
                return true;
            },
            py::arg("feature"), "Index the descriptors of a Feature (of its dimension).")
        .def(
            "set_matrix_data",
            [](KDTree& self, py::handle data) {
                self.tree = tree_from_data(data);
                return true;
            },
            py::arg("data"), "Index an (N, d) array (one point per row).")
        .def("size", &tree_size)
        .def("__len__", &tree_size)
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
