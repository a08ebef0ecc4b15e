// SPDX-License-Identifier: MIT
#include "o3d/registration/pose_graph_system.h"

#include <Eigen/Cholesky>
#include <Eigen/OrderingMethods>
#include <algorithm>
#include <limits>

namespace o3d::registration::detail {
namespace {

/// Free nodes in an approximate-minimum-degree order of the graph whose edges are `pairs` (free indices).
std::vector<int> elimination_order(int num_free, const std::vector<std::pair<int, int>>& pairs) {
    std::vector<Eigen::Triplet<double>> pattern;
    pattern.reserve(static_cast<size_t>(num_free) + pairs.size());
    for (int f = 0; f < num_free; ++f) pattern.emplace_back(f, f, 1.0);
    for (const auto& [a, b] : pairs) pattern.emplace_back(a, b, 1.0);
    Eigen::SparseMatrix<double> graph(num_free, num_free);
    graph.setFromTriplets(pattern.begin(), pattern.end());
    Eigen::AMDOrdering<int>::PermutationType order;  // order.indices()[k]: the node eliminated k-th
    Eigen::AMDOrdering<int>()(graph, order);
    std::vector<int> position(static_cast<size_t>(num_free));
    for (int k = 0; k < num_free; ++k) position[static_cast<size_t>(order.indices()[k])] = k;
    return position;
}

}  // namespace

NormalEquations::NormalEquations(int num_nodes, const std::vector<PoseGraphEdge>& edges, int fixed_node)
    : free_index_(static_cast<size_t>(num_nodes), -1),
      b_(Eigen::VectorXd::Zero(6 * static_cast<Eigen::Index>(num_nodes))) {
    int num_free = 0;
    for (int i = 0; i < num_nodes; ++i)
        if (i != fixed_node) free_index_[static_cast<size_t>(i)] = num_free++;
    std::vector<std::pair<int, int>> pairs;
    pairs.reserve(edges.size());
    for (const auto& e : edges) {
        const int s = free_index_[static_cast<size_t>(e.source_node_id)];
        const int t = free_index_[static_cast<size_t>(e.target_node_id)];
        if (s >= 0 && t >= 0 && s != t) pairs.emplace_back(s, t);
    }
    const std::vector<int> position = elimination_order(num_free, pairs);
    for (int& f : free_index_)
        if (f >= 0) f = position[static_cast<size_t>(f)];
    for (auto& [a, b] : pairs) {
        a = position[static_cast<size_t>(a)];
        b = position[static_cast<size_t>(b)];
        if (a > b) std::swap(a, b);
    }

    // Upper triangle, block column by block column: the diagonal block and one block per neighbour above it.
    std::vector<std::vector<int>> rows_of(static_cast<size_t>(num_free));
    for (int f = 0; f < num_free; ++f) rows_of[static_cast<size_t>(f)].push_back(f);
    for (const auto& [a, b] : pairs) rows_of[static_cast<size_t>(b)].push_back(a);
    std::vector<int> first_block(static_cast<size_t>(num_free) + 1, 0);
    for (int f = 0; f < num_free; ++f) {
        auto& rows = rows_of[static_cast<size_t>(f)];
        std::sort(rows.begin(), rows.end());
        rows.erase(std::unique(rows.begin(), rows.end()), rows.end());
        first_block[static_cast<size_t>(f) + 1] = first_block[static_cast<size_t>(f)] + static_cast<int>(rows.size());
    }
    const Eigen::Index dim = 6 * static_cast<Eigen::Index>(num_free);
    h_.resize(dim, dim);
    h_.resizeNonZeros(36 * first_block.back());
    int* outer = h_.outerIndexPtr();
    int* inner = h_.innerIndexPtr();
    blocks_.resize(static_cast<size_t>(first_block.back()));
    int at = 0;
    for (int f = 0; f < num_free; ++f) {
        const auto& rows = rows_of[static_cast<size_t>(f)];
        for (int c = 0; c < 6; ++c) {
            outer[6 * f + c] = at;
            for (size_t p = 0; p < rows.size(); ++p) {
                blocks_[static_cast<size_t>(first_block[static_cast<size_t>(f)]) + p][static_cast<size_t>(c)] = at;
                for (int r = 0; r < 6; ++r) inner[at++] = 6 * rows[p] + r;
            }
        }
    }
    outer[dim] = at;
    const auto block_of = [&](int row, int col) {
        const auto& rows = rows_of[static_cast<size_t>(col)];
        return first_block[static_cast<size_t>(col)] +
               static_cast<int>(std::lower_bound(rows.begin(), rows.end(), row) - rows.begin());
    };
    diagonal_.resize(static_cast<size_t>(dim));
    for (int f = 0; f < num_free; ++f) {
        const Block& d = blocks_[static_cast<size_t>(block_of(f, f))];
        for (int c = 0; c < 6; ++c) diagonal_[static_cast<size_t>(6 * f + c)] = d[static_cast<size_t>(c)] + c;
    }

    slots_.reserve(edges.size());
    for (const auto& e : edges) {
        EdgeSlots slot;
        slot.source_node = e.source_node_id;
        slot.target_node = e.target_node_id;
        const int s = free_index_[static_cast<size_t>(e.source_node_id)];
        const int t = free_index_[static_cast<size_t>(e.target_node_id)];
        if (s >= 0) slot.source_block = block_of(s, s);
        if (t >= 0) slot.target_block = block_of(t, t);
        if (s >= 0 && t >= 0 && s != t) slot.cross_block = block_of(std::min(s, t), std::max(s, t));
        slots_.push_back(slot);
    }
    free_rhs_.resize(dim);
    clear();
    ldlt_.analyzePattern(h_);
}

void NormalEquations::clear() {
    std::fill(h_.valuePtr(), h_.valuePtr() + h_.nonZeros(), 0.0);
    b_.setZero();
}

// The factorization reads the upper triangle. Each block goes in transposed: for a symmetric information
// matrix that changes nothing, and for any other the solve reads H's lower triangle, as Open3D's does.
void NormalEquations::add_block(int block, const Eigen::Matrix<double, 6, 6>& k, bool subtract) {
    double* values = h_.valuePtr();
    const Block& starts = blocks_[static_cast<size_t>(block)];
    for (int c = 0; c < 6; ++c) {
        double* column = values + starts[static_cast<size_t>(c)];
        if (subtract)
            for (int r = 0; r < 6; ++r) column[r] -= k(c, r);
        else
            for (int r = 0; r < 6; ++r) column[r] += k(c, r);
    }
}

void NormalEquations::add_edge(size_t edge, const Eigen::Matrix<double, 6, 6>& k,
                               const Eigen::Matrix<double, 6, 1>& g) {
    const EdgeSlots& slot = slots_[edge];
    if (slot.source_node == slot.target_node) return;  // a self-edge adds K - K - K + K: nothing
    if (slot.source_block >= 0) add_block(slot.source_block, k, false);
    if (slot.target_block >= 0) add_block(slot.target_block, k, false);
    if (slot.cross_block >= 0) add_block(slot.cross_block, k, true);
    b_.segment<6>(6 * static_cast<Eigen::Index>(slot.source_node)) -= g;
    b_.segment<6>(6 * static_cast<Eigen::Index>(slot.target_node)) += g;
}

double NormalEquations::max_diagonal() const {
    double best = -std::numeric_limits<double>::infinity();
    for (const int d : diagonal_) best = std::max(best, h_.valuePtr()[d]);
    return diagonal_.empty() ? 0.0 : best;
}

bool NormalEquations::solve(double lambda, Eigen::VectorXd& delta) {
    delta.setZero(b_.size());
    if (diagonal_.empty()) return true;
    double* values = h_.valuePtr();
    if (lambda != 0.0) {
        undamped_.resize(diagonal_.size());
        for (size_t k = 0; k < diagonal_.size(); ++k) {
            undamped_[k] = values[diagonal_[k]];
            values[diagonal_[k]] += lambda;
        }
    }
    for (size_t node = 0; node < free_index_.size(); ++node)
        if (const int f = free_index_[node]; f >= 0)
            free_rhs_.segment<6>(6 * static_cast<Eigen::Index>(f)) = b_.segment<6>(6 * static_cast<Eigen::Index>(node));

    Eigen::VectorXd x;
    ldlt_.factorize(h_);
    bool solved = ldlt_.info() == Eigen::Success;
    if (solved) {
        x = ldlt_.solve(free_rhs_);
        solved = ldlt_.info() == Eigen::Success;
    }
    if (!solved) {
        // A zero pivot: the pivoting dense factorization still gives a step where one exists.
        const Eigen::SparseMatrix<double> full = h_.selfadjointView<Eigen::Upper>();
        x = Eigen::MatrixXd(full).ldlt().solve(free_rhs_);
    }
    if (lambda != 0.0)
        for (size_t k = 0; k < diagonal_.size(); ++k) values[diagonal_[k]] = undamped_[k];

    for (size_t node = 0; node < free_index_.size(); ++node)
        if (const int f = free_index_[node]; f >= 0)
            delta.segment<6>(6 * static_cast<Eigen::Index>(node)) = x.segment<6>(6 * static_cast<Eigen::Index>(f));
    return delta.allFinite();
}

}  // namespace o3d::registration::detail
