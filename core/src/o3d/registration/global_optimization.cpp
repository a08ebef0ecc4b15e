// SPDX-License-Identifier: MIT
// Open3D's GlobalOptimization: validate, optimize, prune, optimize, prune, restore the reference node.
#include "o3d/registration/global_optimization.h"

#include <Eigen/LU>
#include <cmath>
#include <string>
#include <vector>

#include "o3d/registration/global_optimization_pass.h"
#include "o3d/utility/error.h"
#include "o3d/utility/parallel.h"

namespace o3d::registration {
namespace {

void require(bool ok, const std::string& message) {
    if (!ok) throw InvalidArgument("global optimization: " + message);
}

void check_options(const GlobalOptimizationOptions& options, size_t num_nodes) {
    const auto& c = options.criteria;
    require(c.max_iteration >= 0, "max_iteration must be >= 0, got " + std::to_string(c.max_iteration));
    require(c.max_iteration_lm >= 1, "max_iteration_lm must be >= 1, got " + std::to_string(c.max_iteration_lm));
    const auto threshold = [](double x) { return x >= 0.0 && std::isfinite(x); };
    require(threshold(c.min_relative_increment), "min_relative_increment must be finite and >= 0");
    require(threshold(c.min_relative_residual_increment), "min_relative_residual_increment must be finite and >= 0");
    require(threshold(c.min_right_term), "min_right_term must be finite and >= 0");
    require(threshold(c.min_residual), "min_residual must be finite and >= 0");
    require(c.lower_scale_factor > 0.0 && c.lower_scale_factor <= c.upper_scale_factor &&
                std::isfinite(c.upper_scale_factor),
            "the scale factors must satisfy 0 < lower_scale_factor <= upper_scale_factor < inf");
    const auto& o = options.option;
    require(o.max_correspondence_distance > 0.0 && std::isfinite(o.max_correspondence_distance),
            "max_correspondence_distance must be finite and > 0");
    require(o.preference_loop_closure > 0.0 && std::isfinite(o.preference_loop_closure),
            "preference_loop_closure must be finite and > 0");
    require(o.edge_prune_threshold >= 0.0 && o.edge_prune_threshold <= 1.0, "edge_prune_threshold must be in [0, 1]");
    require(o.reference_node >= -1 && (o.reference_node == -1 || static_cast<size_t>(o.reference_node) < num_nodes),
            "reference_node " + std::to_string(o.reference_node) + " is not -1 or a node index (graph has " +
                std::to_string(num_nodes) + " nodes)");
    require(options.num_threads >= 0, "num_threads must be >= 0, got " + std::to_string(options.num_threads));
    require(options.method == GlobalOptimizationMethod::GaussNewton ||
                options.method == GlobalOptimizationMethod::LevenbergMarquardt,
            "unknown method");
}

bool invertible(const Eigen::Matrix4d& m) {
    if (!m.allFinite()) return false;
    Eigen::Matrix4d inverse;
    bool ok = false;
    m.computeInverseWithCheck(inverse, ok);
    return ok && inverse.allFinite();
}

/// Every node reachable from node 0 over edges of either direction (Open3D's connectivity test).
bool connected(const PoseGraph& graph) {
    const size_t n = graph.nodes.size();
    if (n == 0) return true;
    std::vector<std::vector<int>> neighbours(n);
    for (const auto& e : graph.edges) {
        neighbours[static_cast<size_t>(e.source_node_id)].push_back(e.target_node_id);
        neighbours[static_cast<size_t>(e.target_node_id)].push_back(e.source_node_id);
    }
    std::vector<char> seen(n, 0);
    std::vector<int> stack{0};
    seen[0] = 1;
    size_t reached = 1;
    while (!stack.empty()) {
        const int i = stack.back();
        stack.pop_back();
        for (const int j : neighbours[static_cast<size_t>(i)])
            if (!seen[static_cast<size_t>(j)]) {
                seen[static_cast<size_t>(j)] = 1;
                ++reached;
                stack.push_back(j);
            }
    }
    return reached == n;
}

void check_graph(const PoseGraph& graph) {
    const int64_t n = static_cast<int64_t>(graph.nodes.size());
    for (size_t i = 0; i < graph.nodes.size(); ++i)
        require(invertible(graph.nodes[i].pose),
                "nodes[" + std::to_string(i) + "].pose is not a finite, invertible matrix");
    for (size_t k = 0; k < graph.edges.size(); ++k) {
        const PoseGraphEdge& e = graph.edges[k];
        const std::string name = "edges[" + std::to_string(k) + "]";
        require(e.source_node_id >= 0 && e.source_node_id < n && e.target_node_id >= 0 && e.target_node_id < n,
                name + " joins nodes " + std::to_string(e.source_node_id) + " and " +
                    std::to_string(e.target_node_id) + " but the graph has " + std::to_string(n) + " nodes");
        require(invertible(e.transformation), name + ".transformation is not a finite, invertible matrix");
        require(e.information.allFinite(), name + ".information has a NaN or infinite entry");
        if (e.uncertain)
            require(e.confidence >= 0.0 && e.confidence <= 1.0, name + ".confidence must be in [0, 1]");
        else
            require(e.confidence == 1.0, name + " is certain but its confidence is not 1");
    }
    require(connected(graph), "the graph is not connected");
}

/// Uncertain edges need a positive line-process scale, or their confidences are 0/0.
void check_line_process(const PoseGraph& graph, const GlobalOptimizationOption& option) {
    bool any_uncertain = false;
    for (const auto& e : graph.edges) any_uncertain = any_uncertain || e.uncertain;
    if (!any_uncertain) return;
    const double mu = detail::line_process_scale(graph.edges, option);
    require(mu > 0.0 && std::isfinite(mu),
            "the line-process scale preference_loop_closure * max_correspondence_distance^2 * mean information(5, 5) "
            "is " + std::to_string(mu) + "; it must be > 0 (information(5, 5) counts an edge's point pairs)");
}

/// Open3D's CreatePoseGraphWithoutInvalidEdges: uncertain edges stay only with a confidence above the threshold.
int prune(PoseGraph& graph, double threshold) {
    const size_t before = graph.edges.size();
    std::vector<PoseGraphEdge> kept;
    kept.reserve(before);
    for (auto& e : graph.edges)
        if (!e.uncertain || e.confidence > threshold) kept.push_back(std::move(e));
    graph.edges = std::move(kept);
    return static_cast<int>(before - graph.edges.size());
}

detail::PassResult run_pass(PoseGraph& graph, const GlobalOptimizationOptions& options, int threads, int reference,
                            int pass) {
    check_line_process(graph, options.option);
    const detail::PassProgress progress(options.progress, pass, options.criteria.max_iteration);
    if (options.method == GlobalOptimizationMethod::GaussNewton)
        return detail::gauss_newton_pass(graph, options, threads, reference, progress);
    return detail::levenberg_marquardt_pass(graph, options, threads, progress);
}

}  // namespace

GlobalOptimizationSummary global_optimization(PoseGraph& graph, const GlobalOptimizationOptions& options) {
    check_options(options, graph.nodes.size());
    check_graph(graph);
    GlobalOptimizationSummary summary;
    if (graph.edges.empty()) return summary;  // nothing constrains the poses

    const int threads = utility::resolve_num_threads(options.num_threads);
    const int reference = options.option.reference_node < 0 ? 0 : options.option.reference_node;
    // Work on a copy, so that a cancelled or failed call leaves the caller's graph as it was.
    PoseGraph work = graph;
    const detail::PassResult first = run_pass(work, options, threads, reference, 0);
    summary.pruned_edges += prune(work, options.option.edge_prune_threshold);
    const detail::PassResult second = run_pass(work, options, threads, reference, 1);
    summary.pruned_edges += prune(work, options.option.edge_prune_threshold);
    summary.iterations = first.iterations + second.iterations;
    summary.initial_residual = first.initial_residual;
    summary.final_residual = second.final_residual;

    // One rigid motion of the whole graph puts the reference node back (Gauss-Newton never moved it).
    const Eigen::Matrix4d& original = graph.nodes[static_cast<size_t>(reference)].pose;
    const Eigen::Matrix4d& moved = work.nodes[static_cast<size_t>(reference)].pose;
    if (moved != original) {
        const Eigen::Matrix4d compensation = original * moved.inverse();
        for (auto& node : work.nodes) node.pose = compensation * node.pose;
        work.nodes[static_cast<size_t>(reference)].pose = original;  // exactly, not to rounding
    }
    for (const auto& node : work.nodes)
        if (!node.pose.allFinite())
            throw NotConverged("global optimization diverged (check that the information matrices are positive "
                               "semi-definite)");
    graph = std::move(work);
    return summary;
}

}  // namespace o3d::registration
