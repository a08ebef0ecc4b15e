// SPDX-License-Identifier: MIT
// o3d.pipelines.registration natives over registration.h: ICP (with a GIL-safe, cancellable progress
// callback), evaluation, information matrix, and the option/result classes.
#include <memory>
#include <optional>

#include "common.h"

namespace o3dpy {
namespace {

struct Estimation {
    int32_t kind = O3D_ESTIMATION_POINT_TO_POINT;
    bool with_scaling = false;
};
struct PointToPoint : Estimation {};
struct PointToPlane : Estimation {
    PointToPlane() { kind = O3D_ESTIMATION_POINT_TO_PLANE; }
};

struct Criteria {
    double relative_fitness = 1e-6;
    double relative_rmse = 1e-6;
    int32_t max_iteration = 30;
};

struct Result {
    py::object transformation;
    double fitness = 0.0;
    double inlier_rmse = 0.0;
    py::object correspondence_set;
};

using ResultPtr = std::unique_ptr<o3d_registration_result_t, void (*)(o3d_registration_result_t*)>;

py::array_t<double> identity4() {
    py::array_t<double> a(std::vector<py::ssize_t>{4, 4});
    double* p = a.mutable_data();
    for (int i = 0; i < 16; ++i) p[i] = (i % 5 == 0) ? 1.0 : 0.0;
    return a;
}

std::array<double, 16> mat4_or_identity(py::handle T, const char* what) {
    if (T.is_none()) {
        std::array<double, 16> id{};
        for (int i = 0; i < 4; ++i) id[i * 5] = 1.0;
        return id;
    }
    return as_mat4(T, what);
}

Result convert(o3d_registration_result_t* r) {
    Result out;
    py::array_t<double> T(std::vector<py::ssize_t>{4, 4});
    check(o3d_registration_result_get_transformation(r, T.mutable_data()));
    check(o3d_registration_result_get_fitness(r, &out.fitness));
    check(o3d_registration_result_get_inlier_rmse(r, &out.inlier_rmse));
    size_t n = 0;
    o3d_status s = o3d_registration_result_get_correspondence_set(r, nullptr, 0, &n);
    if (s != O3D_OK && s != O3D_ERROR_BUFFER_TOO_SMALL) check(s);
    py::array_t<int32_t> c(std::vector<py::ssize_t>{(py::ssize_t)n, 2});
    if (n) check(o3d_registration_result_get_correspondence_set(r, c.mutable_data(), n, &n));
    out.transformation = T;
    out.correspondence_set = c;
    return out;
}

/// Lock source and target for reading (once when they are the same cloud), GIL released, then call f.
template <typename F>
void with_pair(const PyPointCloud& source, const PyPointCloud& target, F&& f) {
    CloudPtr a = source.h, b = target.h;
    o3d_status s;
    {
        py::gil_scoped_release release;
        std::shared_lock<std::shared_mutex> la(a->mutex);
        std::shared_lock<std::shared_mutex> lb(b->mutex, std::defer_lock);
        if (b != a) lb.lock();
        s = f(a->pc, b->pc);
    }
    check(s);
}

struct Progress {
    py::object callback;  // callable(fraction) -> truthy to cancel; may be None
    std::optional<py::error_already_set> error;
};

int32_t progress_trampoline(double fraction, void* user_data) {
    auto* p = static_cast<Progress*>(user_data);
    py::gil_scoped_acquire gil;
    if (PyErr_CheckSignals() != 0) {  // Ctrl-C while ICP runs: cancel, re-raise KeyboardInterrupt after
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

Result icp(const PyPointCloud& source, const PyPointCloud& target, double max_dist, py::handle init,
           py::handle estimation, py::handle criteria, py::object progress, int32_t num_threads) {
    o3d_icp_options_t o;
    check(o3d_icp_options_init(&o, sizeof(o)));
    if (!estimation.is_none()) {
        if (!py::isinstance<Estimation>(estimation))
            invalid("estimation_method: expected TransformationEstimationPointToPoint or TransformationEstimationPointToPlane");
        const auto& e = estimation.cast<const Estimation&>();
        o.estimation = e.kind;
        o.with_scaling = e.with_scaling ? 1 : 0;
    }
    if (!criteria.is_none()) {
        if (!py::isinstance<Criteria>(criteria)) invalid("criteria: expected ICPConvergenceCriteria");
        const auto& c = criteria.cast<const Criteria&>();
        o.relative_fitness = c.relative_fitness;
        o.relative_rmse = c.relative_rmse;
        o.max_iteration = c.max_iteration;
    }
    o.num_threads = num_threads;
    if (!progress.is_none() && !PyCallable_Check(progress.ptr())) invalid("progress: expected a callable or None");
    Progress ctx{progress, std::nullopt};
    o.progress = &progress_trampoline;
    o.user_data = &ctx;
    auto T = mat4_or_identity(init, "init");
    o3d_registration_result_t* raw = nullptr;
    CloudPtr a = source.h, b = target.h;
    o3d_status s;
    {
        py::gil_scoped_release release;
        std::shared_lock<std::shared_mutex> la(a->mutex);
        std::shared_lock<std::shared_mutex> lb(b->mutex, std::defer_lock);
        if (b != a) lb.lock();
        s = o3d_register_icp(&raw, a->pc, b->pc, max_dist, T.data(), &o);
    }
    ResultPtr r(raw, o3d_registration_result_destroy);
    if (ctx.error) throw std::move(*ctx.error);  // the callback's own exception (or KeyboardInterrupt)
    check(s);
    return convert(r.get());
}

}  // namespace

void declare_registration(py::module_& m) {
    py::class_<Estimation>(m, "TransformationEstimation", "Base of the ICP transformation estimation methods.");
    py::class_<PointToPoint, Estimation>(m, "TransformationEstimationPointToPoint");
    py::class_<PointToPlane, Estimation>(m, "TransformationEstimationPointToPlane");
    py::class_<Criteria>(m, "ICPConvergenceCriteria");
    py::class_<Result>(m, "RegistrationResult");
}

void define_registration(py::module_& m) {
    static_cast<py::class_<PointToPoint, Estimation>>(m.attr("TransformationEstimationPointToPoint"))
        .def(py::init([](bool with_scaling) {
                 PointToPoint e;
                 e.with_scaling = with_scaling;
                 return e;
             }),
             py::arg("with_scaling") = false, "Point-to-point ICP (with_scaling=True also estimates a scale).")
        .def_property(
            "with_scaling", [](const PointToPoint& e) { return e.with_scaling; },
            [](PointToPoint& e, bool v) { e.with_scaling = v; })
        .def("__repr__", [](const PointToPoint& e) {
            return std::string("TransformationEstimationPointToPoint(with_scaling=") + (e.with_scaling ? "True" : "False") + ")";
        });
    static_cast<py::class_<PointToPlane, Estimation>>(m.attr("TransformationEstimationPointToPlane"))
        .def(py::init<>(), "Point-to-plane ICP (the target needs normals).")
        .def("__repr__", [](const PointToPlane&) { return std::string("TransformationEstimationPointToPlane()"); });
    static_cast<py::class_<Criteria>>(m.attr("ICPConvergenceCriteria"))
        .def(py::init([](double rf, double rr, int32_t it) { return Criteria{rf, rr, it}; }), py::arg("relative_fitness") = 1e-6,
             py::arg("relative_rmse") = 1e-6, py::arg("max_iteration") = 30)
        .def_readwrite("relative_fitness", &Criteria::relative_fitness)
        .def_readwrite("relative_rmse", &Criteria::relative_rmse)
        .def_readwrite("max_iteration", &Criteria::max_iteration)
        .def("__repr__", [](const Criteria& c) {
            return "ICPConvergenceCriteria(relative_fitness=" + std::to_string(c.relative_fitness) +
                   ", relative_rmse=" + std::to_string(c.relative_rmse) + ", max_iteration=" + std::to_string(c.max_iteration) + ")";
        });
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

    m.def("_registration_icp", &icp, py::arg("source"), py::arg("target"), py::arg("max_correspondence_distance"),
          py::arg("init") = py::none(), py::arg("estimation_method") = py::none(), py::arg("criteria") = py::none(),
          py::arg("progress") = py::none(), py::arg("num_threads") = 0,
          "ICP; progress(fraction) is called after each iteration and cancels when it returns True or raises.");
    m.def(
        "evaluate_registration",
        [](const PyPointCloud& source, const PyPointCloud& target, double max_dist, py::handle transformation) {
            auto T = mat4_or_identity(transformation, "transformation");
            o3d_registration_result_t* raw = nullptr;
            with_pair(source, target, [&](const o3d_pointcloud_t* a, const o3d_pointcloud_t* b) {
                return o3d_evaluate_registration(&raw, a, b, max_dist, T.data());
            });
            ResultPtr r(raw, o3d_registration_result_destroy);
            return convert(r.get());
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
                return o3d_get_information_matrix_from_point_clouds(a, b, max_dist, T.data(), p);
            });
            return out;
        },
        py::arg("source"), py::arg("target"), py::arg("max_correspondence_distance"), py::arg("transformation"),
        "The (6, 6) information matrix of the correspondences under transformation.");
}

}  // namespace o3dpy
