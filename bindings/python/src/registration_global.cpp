// SPDX-License-Identifier: MIT
// Global registration over registration.h: correspondence checkers, RANSACConvergenceCriteria, RANSAC on
// features or given correspondences, FastGlobalRegistrationOption and FGR, and the global random seed.
// Long calls release the GIL; progress callbacks run on the calling thread with the GIL re-acquired.
#include <cstdio>
#include <tuple>

#include "generated/option_inits.h"
#include "registration_types.h"

namespace o3dpy {
namespace {

struct Checker {
    o3d_correspondence_checker_t c{};
    bool require_alignment = false;
    Checker(int32_t kind, bool alignment) : require_alignment(alignment) {
        check(o3d_correspondence_checker_init(&c, sizeof(c), kind));
    }
};
struct EdgeLengthChecker : Checker {
    explicit EdgeLengthChecker(double t) : Checker(O3D_CHECKER_EDGE_LENGTH, false) { c.threshold = t; }
};
struct DistanceChecker : Checker {
    explicit DistanceChecker(double t) : Checker(O3D_CHECKER_DISTANCE, true) { c.threshold = t; }
};
struct NormalChecker : Checker {
    explicit NormalChecker(double t) : Checker(O3D_CHECKER_NORMAL, true) { c.threshold = t; }
};

/// RANSACConvergenceCriteria: the C options, showing its fields.
struct RansacCriteria {
    o3d_ransac_options_t o = init_of(&o3d_ransac_options_init);
};
const FieldNames ransac_criteria_fields = {"max_iteration", "confidence"};

/// FastGlobalRegistrationOption: the C options (minus threads/progress) plus an optional seed.
struct FgrOption {
    o3d_fgr_options_t o{};
    py::object seed = py::none();
    FgrOption() { check(o3d_fgr_options_init(&o, sizeof(o))); }
};

std::string fixed6(double v) {
    char buf[64];
    std::snprintf(buf, sizeof buf, "%f", v);
    return buf;
}

std::string shortest(double v) {
    char buf[64];
    std::snprintf(buf, sizeof buf, "%g", v);
    return buf;
}

std::vector<o3d_correspondence_checker_t> as_checkers(py::handle checkers) {
    std::vector<o3d_correspondence_checker_t> out;
    if (checkers.is_none()) return out;
    if (!py::isinstance<py::iterable>(checkers)) invalid("checkers: expected a list of CorrespondenceChecker");
    for (py::handle c : checkers) {
        if (!py::isinstance<Checker>(c)) invalid("checkers: expected CorrespondenceChecker objects");
        out.push_back(c.cast<const Checker&>().c);
    }
    return out;
}

o3d_ransac_options_t ransac_options(py::handle estimation, int32_t ransac_n, py::handle criteria, py::handle seed,
                                    int32_t num_threads, Progress& progress) {
    o3d_ransac_options_t o = init_of(&o3d_ransac_options_init);
    static const Estimation point_to_point;
    const Estimation& e = as_estimation(estimation, point_to_point);
    // The C call accepts point-to-point and point-to-plane (it rejects the others) and has no kernel: a robust
    // kernel would be ignored, so it is refused rather than dropped.
    if (e.kernel && e.kernel->kind != O3D_KERNEL_L2)
        invalid("estimation_method: RANSAC takes no robust kernel (use L2Loss, or refine with registration_icp)");
    o.estimation = e.kind;
    o.with_scaling = e.with_scaling ? 1 : 0;
    o.ransac_n = ransac_n;
    if (!criteria.is_none()) {
        if (!py::isinstance<RansacCriteria>(criteria)) invalid("criteria: expected RANSACConvergenceCriteria");
        copy_fields(o, criteria.cast<const RansacCriteria&>().o, ransac_criteria_fields);
    }
    std::tie(o.use_seed, o.seed) = seed_fields(seed);
    o.num_threads = num_threads;
    o.progress = &progress_trampoline;
    o.user_data = &progress;
    return o;
}

o3d_fgr_options_t fgr_options(py::handle option, py::handle seed, int32_t num_threads, Progress& progress) {
    o3d_fgr_options_t o;
    py::handle chosen_seed = seed;
    if (option.is_none()) {
        check(o3d_fgr_options_init(&o, sizeof(o)));
    } else {
        if (!py::isinstance<FgrOption>(option)) invalid("option: expected FastGlobalRegistrationOption");
        const auto& f = option.cast<const FgrOption&>();
        o = f.o;
        if (seed.is_none()) chosen_seed = f.seed;  // the call's seed wins over the option's
    }
    std::tie(o.use_seed, o.seed) = seed_fields(chosen_seed);
    o.num_threads = num_threads;
    o.progress = &progress_trampoline;
    o.user_data = &progress;
    return o;
}

/// Run a registration call on two clouds (and features) with shared locks and the GIL released.
template <typename F>
Result run_registration(const PyPointCloud& source, const PyPointCloud& target, const PyFeature* sf,
                        const PyFeature* tf, Progress& progress, F&& f) {
    CloudPtr a = source.h, b = target.h;
    FeaturePtr fa = sf ? sf->h : nullptr, fb = tf ? tf->h : nullptr;
    o3d_registration_result_t* raw = nullptr;
    o3d_status s;
    {
        py::gil_scoped_release release;
        SharedLocks locks;
        locks.add(a->mutex);
        locks.add(b->mutex);
        if (fa) locks.add(fa->mutex);
        if (fb) locks.add(fb->mutex);
        s = f(&raw, a->p, b->p, fa ? fa->p : nullptr, fb ? fb->p : nullptr);
    }
    ResultPtr r(raw, o3d_registration_result_destroy);
    progress.rethrow();
    check(s);
    return convert_result(r.get());
}

Result ransac_features(const PyPointCloud& source, const PyPointCloud& target, const PyFeature& source_feature,
                       const PyFeature& target_feature, bool mutual_filter, double max_dist, py::handle estimation,
                       int32_t ransac_n, py::handle checkers, py::handle criteria, py::handle seed, int32_t num_threads,
                       py::object callback) {
    Progress progress(std::move(callback));
    o3d_ransac_options_t o = ransac_options(estimation, ransac_n, criteria, seed, num_threads, progress);
    o.mutual_filter = mutual_filter ? 1 : 0;
    auto cs = as_checkers(checkers);
    return run_registration(source, target, &source_feature, &target_feature, progress,
                            [&](o3d_registration_result_t** out, const o3d_pointcloud_t* a, const o3d_pointcloud_t* b,
                                const o3d_feature_t* fa, const o3d_feature_t* fb) {
                                return o3d_register_ransac_based_on_feature_matching(
                                    out, a, b, fa, fb, max_dist, cs.empty() ? nullptr : cs.data(), cs.size(), &o);
                            });
}

Result ransac_corres(const PyPointCloud& source, const PyPointCloud& target, py::handle corres, double max_dist,
                     py::handle estimation, int32_t ransac_n, py::handle checkers, py::handle criteria, py::handle seed,
                     int32_t num_threads, py::object callback) {
    Progress progress(std::move(callback));
    o3d_ransac_options_t o = ransac_options(estimation, ransac_n, criteria, seed, num_threads, progress);
    auto pairs = as_corres(corres, "corres");
    const int32_t* cp = pairs.size() ? pairs.data() : nullptr;
    size_t n = (size_t)pairs.shape(0);
    auto cs = as_checkers(checkers);
    return run_registration(source, target, nullptr, nullptr, progress,
                            [&](o3d_registration_result_t** out, const o3d_pointcloud_t* a, const o3d_pointcloud_t* b,
                                const o3d_feature_t*, const o3d_feature_t*) {
                                return o3d_register_ransac_based_on_correspondence(
                                    out, a, b, cp, n, max_dist, cs.empty() ? nullptr : cs.data(), cs.size(), &o);
                            });
}

Result fgr_features(const PyPointCloud& source, const PyPointCloud& target, const PyFeature& source_feature,
                    const PyFeature& target_feature, py::handle option, py::handle seed, int32_t num_threads,
                    py::object callback) {
    Progress progress(std::move(callback));
    o3d_fgr_options_t o = fgr_options(option, seed, num_threads, progress);
    return run_registration(source, target, &source_feature, &target_feature, progress,
                            [&](o3d_registration_result_t** out, const o3d_pointcloud_t* a, const o3d_pointcloud_t* b,
                                const o3d_feature_t* fa, const o3d_feature_t* fb) {
                                return o3d_register_fgr_based_on_feature_matching(out, a, b, fa, fb, &o);
                            });
}

Result fgr_corres(const PyPointCloud& source, const PyPointCloud& target, py::handle corres, py::handle option,
                  py::handle seed, int32_t num_threads, py::object callback) {
    Progress progress(std::move(callback));
    o3d_fgr_options_t o = fgr_options(option, seed, num_threads, progress);
    auto pairs = as_corres(corres, "corres");
    const int32_t* cp = pairs.size() ? pairs.data() : nullptr;
    size_t n = (size_t)pairs.shape(0);
    return run_registration(source, target, nullptr, nullptr, progress,
                            [&](o3d_registration_result_t** out, const o3d_pointcloud_t* a, const o3d_pointcloud_t* b,
                                const o3d_feature_t*, const o3d_feature_t*) {
                                return o3d_register_fgr_based_on_correspondence(out, a, b, cp, n, &o);
                            });
}

template <typename C, typename Arg>  // Arg: py::arg, or py::arg_v with a default
void def_threshold(py::module_& m, const char* cls, const char* field, const char* repr_field, Arg ctor_arg,
                   const char* doc) {
    std::string rf = repr_field, name = cls;
    static_cast<py::class_<C, Checker>>(m.attr(cls))
        .def(py::init<double>(), ctor_arg, doc)
        .def(py::init<const C&>(), py::arg("other"), "Copy constructor")
        .def_property(
            field, [](const C& c) { return c.c.threshold; }, [](C& c, double v) { c.c.threshold = v; })
        .def("__repr__", [rf, name](const C& c) { return name + " with " + rf + "=" + fixed6(c.c.threshold); });
}

}  // namespace

void declare_registration_global(py::module_& m) {
    py::class_<Checker>(m, "CorrespondenceChecker",
                        "Base of the correspondence checkers that prune RANSAC hypotheses early.");
    py::class_<EdgeLengthChecker, Checker>(m, "CorrespondenceCheckerBasedOnEdgeLength",
                                           "Edges between the drawn points must have similar lengths in both clouds.");
    py::class_<DistanceChecker, Checker>(m, "CorrespondenceCheckerBasedOnDistance",
                                         "Aligned corresponding points must lie within distance_threshold.");
    py::class_<NormalChecker, Checker>(m, "CorrespondenceCheckerBasedOnNormal",
                                       "Aligned corresponding normals must differ by less than normal_angle_threshold "
                                       "(radians); both clouds need normals.");
    py::class_<RansacCriteria>(m, "RANSACConvergenceCriteria");
    py::class_<FgrOption>(m, "FastGlobalRegistrationOption");
}

void define_registration_global(py::module_& m) {
    const o3d_ransac_options_t rd = init_of(&o3d_ransac_options_init);
    static_cast<py::class_<Checker>>(m.attr("CorrespondenceChecker"))
        .def_property_readonly(
            "require_pointcloud_alignment_", [](const Checker& c) { return c.require_alignment; },
            "Whether the check needs the clouds aligned by the hypothesis (distance, normal) or not (edge length).")
        .def(
            "Check",
            [](const Checker& self, const PyPointCloud& source, const PyPointCloud& target, py::handle corres,
               py::handle transformation) {
                auto pairs = as_corres(corres, "corres");
                auto T = mat4_or_identity(transformation, "transformation");
                const int32_t* cp = pairs.size() ? pairs.data() : nullptr;
                size_t n = (size_t)pairs.shape(0);
                int32_t passed = 0;
                CloudPtr a = source.h, b = target.h;
                o3d_status s;
                {
                    py::gil_scoped_release release;
                    SharedLocks locks;
                    locks.add(a->mutex);
                    locks.add(b->mutex);
                    s = o3d_correspondence_checker_check(&passed, &self.c, a->p, b->p, cp, n, T.data());
                }
                check(s);
                return passed != 0;
            },
            py::arg("source"), py::arg("target"), py::arg("corres"), py::arg("transformation"),
            "Does the hypothesis (corres moved by transformation) pass this checker?");
    o3d_correspondence_checker_t edge{};
    check(o3d_correspondence_checker_init(&edge, sizeof(edge), O3D_CHECKER_EDGE_LENGTH));
    def_threshold<EdgeLengthChecker>(m, "CorrespondenceCheckerBasedOnEdgeLength", "similarity_threshold",
                                     "similarity_threshold", py::arg("similarity_threshold") = edge.threshold,
                                     "similarity_threshold in (0, 1]: every pair of edge lengths must agree to this ratio.");
    // Open3D gives distance and angle no default; the C init's (0.075, 30 deg) stay C-only.
    def_threshold<DistanceChecker>(m, "CorrespondenceCheckerBasedOnDistance", "distance_threshold", "distance_threshold",
                                   py::arg("distance_threshold"), "distance_threshold > 0.");
    def_threshold<NormalChecker>(m, "CorrespondenceCheckerBasedOnNormal", "normal_angle_threshold", "normal_threshold",
                                 py::arg("normal_angle_threshold"), "normal_angle_threshold in radians, > 0.");

    auto ransac_criteria = static_cast<py::class_<RansacCriteria>>(m.attr("RANSACConvergenceCriteria"));
    def_ransac_convergence_criteria_init(ransac_criteria);
    ransac_criteria
        .def(py::init<const RansacCriteria&>(), py::arg("other"), "Copy constructor")
        .def("__repr__", [](const RansacCriteria& c) {
            char buf[64];
            std::snprintf(buf, sizeof buf, "%e", c.o.confidence);
            return "RANSACConvergenceCriteria(max_iteration=" + std::to_string(c.o.max_iteration) + ", confidence=" + buf + ")";
        });
    def_fields(ransac_criteria, ransac_criteria_fields);

    FgrOption fd;
    static_cast<py::class_<FgrOption>>(m.attr("FastGlobalRegistrationOption"))
        .def(py::init([](double division_factor, bool use_absolute_scale, bool decrease_mu, double max_dist,
                         int32_t iteration_number, double tuple_scale, int32_t maximum_tuple_count, bool tuple_test,
                         py::object seed) {
                 FgrOption f;
                 f.o.division_factor = division_factor;
                 f.o.use_absolute_scale = use_absolute_scale ? 1 : 0;
                 f.o.decrease_mu = decrease_mu ? 1 : 0;
                 f.o.maximum_correspondence_distance = max_dist;
                 f.o.iteration_number = iteration_number;
                 f.o.tuple_scale = tuple_scale;
                 f.o.maximum_tuple_count = maximum_tuple_count;
                 f.o.tuple_test = tuple_test ? 1 : 0;
                 seed_fields(seed);  // validate now
                 f.seed = std::move(seed);
                 return f;
             }),
             py::arg("division_factor") = fd.o.division_factor, py::arg("use_absolute_scale") = fd.o.use_absolute_scale != 0,
             // Open3D 0.20's Python constructor defaults decrease_mu to False (its C++ default, used when the
             // registration functions get no option, is True): kept, so Open3D scripts get the same result.
             py::arg("decrease_mu") = false, py::arg("maximum_correspondence_distance") = fd.o.maximum_correspondence_distance,
             py::arg("iteration_number") = fd.o.iteration_number, py::arg("tuple_scale") = fd.o.tuple_scale,
             py::arg("maximum_tuple_count") = fd.o.maximum_tuple_count, py::arg("tuple_test") = fd.o.tuple_test != 0,
             py::kw_only(), py::arg("seed") = py::none(),
             "Fast Global Registration options. seed (o3d extra): None draws from the global generator "
             "(o3d.utility.random.seed), an int fixes the random tuples.")
        .def(py::init<const FgrOption&>(), py::arg("other"), "Copy constructor")
        .def_property(
            "seed", [](const FgrOption& f) { return f.seed; },
            [](FgrOption& f, py::object v) {
                seed_fields(v);
                f.seed = std::move(v);
            },
            "o3d extra: None (global generator) or an int.")
        .def("__repr__", [](const FgrOption& f) {
            auto b = [](int32_t v) { return std::string(v ? "true" : "false"); };
            return "FastGlobalRegistrationOption(\ndivision_factor=" + shortest(f.o.division_factor) +
                   ",\nuse_absolute_scale=" + b(f.o.use_absolute_scale) + ",\ndecrease_mu=" + b(f.o.decrease_mu) +
                   ",\nmaximum_correspondence_distance=" + shortest(f.o.maximum_correspondence_distance) +
                   ",\niteration_number=" + std::to_string(f.o.iteration_number) + ",\ntuple_scale=" + shortest(f.o.tuple_scale) +
                   ",\nmaximum_tuple_count=" + std::to_string(f.o.maximum_tuple_count) + ",\ntuple_test=" + b(f.o.tuple_test) +
                   ",\n)";
        });
    auto fgr = static_cast<py::class_<FgrOption>>(m.attr("FastGlobalRegistrationOption"));
    def_fields(fgr);

    // Defaults of the Python wrappers (o3d/pipelines/registration.py).
    m.attr("_ransac_defaults") = py::dict(py::arg("ransac_n") = rd.ransac_n, py::arg("num_threads") = rd.num_threads);
    m.attr("_fgr_defaults") = py::dict(py::arg("num_threads") = fd.o.num_threads);
    m.def("_registration_ransac_based_on_feature_matching", &ransac_features, py::arg("source"), py::arg("target"),
          py::arg("source_feature"), py::arg("target_feature"), py::arg("mutual_filter"),
          py::arg("max_correspondence_distance"), py::arg("estimation_method") = py::none(), py::arg("ransac_n") = rd.ransac_n,
          py::arg("checkers") = py::none(), py::arg("criteria") = py::none(), py::arg("seed") = py::none(),
          py::arg("num_threads") = rd.num_threads, py::arg("progress") = py::none());
    m.def("_registration_ransac_based_on_correspondence", &ransac_corres, py::arg("source"), py::arg("target"),
          py::arg("corres"), py::arg("max_correspondence_distance"), py::arg("estimation_method") = py::none(),
          py::arg("ransac_n") = rd.ransac_n, py::arg("checkers") = py::none(), py::arg("criteria") = py::none(),
          py::arg("seed") = py::none(), py::arg("num_threads") = rd.num_threads, py::arg("progress") = py::none());
    m.def("_registration_fgr_based_on_feature_matching", &fgr_features, py::arg("source"), py::arg("target"),
          py::arg("source_feature"), py::arg("target_feature"), py::arg("option") = py::none(),
          py::arg("seed") = py::none(), py::arg("num_threads") = fd.o.num_threads, py::arg("progress") = py::none());
    m.def("_registration_fgr_based_on_correspondence", &fgr_corres, py::arg("source"), py::arg("target"),
          py::arg("corres"), py::arg("option") = py::none(), py::arg("seed") = py::none(),
          py::arg("num_threads") = fd.o.num_threads, py::arg("progress") = py::none());
    m.def(
        "_random_seed",
        [](py::handle seed) {
            if (seed.is_none()) invalid("seed: expected an integer");
            check(o3d_random_seed(seed_fields(seed).second));
        },
        py::arg("seed"), "Seed the global generator of the randomized calls (RANSAC, FGR) that get no seed.");
}

}  // namespace o3dpy
