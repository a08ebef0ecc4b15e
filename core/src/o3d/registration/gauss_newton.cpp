// SPDX-License-Identifier: MIT
// Open3D's GlobalOptimizationGaussNewton::OptimizePoseGraph, with the reference node held fixed in the solve.
#include "o3d/registration/global_optimization_pass.h"
#include "o3d/utility/error.h"

namespace o3d::registration::detail {

PassResult gauss_newton_pass(PoseGraph& graph, const GlobalOptimizationOptions& options, int num_threads,
                             int fixed_node, const PassProgress& progress) {
    const auto& criteria = options.criteria;
    PassState state(graph, options.option, num_threads, fixed_node);
    PassResult result;
    double current = state.objective.residual(state.errors);
    result.initial_residual = current;
    state.relinearize();

    Eigen::VectorXd delta;
    if (!small_right_term(state.system.rhs(), criteria)) {
        for (int iteration = 0;; ++iteration) {
            result.iterations = iteration + 1;
            if (!state.system.solve(0.0, delta))
                throw NotConverged("global optimization: the Gauss-Newton system is singular");
            if (small_increment(delta, state.pose_norm, criteria)) break;
            state.try_step(delta);
            // Scored with the confidences of the current poses, as in Open3D.
            const double next = state.objective.residual(state.trial_errors);
            if (small_residual_decrease(current, next, criteria)) break;
            current = next;
            state.accept_trial();
            state.relinearize();
            if (small_right_term(state.system.rhs(), criteria)) break;
            progress.iteration_done(iteration);
            if (current < criteria.min_residual || iteration >= criteria.max_iteration) break;
        }
    }
    progress.pass_done();
    result.final_residual = current;
    state.store(graph);
    return result;
}

}  // namespace o3d::registration::detail
