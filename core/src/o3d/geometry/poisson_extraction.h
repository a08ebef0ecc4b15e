// SPDX-License-Identifier: MIT
#pragma once
/// @file poisson_extraction.h
/// @brief Internal to Poisson reconstruction: evaluation of the solved function on the octree and
/// crack-free marching-cubes extraction of its iso-surface at the finest depth.
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

/// @brief Marching cubes on the finest-depth cells that the iso-surface crosses, found by following the
/// surface from `seed_cells` (finest-depth cell keys) and from sign changes on the complete grid of depth
/// `seed_depth`. Vertices sit on cell edges and are shared by edge, and every face is split the same way
/// by both of its cells, so the mesh has no cracks and is edge-manifold. With `close_at_boundary` the domain
/// boundary counts as outside, so the mesh is closed even where the surface would leave the cube.
/// @returns false when `keep_going` asks to stop.
bool extract_iso_surface(const std::vector<Level>& levels, const FunctionEvaluator& chi, double iso,
                         const std::vector<Key>& seed_cells, int seed_depth, IsoSurface& out,
                         const std::function<bool()>& keep_going, int threads, bool close_at_boundary);

}  // namespace o3d::geometry::poisson
