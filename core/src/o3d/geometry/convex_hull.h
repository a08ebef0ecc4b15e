// SPDX-License-Identifier: MIT
#pragma once
/// @file convex_hull.h
/// @brief 3-D convex hull through Qhull (Open3D's Qhull::ComputeConvexHull / compute_convex_hull).
#include <Eigen/Core>
#include <vector>

#include "o3d/geometry/triangle_mesh.h"

namespace o3d::geometry {

/// @brief A hull as a triangle mesh plus, for each mesh vertex, the index of the input point it is.
struct ConvexHull {
    TriangleMesh mesh;
    std::vector<int> point_indices;
};

/// @brief Convex hull of `points`: triangulated facets ("Qt"), each wound so its normal points out of
/// the hull; vertices are the input points themselves (numbered in order of first use), never the
/// joggled copies. `joggle_inputs` adds "QJ" so coplanar or cospherical sets still give a hull.
/// @throws InvalidArgument on fewer than 4 points, a non-finite point, or a degenerate (flat) set
/// Qhull rejects without joggling (the message carries Qhull's reason).
ConvexHull compute_convex_hull(const std::vector<Eigen::Vector3d>& points, bool joggle_inputs = false);

}  // namespace o3d::geometry
