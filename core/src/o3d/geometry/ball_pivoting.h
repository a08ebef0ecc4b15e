// SPDX-License-Identifier: MIT
#pragma once
/// @file ball_pivoting.h
/// @brief Ball pivoting surface reconstruction (Bernardini et al. 1999), Open3D's
/// TriangleMesh.create_from_point_cloud_ball_pivoting.
#include <functional>
#include <vector>

#include "o3d/geometry/point_cloud.h"
#include "o3d/geometry/triangle_mesh.h"

namespace o3d::geometry {

/// @brief Interpolate the oriented cloud with the triangles whose vertices a ball of radius rho touches
/// while containing no other point. For each radius in turn: the boundary edges left by the previous
/// radius whose triangle also has an empty ball of the new radius are pivoted again, then new seed
/// triangles are searched among the points not yet used, each grown by pivoting the ball around the
/// edges of its front. Processing is sequential in a fixed order, so the result is deterministic.
///
/// The mesh's vertices are all input points, in order (unused ones stay unreferenced), with the cloud's
/// normals and colors; triangles are wound so their normals agree with the point normals (a vertex with a
/// zero normal takes its orientation from its neighbours), and triangle_normals holds their unit normals.
/// The mesh is edge manifold and consistently oriented. Copies of a used point (closer to it than 1e-8 of
/// the cloud's bounding-box diagonal, or 1e-4 of the first radius if less) stay unreferenced. A radius too
/// small to fit any triangle yields no triangles (not an error).
/// @param radii increasing ball radii.
/// @param progress called with the fraction done in [0, 1]; returning false cancels.
/// @throws InvalidArgument on an empty cloud, a cloud without normals, a non-finite point or normal,
/// more than 2^31 - 1 points, empty radii, a radius that is not finite and > 0, or radii not strictly
/// increasing. @throws Cancelled when `progress` returns false.
TriangleMesh create_from_point_cloud_ball_pivoting(const PointCloud& cloud, const std::vector<double>& radii,
                                                   const std::function<bool(double)>& progress = {});

}  // namespace o3d::geometry
