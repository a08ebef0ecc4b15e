// SPDX-License-Identifier: MIT
// o3d.pipelines.registration natives over registration.h: ICP with every estimation (point-to-point,
// point-to-plane, colored, generalized, symmetric; robust kernels) and a GIL-safe, cancellable progress
// callback, evaluation, information matrix, the option/result classes, and the helpers the global
// registration and pose-graph bindings share (registration_types.h).
#include <cstdio>
#include <memory>
#include <optional>
#include <sstream>

#include "generated/option_inits.h"
#include "registration_types.h"

namespace o3dpy {
namespace {

struct PointToPoint : Estimation {};
struct PointToPlane : Estimation {
    PointToPlane() { kind = O3D_ESTIMATION_POINT_TO_PLANE; }
};
struct ColoredICP : Estimation {
    ColoredICP() { kind = O3D_ESTIMATION_COLORED; }
};
struct GeneralizedICP : Estimation {
    GeneralizedICP() { kind = O3D_ESTIMATION_GENERALIZED; }
};
struct Symmetric : Estimation {
    Symmetric() { kind = O3D_ESTIMATION_SYMMETRIC; }
};

/// ICPConvergenceCriteria: the C options, showing its fields.
struct Criteria {
    o3d_icp_options_t o = init_of(&o3d_icp_options_init);
};
const FieldNames criteria_fields = {"relative_fitness", "relative_rmse", "max_iteration"};

py::array_t<double> identity4() {
    py::array_t<double> a(std::vector<py::ssize_t>{4, 4});
    double* p = a.mutable_data();
    for (int i = 0; i < 16; ++i) p[i] = (i % 5 == 0) ? 1.0 : 0.0;
    return a;
}

std::string shortest(double v) {  // 0.968, 0.001: as Open3D prints these parameters
    std::ostringstream s;
    s << v;
    return s.str();
}

/// Lock source and target for reading (once when they are the same cloud), GIL released, then call f.
template <typename F>
void with_pair(const PyPointCloud& source, const PyPointCloud& target, F&& f) {
    CloudPtr a = source.h, b = target.h;
    o3d_status s;
    {
        py::gil_scoped_release release;
        SharedLocks locks;
        locks.add(a->mutex);
        locks.add(b->mutex);
        s = f(a->p, b->p);
    }
    check(s);
}

Result icp(const PyPointCloud& source, const PyPointCloud& target, double max_dist, py::handle init,
           py::handle estimation, py::handle criteria, py::object progress, int32_t num_threads) {
    o3d_icp_options_t o = init_of(&o3d_icp_options_init);
    static const Estimation point_to_point;
    const Estimation& e = as_estimation(estimation, point_to_point);
    o.estimation = e.kind;
    o.with_scaling = e.with_scaling ? 1 : 0;
    o.kernel = e.kernel->kind;
    o.kernel_k = e.kernel->k;
    o.lambda_geometric = e.lambda_geometric;
    o.epsilon = e.epsilon;
    if (!criteria.is_none()) {
        if (!py::isinstance<Criteria>(criteria)) invalid("criteria: expected ICPConvergenceCriteria");
        copy_fields(o, criteria.cast<const Criteria&>().o, criteria_fields);
    }
    o.num_threads = num_threads;
    Progress ctx(progress);
    o.progress = &progress_trampoline;
    o.user_data = &ctx;
    auto T = mat4_or_identity(init, "init");
    o3d_registration_result_t* raw = nullptr;
    CloudPtr a = source.h, b = target.h;
    o3d_status s;
    {
        py::gil_scoped_release release;
        SharedLocks locks;
        locks.add(a->mutex);
        locks.add(b->mutex);
        s = o3d_register_icp(&raw, a->p, b->p, max_dist, T.data(), &o);
    }
    ResultPtr r(raw, o3d_registration_result_destroy);
    ctx.rethrow();  // the callback's own exception (or KeyboardInterrupt)
    check(s);
    return convert_result(r.get());
}

template <typename E>
py::class_<E, Estimation> estimation_class(py::module_& m, const char* name) {
    return static_cast<py::class_<E, Estimation>>(m.attr(name));
}

template <typename E>
void def_kernel(py::class_<E, Estimation>& c) {
    c.def_property(
        "kernel", [](const E& e) { return e.kernel; }, [](E& e, py::handle k) { e.kernel = as_kernel(k); },
        "The robust kernel weighting the residuals (shared: changing its k changes this estimation).");
}

}  // namespace

// ---- helpers shared with registration_global.cpp and pose_graph.cpp

Result convert_result(o3d_registration_result_t* r) {
    Result out;
    py::array_t<double> T(std::vector<py::ssize_t>{4, 4});
    check(o3d_registration_result_get_transformation(T.mutable_data(), r));
    check(o3d_registration_result_get_fitness(&out.fitness, r));
    check(o3d_registration_result_get_inlier_rmse(&out.inlier_rmse, r));
    size_t n = 0;
    o3d_status s = o3d_registration_result_get_correspondence_set(nullptr, 0, &n, r);
    if (s != O3D_OK && s != O3D_ERROR_BUFFER_TOO_SMALL) check(s);
    py::array_t<int32_t> c(std::vector<py::ssize_t>{(py::ssize_t)n, 2});
    if (n) check(o3d_registration_result_get_correspondence_set(c.mutable_data(), n, &n, r));
    out.transformation = T;
    out.correspondence_set = c;
    return out;
}

std::array<double, 16> mat4_or_identity(py::handle T, const char* what) {
    if (T.is_none()) {
        std::array<double, 16> id{};
        for (int i = 0; i < 4; ++i) id[i * 5] = 1.0;
        return id;
    }
    return as_mat4(T, what);
}

const Estimation& as_estimation(py::handle obj, const Estimation& fallback) {
    if (obj.is_none()) return fallback;
    if (!py::isinstance<Estimation>(obj))
        invalid("estimation_method: expected a TransformationEstimation (PointToPoint, PointToPlane, ForColoredICP, "
                "ForGeneralizedICP or Symmetric)");
    return obj.cast<const Estimation&>();
}

py::array_t<int32_t, py::array::c_style> as_corres(py::handle obj, const char* what) {
    if (obj.is_none()) invalid(std::string(what) + ": expected (N, 2) index pairs, got None");
    py::array a = py::array::ensure(obj);
    if (!a) invalid(std::string(what) + ": expected (N, 2) index pairs (Vector2iVector, ndarray or a list of pairs)");
    if (a.size() == 0) return py::array_t<int32_t, py::array::c_style>(std::vector<py::ssize_t>{0, 2});
    char kind = a.dtype().kind();
    if (kind != 'i' && kind != 'u') invalid(std::string(what) + ": expected integer index pairs, got dtype " +
                                            std::string(py::str(a.dtype())));
    if (a.ndim() != 2 || a.shape(1) != 2)
        invalid(std::string(what) + ": expected shape (N, 2), got " + std::string(py::str(py::tuple(a.attr("shape")))));
    if (!a.dtype().is(py::dtype::of<int32_t>())) {  // no silent wrap-around of wide integers
        long long lo = a.attr("min")().cast<long long>();
        py::object hi = a.attr("max")();
        if (lo < 0 || hi.cast<unsigned long long>() > 0x7fffffffULL)
            invalid(std::string(what) + ": index out of the int32 range");
    }
    auto out = py::array_t<int32_t, py::array::c_style | py::array::forcecast>::ensure(a);
    if (!out) throw py::error_already_set();
    return out;
}

Progress::Progress(py::object cb) : callback(std::move(cb)) {
    if (!callback.is_none() && !PyCallable_Check(callback.ptr())) invalid("progress: expected a callable or None");
}

void Progress::rethrow() {
    if (error) {
        py::error_already_set e = std::move(*error);
        error.reset();
        throw e;
    }
}

int32_t progress_trampoline(double fraction, void* user_data) {
    auto* p = static_cast<Progress*>(user_data);
    py::gil_scoped_acquire gil;
    if (PyErr_CheckSignals() != 0) {  // Ctrl-C during the call: cancel, re-raise KeyboardInterrupt after
        p->error.emplace();
        return 1;
    }
    if (p->callback.is_none()) return 0;
    try {
        return py::bool_(p->callback(fraction)) ? 1 : 0;
    } catch (py::error_already_set& e) {
        p->error.emplace(std::move(e));
        return 1;
    }
}

std::pair<int32_t, uint64_t> seed_fields(py::handle seed) {
    if (seed.is_none()) return {0, 0};
    if (PyBool_Check(seed.ptr()) || !PyIndex_Check(seed.ptr())) invalid("seed: expected an integer or None");
    py::object i = py::reinterpret_steal<py::object>(PyNumber_Index(seed.ptr()));
    if (!i) throw py::error_already_set();
    return {1, (uint64_t)PyLong_AsUnsignedLongLongMask(i.ptr())};
}

// ---- registration

void declare_registration(py::module_& m) {
    py::class_<Estimation>(m, "TransformationEstimation", "Base of the ICP transformation estimation methods.");
    py::class_<PointToPoint, Estimation>(m, "TransformationEstimationPointToPoint");
    py::class_<PointToPlane, Estimation>(m, "TransformationEstimationPointToPlane");
    py::class_<ColoredICP, Estimation>(m, "TransformationEstimationForColoredICP");
    py::class_<GeneralizedICP, Estimation>(m, "TransformationEstimationForGeneralizedICP");
    py::class_<Symmetric, Estimation>(m, "TransformationEstimationSymmetric");
    py::class_<Criteria>(m, "ICPConvergenceCriteria");
    py::class_<Result>(m, "RegistrationResult");
    declare_robust_kernel(m);
    declare_feature(m);
    declare_registration_global(m);
    declare_pose_graph(m);
}

void define_registration(py::module_& m) {
    const o3d_icp_options_t dicp = init_of(&o3d_icp_options_init);
    define_robust_kernel(m);
    auto p2p = estimation_class<PointToPoint>(m, "TransformationEstimationPointToPoint");
    p2p.def(py::init([](bool with_scaling) {
               PointToPoint e;
               e.with_scaling = with_scaling;
               return e;
           }),
           py::arg("with_scaling") = false, "Point-to-point ICP (with_scaling=True also estimates a scale).")
        .def(py::init<const PointToPoint&>(), py::arg("other"), "Copy constructor")
        .def_property(
            "with_scaling", [](const PointToPoint& e) { return e.with_scaling; },
            [](PointToPoint& e, bool v) { e.with_scaling = v; })
        .def("__repr__", [](const PointToPoint& e) {
            return std::string("TransformationEstimationPointToPoint(with_scaling=") + (e.with_scaling ? "True" : "False") + ")";
        });

    auto p2l = estimation_class<PointToPlane>(m, "TransformationEstimationPointToPlane");
    p2l.def(py::init([](py::handle kernel) {
               PointToPlane e;
               e.kernel = as_kernel(kernel);
               return e;
           }),
           py::arg("kernel") = py::none(), "Point-to-plane ICP (the target needs normals), residuals weighted by kernel.")
        .def(py::init<const PointToPlane&>(), py::arg("other"), "Copy constructor")
        .def("__repr__", [](const PointToPlane&) { return std::string("TransformationEstimationPointToPlane"); });
    def_kernel(p2l);

    auto colored = estimation_class<ColoredICP>(m, "TransformationEstimationForColoredICP");
    colored
        .def(py::init([](double lambda_geometric, py::handle kernel) {
                 ColoredICP e;
                 e.lambda_geometric = lambda_geometric;
                 e.kernel = as_kernel(kernel);
                 return e;
             }),
             py::arg("lambda_geometric") = dicp.lambda_geometric, py::arg("kernel") = py::none(),
             "Colored ICP (Park et al. 2017): both clouds need colors, the target normals; lambda_geometric in [0, 1] "
             "weighs the geometric term against the photometric one.")
        .def(py::init([](const KernelPtr& kernel) {
                 ColoredICP e;
                 e.kernel = kernel;
                 return e;
             }),
             py::arg("kernel"))
        .def(py::init<const ColoredICP&>(), py::arg("other"), "Copy constructor")
        .def_readwrite("lambda_geometric", &ColoredICP::lambda_geometric)
        .def("__repr__", [](const ColoredICP& e) {
            return "TransformationEstimationForColoredICP(lambda_geometric=" + shortest(e.lambda_geometric) + ")";
        });
    def_kernel(colored);

    auto gicp = estimation_class<GeneralizedICP>(m, "TransformationEstimationForGeneralizedICP");
    gicp.def(py::init([](double epsilon, py::handle kernel) {
                GeneralizedICP e;
                e.epsilon = epsilon;
                e.kernel = as_kernel(kernel);
                return e;
            }),
            py::arg("epsilon") = dicp.epsilon, py::arg("kernel") = py::none(),
            "Generalized ICP (Segal et al. 2009); epsilon regularises the per-point covariances.")
        .def(py::init([](const KernelPtr& kernel) {
                 GeneralizedICP e;
                 e.kernel = kernel;
                 return e;
             }),
             py::arg("kernel"))
        .def(py::init<const GeneralizedICP&>(), py::arg("other"), "Copy constructor")
        .def_readwrite("epsilon", &GeneralizedICP::epsilon)
        .def("__repr__", [](const GeneralizedICP& e) {
            return "TransformationEstimationForGeneralizedICP(epsilon=" + shortest(e.epsilon) + ")";
        });
    def_kernel(gicp);

    auto sym = estimation_class<Symmetric>(m, "TransformationEstimationSymmetric");
    sym.def(py::init([](py::handle kernel) {
               Symmetric e;
               e.kernel = as_kernel(kernel);
               return e;
           }),
           py::arg("kernel") = py::none(), "Symmetric point-to-plane ICP (Rusinkiewicz 2019): both clouds need normals.")
        .def(py::init<const Symmetric&>(), py::arg("other"), "Copy constructor")
        .def("__repr__", [](const Symmetric&) { return std::string("TransformationEstimationSymmetric"); });
    def_kernel(sym);

    auto criteria = static_cast<py::class_<Criteria>>(m.attr("ICPConvergenceCriteria"));
    def_icp_convergence_criteria_init(criteria);
    criteria
        .def(py::init<const Criteria&>(), py::arg("other"), "Copy constructor")
        .def("__repr__", [](const Criteria& c) {
            return "ICPConvergenceCriteria(relative_fitness=" + std::to_string(c.o.relative_fitness) + ", relative_rmse=" +
                   std::to_string(c.o.relative_rmse) + ", max_iteration=" + std::to_string(c.o.max_iteration) + ")";
        });
    def_fields(criteria, criteria_fields);
    static_cast<py::class_<Result>>(m.attr("RegistrationResult"))
        .def(py::init([]() {
            Result r;
            r.transformation = identity4();
            r.correspondence_set = py::array_t<int32_t>(std::vector<py::ssize_t>{0, 2});
            return r;
        }))
        .def_readwrite("transformation", &Result::transformation, "(4, 4) float64 ndarray.")
        .def_readwrite("fitness", &Result::fitness, "Inlier count / number of source points.")
        .def_readwrite("inlier_rmse", &Result::inlier_rmse, "RMS distance of the inlier pairs.")
        .def_readwrite("correspondence_set", &Result::correspondence_set, "(N, 2) int32 (source, target) index pairs.")
        .def("__repr__", [](const Result& r) {
            return "RegistrationResult with fitness=" + std::to_string(r.fitness) + ", inlier_rmse=" + std::to_string(r.inlier_rmse) +
                   ", and correspondence_set size of " + std::to_string(py::len(r.correspondence_set)) +
                   "\nAccess transformation to get result.";
        });

    m.attr("_icp_defaults") = py::dict(py::arg("num_threads") = dicp.num_threads);  // for the Python wrappers
    m.def("_registration_icp", &icp, py::arg("source"), py::arg("target"), py::arg("max_correspondence_distance"),
          py::arg("init") = py::none(), py::arg("estimation_method") = py::none(), py::arg("criteria") = py::none(),
          py::arg("progress") = py::none(), py::arg("num_threads") = dicp.num_threads,
          "ICP with any estimation; progress(fraction) is called after each iteration and cancels when it returns "
          "True or raises.");
    m.def(
        "evaluate_registration",
        [](const PyPointCloud& source, const PyPointCloud& target, double max_dist, py::handle transformation) {
            auto T = mat4_or_identity(transformation, "transformation");
            o3d_registration_result_t* raw = nullptr;
            with_pair(source, target, [&](const o3d_pointcloud_t* a, const o3d_pointcloud_t* b) {
                return o3d_evaluate_registration(&raw, a, b, max_dist, T.data());
            });
            ResultPtr r(raw, o3d_registration_result_destroy);
            return convert_result(r.get());
        },
        py::arg("source"), py::arg("target"), py::arg("max_correspondence_distance"),
        py::arg("transformation") = py::none(), "Fitness, inlier RMSE and correspondences of source moved by transformation.");
    m.def(
        "get_information_matrix_from_point_clouds",
        [](const PyPointCloud& source, const PyPointCloud& target, double max_dist, py::handle transformation) {
            auto T = mat4_or_identity(transformation, "transformation");
            py::array_t<double> out(std::vector<py::ssize_t>{6, 6});
            double* p = out.mutable_data();
            with_pair(source, target, [&](const o3d_pointcloud_t* a, const o3d_pointcloud_t* b) {
                return o3d_get_information_matrix_from_point_clouds(p, a, b, max_dist, T.data());
            });
            return out;
        },
        py::arg("source"), py::arg("target"), py::arg("max_correspondence_distance"), py::arg("transformation"),
        "The (6, 6) information matrix of the correspondences under transformation.");
    define_feature(m);
    define_registration_global(m);
    define_pose_graph(m);
}

}  // namespace o3dpy
