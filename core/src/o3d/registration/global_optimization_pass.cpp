// SPDX-License-Identifier: MIT
#include "o3d/registration/global_optimization_pass.h"

#include <cmath>
#include <string>

#include "o3d/utility/error.h"

namespace o3d::registration::detail {

void PassProgress::report(double fraction) const {
    if (callback_ && !callback_(fraction))
        throw Cancelled("global optimization cancelled by the progress callback at " +
                        std::to_string(static_cast<int>(fraction * 100.0)) + "%");
}

double line_process_scale(const std::vector<PoseGraphEdge>& edges, const GlobalOptimizationOption& option) {
    if (edges.empty()) return 0.0;
    // Information(5, 5) counts the point pairs behind an edge (see Section 5 of Choi et al. 2015).
    double mean_pairs = 0.0;
    for (const auto& e : edges) mean_pairs += e.information(5, 5);
    mean_pairs /= static_cast<double>(edges.size());
    return option.preference_loop_closure * option.max_correspondence_distance * option.max_correspondence_distance *
           mean_pairs;
}

PassState::PassState(const PoseGraph& graph, const GlobalOptimizationOption& option, int num_threads,
                     int fixed_node)
    : objective(graph.edges, line_process_scale(graph.edges, option), num_threads),
      system(static_cast<int>(graph.nodes.size()), graph.edges, fixed_node) {
    poses.reserve(graph.nodes.size());
    for (const auto& node : graph.nodes) poses.push_back(node.pose);
    trial = poses;
    objective.errors(poses, errors);
    double norm2 = 0.0;
    for (const auto& p : poses) norm2 += pose_vector_squared_norm(p);
    pose_norm = std::sqrt(norm2);
}

void PassState::try_step(const Eigen::VectorXd& delta) {
    for (size_t i = 0; i < poses.size(); ++i)
        trial[i] = step_transform(delta.segment<6>(6 * static_cast<Eigen::Index>(i))) * poses[i];
    objective.errors(trial, trial_errors);
}

void PassState::accept_trial() {
    poses.swap(trial);
    errors.swap(trial_errors);
    double norm2 = 0.0;
    for (const auto& p : poses) norm2 += pose_vector_squared_norm(p);
    pose_norm = std::sqrt(norm2);
}

void PassState::relinearize() {
    objective.update_confidences(errors);
    objective.linearize(poses, errors, system);
}

void PassState::store(PoseGraph& graph) const {
    for (size_t i = 0; i < poses.size(); ++i) graph.nodes[i].pose = poses[i];
    const auto& confidence = objective.confidences();
    for (size_t k = 0; k < graph.edges.size(); ++k) graph.edges[k].confidence = confidence[k];
}

bool small_increment(const Eigen::VectorXd& delta, double pose_norm, const GlobalOptimizationConvergenceCriteria& c) {
    return delta.norm() < c.min_relative_increment * (pose_norm + c.min_relative_increment);
}

bool small_residual_decrease(double current, double next, const GlobalOptimizationConvergenceCriteria& c) {
    return current - next < c.min_relative_residual_increment * current;
}

bool small_right_term(const Eigen::VectorXd& b, const GlobalOptimizationConvergenceCriteria& c) {
    // Open3D compares the largest signed entry, not the largest magnitude.
    return b.size() == 0 || b.maxCoeff() < c.min_right_term;
}

}  // namespace o3d::registration::detail
