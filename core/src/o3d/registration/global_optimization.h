// SPDX-License-Identifier: MIT
#pragma once
/// @file global_optimization.h
/// @brief Pose-graph optimization (Open3D's global_optimization): Gauss-Newton or Levenberg-Marquardt
/// over the node poses, with the line process of Choi, Zhou and Koltun, "Robust Reconstruction of Indoor
/// Scenes" (CVPR 2015) down-weighting loop closures that disagree with the rest of the graph.
///
/// Each edge (s, t, T) has the error e = lin(T^-1 pose_t^-1 pose_s), lin(M) = ((M21 - M12) / 2,
/// (M02 - M20) / 2, (M10 - M01) / 2, M03, M13, M23), and the objective is
///   sum_edges l e^T Lambda e + mu (sqrt(l) - 1)^2,
/// l = 1 for certain edges and, for uncertain ones, l = (mu / (mu + e^T Lambda e))^2 after each step;
/// mu = preference_loop_closure * max_correspondence_distance^2 * mean over edges of Lambda(5, 5)
/// (the correspondence count of an information matrix made from point pairs). A step left-multiplies
/// each pose by Rz(d2) Ry(d1) Rx(d0) with translation (d3, d4, d5).
#include <functional>

#include "o3d/registration/pose_graph.h"

namespace o3d::registration {

/// @brief GlobalOptimizationGaussNewton / GlobalOptimizationLevenbergMarquardt.
enum class GlobalOptimizationMethod { GaussNewton, LevenbergMarquardt };

/// @brief GlobalOptimizationConvergenceCriteria (Open3D's defaults). A pass stops when the step is
/// small against the poses (|delta| < min_relative_increment (|x| + min_relative_increment), x the poses as
/// Euler angles and translations), the objective stops falling (by less than
/// min_relative_residual_increment of itself), the largest entry of the right-hand side J^T Lambda e falls
/// below min_right_term, the objective below min_residual, or after max_iteration + 1 iterations.
struct GlobalOptimizationConvergenceCriteria {
    int max_iteration = 100;
    double min_relative_increment = 1e-6;
    double min_relative_residual_increment = 1e-6;
    double min_right_term = 1e-6;
    double min_residual = 1e-6;
    int max_iteration_lm = 20;  ///< LM: damping retries per iteration
    /// LM: after an accepted step with gain ratio rho, lambda *= clamp(1 - (2 rho - 1)^3, lower, upper).
    double upper_scale_factor = 2.0 / 3.0;
    double lower_scale_factor = 1.0 / 3.0;
};

/// @brief GlobalOptimizationOption.
struct GlobalOptimizationOption {
    double max_correspondence_distance = 0.075;  ///< sets the line-process scale mu
    double edge_prune_threshold = 0.25;          ///< uncertain edges keep only with confidence above it
    double preference_loop_closure = 1.0;        ///< scales mu: larger keeps more loop closures
    int reference_node = -1;                     ///< node whose pose is kept; -1: node 0
};

/// @brief Everything global_optimization takes besides the graph.
struct GlobalOptimizationOptions {
    GlobalOptimizationMethod method = GlobalOptimizationMethod::LevenbergMarquardt;
    GlobalOptimizationConvergenceCriteria criteria;
    GlobalOptimizationOption option;
    int num_threads = 0;  ///< 0 = library default; the result does not depend on it
    /// Called on the calling thread after each iteration with the fraction done over both passes
    /// (each pass counts max_iteration + 1 iterations). Returning false cancels (o3d::Cancelled).
    std::function<bool(double)> progress;
};

/// @brief What global_optimization did.
struct GlobalOptimizationSummary {
    int iterations = 0;            ///< iterations of both passes
    double initial_residual = 0;   ///< the objective before the first pass
    double final_residual = 0;     ///< the objective the second pass ended at
    int pruned_edges = 0;          ///< uncertain edges removed (after either pass)
};

/// @brief Optimize the node poses in place, as Open3D does: one pass with the line process, removal of the
/// uncertain edges whose confidence is not above edge_prune_threshold, a second pass, a second removal;
/// then every pose is moved by one rigid motion that puts the reference node back where it was.
/// Edge confidences are updated. Results are bitwise identical for any thread count.
/// Gauss-Newton holds the reference node fixed during the solve (its normal equations are singular
/// otherwise); Levenberg-Marquardt solves the damped system over all nodes, as Open3D, and fixes the
/// gauge at the end.
/// @see o3d.pipelines.registration.global_optimization
/// @throws o3d::InvalidArgument (graph unchanged) on an edge naming a missing node, a non-finite or singular
/// pose or transformation, a non-finite information matrix, a certain edge whose confidence is not 1, an
/// uncertain edge whose confidence is outside [0, 1], a graph that is not connected, a reference_node
/// outside [-1, nodes), bad criteria (thresholds negative or not finite, max_iteration < 0, max_iteration_lm < 1,
/// scale factors not 0 < lower <= upper), max_correspondence_distance or preference_loop_closure not > 0,
/// edge_prune_threshold outside [0, 1], num_threads < 0, or uncertain edges with a line-process scale mu
/// that is not > 0. @throws o3d::Cancelled (graph unchanged) when `progress` returns false.
/// @throws o3d::NotConverged (graph unchanged) when the poses become non-finite (an indefinite information
/// matrix can send them off).
GlobalOptimizationSummary global_optimization(PoseGraph& graph, const GlobalOptimizationOptions& options = {});

}  // namespace o3d::registration
