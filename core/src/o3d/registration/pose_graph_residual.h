// SPDX-License-Identifier: MIT
#pragma once
/// @file pose_graph_residual.h
/// @brief Internal: the objective of one global-optimization pass over a fixed edge set: edge errors,
/// their Jacobians, the line-process confidences and the robust residual (Choi et al. 2015, Eq. 2, 6, 9).
#include <Eigen/Core>
#include <vector>

#include "o3d/registration/pose_graph.h"

namespace o3d::registration::detail {

using Vector6d = Eigen::Matrix<double, 6, 1>;
using Poses = std::vector<Eigen::Matrix4d>;
using EdgeErrors = std::vector<Vector6d>;

class NormalEquations;

/// @brief The pose that left-multiplies a pose for a step d: Rz(d2) Ry(d1) Rx(d0), translation d3..d5.
Eigen::Matrix4d step_transform(const Vector6d& d);
/// @brief Squared norm of a pose written as (Euler angles x, y, z, translation): the scale that the
/// relative-increment test compares steps against.
double pose_vector_squared_norm(const Eigen::Matrix4d& pose);

/// @brief One pass's edges and confidences, evaluated for any set of node poses. Per-edge work runs in
/// parallel; every sum is taken serially in edge order, so results do not depend on the thread count.
class PoseGraphObjective {
public:
    /// @param edges validated edges (ids in range, invertible transformations); must outlive this.
    /// @param mu the line-process scale of this pass.
    PoseGraphObjective(const std::vector<PoseGraphEdge>& edges, double mu, int num_threads);

    /// @brief Every edge's error for `poses`, into `out` (resized to the edge count).
    void errors(const Poses& poses, EdgeErrors& out);
    /// @brief sum of l e^T Lambda e + mu (sqrt(l) - 1)^2 with the current confidences l.
    double residual(const EdgeErrors& errors);
    /// @brief Line process: l = (mu / (mu + e^T Lambda e))^2 on every uncertain edge.
    void update_confidences(const EdgeErrors& errors);
    /// @brief The Gauss-Newton system of the objective at `poses` (whose errors are `errors`).
    void linearize(const Poses& poses, const EdgeErrors& errors, NormalEquations& system);

    const std::vector<double>& confidences() const { return confidence_; }

private:
    struct EdgeBlock {
        Eigen::Matrix<double, 6, 6> hessian;  // l Js^T Lambda Js
        Vector6d gradient;                    // l Js^T Lambda^T e
    };
    const Poses& inverses(const Poses& poses);
    bool parallel() const;

    const std::vector<PoseGraphEdge>& edges_;
    std::vector<Eigen::Matrix4d> measurement_inverse_;  // T^-1 per edge, fixed for the pass
    std::vector<double> confidence_;
    double mu_;
    int num_threads_;
    Poses inverse_;                  // scratch: the poses' inverses
    std::vector<EdgeBlock> blocks_;  // scratch: per-edge contributions to the system
};

}  // namespace o3d::registration::detail
