// SPDX-License-Identifier: MIT
#pragma once
/// @file poisson_density.h
/// @brief Internal to Poisson reconstruction: hat-kernel splats of the samples at one depth and, by the
/// two-scale relation, at every coarser depth. They give the sampling-density estimate (sample weights of
/// the normal field, per-vertex densities) and the per-vertex colours.
#include <Eigen/Core>
#include <vector>

#include "o3d/geometry/poisson_octree.h"

namespace o3d::geometry::poisson {

class LevelSplat {
public:
    /// @brief Splats, per sample, the weight 1 and `channels` values (values[s*channels + c]) onto the hats
    /// of depth `depth`, then restricts down to depth 0.
    void build(const std::vector<Eigen::Vector3d>& u, const std::vector<double>& values, int channels, int depth);
    /// @brief Hat-interpolated splat at unit-cube point `u` at depth d <= depth(): out[0] = the kernel
    /// density (sum of hats), out[1..channels] the splatted values.
    void eval(const Eigen::Vector3d& u, int d, double* out) const;
    int depth() const { return int(levels_.size()) - 1; }
    int channels() const { return stride_ - 1; }

private:
    struct Grid {
        std::vector<Key> keys;
        KeyIndex index;
        std::vector<double> data;  ///< stride_ per key
    };
    std::vector<Grid> levels_;
    int stride_ = 1;
};

/// @brief PoissonRecon's per-vertex density: the depth at which the local sampling would put about one
/// sample per cell, estimated at the finest depth of `splat` where the kernel sees at least one sample
/// (falling back to coarser depths away from the samples, so it is finite everywhere).
double density_depth(const LevelSplat& splat, const Eigen::Vector3d& u);

}  // namespace o3d::geometry::poisson
