// SPDX-License-Identifier: MIT
#pragma once
/// @file poisson_extraction.h
/// @brief Internal to Poisson reconstruction: evaluation of the solved function on the octree and
/// crack-free marching-cubes extraction of its iso-surface on the octree leaves.
#include <Eigen/Core>
#include <functional>
#include <vector>

#include "o3d/geometry/poisson_octree.h"

namespace o3d::geometry::poisson {

/// @brief Evaluates chi = sum over depths of the hat expansions, from the accumulated per-depth solutions.
class FunctionEvaluator {
public:
    explicit FunctionEvaluator(const std::vector<Level>& levels) : levels_(levels) {}
    /// chi at unit-cube point u.
    double at(const Eigen::Vector3d& u) const;
    /// chi at the finest-depth grid vertex (x, y, z).
    double at_vertex(int x, int y, int z) const;

private:
    // Trilinear value in the cell of depth d containing grid point g (finest-depth units / 2^shift) if all
    // eight corners are known there; the finest such depth carries every correction reaching the point.
    bool try_level(int d, const double g[3], double& out) const;
    const std::vector<Level>& levels_;
};

struct IsoSurface {
    std::vector<Eigen::Vector3d> vertices;  ///< unit-cube coordinates
    std::vector<Eigen::Vector3i> triangles; ///< outward (towards larger chi) by the right-hand rule
};

/// @brief Marching cubes on the leaves of the octree (a depth-d cell is split when a depth-(d+1) unknown lies
/// in its closure), so the surface is as fine as the octree where it passes: finest near the samples,
/// coarse where it bridges unsampled regions. Cells of different sizes share sub-edge crossings and face
/// segments, so the mesh has no cracks and is edge-manifold. The work is split into the cells of depth
/// `task_depth`. With `close_at_boundary` the domain boundary counts as outside, so the mesh is closed even
/// where the surface would leave the cube. @returns false when `keep_going` asks to stop.
bool extract_iso_surface(const std::vector<Level>& levels, const FunctionEvaluator& chi, double iso, int task_depth,
                         IsoSurface& out, const std::function<bool()>& keep_going, int threads,
                         bool close_at_boundary);

}  // namespace o3d::geometry::poisson
