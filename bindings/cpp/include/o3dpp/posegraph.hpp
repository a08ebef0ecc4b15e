// SPDX-License-Identifier: MIT
#pragma once
/// @file posegraph.hpp
/// @brief o3dpp::PoseGraph (multiway registration: node poses, edges with information matrices),
/// Open3D's JSON files, and global_optimization (Gauss-Newton / Levenberg-Marquardt with the line
/// process that prunes false loop closures). Matrices are row-major; an edge (s, t, T) says
/// pose_t^-1 * pose_s ~ T.
#include <cstdint>
#include <string>
#include <tuple>
#include <vector>

#include "o3d/io.h"
#include "o3d/posegraph.h"
#include "o3dpp/arrays.hpp"
#include "o3dpp/common.hpp"
#include "o3dpp/error.hpp"
#include "o3dpp/generated/options.hpp"
#include "o3dpp/generated/posegraph.hpp"
#include "o3dpp/handle.hpp"
#include "o3dpp/span.hpp"

namespace o3dpp {

/// @brief PoseGraphEdge; defaults from o3d_pose_graph_edge_init (0 -> 0, identity, odometry, confidence 1).
struct PoseGraphEdge : detail::PoseGraphEdgeBase {
    PoseGraphEdge() = default;
    /// @brief Edge source -> target with transform `t`; the other fields as given or the library's defaults.
    PoseGraphEdge(int32_t source, int32_t target, const Mat4& t) : PoseGraphEdge() {
        source_node_id = source;
        target_node_id = target;
        transformation = t;
    }
    PoseGraphEdge(int32_t source, int32_t target, const Mat4& t, const Mat6& info) : PoseGraphEdge(source, target, t) {
        information = info;
    }
    PoseGraphEdge(int32_t source, int32_t target, const Mat4& t, const Mat6& info, bool is_uncertain)
        : PoseGraphEdge(source, target, t, info) {
        uncertain = is_uncertain;
    }
    PoseGraphEdge(int32_t source, int32_t target, const Mat4& t, const Mat6& info, bool is_uncertain,
                  double edge_confidence)
        : PoseGraphEdge(source, target, t, info, is_uncertain) {
        confidence = edge_confidence;
    }
    /// @brief The library's default edge (o3d_pose_graph_edge_init).
    static PoseGraphEdge library_default() { return PoseGraphEdge(); }
    bool operator==(const PoseGraphEdge& o) const {
        return std::tie(source_node_id, target_node_id, transformation, information, uncertain, confidence) ==
               std::tie(o.source_node_id, o.target_node_id, o.transformation, o.information, o.uncertain,
                        o.confidence);
    }
    bool operator!=(const PoseGraphEdge& o) const { return !(*this == o); }
};

/// @brief A pose graph: one pose (rigid 4x4) per node, and edges. Move-only; clone() deep-copies. The node
/// methods are generated (detail::PoseGraphCalls).
class PoseGraph : public Owner<PoseGraph, o3d_pose_graph_t, &o3d_pose_graph_destroy>,
                  public detail::PoseGraphCalls<PoseGraph> {
    friend class detail::PoseGraphCalls<PoseGraph>;  // checks its calls with done
public:
    /// @brief An empty graph.
    PoseGraph() : Owner(make(&o3d_pose_graph_create)) {}
    /// @brief Take ownership of `owned` (must not be NULL).
    explicit PoseGraph(o3d_pose_graph_t* owned) : Owner(owned) {}

    /// @brief Deep copy.
    PoseGraph clone() const { return derive(&o3d_pose_graph_clone); }

    std::vector<Mat4> nodes() const { return detail::collect(num_nodes(), [&](std::size_t i) { return node(i); }); }

    /// @brief Append an edge (node ids are checked by global_optimization).
    void add_edge(const PoseGraphEdge& edge) {
        const o3d_pose_graph_edge_t c = edge.to_c();
        check(o3d_pose_graph_add_edge(get(), &c));
    }
    PoseGraphEdge edge(std::size_t index) const {
        o3d_pose_graph_edge_t c = PoseGraphEdge::library_defaults();
        check(o3d_pose_graph_get_edge(&c, get(), index));
        return PoseGraphEdge::from_c(c);
    }
    void set_edge(std::size_t index, const PoseGraphEdge& edge) {
        const o3d_pose_graph_edge_t c = edge.to_c();
        check(o3d_pose_graph_set_edge(get(), index, &c));
    }
    std::vector<PoseGraphEdge> edges() const {
        return detail::collect(num_edges(), [&](std::size_t i) { return edge(i); });
    }
};

/// @brief Read Open3D's JSON pose graph. @see o3d.io.read_pose_graph
inline PoseGraph read_pose_graph(const std::string& path) {
    return PoseGraph::create(&o3d_io_read_pose_graph, path.c_str());
}
/// @brief Write `graph` in Open3D's JSON layout. @see o3d.io.write_pose_graph
inline void write_pose_graph(const std::string& path, const PoseGraph& graph) {
    check(o3d_io_write_pose_graph(path.c_str(), graph.get()));
}

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
    o3d_global_optimization_summary_t s{};
    s.struct_size = sizeof s;
    check(detail::with_progress(options.to_c(), options.progress, [&](const o3d_global_optimization_options_t* c) {
        return o3d_global_optimization(&s, graph.get(), c);
    }));
    return {s.iterations, s.initial_residual, s.final_residual, s.pruned_edges};
}

}  // namespace o3dpp
