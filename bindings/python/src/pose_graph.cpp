// SPDX-License-Identifier: MIT
// o3d.pipelines.registration.PoseGraph (its node/edge accessors; the list-like PoseGraphNodeVector /
// PoseGraphEdgeVector and the PoseGraphNode / PoseGraphEdge views live in o3d/pipelines/_pose_graph.py),
// GlobalOptimization{GaussNewton,LevenbergMarquardt,ConvergenceCriteria,Option}, global_optimization and
// o3d.io.read_pose_graph / write_pose_graph, over posegraph.h.
#include <cstdio>

#include "generated/option_inits.h"
#include "generated/posegraph_methods.h"
#include "registration_types.h"

namespace o3dpy {
namespace {

using GraphHandle = Handle<o3d_pose_graph_t, &o3d_pose_graph_destroy>;
using GraphPtr = std::shared_ptr<GraphHandle>;

struct PyPoseGraph {
    GraphPtr h;
    PyPoseGraph() {
        o3d_pose_graph_t* raw = nullptr;
        check(o3d_pose_graph_create(&raw));
        h = std::make_shared<GraphHandle>(raw);
    }
    explicit PyPoseGraph(o3d_pose_graph_t* raw) : h(std::make_shared<GraphHandle>(raw)) {}
};

struct Method {
    int32_t kind = O3D_GLOBAL_OPTIMIZATION_LEVENBERG_MARQUARDT;
};
struct GaussNewton : Method {
    GaussNewton() { kind = O3D_GLOBAL_OPTIMIZATION_GAUSS_NEWTON; }
};
struct LevenbergMarquardt : Method {};

o3d_global_optimization_options_t defaults() { return init_of(&o3d_global_optimization_options_init); }

/// GlobalOptimizationConvergenceCriteria and GlobalOptimizationOption: each the C options, showing its fields.
struct Criteria {
    o3d_global_optimization_options_t o = defaults();
};
struct Option {
    o3d_global_optimization_options_t o = defaults();
};
const FieldNames criteria_fields = {"max_iteration",  "min_relative_increment", "min_relative_residual_increment",
                                    "min_right_term", "min_residual",           "max_iteration_lm",
                                    "upper_scale_factor", "lower_scale_factor"};
const FieldNames option_fields = {"max_correspondence_distance", "edge_prune_threshold", "preference_loop_closure",
                                  "reference_node"};

struct Summary {
    int32_t iterations = 0;
    double initial_residual = 0.0;
    double final_residual = 0.0;
    int32_t pruned_edges = 0;
};

size_t as_index(int64_t i) {
    if (i < 0) throw py::index_error("pose graph index out of range");
    return (size_t)i;
}

py::array readonly_matrix(const double* v, py::ssize_t rows, py::ssize_t cols) {
    py::array_t<double> a(std::vector<py::ssize_t>{rows, cols});
    std::memcpy(a.mutable_data(), v, sizeof(double) * (size_t)(rows * cols));
    a.attr("setflags")(py::arg("write") = false);
    return std::move(a);
}

std::array<double, 36> as_mat6(py::handle obj, const char* what) {
    py::array a = py::array::ensure(obj);
    if (!a) invalid(std::string(what) + ": expected a (6, 6) array of numbers");
    char kind = a.dtype().kind();
    if (kind != 'f' && kind != 'i' && kind != 'u') invalid(std::string(what) + ": expected numbers");
    if (a.ndim() != 2 || a.shape(0) != 6 || a.shape(1) != 6) invalid(std::string(what) + ": expected shape (6, 6)");
    auto d = py::array_t<double, py::array::c_style | py::array::forcecast>::ensure(a);
    if (!d) throw py::error_already_set();
    std::array<double, 36> out{};
    std::memcpy(out.data(), d.data(), sizeof out);
    return out;
}

o3d_pose_graph_edge_t make_edge(int32_t s, int32_t t, py::handle T, py::handle info, bool uncertain, double confidence) {
    o3d_pose_graph_edge_t e = init_of(&o3d_pose_graph_edge_init);
    e.source_node_id = s;
    e.target_node_id = t;
    if (!T.is_none()) {
        auto m = as_mat4(T, "transformation");
        std::memcpy(e.transformation, m.data(), sizeof e.transformation);
    }
    if (!info.is_none()) {
        auto m = as_mat6(info, "information");
        std::memcpy(e.information, m.data(), sizeof e.information);
    }
    e.uncertain = uncertain ? 1 : 0;
    e.confidence = confidence;
    return e;
}

py::tuple edge_tuple(const o3d_pose_graph_edge_t& e) {
    return py::make_tuple(e.source_node_id, e.target_node_id, readonly_matrix(e.transformation, 4, 4),
                          readonly_matrix(e.information, 6, 6), e.uncertain != 0, e.confidence);
}

PyPoseGraph clone(const PyPoseGraph& g) {
    o3d_pose_graph_t* out = nullptr;
    locked_const(g.h, [&](const o3d_pose_graph_t* p) { return o3d_pose_graph_clone(&out, p); });
    return PyPoseGraph(out);
}

size_t count(const PyPoseGraph& g, bool nodes) {
    size_t n = 0;
    locked_const(g.h, [&](const o3d_pose_graph_t* p) {
        return nodes ? o3d_pose_graph_num_nodes(&n, p) : o3d_pose_graph_num_edges(&n, p);
    });
    return n;
}

Summary optimize(PyPoseGraph& graph, py::handle method, py::handle criteria, py::handle option, py::object progress,
                 int32_t num_threads) {
    o3d_global_optimization_options_t o = defaults();
    if (!method.is_none()) {
        if (!py::isinstance<Method>(method))
            invalid("method: expected GlobalOptimizationGaussNewton() or GlobalOptimizationLevenbergMarquardt()");
        o.method = method.cast<const Method&>().kind;
    }
    if (!criteria.is_none()) {
        if (!py::isinstance<Criteria>(criteria)) invalid("criteria: expected GlobalOptimizationConvergenceCriteria");
        copy_fields(o, criteria.cast<const Criteria&>().o, criteria_fields);
    }
    if (!option.is_none()) {
        if (!py::isinstance<Option>(option)) invalid("option: expected GlobalOptimizationOption");
        copy_fields(o, option.cast<const Option&>().o, option_fields);
    }
    o.num_threads = num_threads;
    Progress ctx(std::move(progress));
    o.progress = &progress_trampoline;
    o.user_data = &ctx;
    o3d_global_optimization_summary_t s{};
    s.struct_size = sizeof(s);
    GraphPtr h = graph.h;
    o3d_status st;
    {
        py::gil_scoped_release release;
        std::unique_lock<std::shared_mutex> lock(h->mutex);
        st = o3d_global_optimization(&s, h->p, &o);
    }
    ctx.rethrow();
    check(st);
    return Summary{s.iterations, s.initial_residual, s.final_residual, s.pruned_edges};
}

std::string g6(double v) {
    char buf[64];
    std::snprintf(buf, sizeof buf, "%f", v);
    return buf;
}

}  // namespace

void declare_pose_graph(py::module_& m) {
    py::class_<PyPoseGraph>(m, "PoseGraph",
                            "Nodes (poses) and edges (relative transformations with information matrices) for multiway "
                            "registration. `nodes` and `edges` are list-like views that read and write the graph.");
    py::class_<Method>(m, "GlobalOptimizationMethod", "Base of the pose-graph optimization methods.");
    py::class_<GaussNewton, Method>(m, "GlobalOptimizationGaussNewton");
    py::class_<LevenbergMarquardt, Method>(m, "GlobalOptimizationLevenbergMarquardt");
    py::class_<Criteria>(m, "GlobalOptimizationConvergenceCriteria");
    py::class_<Option>(m, "GlobalOptimizationOption");
    py::class_<Summary>(m, "GlobalOptimizationSummary",
                        "What global_optimization did (o3d extra): iterations, residuals before/after, pruned edges.");
}

void define_pose_graph(py::module_& m) {
    auto graph = static_cast<py::class_<PyPoseGraph>>(m.attr("PoseGraph"));
    def_pose_graph_methods(graph);
    graph.def(py::init<>(), "An empty graph.")
        .def(py::init(&clone), py::arg("other"), "Copy constructor (a deep copy).")
        .def("__copy__", &clone)
        .def("__deepcopy__", [](const PyPoseGraph& g, py::handle) { return clone(g); }, py::arg("memo"))
        .def("_get_edge",
             [](const PyPoseGraph& g, int64_t i) {
                 o3d_pose_graph_edge_t e = init_of(&o3d_pose_graph_edge_init);
                 size_t k = as_index(i);
                 locked_const(g.h, [&](const o3d_pose_graph_t* p) { return o3d_pose_graph_get_edge(&e, p, k); });
                 return edge_tuple(e);
             })
        .def("_set_edge",
             [](PyPoseGraph& g, int64_t i, int32_t s, int32_t t, py::handle T, py::handle info, bool uncertain,
                double confidence) {
                 o3d_pose_graph_edge_t e = make_edge(s, t, T, info, uncertain, confidence);
                 size_t k = as_index(i);
                 locked_mut(g.h, [&](o3d_pose_graph_t* p) { return o3d_pose_graph_set_edge(p, k, &e); });
             })
        .def("_add_edge",
             [](PyPoseGraph& g, int32_t s, int32_t t, py::handle T, py::handle info, bool uncertain, double confidence) {
                 o3d_pose_graph_edge_t e = make_edge(s, t, T, info, uncertain, confidence);
                 locked_mut(g.h, [&](o3d_pose_graph_t* p) { return o3d_pose_graph_add_edge(p, &e); });
             })
        .def("__repr__", [](const PyPoseGraph& g) {
            return "PoseGraph with " + std::to_string(count(g, true)) + " nodes and " + std::to_string(count(g, false)) +
                   " edges.";
        });

    static_cast<py::class_<Method>>(m.attr("GlobalOptimizationMethod"))
        .def(
            "OptimizePoseGraph",
            [](const Method& self, PyPoseGraph& graph, py::handle criteria, py::handle option) {
                optimize(graph, py::cast(self), criteria, option, py::none(), defaults().num_threads);
            },
            py::arg("pose_graph"), py::arg("criteria"), py::arg("option"), "Optimize pose_graph in place with this method.");
    static_cast<py::class_<GaussNewton, Method>>(m.attr("GlobalOptimizationGaussNewton"))
        .def(py::init<>())
        .def(py::init<const GaussNewton&>(), py::arg("other"), "Copy constructor")
        .def("__repr__", [](const GaussNewton&) { return std::string("GlobalOptimizationGaussNewton"); });
    static_cast<py::class_<LevenbergMarquardt, Method>>(m.attr("GlobalOptimizationLevenbergMarquardt"))
        .def(py::init<>())
        .def(py::init<const LevenbergMarquardt&>(), py::arg("other"), "Copy constructor")
        .def("__repr__", [](const LevenbergMarquardt&) { return std::string("GlobalOptimizationLevenbergMarquardt"); });

    auto criteria = static_cast<py::class_<Criteria>>(m.attr("GlobalOptimizationConvergenceCriteria"));
    def_global_optimization_convergence_criteria_init(criteria);
    criteria.def(py::init<const Criteria&>(), py::arg("other"), "Copy constructor")
        .def("__repr__", [](const Criteria& c) {
            return "GlobalOptimizationConvergenceCriteria\n> max_iteration : " + std::to_string(c.o.max_iteration) +
                   "\n> min_relative_increment : " + g6(c.o.min_relative_increment) +
                   "\n> min_relative_residual_increment : " + g6(c.o.min_relative_residual_increment) +
                   "\n> min_right_term : " + g6(c.o.min_right_term) + "\n> min_residual : " + g6(c.o.min_residual) +
                   "\n> max_iteration_lm : " + std::to_string(c.o.max_iteration_lm) + "\n> upper_scale_factor : " +
                   g6(c.o.upper_scale_factor) + "\n> lower_scale_factor : " + g6(c.o.lower_scale_factor);
        });
    def_fields(criteria, criteria_fields);

    auto option = static_cast<py::class_<Option>>(m.attr("GlobalOptimizationOption"));
    option.def(py::init<>(),
             "Open3D's defaults: max_correspondence_distance 0.075, edge_prune_threshold 0.25, preference_loop_closure 1.0, "
             "reference_node -1 (the first node).");
    def_global_optimization_option_init(option);
    option.def(py::init<const Option&>(), py::arg("other"), "Copy constructor")
        .def("__repr__", [](const Option& p) {
            return "GlobalOptimizationOption\n> max_correspondence_distance : " + g6(p.o.max_correspondence_distance) +
                   "\n> edge_prune_threshold : " + g6(p.o.edge_prune_threshold) +
                   "\n> preference_loop_closure : " + g6(p.o.preference_loop_closure) +
                   "\n> reference_node : " + std::to_string(p.o.reference_node);
        });
    def_fields(option, option_fields);

    static_cast<py::class_<Summary>>(m.attr("GlobalOptimizationSummary"))
        .def_readonly("iterations", &Summary::iterations, "Iterations of both passes.")
        .def_readonly("initial_residual", &Summary::initial_residual, "Robust objective before the first pass.")
        .def_readonly("final_residual", &Summary::final_residual, "Robust objective after the last pass.")
        .def_readonly("pruned_edges", &Summary::pruned_edges, "Uncertain edges removed (confidence below the threshold).")
        .def("__repr__", [](const Summary& s) {
            return "GlobalOptimizationSummary(iterations=" + std::to_string(s.iterations) + ", initial_residual=" +
                   g6(s.initial_residual) + ", final_residual=" + g6(s.final_residual) +
                   ", pruned_edges=" + std::to_string(s.pruned_edges) + ")";
        });

    m.def("_global_optimization", &optimize, py::arg("pose_graph"), py::arg("method") = py::none(),
          py::arg("criteria") = py::none(), py::arg("option") = py::none(), py::arg("progress") = py::none(),
          py::arg("num_threads") = defaults().num_threads);
    m.attr("_global_optimization_defaults") = py::dict(py::arg("num_threads") = defaults().num_threads);
    m.def("_pose_graph_edge_defaults", [] { return edge_tuple(init_of(&o3d_pose_graph_edge_init)); },
          "(source, target, transformation, information, uncertain, confidence) of o3d_pose_graph_edge_init.");
    m.def(
        "read_pose_graph",
        [](py::handle filename) {
            std::string path = path_of(filename);
            o3d_pose_graph_t* out = nullptr;
            check(nogil([&] { return o3d_io_read_pose_graph(&out, path.c_str()); }), path);
            return PyPoseGraph(out);
        },
        py::arg("filename"),
        "Read Open3D's JSON pose graph. Failures raise (O3DFileNotFoundError, O3DIOError, ParseError) where Open3D "
        "returns an empty graph.");
    m.def(
        "write_pose_graph",
        [](py::handle filename, const PyPoseGraph& pose_graph) {
            std::string path = path_of(filename);
            GraphPtr h = pose_graph.h;
            o3d_status s;
            {
                py::gil_scoped_release release;
                std::shared_lock<std::shared_mutex> lock(h->mutex);
                s = o3d_io_write_pose_graph(path.c_str(), h->p);
            }
            check(s, path);
        },
        py::arg("filename"), py::arg("pose_graph"), "Write a pose graph in Open3D's JSON layout (failures raise).");
}

}  // namespace o3dpy
