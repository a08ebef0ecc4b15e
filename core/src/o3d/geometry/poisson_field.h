// SPDX-License-Identifier: MIT
#pragma once
/// @file poisson_field.h
/// @brief Internal to Poisson reconstruction: the samples' normal field V, splatted at each sample's own
/// depth (as deep as its local sampling density supports, so sparse regions get no spurious fine detail),
/// and the gradient right-hand sides <grad B_v, V> it induces on every depth.
#include <Eigen/Core>
#include <vector>

#include "o3d/geometry/poisson_octree.h"
#include "o3d/geometry/poisson_system.h"

namespace o3d::geometry::poisson {

/// @brief Hat coefficients (per key of `L`, plus a trailing zero) of the field of the samples whose depth is
/// L.depth: V_w = sum_s a_s N_s B_w(s) / h^3, so that V integrates to sum_s a_s N_s.
std::vector<Eigen::Vector3d> splat_field(const Level& L, const std::vector<Eigen::Vector3d>& u,
                                         const std::vector<Eigen::Vector3d>& area_normals,
                                         const std::vector<int8_t>& sample_depth);
/// @brief A coarser field expressed on the finer hats (two-scale relation), added to `fine_field`.
void add_prolonged_field(const Level& coarse, const std::vector<Eigen::Vector3d>& coarse_field, const Level& fine,
                         std::vector<Eigen::Vector3d>& fine_field, int threads);
/// @brief Adds <grad B_v, V> on the active rows of `L` (neighbours from `S`) for V given by its hat
/// coefficients on L's keys (plus a trailing zero).
void add_field_rows(const Level& L, const LevelSystem& S, const std::vector<Eigen::Vector3d>& field,
                    std::vector<double>& rhs, int threads);
/// @brief Per depth, the gradient rows of the field of the samples at that depth or deeper: each depth's
/// own samples scattered onto its rows, plus the finer rows restricted (coarse hats are combinations of fine
/// ones).
std::vector<std::vector<double>> deep_rhs(const std::vector<Level>& levels, const std::vector<Eigen::Vector3d>& u,
                                          const std::vector<Eigen::Vector3d>& area_normals,
                                          const std::vector<int8_t>& sample_depth, int threads);

/// @brief The rest of the rows, coarse to fine (alongside the cascade, which has each depth's neighbour
/// table): the field of the shallower samples, carried down the depths by the two-scale relation.
class ShallowField {
public:
    ShallowField(int depth, const std::vector<Eigen::Vector3d>& u, const std::vector<Eigen::Vector3d>& area_normals,
                 const std::vector<int8_t>& sample_depth, int threads);
    /// Adds depth d's rows of the field of the samples above d to `rhs`; call for d = 0, 1, ... in turn.
    void add_rows(const std::vector<Level>& levels, int d, const LevelSystem& S, std::vector<double>& rhs);

private:
    const std::vector<Eigen::Vector3d>* u_;
    const std::vector<Eigen::Vector3d>* area_normals_;
    const std::vector<int8_t>* sample_depth_;
    int threads_;
    std::vector<char> has_;
    std::vector<Eigen::Vector3d> carried_;  ///< field of the samples at depths < d, on depth d-1's keys
};

}  // namespace o3d::geometry::poisson
