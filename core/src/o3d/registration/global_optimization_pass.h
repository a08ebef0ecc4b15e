// SPDX-License-Identifier: MIT
#pragma once
/// @file global_optimization_pass.h
/// @brief Internal: one optimization pass of global_optimization (Gauss-Newton or Levenberg-Marquardt)
/// over a validated graph, following Open3D's loops and stopping tests step for step.
#include <functional>

#include "o3d/registration/global_optimization.h"
#include "o3d/registration/pose_graph_residual.h"
#include "o3d/registration/pose_graph_system.h"

namespace o3d::registration::detail {

/// @brief Reports iterations to the caller's progress callback; throws o3d::Cancelled when it says stop.
class PassProgress {
public:
    PassProgress(const std::function<bool(double)>& callback, int pass, int max_iteration)
        : callback_(callback), pass_(pass), per_pass_(static_cast<double>(max_iteration) + 1.0) {}
    /// @brief After iteration `iteration` (from 0) of this pass.
    void iteration_done(int iteration) const { report((pass_ + (iteration + 1) / per_pass_) / 2.0); }
    /// @brief At the end of the pass, however early it stopped.
    void pass_done() const { report((pass_ + 1) / 2.0); }

private:
    void report(double fraction) const;
    const std::function<bool(double)>& callback_;
    int pass_;
    double per_pass_;
};

/// @brief What a pass did.
struct PassResult {
    int iterations = 0;
    double initial_residual = 0.0;  ///< with the confidences the pass started from
    double final_residual = 0.0;    ///< the last accepted objective
};

/// @brief mu = preference_loop_closure * max_correspondence_distance^2 * mean of information(5, 5).
double line_process_scale(const std::vector<PoseGraphEdge>& edges, const GlobalOptimizationOption& option);

/// @brief The working set of a pass: the objective, the normal equations, current and trial poses.
struct PassState {
    /// @param fixed_node held fixed in the solve (-1: none, the damped LM system is regular).
    PassState(const PoseGraph& graph, const GlobalOptimizationOption& option, int num_threads, int fixed_node);

    /// @brief poses <- step(delta) poses, into `trial`, and the trial's edge errors.
    void try_step(const Eigen::VectorXd& delta);
    /// @brief Make the trial current: poses, errors and |x|.
    void accept_trial();
    /// @brief Refresh the confidences and the normal equations at the current poses.
    void relinearize();
    /// @brief Write the poses and confidences back into `graph`.
    void store(PoseGraph& graph) const;

    PoseGraphObjective objective;
    NormalEquations system;
    Poses poses, trial;
    EdgeErrors errors, trial_errors;
    double pose_norm = 0.0;  ///< |x|, the poses as Euler angles and translations
};

/// @brief Open3D's stopping tests.
bool small_increment(const Eigen::VectorXd& delta, double pose_norm, const GlobalOptimizationConvergenceCriteria& c);
bool small_residual_decrease(double current, double next, const GlobalOptimizationConvergenceCriteria& c);
bool small_right_term(const Eigen::VectorXd& b, const GlobalOptimizationConvergenceCriteria& c);

/// @brief Gauss-Newton with `fixed_node` held (the undamped system is singular without it).
PassResult gauss_newton_pass(PoseGraph& graph, const GlobalOptimizationOptions& options, int num_threads,
                             int fixed_node, const PassProgress& progress);
/// @brief Levenberg-Marquardt on the damped system over all nodes.
PassResult levenberg_marquardt_pass(PoseGraph& graph, const GlobalOptimizationOptions& options, int num_threads,
                                    const PassProgress& progress);

}  // namespace o3d::registration::detail
