// SPDX-License-Identifier: MIT
// Open3D's GlobalOptimizationLevenbergMarquardt::OptimizePoseGraph: the same damping schedule, gain ratio
// and stopping tests, on the damped system over all nodes (regular for any lambda > 0).
#include <algorithm>
#include <cmath>

#include "o3d/registration/global_optimization_pass.h"
#include "o3d/utility/error.h"

namespace o3d::registration::detail {

PassResult levenberg_marquardt_pass(PoseGraph& graph, const GlobalOptimizationOptions& options, int num_threads,
                                    const PassProgress& progress) {
    const auto& criteria = options.criteria;
    PassState state(graph, options.option, num_threads, -1);
    PassResult result;
    double current = state.objective.residual(state.errors);
    result.initial_residual = current;
    state.relinearize();

    constexpr double kTau = 1e-5;  // initial damping relative to the largest diagonal entry of H
    double lambda = kTau * state.system.max_diagonal();
    double growth = 2.0;  // lambda's factor after a rejected step; doubles while steps keep failing
    double rho = 0.0;     // gain ratio of the last tried step; kept across iterations, as in Open3D
    Eigen::VectorXd delta;
    bool stop = small_right_term(state.system.rhs(), criteria);
    for (int iteration = 0; !stop; ++iteration) {
        result.iterations = iteration + 1;
        int tries = 0;
        do {
            if (!state.system.solve(lambda, delta))
                throw NotConverged("global optimization: the Levenberg-Marquardt system is singular");
            stop = small_increment(delta, state.pose_norm, criteria);
            if (!stop) {
                state.try_step(delta);
                const double next = state.objective.residual(state.trial_errors);
                // Actual over predicted decrease; the 1e-3 keeps a vanishing prediction finite.
                rho = (current - next) / (delta.dot(lambda * delta + state.system.rhs()) + 1e-3);
                if (rho > 0) {
                    stop = small_residual_decrease(current, next, criteria);
                    if (stop) break;
                    const double alpha = std::min(1.0 - std::pow(2.0 * rho - 1.0, 3), criteria.upper_scale_factor);
                    lambda *= std::max(criteria.lower_scale_factor, alpha);
                    growth = 2.0;
                    current = next;
                    state.accept_trial();
                    state.relinearize();
                    stop = small_right_term(state.system.rhs(), criteria);
                    if (stop) break;
                } else {
                    lambda *= growth;
                    growth *= 2.0;
                }
            }
            ++tries;
            stop = stop || tries >= criteria.max_iteration_lm;
        } while (!(rho > 0 || stop));
        progress.iteration_done(iteration);
        stop = stop || current < criteria.min_residual || iteration >= criteria.max_iteration;
    }
    progress.pass_done();
    result.final_residual = current;
    state.store(graph);
    return result;
}

}  // namespace o3d::registration::detail
