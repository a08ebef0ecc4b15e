// SPDX-License-Identifier: MIT
#pragma once
/// @file poisson_solver.h
/// @brief Internal to Poisson reconstruction: the cascadic coarse-to-fine solve (Kazhdan & Hoppe 2013).
/// Each depth solves, by Jacobi-preconditioned conjugate gradients, for its correction to the function
/// already fixed by the coarser depths; the coarser solution enters through its exact prolongation.
#include <Eigen/Core>
#include <functional>
#include <vector>

#include "o3d/geometry/poisson_octree.h"
#include "o3d/geometry/poisson_system.h"

namespace o3d::geometry::poisson {

struct CascadeInput {
    const std::vector<Eigen::Vector3d>* u = nullptr;             ///< samples, unit-cube coordinates
    const std::vector<Eigen::Vector3d>* area_normals = nullptr;  ///< normal * estimated sample area
    const std::vector<CellSamples>* cells = nullptr;             ///< samples aggregated per depth
    const std::vector<int8_t>* sample_depth = nullptr;           ///< depth each sample's normal is splatted at
    double screening = 0;     ///< alpha * area / samples: screening weight per sample at depth 0
    double target = 0.5;      ///< the value chi should take at the samples
    int threads = 1;
    /// Called with the fraction of the solve done; false cancels (the caller throws).
    std::function<bool(double)> progress;
};

/// @brief Fills levels[d].y for every depth. @returns false when cancelled.
bool solve_cascade(std::vector<Level>& levels, const CascadeInput& in);

/// @brief The accumulated solution prolonged from `coarse` onto every key of `fine` (plus a trailing 0).
std::vector<double> prolong(const Level& coarse, const Level& fine, int threads);

}  // namespace o3d::geometry::poisson
