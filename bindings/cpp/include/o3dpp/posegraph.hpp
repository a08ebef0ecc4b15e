// SPDX-License-Identifier: MIT
#pragma once
/// @file posegraph.hpp
/// @brief o3dpp::PoseGraph (multiway registration: node poses, edges with information matrices),
/// Open3D's JSON files, and global_optimization (Gauss-Newton / Levenberg-Marquardt with the line
/// process that prunes false loop closures). Matrices are row-major; an edge (s, t, T) says
/// pose_t^-1 * pose_s ~ T.
#include <cstdint>
#include <string>
#include <vector>

#include "o3d/posegraph.h"
#include "o3dpp/common.hpp"
#include "o3dpp/error.hpp"
#include "o3dpp/handle.hpp"
#include "o3dpp/span.hpp"

namespace o3dpp {

/// @brief PoseGraphEdge, Open3D defaults (0 -> 0, identity, odometry, confidence 1).
struct PoseGraphEdge {
    int32_t source_node_id = 0;
    int32_t target_node_id = 0;
    Mat4 transformation = identity4();
    Mat6 information = identity6();
    bool uncertain = false;  ///< a loop closure the line process may prune
    double confidence = 1.0;

    PoseGraphEdge() = default;
    PoseGraphEdge(int32_t source, int32_t target, const Mat4& t, const Mat6& info = identity6(),
                  bool is_uncertain = false, double edge_confidence = 1.0)
        : source_node_id(source),
          target_node_id(target),
          transformation(t),
          information(info),
          uncertain(is_uncertain),
          confidence(edge_confidence) {}

    static Mat6 identity6() {
        Mat6 m{};
        for (int i = 0; i < 6; ++i) m[i * 6 + i] = 1.0;
        return m;
    }

    o3d_pose_graph_edge_t to_c() const {
        o3d_pose_graph_edge_t c = raw();
        c.source_node_id = source_node_id;
        c.target_node_id = target_node_id;
        for (int i = 0; i < 16; ++i) c.transformation[i] = transformation[i];
        for (int i = 0; i < 36; ++i) c.information[i] = information[i];
        c.uncertain = uncertain ? 1 : 0;
        c.confidence = confidence;
        return c;
    }
    static PoseGraphEdge from_c(const o3d_pose_graph_edge_t& c) {
        PoseGraphEdge e;
        e.source_node_id = c.source_node_id;
        e.target_node_id = c.target_node_id;
        for (int i = 0; i < 16; ++i) e.transformation[i] = c.transformation[i];
        for (int i = 0; i < 36; ++i) e.information[i] = c.information[i];
        e.uncertain = c.uncertain != 0;
        e.confidence = c.confidence;
        return e;
    }
    /// @brief The library's default edge (o3d_pose_graph_edge_init).
    static PoseGraphEdge library_default() { return from_c(raw()); }

    bool operator==(const PoseGraphEdge& o) const {
        return source_node_id == o.source_node_id && target_node_id == o.target_node_id &&
               transformation == o.transformation && information == o.information && uncertain == o.uncertain &&
               confidence == o.confidence;
    }
    bool operator!=(const PoseGraphEdge& o) const { return !(*this == o); }

private:
    static o3d_pose_graph_edge_t raw() {
        o3d_pose_graph_edge_t c;
        check(o3d_pose_graph_edge_init(&c, sizeof c));
        return c;
    }
};

/// @brief A pose graph: one pose (rigid 4x4) per node, and edges. Move-only; clone() deep-copies.
class PoseGraph {
public:
    /// @brief An empty graph.
    PoseGraph() {
        o3d_pose_graph_t* g = nullptr;
        check(o3d_pose_graph_create(&g));
        h_.reset(g);
    }
    /// @brief Take ownership of `owned` (must not be NULL).
    explicit PoseGraph(o3d_pose_graph_t* owned) : h_(owned) {
        if (!owned) throw Error(O3D_ERROR_INVALID_ARGUMENT, "o3dpp::PoseGraph: NULL handle");
    }
    PoseGraph(PoseGraph&&) noexcept = default;
    PoseGraph& operator=(PoseGraph&&) noexcept = default;
    PoseGraph(const PoseGraph&) = delete;
    PoseGraph& operator=(const PoseGraph&) = delete;

    o3d_pose_graph_t* get() const noexcept { return h_.get(); }
    o3d_pose_graph_t* release() noexcept { return h_.release(); }
    explicit operator bool() const noexcept { return static_cast<bool>(h_); }

    /// @brief Deep copy.
    PoseGraph clone() const {
        o3d_pose_graph_t* g = nullptr;
        check(o3d_pose_graph_clone(&g, get()));
        return PoseGraph(g);
    }

    std::size_t num_nodes() const {
        size_t n = 0;
        check(o3d_pose_graph_num_nodes(&n, get()));
        return n;
    }
    std::size_t num_edges() const {
        size_t n = 0;
        check(o3d_pose_graph_num_edges(&n, get()));
        return n;
    }

    /// @brief Append a node (a finite rigid transform).
    void add_node(const Mat4& pose = identity4()) { check(o3d_pose_graph_add_node(get(), pose.data())); }
    Mat4 node(std::size_t index) const {
        Mat4 pose{};
        check(o3d_pose_graph_get_node(pose.data(), get(), index));
        return pose;
    }
    void set_node(std::size_t index, const Mat4& pose) { check(o3d_pose_graph_set_node(get(), index, pose.data())); }
    std::vector<Mat4> nodes() const {
        std::vector<Mat4> out;
        const std::size_t n = num_nodes();
        out.reserve(n);
        for (std::size_t i = 0; i < n; ++i) out.push_back(node(i));
        return out;
    }

    /// @brief Append an edge (node ids are checked by global_optimization).
    void add_edge(const PoseGraphEdge& edge) {
        const o3d_pose_graph_edge_t c = edge.to_c();
        check(o3d_pose_graph_add_edge(get(), &c));
    }
    PoseGraphEdge edge(std::size_t index) const {
        o3d_pose_graph_edge_t c = PoseGraphEdge().to_c();
        check(o3d_pose_graph_get_edge(&c, get(), index));
        return PoseGraphEdge::from_c(c);
    }
    void set_edge(std::size_t index, const PoseGraphEdge& edge) {
        const o3d_pose_graph_edge_t c = edge.to_c();
        check(o3d_pose_graph_set_edge(get(), index, &c));
    }
    std::vector<PoseGraphEdge> edges() const {
        std::vector<PoseGraphEdge> out;
        const std::size_t n = num_edges();
        out.reserve(n);
        for (std::size_t i = 0; i < n; ++i) out.push_back(edge(i));
        return out;
    }

    /// @brief Remove every node and edge.
    void clear() { check(o3d_pose_graph_clear(get())); }

private:
    UniqueHandle<o3d_pose_graph_t, &o3d_pose_graph_destroy> h_;
};

/// @brief Read Open3D's JSON pose graph. @see o3d.io.read_pose_graph
inline PoseGraph read_pose_graph(const std::string& path) {
    o3d_pose_graph_t* g = nullptr;
    check(o3d_io_read_pose_graph(&g, path.c_str()));
    return PoseGraph(g);
}
/// @brief Write `graph` in Open3D's JSON layout. @see o3d.io.write_pose_graph
inline void write_pose_graph(const std::string& path, const PoseGraph& graph) {
    check(o3d_io_write_pose_graph(path.c_str(), graph.get()));
}

enum class GlobalOptimizationMethod : int32_t {
    GaussNewton = O3D_GLOBAL_OPTIMIZATION_GAUSS_NEWTON,
    LevenbergMarquardt = O3D_GLOBAL_OPTIMIZATION_LEVENBERG_MARQUARDT
};

/// @brief GlobalOptimizationConvergenceCriteria + GlobalOptimizationOption, method, threads,
/// progress; Open3D defaults.
struct GlobalOptimizationOptions {
    GlobalOptimizationMethod method = GlobalOptimizationMethod::LevenbergMarquardt;
    int max_iteration = 100;
    double min_relative_increment = 1e-6;
    double min_relative_residual_increment = 1e-6;
    double min_right_term = 1e-6;
    double min_residual = 1e-6;
    int max_iteration_lm = 20;
    double upper_scale_factor = 2.0 / 3.0;
    double lower_scale_factor = 1.0 / 3.0;
    double max_correspondence_distance = 0.075;
    double edge_prune_threshold = 0.25;
    double preference_loop_closure = 1.0;
    int reference_node = -1;  ///< -1: the first node
    int num_threads = 0;
    /// @brief Fraction of max_iteration done over both passes; return false to cancel (the graph
    /// is then left unchanged). An exception it throws cancels the call and is rethrown.
    ProgressCallback progress;

    o3d_global_optimization_options_t to_c() const {
        o3d_global_optimization_options_t c;
        check(o3d_global_optimization_options_init(&c, sizeof c));
        c.method = static_cast<int32_t>(method);
        c.max_iteration = max_iteration;
        c.min_relative_increment = min_relative_increment;
        c.min_relative_residual_increment = min_relative_residual_increment;
        c.min_right_term = min_right_term;
        c.min_residual = min_residual;
        c.max_iteration_lm = max_iteration_lm;
        c.upper_scale_factor = upper_scale_factor;
        c.lower_scale_factor = lower_scale_factor;
        c.max_correspondence_distance = max_correspondence_distance;
        c.edge_prune_threshold = edge_prune_threshold;
        c.preference_loop_closure = preference_loop_closure;
        c.reference_node = reference_node;
        c.num_threads = num_threads;
        return c;
    }
};

/// @brief What a global optimization did.
struct GlobalOptimizationSummary {
    int iterations = 0;             ///< of both passes
    double initial_residual = 0.0;  ///< robust objective before the first pass
    double final_residual = 0.0;    ///< after the last pass
    int pruned_edges = 0;           ///< uncertain edges removed
};

/// @brief Optimize the node poses of `graph` in place (Open3D's global_optimization): line process,
/// prune uncertain edges below edge_prune_threshold, optimize again. An edge naming a missing node is
/// an Error and leaves `graph` unchanged.
inline GlobalOptimizationSummary global_optimization(PoseGraph& graph, const GlobalOptimizationOptions& options = {}) {
    o3d_global_optimization_options_t c = options.to_c();
    detail::ProgressContext ctx;
    if (options.progress) {
        ctx.callback = &options.progress;
        c.progress = &detail::progress_trampoline;
        c.user_data = &ctx;
    }
    o3d_global_optimization_summary_t s{};
    s.struct_size = sizeof s;
    detail::check_progress(o3d_global_optimization(&s, graph.get(), &c), ctx);
    return {s.iterations, s.initial_residual, s.final_residual, s.pruned_edges};
}

}  // namespace o3dpp
