/* SPDX-License-Identifier: MIT */
/**
 * @file posegraph.h
 * @brief Pose graphs for multiway registration: nodes (poses), edges (relative transformations with
 * information matrices), Open3D's JSON files, and global optimization (Gauss-Newton or
 * Levenberg-Marquardt with the line process that prunes false loop closures, Choi et al. 2015).
 *
 * Mirrors o3d.pipelines.registration.PoseGraph / PoseGraphNode / PoseGraphEdge / global_optimization and
 * o3d.io.read_pose_graph / write_pose_graph. Matrices are row-major: 16 doubles for a 4x4 pose or
 * transformation, 36 for a 6x6 information matrix (rotation first, then translation, as Open3D).
 * An edge (s, t, T) says that T maps points of node s's frame into node t's frame:
 * pose_t^-1 * pose_s ~ T.
 */
#ifndef O3D_POSEGRAPH_H
#define O3D_POSEGRAPH_H

#include "o3d/common.h"
#include "o3d/types.h"

O3D_BEGIN_DECL


/** PoseGraphEdge. */
typedef struct o3d_pose_graph_edge {
    uint32_t struct_size;      /**< sizeof(o3d_pose_graph_edge_t) */
    int32_t source_node_id;    /**< default 0 */
    int32_t target_node_id;    /**< default 0 */
    double transformation[16]; /**< default identity */
    double information[36];    /**< default identity */
    int32_t uncertain;         /**< 1: a loop closure the line process may prune; default 0 (odometry) */
    double confidence;         /**< line-process weight in [0, 1]; default 1 */
} o3d_pose_graph_edge_t;

/** @brief Fill an edge with defaults. */
O3D_API o3d_status o3d_pose_graph_edge_init(o3d_pose_graph_edge_t* edge, uint32_t struct_size);

/** @brief An empty graph. */
O3D_API o3d_status o3d_pose_graph_create(o3d_pose_graph_t** out);
/** @brief Destroy. NULL is a no-op. */
O3D_API void o3d_pose_graph_destroy(o3d_pose_graph_t* graph);
/** @brief Deep copy. */
O3D_API o3d_status o3d_pose_graph_clone(o3d_pose_graph_t** out, const o3d_pose_graph_t* graph);
O3D_API o3d_status o3d_pose_graph_num_nodes(size_t* out, const o3d_pose_graph_t* graph);
O3D_API o3d_status o3d_pose_graph_num_edges(size_t* out, const o3d_pose_graph_t* graph);
/** @brief Append a node with `pose` (NULL: identity); must be a finite rigid transform. */
O3D_API o3d_status o3d_pose_graph_add_node(o3d_pose_graph_t* graph, const double pose[16]);
O3D_API o3d_status o3d_pose_graph_get_node(double out_pose[16], const o3d_pose_graph_t* graph, size_t index);
O3D_API o3d_status o3d_pose_graph_set_node(o3d_pose_graph_t* graph, size_t index, const double pose[16]);
/** @brief Append an edge. Node ids are checked by global optimization, not here (Open3D builds edges first). */
O3D_API o3d_status o3d_pose_graph_add_edge(o3d_pose_graph_t* graph, const o3d_pose_graph_edge_t* edge);
O3D_API o3d_status o3d_pose_graph_get_edge(o3d_pose_graph_edge_t* out_edge, const o3d_pose_graph_t* graph,
                                           size_t index);
O3D_API o3d_status o3d_pose_graph_set_edge(o3d_pose_graph_t* graph, size_t index, const o3d_pose_graph_edge_t* edge);
/** @brief Remove every node and edge. */
O3D_API o3d_status o3d_pose_graph_clear(o3d_pose_graph_t* graph);


#define O3D_GLOBAL_OPTIMIZATION_GAUSS_NEWTON 0        /**< GlobalOptimizationGaussNewton */
#define O3D_GLOBAL_OPTIMIZATION_LEVENBERG_MARQUARDT 1 /**< GlobalOptimizationLevenbergMarquardt */

/** GlobalOptimizationConvergenceCriteria + GlobalOptimizationOption, method, threads, progress. */
typedef struct o3d_global_optimization_options {
    uint32_t struct_size;                   /**< sizeof(o3d_global_optimization_options_t) */
    int32_t method;                         /**< O3D_GLOBAL_OPTIMIZATION_*; default LEVENBERG_MARQUARDT */
    int32_t max_iteration;                  /**< >= 0; default 100 */
    double min_relative_increment;          /**< default 1e-6 */
    double min_relative_residual_increment; /**< default 1e-6 */
    double min_right_term;                  /**< default 1e-6 */
    double min_residual;                    /**< default 1e-6 */
    int32_t max_iteration_lm;               /**< LM damping retries per iteration; default 20 */
    double upper_scale_factor;              /**< LM; default 2/3 */
    double lower_scale_factor;              /**< LM; default 1/3 */
    double max_correspondence_distance;     /**< sets the line-process scale mu; default 0.075 */
    double edge_prune_threshold;            /**< uncertain edges whose confidence ends below it are removed; default 0.25 */
    double preference_loop_closure;         /**< weight of loop closures against odometry; default 1.0 */
    int32_t reference_node;                 /**< node kept fixed; -1 (default): the first node */
    int32_t num_threads;                    /**< >= 0; 0 = library default; the result does not depend on it */
    o3d_progress_callback progress;         /**< fraction of max_iteration done over both passes; may be NULL */
    void* user_data;
} o3d_global_optimization_options_t;

/** @brief Fill defaults (Open3D's). */
O3D_API o3d_status o3d_global_optimization_options_init(o3d_global_optimization_options_t* opts,
                                                        uint32_t struct_size);

/** What a global optimization did. */
typedef struct o3d_global_optimization_summary {
    uint32_t struct_size;    /**< set by the caller: sizeof(o3d_global_optimization_summary_t) */
    int32_t iterations;      /**< iterations of both passes */
    double initial_residual; /**< the robust objective before the first pass */
    double final_residual;   /**< the robust objective after the last pass */
    int32_t pruned_edges;    /**< edges removed for a confidence below edge_prune_threshold */
} o3d_global_optimization_summary_t;

/**
 * @brief Optimize the node poses of `graph` in place (Open3D's global_optimization): optimize with the
 * line process, remove uncertain edges whose confidence fell below edge_prune_threshold, optimize again.
 * Edge confidences are updated. An edge naming a missing node is an error and leaves `graph` unchanged;
 * so does cancelling from `progress`. `summary` may be NULL.
 */
O3D_API o3d_status o3d_global_optimization(o3d_global_optimization_summary_t* summary, o3d_pose_graph_t* graph,
                                           const o3d_global_optimization_options_t* opts);

O3D_END_DECL

#endif /* O3D_POSEGRAPH_H */
