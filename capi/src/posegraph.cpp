// SPDX-License-Identifier: MIT
// C API: posegraph.h.
#include <Eigen/LU>
#include <cmath>
#include <cstring>
#include <memory>
#include <string>

#include "camera_internal.h"
#include "internal.h"
#include "o3d/camera/camera_checks.h"
#include "o3d/io/pose_graph_io.h"
#include "o3d/posegraph.h"
#include "o3d/registration/global_optimization.h"
#include "o3d/registration/pose_graph.h"

struct o3d_pose_graph {
    o3d::registration::PoseGraph graph;
};

namespace {

namespace reg = o3d::registration;
using o3d::capi::require;

// clang-format off
const o3d_pose_graph_edge_t kEdgeDefaults = {
    sizeof(o3d_pose_graph_edge_t), 0, 0,
    {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1},
    {1, 0, 0, 0, 0, 0, 0, 1, 0, 0, 0, 0, 0, 0, 1, 0, 0, 0, 0, 0, 0, 1, 0, 0, 0, 0, 0, 0, 1, 0, 0, 0, 0, 0, 0, 1},
    0, 1.0,
};

const o3d_global_optimization_options_t kOptionsDefaults = {
    sizeof(o3d_global_optimization_options_t), O3D_GLOBAL_OPTIMIZATION_LEVENBERG_MARQUARDT,
    100, 1e-6, 1e-6, 1e-6, 1e-6, 20, 2.0 / 3.0, 1.0 / 3.0,
    0.075, 0.25, 1.0, -1, 0, nullptr, nullptr,
};
// clang-format on

/// Rotation columns may drift from orthonormal by rounding (products of many poses), not more.
constexpr double kRigidTolerance = 1e-6;

/// A caller's pose: finite, last row (0, 0, 0, 1), an orthonormal right-handed rotation block.
Eigen::Matrix4d read_pose(const double* m, const char* name) {
    const Eigen::Matrix4d pose = o3d::capi::matrix_from_row_major(m);
    o3d::camera::require_rigid_layout(pose, name);
    const Eigen::Matrix3d r = pose.topLeftCorner<3, 3>();
    const double drift = (r.transpose() * r - Eigen::Matrix3d::Identity()).cwiseAbs().maxCoeff();
    if (!(drift <= kRigidTolerance) || !(r.determinant() > 0.0))
        throw o3d::InvalidArgument(std::string(name) + ": the rotation block is not a rotation (R^T R differs from "
                                   "I by " + std::to_string(drift) + ")");
    return pose;
}

template <int Rows>
Eigen::Matrix<double, Rows, Rows> read_matrix(const double* m, const char* name) {
    using RowMajor = Eigen::Matrix<double, Rows, Rows, Eigen::RowMajor>;
    const Eigen::Matrix<double, Rows, Rows> out = Eigen::Map<const RowMajor>(m);
    if (!out.allFinite()) throw o3d::InvalidArgument(std::string(name) + " has a NaN or infinite entry");
    return out;
}

template <int Rows>
void write_matrix(const Eigen::Matrix<double, Rows, Rows>& m, double* out) {
    Eigen::Map<Eigen::Matrix<double, Rows, Rows, Eigen::RowMajor>> row_major(out);
    row_major = m;
}

reg::PoseGraphEdge edge_from(const o3d_pose_graph_edge_t* user) {
    const o3d_pose_graph_edge_t e = o3d::capi::read_options(require(user, "edge"), kEdgeDefaults, "edge");
    reg::PoseGraphEdge out;
    out.source_node_id = e.source_node_id;
    out.target_node_id = e.target_node_id;
    out.transformation = read_matrix<4>(e.transformation, "edge.transformation");
    out.information = read_matrix<6>(e.information, "edge.information");
    out.uncertain = e.uncertain != 0;
    if (!(e.confidence >= 0.0 && e.confidence <= 1.0))
        throw o3d::InvalidArgument("edge.confidence must be in [0, 1]");
    out.confidence = e.confidence;
    return out;
}

/// Write `edge` into the first out->struct_size bytes of `out` (an older, shorter struct gets what fits).
void edge_to(const reg::PoseGraphEdge& edge, o3d_pose_graph_edge_t* out) {
    o3d_pose_graph_edge_t e = kEdgeDefaults;
    e.source_node_id = edge.source_node_id;
    e.target_node_id = edge.target_node_id;
    write_matrix<4>(edge.transformation, e.transformation);
    write_matrix<6>(edge.information, e.information);
    e.uncertain = edge.uncertain ? 1 : 0;
    e.confidence = edge.confidence;
    o3d::capi::init_options(out, out->struct_size, e, "out_edge");
}

void check_index(size_t index, size_t count, const char* what) {
    if (index >= count)
        throw o3d::InvalidArgument(std::string(what) + " index " + std::to_string(index) + " is out of range (" +
                                   std::to_string(count) + " " + what + "s)");
}

reg::GlobalOptimizationOptions to_core(const o3d_global_optimization_options_t& o) {
    reg::GlobalOptimizationOptions out;
    if (o.method == O3D_GLOBAL_OPTIMIZATION_GAUSS_NEWTON)
        out.method = reg::GlobalOptimizationMethod::GaussNewton;
    else if (o.method == O3D_GLOBAL_OPTIMIZATION_LEVENBERG_MARQUARDT)
        out.method = reg::GlobalOptimizationMethod::LevenbergMarquardt;
    else
        throw o3d::InvalidArgument("opts.method " + std::to_string(o.method) + " is not an O3D_GLOBAL_OPTIMIZATION_*");
    out.criteria.max_iteration = o.max_iteration;
    out.criteria.min_relative_increment = o.min_relative_increment;
    out.criteria.min_relative_residual_increment = o.min_relative_residual_increment;
    out.criteria.min_right_term = o.min_right_term;
    out.criteria.min_residual = o.min_residual;
    out.criteria.max_iteration_lm = o.max_iteration_lm;
    out.criteria.upper_scale_factor = o.upper_scale_factor;
    out.criteria.lower_scale_factor = o.lower_scale_factor;
    out.option.max_correspondence_distance = o.max_correspondence_distance;
    out.option.edge_prune_threshold = o.edge_prune_threshold;
    out.option.preference_loop_closure = o.preference_loop_closure;
    out.option.reference_node = o.reference_node;
    out.num_threads = o3d::capi::to_num_threads(o.num_threads);
    out.progress = o3d::capi::to_progress(o.progress, o.user_data);
    return out;
}

void check_summary_size(const o3d_global_optimization_summary_t* summary) {
    if (summary && (summary->struct_size < sizeof(uint32_t) || summary->struct_size > sizeof(*summary)))
        throw o3d::InvalidArgument("summary.struct_size " + std::to_string(summary->struct_size) +
                                   " is not a size this library knows (expected " + std::to_string(sizeof(*summary)) +
                                   ")");
}

}  // namespace

extern "C" {

O3D_API o3d_status o3d_pose_graph_edge_init(o3d_pose_graph_edge_t* edge, uint32_t struct_size) {
    return o3d::capi::guard(__func__, [&] { o3d::capi::init_options(edge, struct_size, kEdgeDefaults, "edge"); });
}

O3D_API o3d_status o3d_pose_graph_create(o3d_pose_graph_t** out) {
    return o3d::capi::guard(__func__, [&] {
        require(out, "out");
        *out = nullptr;
        *out = new o3d_pose_graph();
    });
}

O3D_API void o3d_pose_graph_destroy(o3d_pose_graph_t* graph) { delete graph; }

O3D_API o3d_status o3d_pose_graph_clone(o3d_pose_graph_t** out, const o3d_pose_graph_t* graph) {
    return o3d::capi::guard(__func__, [&] {
        require(out, "out");
        *out = nullptr;
        require(graph, "graph");
        *out = new o3d_pose_graph(*graph);
    });
}

O3D_API o3d_status o3d_pose_graph_num_nodes(size_t* out, const o3d_pose_graph_t* graph) {
    return o3d::capi::guard(__func__, [&] {
        require(graph, "graph");
        *require(out, "out") = graph->graph.nodes.size();
    });
}

O3D_API o3d_status o3d_pose_graph_num_edges(size_t* out, const o3d_pose_graph_t* graph) {
    return o3d::capi::guard(__func__, [&] {
        require(graph, "graph");
        *require(out, "out") = graph->graph.edges.size();
    });
}

O3D_API o3d_status o3d_pose_graph_add_node(o3d_pose_graph_t* graph, const double pose[16]) {
    return o3d::capi::guard(__func__, [&] {
        require(graph, "graph");
        reg::PoseGraphNode node;
        node.pose = read_pose(pose, "pose");
        graph->graph.nodes.push_back(node);
    });
}

O3D_API o3d_status o3d_pose_graph_get_node(double out_pose[16], const o3d_pose_graph_t* graph, size_t index) {
    return o3d::capi::guard(__func__, [&] {
        require(graph, "graph");
        require(out_pose, "out_pose");
        check_index(index, graph->graph.nodes.size(), "node");
        o3d::capi::matrix_to_row_major(graph->graph.nodes[index].pose, out_pose);
    });
}

O3D_API o3d_status o3d_pose_graph_set_node(o3d_pose_graph_t* graph, size_t index, const double pose[16]) {
    return o3d::capi::guard(__func__, [&] {
        require(graph, "graph");
        require(pose, "pose");
        check_index(index, graph->graph.nodes.size(), "node");
        graph->graph.nodes[index].pose = read_pose(pose, "pose");
    });
}

O3D_API o3d_status o3d_pose_graph_add_edge(o3d_pose_graph_t* graph, const o3d_pose_graph_edge_t* edge) {
    return o3d::capi::guard(__func__, [&] {
        require(graph, "graph");
        graph->graph.edges.push_back(edge_from(edge));
    });
}

O3D_API o3d_status o3d_pose_graph_get_edge(o3d_pose_graph_edge_t* out_edge, const o3d_pose_graph_t* graph,
                                           size_t index) {
    return o3d::capi::guard(__func__, [&] {
        require(graph, "graph");
        require(out_edge, "out_edge");
        check_index(index, graph->graph.edges.size(), "edge");
        edge_to(graph->graph.edges[index], out_edge);
    });
}

O3D_API o3d_status o3d_pose_graph_set_edge(o3d_pose_graph_t* graph, size_t index, const o3d_pose_graph_edge_t* edge) {
    return o3d::capi::guard(__func__, [&] {
        require(graph, "graph");
        require(edge, "edge");
        check_index(index, graph->graph.edges.size(), "edge");
        graph->graph.edges[index] = edge_from(edge);
    });
}

O3D_API o3d_status o3d_pose_graph_clear(o3d_pose_graph_t* graph) {
    return o3d::capi::guard(__func__, [&] {
        require(graph, "graph");
        graph->graph = reg::PoseGraph();
    });
}

O3D_API o3d_status o3d_io_read_pose_graph(o3d_pose_graph_t** out, const char* path) {
    return o3d::capi::guard(__func__, [&] {
        require(out, "out");
        *out = nullptr;
        require(path, "path");
        auto handle = std::make_unique<o3d_pose_graph>();
        handle->graph = o3d::io::read_pose_graph(path);
        *out = handle.release();
    });
}

O3D_API o3d_status o3d_io_write_pose_graph(const char* path, const o3d_pose_graph_t* graph) {
    return o3d::capi::guard(__func__, [&] {
        require(path, "path");
        require(graph, "graph");
        o3d::io::write_pose_graph(path, graph->graph);
    });
}

O3D_API o3d_status o3d_global_optimization_options_init(o3d_global_optimization_options_t* opts,
                                                        uint32_t struct_size) {
    return o3d::capi::guard(__func__, [&] { o3d::capi::init_options(opts, struct_size, kOptionsDefaults, "opts"); });
}

O3D_API o3d_status o3d_global_optimization(o3d_global_optimization_summary_t* summary, o3d_pose_graph_t* graph,
                                           const o3d_global_optimization_options_t* opts) {
    return o3d::capi::guard(__func__, [&] {
        require(graph, "graph");
        const reg::GlobalOptimizationOptions options =
            to_core(o3d::capi::read_options(opts, kOptionsDefaults, "opts"));
        check_summary_size(summary);
        const reg::GlobalOptimizationSummary s = reg::global_optimization(graph->graph, options);
        if (!summary) return;
        o3d_global_optimization_summary_t out{};
        out.struct_size = summary->struct_size;
        out.iterations = s.iterations;
        out.initial_residual = s.initial_residual;
        out.final_residual = s.final_residual;
        out.pruned_edges = s.pruned_edges;
        std::memcpy(summary, &out, summary->struct_size);
    });
}

}  // extern "C"
