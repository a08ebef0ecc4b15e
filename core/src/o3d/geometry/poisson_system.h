// SPDX-License-Identifier: MIT
#pragma once
/// @file poisson_system.h
/// @brief Internal to Poisson reconstruction: the screened-Poisson linear system of one octree depth in the
/// trilinear hat basis. Rows are the depth's active vertices; the operator is the gradient stiffness
/// (a constant 27-point stencil scaled by the cell size) plus the screening mass of the samples, which are
/// aggregated per cell (weight, mean position) as in Kazhdan & Hoppe 2013 so coarse depths stay cheap.
#include <Eigen/Core>
#include <array>
#include <cstdint>
#include <vector>

#include "o3d/geometry/poisson_octree.h"

namespace o3d::geometry::poisson {

/// @brief Samples aggregated into the cells of one depth.
struct CellSamples {
    std::vector<Key> cell;             ///< cell key (its minimum corner), sorted
    std::vector<double> weight;        ///< number of samples in the cell
    std::vector<Eigen::Vector3d> mean; ///< their mean position (unit-cube coordinates)
};
/// @brief Aggregates unit-cube positions into the cells of depth `depth`.
CellSamples aggregate_samples(const std::vector<Eigen::Vector3d>& u, int depth);
/// @brief Merges one depth's cells into their parents.
CellSamples aggregate_parents(const CellSamples& fine);

/// @brief Cell (clamped to the grid) containing unit-cube point `u` at resolution `res`, and the
/// fractional position inside it.
inline void locate(const Eigen::Vector3d& u, int res, int cell[3], double frac[3]) {
    for (int a = 0; a < 3; ++a) {
        const double g = u[a] * res;
        int c = int(g >= 0 ? g : 0);
        if (c > res - 1) c = res - 1;
        cell[a] = c;
        frac[a] = std::min(std::max(g - c, 0.0), 1.0);
    }
}
/// @brief The 8 hat weights of a cell's corners (corner k = bits x,y,z) at fractional position `f`.
inline void corner_weights(const double f[3], double w[8]) {
    for (int k = 0; k < 8; ++k)
        w[k] = ((k & 1) ? f[0] : 1 - f[0]) * ((k & 2) ? f[1] : 1 - f[1]) * ((k & 4) ? f[2] : 1 - f[2]);
}

/// @brief The linear system of one depth.
struct LevelSystem {
    double h = 1;     ///< cell size (unit cube)
    double beta = 0;  ///< screening weight per sample at this depth
    std::vector<std::array<int32_t, 27>> nbr;  ///< per active row: the 3x3x3 neighbours (dummy = keys.size())
    std::vector<double> rhs;                   ///< gradient part of the right-hand side (active rows)
    std::vector<double> pt_weight;             ///< screening points: beta * samples
    std::vector<std::array<double, 8>> pt_bw;  ///< their corner hat weights
    std::vector<std::array<int32_t, 8>> pt_corner;  ///< their corners (indices into keys)
    std::vector<int32_t> cell_point;  ///< per key: screening point of the cell with that minimum corner, or -1
    /// Gradient stiffness <grad B_v, grad B_w> (w = v + offset) integrated over the unit cube (Neumann
    /// boundary, so constants are free and the screening sets the level); variant bit a = v on a face ⊥ axis a.
    std::array<std::array<double, 27>, 8> stencil{};
    std::vector<uint8_t> variant;  ///< per active row
};

/// @brief Neighbour table, screening points and stencil of a level (the rhs is filled separately).
void assemble_level(const Level& L, const CellSamples& cells, double beta, LevelSystem& S, int threads);
/// @brief rhs of depth d-1 from depth d: the coarse hats are combinations of fine ones (two-scale relation),
/// so <grad B_coarse, V> is the same combination of the fine rows.
std::vector<double> restrict_rhs(const Level& fine, const std::vector<double>& fine_rhs, const Level& coarse,
                                 int threads);
/// @brief out[active rows] = A z, with z sized keys.size()+1 (last entry 0, the dummy neighbour).
/// `scratch` holds one value per screening point.
void apply_operator(const LevelSystem& S, const double* z, double* out, size_t n_active, double* scratch,
                    int threads);
/// @brief Screening target term beta * sum_samples B_v(s) * target on active rows, added to `rhs`.
void add_screening_target(const LevelSystem& S, double target, std::vector<double>& rhs);
/// @brief Diagonal of the operator on the active rows (Jacobi preconditioner).
std::vector<double> operator_diagonal(const LevelSystem& S, size_t n_active);

}  // namespace o3d::geometry::poisson
