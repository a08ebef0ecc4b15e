// SPDX-License-Identifier: MIT
// o3d.pipelines.registration.Feature, compute_fpfh_feature and correspondences_from_features, and
// o3d.io.read_feature / write_feature, over feature.h.
#include "registration_types.h"

namespace o3dpy {
namespace {

PyFeature adopt_feature(o3d_feature_t* raw) { return PyFeature(raw); }

/// Zero-copy (dimension, num) float64 view: descriptor i is column i, contiguous in memory (Fortran
/// order), as Open3D's Eigen matrix: the transpose of the C (num, dimension) array.
py::object data_view(const PyFeature& f) { return array_view<o3d_feature_t>(f.h, O3D_FEATURE_DATA, true).attr("T"); }

/// A feature holding a copy of a (dimension, num) array-like.
PyFeature from_matrix(py::handle data) {
    py::array a = py::array::ensure(data);
    if (!a) invalid("data: expected a (dimension, num) array of numbers");
    char kind = a.dtype().kind();
    if (kind != 'f' && kind != 'i' && kind != 'u') invalid("data: expected numbers, got dtype " + std::string(py::str(a.dtype())));
    if (a.ndim() != 2) invalid("data: expected a 2-D (dimension, num) array, got " + std::to_string(a.ndim()) + " dimensions");
    auto f = py::array_t<double, py::array::f_style | py::array::forcecast>::ensure(a);
    if (!f) throw py::error_already_set();
    size_t dim = (size_t)f.shape(0), num = (size_t)f.shape(1);
    o3d_feature_t* out = nullptr;
    const double* p = f.size() ? f.data() : nullptr;
    check(nogil([&] { return o3d_feature_create_from_data(&out, p, dim, num); }));
    return adopt_feature(out);
}

PyFeature clone(const PyFeature& f) {
    o3d_feature_t* out = nullptr;
    locked_const(f.h, [&](const o3d_feature_t* p) { return o3d_feature_clone(&out, p); });
    return adopt_feature(out);
}

py::array_t<int64_t> as_indices(py::handle obj, const char* what) {
    py::array a = py::array::ensure(obj);
    if (!a) invalid(std::string(what) + ": expected a sequence of integers");
    if (a.size() == 0) return py::array_t<int64_t>((py::ssize_t)0);
    char kind = a.dtype().kind();
    if (kind != 'i' && kind != 'u') invalid(std::string(what) + ": expected integers, got dtype " + std::string(py::str(a.dtype())));
    if (a.ndim() != 1) invalid(std::string(what) + ": expected a 1-D sequence of integers");
    auto out = py::array_t<int64_t, py::array::c_style | py::array::forcecast>::ensure(a);
    if (!out) throw py::error_already_set();
    return out;
}

PyFeature compute_fpfh(const PyPointCloud& input, py::handle search_param, py::handle indices, int32_t num_threads) {
    o3d_search_param_t p = to_search_param(search_param);
    py::array_t<int64_t> idx = indices.is_none() ? py::array_t<int64_t>((py::ssize_t)0) : as_indices(indices, "indices");
    o3d_feature_t* out = nullptr;
    CloudPtr h = input.h;
    const int64_t* ip = idx.size() ? idx.data() : nullptr;
    size_t n = (size_t)idx.size();
    locked_const(h, [&](const o3d_pointcloud_t* pc) {
        return o3d_compute_fpfh_feature(&out, pc, &p, ip, n, num_threads);
    });
    PyFeature all = adopt_feature(out);
    if (!indices.is_none() && n == 0) {
        // Open3D: an empty index list gives a 33 x 0 feature; the C call treats "no indices" as "every
        // point" (and validated the cloud above), so keep the descriptor length and drop the columns.
        check(o3d_feature_resize(all.h->p, all.dimension(), 0));
    }
    return all;
}

py::array_t<int32_t> correspondences(const PyFeature& source, const PyFeature& target, bool mutual_filter,
                                     double ratio, int32_t num_threads) {
    FeaturePtr a = source.h, b = target.h;
    std::vector<int32_t> pairs;
    size_t n = 0;
    o3d_status s;
    {
        py::gil_scoped_release release;
        SharedLocks locks;
        locks.add(a->mutex);
        locks.add(b->mutex);
        size_t capacity = 0;
        s = o3d_feature_num(&capacity, a->p);  // at most one pair per source descriptor
        if (s == O3D_OK) {
            pairs.resize(2 * capacity);
            s = o3d_correspondences_from_features(pairs.empty() ? nullptr : pairs.data(), capacity, &n, a->p, b->p,
                                                  mutual_filter ? 1 : 0, ratio, num_threads);
        }
    }
    check(s);
    py::array_t<int32_t> out(std::vector<py::ssize_t>{(py::ssize_t)n, 2});
    if (n) std::memcpy(out.mutable_data(), pairs.data(), 2 * n * sizeof(int32_t));
    return out;
}

}  // namespace

PyFeature::PyFeature() : Geom(nullptr) { check(o3d_feature_create(&h->p, 0, 0)); }

size_t PyFeature::dimension() const {
    size_t d = 0;
    check(o3d_feature_dimension(&d, h->p));
    return d;
}

size_t PyFeature::num() const {
    size_t n = 0;
    check(o3d_feature_num(&n, h->p));
    return n;
}

void declare_feature(py::module_& m) {
    py::class_<PyFeature>(m, "Feature",
                          "Per-point descriptors: a (dimension, num) float64 matrix, one column per point (33 rows for "
                          "FPFH). `data` is a zero-copy view of it.");
}

void define_feature(py::module_& m) {
    auto cls = static_cast<py::class_<PyFeature>>(m.attr("Feature"));
    def_array_access(cls);
    cls
        .def(py::init<>(), "An empty (0 x 0) feature.")
        .def(py::init(&clone), py::arg("other"), "Copy constructor")
        .def("dimension", &PyFeature::dimension, "Descriptor length.")
        .def("num", &PyFeature::num, "Number of descriptors (points).")
        .def(
            "resize",
            [](PyFeature& self, int64_t dim, int64_t n) {
                if (dim < 0 || n < 0) invalid("resize: dim and n must be >= 0");
                FeaturePtr h = self.for_resize();
                locked_mut(h, [&](o3d_feature_t* p) { return o3d_feature_resize(p, (size_t)dim, (size_t)n); });
            },
            py::arg("dim"), py::arg("n"), "Resize to dim x n; kept values stay when dim is unchanged, new ones are 0.")
        .def_property(
            "data", &data_view, [](PyFeature& self, py::handle data) { self.h = from_matrix(data).h; },
            "(dimension, num) float64 ndarray, a writable zero-copy view (column i = descriptor of point i). "
            "Assigning a (dimension, num) array replaces the matrix (older views keep the old one).")
        .def(
            "select_by_index",
            [](const PyFeature& self, py::handle indices, bool invert) {
                py::array_t<int64_t> idx = as_indices(indices, "indices");
                o3d_feature_t* out = nullptr;
                const int64_t* ip = idx.size() ? idx.data() : nullptr;
                size_t n = (size_t)idx.size();
                locked_const(self.h, [&](const o3d_feature_t* f) {
                    return o3d_feature_select_by_index(&out, f, ip, n, invert ? 1 : 0);
                });
                return adopt_feature(out);
            },
            py::arg("indices"), py::arg("invert") = false,
            "The descriptors of points `indices` (in that order), or of all other points (ascending) with invert=True. "
            "An index out of range raises (Open3D warns and skips it).")
        .def("__copy__", &clone)
        .def("__deepcopy__", [](const PyFeature& self, py::handle) { return clone(self); }, py::arg("memo"))
        .def(py::pickle(
            [](const PyFeature& self) {
                py::array flat = array_copy<o3d_feature_t>(self.h, O3D_FEATURE_DATA).attr("reshape")(-1);
                return py::make_tuple(self.dimension(), self.num(), flat);
            },
            [](py::tuple t) {
                if (t.size() != 3) invalid("Feature: bad pickle state");
                size_t dim = t[0].cast<size_t>(), num = t[1].cast<size_t>();
                auto flat = py::array_t<double, py::array::c_style | py::array::forcecast>::ensure(t[2]);
                if (!flat || (size_t)flat.size() != dim * num) invalid("Feature: bad pickle state");
                o3d_feature_t* out = nullptr;
                check(o3d_feature_create_from_data(&out, flat.size() ? flat.data() : nullptr, dim, num));
                return adopt_feature(out);
            }))
        .def("__repr__", [](const PyFeature& self) {
            return "Feature class with dimension = " + std::to_string(self.dimension()) +
                   " and num = " + std::to_string(self.num()) + "\nAccess its data via data member.";
        });

    m.def("compute_fpfh_feature", &compute_fpfh, py::arg("input"), py::arg("search_param"),
          py::arg("indices") = py::none(), py::kw_only(), py::arg("num_threads") = 0,
          "Fast Point Feature Histograms (33 x N) of a cloud with normals; `indices` selects the points that get a "
          "descriptor (neighbourhoods still come from the whole cloud). num_threads (o3d extra; 0 = default) does not "
          "change the result.");
    m.def("_correspondences_from_features", &correspondences, py::arg("source_features"), py::arg("target_features"),
          py::arg("mutual_filter") = false, py::arg("mutual_consistency_ratio") = 0.1, py::arg("num_threads") = 0,
          "(N, 2) int32 (source, target) nearest-descriptor pairs.");
    m.def(
        "read_feature",
        [](py::handle filename) {
            std::string path = path_of(filename);
            o3d_feature_t* out = nullptr;
            check(nogil([&] { return o3d_io_read_feature(&out, path.c_str()); }), path);
            return adopt_feature(out);
        },
        py::arg("filename"),
        "Read a Feature in Open3D's binary layout (int32 dimension, int32 num, then num x dimension float64). "
        "Failures raise (O3DFileNotFoundError, O3DIOError, ParseError) where Open3D returns an empty Feature.");
    m.def(
        "write_feature",
        [](py::handle filename, const PyFeature& feature) {
            std::string path = path_of(filename);
            FeaturePtr h = feature.h;
            o3d_status s;
            {
                py::gil_scoped_release release;
                std::shared_lock<std::shared_mutex> lock(h->mutex);
                s = o3d_io_write_feature(path.c_str(), h->p);
            }
            check(s, path);
            return true;
        },
        py::arg("filename"), py::arg("feature"), "Write a Feature in the layout read_feature reads; returns True (failures raise).");
}

}  // namespace o3dpy
