// SPDX-License-Identifier: MIT
#pragma once
/// @file pose_graph_system.h
/// @brief Internal: the normal equations H delta = b of a pose graph, 6 unknowns per node, stored as the
/// upper triangle of a sparse matrix whose pattern (one 6x6 block per node and per connected node pair) is
/// fixed for a pass, factored by a sparse LDL^T (Eigen::SimplicialLDLT) analysed once per pass. The nodes
/// are numbered by an approximate-minimum-degree ordering of the node graph, so the factorization reads the
/// matrix in place with no permuted copy and its fill-reducing ordering works on whole 6x6 blocks.
#include <Eigen/Core>
#include <Eigen/SparseCholesky>
#include <Eigen/SparseCore>
#include <array>
#include <vector>

#include "o3d/registration/pose_graph.h"

namespace o3d::registration::detail {

class NormalEquations {
public:
    /// @param fixed_node a node whose step is held at zero (its rows and columns leave the system), or -1.
    NormalEquations(int num_nodes, const std::vector<PoseGraphEdge>& edges, int fixed_node);

    /// @brief Zero H and b.
    void clear();
    /// @brief Add edge `edge`'s terms: H_ss += K, H_tt += K, H_st = H_ts -= K, b_s -= g, b_t += g
    /// (the target Jacobian is minus the source one).
    void add_edge(size_t edge, const Eigen::Matrix<double, 6, 6>& k, const Eigen::Matrix<double, 6, 1>& g);

    /// @brief b over all nodes (the fixed node's entries included), as the convergence tests read it.
    const Eigen::VectorXd& rhs() const { return b_; }
    /// @brief Largest diagonal entry of H over the free nodes.
    double max_diagonal() const;
    /// @brief Solve (H + lambda I) delta = b over the free nodes; the fixed node's step is zero.
    /// A factorization that fails (a zero pivot) falls back to a dense pivoting LDL^T.
    /// @return false when the step is not finite (a singular system).
    bool solve(double lambda, Eigen::VectorXd& delta);

private:
    /// Per stored 6x6 block, the index in the value array of its top row in each of its 6 columns.
    using Block = std::array<int, 6>;
    struct EdgeSlots {
        int source_node = 0;
        int target_node = 0;
        int source_block = -1;  // the nodes' diagonal blocks; -1 for the fixed node
        int target_block = -1;
        int cross_block = -1;  // the off-diagonal block above the diagonal; -1 unless both nodes are free
    };
    void add_block(int block, const Eigen::Matrix<double, 6, 6>& k, bool subtract);

    std::vector<int> free_index_;  // node -> position in the elimination order, or -1 for the fixed node
    Eigen::SparseMatrix<double> h_;
    std::vector<Block> blocks_;
    std::vector<int> diagonal_;     // value index of each diagonal entry of H
    std::vector<double> undamped_;  // scratch: H's diagonal while lambda is added
    std::vector<EdgeSlots> slots_;
    Eigen::VectorXd b_;
    Eigen::VectorXd free_rhs_;
    Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>, Eigen::Upper, Eigen::NaturalOrdering<int>> ldlt_;
};

}  // namespace o3d::registration::detail
