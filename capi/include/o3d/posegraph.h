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
 *
 * **Out of memory:** any function here that allocates may also return O3D_ERROR_OUT_OF_MEMORY; the
 * per-function `@return` lists do not repeat it.
 */
#ifndef O3D_POSEGRAPH_H
#define O3D_POSEGRAPH_H

#include "o3d/common.h"
#include "o3d/types.h"

O3D_BEGIN_DECL


/** A pose-graph edge (o3d.pipelines.registration.PoseGraphEdge). */
typedef struct o3d_pose_graph_edge {
    uint32_t struct_size;      /**< sizeof(o3d_pose_graph_edge_t) */
    int32_t source_node_id;    /**< index of the source node; default 0 */
    int32_t target_node_id;    /**< index of the target node; default 0 */
    double transformation[16]; /**< row-major 4x4: maps points of the source node's frame into the target node's; default identity */
    double information[36];    /**< row-major 6x6 information matrix (rotation first, then translation, as Open3D); default identity */
    o3d_bool uncertain;        /**< 1: a loop closure the line process may prune; default 0 (odometry) */
    double confidence;         /**< line-process weight in [0, 1]; default 1 */
} o3d_pose_graph_edge_t;

/**
 * @brief Fill an edge with defaults.
 *
 * Threads: any thread.
 * @param edge the struct to fill
 * @param struct_size sizeof the struct as the caller knows it (an older, smaller size is accepted)
 * @return O3D_OK, or O3D_ERROR_INVALID_ARGUMENT on a NULL pointer or a `struct_size` this library does not know.
 */
O3D_API o3d_status o3d_pose_graph_edge_init(o3d_pose_graph_edge_t* edge, uint32_t struct_size);

/**
 * @brief An empty graph.
 *
 * Threads: any thread.
 * Ownership: `*out` is the caller's, to free with o3d_pose_graph_destroy(); left NULL on failure.
 * @param out receives the new handle (NULL on failure)
 * @return O3D_OK, or O3D_ERROR_INVALID_ARGUMENT on a NULL pointer.
 */
O3D_API o3d_status o3d_pose_graph_create(o3d_pose_graph_t** out);
/**
 * @brief Destroy. NULL is a no-op.
 *
 * Threads: needs exclusive access to `graph`: no other call may use it during or after.
 * @param graph the handle to destroy (NULL is a no-op)
 */
O3D_API void o3d_pose_graph_destroy(o3d_pose_graph_t* graph);
/**
 * @brief Deep copy.
 *
 * Threads: any thread; concurrent calls on the same handles are safe (all read-only).
 * Ownership: `*out` is the caller's, to free with o3d_pose_graph_destroy(); left NULL on failure.
 * @param out receives the new handle (NULL on failure)
 * @param graph the pose graph
 * @return O3D_OK, or O3D_ERROR_INVALID_ARGUMENT on a NULL pointer.
 */
O3D_API o3d_status o3d_pose_graph_clone(o3d_pose_graph_t** out, const o3d_pose_graph_t* graph);
/**
 * @brief Number of nodes.
 *
 * Threads: any thread; concurrent calls on the same handles are safe (all read-only).
 * @param out receives the node count
 * @param graph the pose graph
 * @return O3D_OK, or O3D_ERROR_INVALID_ARGUMENT on a NULL pointer.
 */
O3D_API o3d_status o3d_pose_graph_num_nodes(size_t* out, const o3d_pose_graph_t* graph);
/**
 * @brief Number of edges.
 *
 * Threads: any thread; concurrent calls on the same handles are safe (all read-only).
 * @param out receives the edge count
 * @param graph the pose graph
 * @return O3D_OK, or O3D_ERROR_INVALID_ARGUMENT on a NULL pointer.
 */
O3D_API o3d_status o3d_pose_graph_num_edges(size_t* out, const o3d_pose_graph_t* graph);
/**
 * @brief Append a node with `pose` (NULL: identity); must be a finite rigid transform.
 *
 * Threads: needs exclusive access to `graph`.
 * @param graph the pose graph
 * @param pose row-major 4x4 rigid transform (NULL: identity)
 * @return O3D_OK, or O3D_ERROR_INVALID_ARGUMENT on a NULL pointer or a pose that is not a finite rigid transform.
 */
O3D_API o3d_status o3d_pose_graph_add_node(o3d_pose_graph_t* graph, const double pose[16]);
/**
 * @brief The pose of node `index`.
 *
 * Threads: any thread; concurrent calls on the same handles are safe (all read-only).
 * @param out_pose receives the row-major 4x4 pose
 * @param graph the pose graph
 * @param index zero-based index (must be below the count)
 * @return O3D_OK, or O3D_ERROR_INVALID_ARGUMENT on a NULL pointer or `index` out of range.
 */
O3D_API o3d_status o3d_pose_graph_get_node(double out_pose[16], const o3d_pose_graph_t* graph, size_t index);
/**
 * @brief Replace the pose of node `index`; it must be a finite rigid transform.
 *
 * Threads: needs exclusive access to `graph`.
 * @param graph the pose graph
 * @param index zero-based index (must be below the count)
 * @param pose row-major 4x4 rigid transform (NULL: identity)
 * @return O3D_OK, or O3D_ERROR_INVALID_ARGUMENT on a NULL pointer, `index` out of range or a pose that is not a
 *   finite rigid transform.
 */
O3D_API o3d_status o3d_pose_graph_set_node(o3d_pose_graph_t* graph, size_t index, const double pose[16]);
/**
 * @brief Append an edge. Node ids are checked by global optimization, not here (Open3D builds edges first).
 *
 * Threads: needs exclusive access to `graph`.
 * @param graph the pose graph
 * @param edge the edge (its struct_size must be set)
 * @return O3D_OK, or O3D_ERROR_INVALID_ARGUMENT on a NULL pointer, a bad `edge->struct_size`, a non-finite matrix or
 *   a confidence outside [0, 1].
 */
O3D_API o3d_status o3d_pose_graph_add_edge(o3d_pose_graph_t* graph, const o3d_pose_graph_edge_t* edge);
/**
 * @brief Edge `index`.
 *
 * Threads: any thread; concurrent calls on the same handles are safe (all read-only).
 * @param out_edge receives the edge (its struct_size must be set)
 * @param graph the pose graph
 * @param index zero-based index (must be below the count)
 * @return O3D_OK, or O3D_ERROR_INVALID_ARGUMENT on a NULL pointer, `index` out of range or an unknown
 *   `out_edge->struct_size`.
 */
O3D_API o3d_status o3d_pose_graph_get_edge(o3d_pose_graph_edge_t* out_edge, const o3d_pose_graph_t* graph,
                                           size_t index);
/**
 * @brief Replace edge `index` (checked as o3d_pose_graph_add_edge does).
 *
 * Threads: needs exclusive access to `graph`.
 * @param graph the pose graph
 * @param index zero-based index (must be below the count)
 * @param edge the edge (its struct_size must be set)
 * @return O3D_OK, or O3D_ERROR_INVALID_ARGUMENT on a NULL pointer, `index` out of range, a bad `edge->struct_size`, a
 *   non-finite matrix or a confidence outside [0, 1].
 */
O3D_API o3d_status o3d_pose_graph_set_edge(o3d_pose_graph_t* graph, size_t index, const o3d_pose_graph_edge_t* edge);
/**
 * @brief Remove every node and edge.
 *
 * Threads: needs exclusive access to `graph`.
 * @param graph the pose graph
 * @return O3D_OK, or O3D_ERROR_INVALID_ARGUMENT on a NULL pointer.
 */
O3D_API o3d_status o3d_pose_graph_clear(o3d_pose_graph_t* graph);

/** The solvers of global_optimization (O3D_GLOBAL_OPTIMIZATION_*). */
typedef int32_t o3d_global_optimization_method;
#define O3D_GLOBAL_OPTIMIZATION_GAUSS_NEWTON 0        /**< GlobalOptimizationGaussNewton */
#define O3D_GLOBAL_OPTIMIZATION_LEVENBERG_MARQUARDT 1 /**< GlobalOptimizationLevenbergMarquardt */

/** GlobalOptimizationConvergenceCriteria + GlobalOptimizationOption, method, threads, progress. */
typedef struct o3d_global_optimization_options {
    uint32_t struct_size;                   /**< sizeof(o3d_global_optimization_options_t) */
    o3d_global_optimization_method method;  /**< O3D_GLOBAL_OPTIMIZATION_*; default LEVENBERG_MARQUARDT */
    o3d_count max_iteration;                /**< iterations per pass; default 100 */
    double min_relative_increment;          /**< default 1e-6 */
    double min_relative_residual_increment; /**< default 1e-6 */
    double min_right_term;                  /**< default 1e-6 */
    double min_residual;                    /**< default 1e-6 */
    o3d_count max_iteration_lm;             /**< LM damping retries per iteration; default 20 */
    double upper_scale_factor;              /**< LM; default 2/3 */
    double lower_scale_factor;              /**< LM; default 1/3 */
    double max_correspondence_distance;     /**< sets the line-process scale mu; default 0.075 */
    double edge_prune_threshold;            /**< uncertain edges whose confidence ends below it are removed; default 0.25 */
    double preference_loop_closure;         /**< weight of loop closures against odometry; default 1.0 */
    o3d_optional_index reference_node;      /**< node kept fixed; -1 (default): the first node */
    o3d_count num_threads;                  /**< 0 = library default; the result does not depend on it */
    o3d_progress_callback progress;         /**< fraction of max_iteration done over both passes; may be NULL */
    void* user_data; /**< passed to `progress` */
} o3d_global_optimization_options_t;

/**
 * @brief Fill defaults (Open3D's).
 *
 * Threads: any thread.
 * @param opts the struct to fill
 * @param struct_size sizeof the struct as the caller knows it (an older, smaller size is accepted)
 * @return O3D_OK, or O3D_ERROR_INVALID_ARGUMENT on a NULL pointer or a `struct_size` this library does not know;
 *   O3D_ERROR_CANCELLED when the progress callback returns non-zero.
 */
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
 *
 * Threads: needs exclusive access to `graph`; the progress callback runs on the calling thread.
 * @param summary receives what was done (may be NULL; its struct_size must be set)
 * @param graph the pose graph
 * @param opts options (NULL: the defaults of the matching `*_init`)
 * @return O3D_OK, or O3D_ERROR_INVALID_ARGUMENT on a NULL pointer, a bad `opts->struct_size`, an unknown
 *   `opts->method`, a negative iteration count or thread count, an edge naming a missing node or a bad
 *   `summary->struct_size`; O3D_ERROR_NOT_CONVERGED when the normal equations are singular or the optimization diverges
 *   (`graph` is left unchanged); O3D_ERROR_CANCELLED when the progress callback returns non-zero.
 */
O3D_API o3d_status o3d_global_optimization(o3d_global_optimization_summary_t* summary, o3d_pose_graph_t* graph,
                                           const o3d_global_optimization_options_t* opts);

O3D_END_DECL

#endif /* O3D_POSEGRAPH_H */
