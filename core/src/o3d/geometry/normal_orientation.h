// SPDX-License-Identifier: MIT
#pragma once
/// @file normal_orientation.h
/// @brief Consistent normal orientation over a Riemannian graph (Hoppe et al. 1992), with the
/// parameters and sign rule of Open3D 0.18+ PointCloud::OrientNormalsConsistentTangentPlane.
#include "o3d/geometry/point_cloud.h"

namespace o3d::geometry {

/// @brief Flip normals so that neighbouring normals agree (Hoppe et al. 1992, "Surface reconstruction
/// from unorganized points"): build the Riemannian graph = Euclidean minimum spanning tree + k-nearest-
/// neighbour graph, weight each edge (i, j) by 1 - |n_i . n_j|, take its minimum spanning tree and walk
/// it from a root, flipping each child whose normal has a negative dot product with its parent's.
///
/// Open3D semantics: the kNN search counts the point itself (k = 10 gives 9 neighbours); the root is
/// the lowest point (minimum z, first index on ties) and its normal is turned to face -z (flipped
/// when n.z > 0), so a closed convex surface comes out outward, an open height field downward.
/// `cos_alpha_tol` drops the edges i->j whose direction lies in the cone around n_i:
/// |n_i . (p_j - p_i)| / |p_j - p_i| > cos_alpha_tol (1 keeps every edge). `lambda` adds
/// lambda * |n_i . (p_j - p_i)| (distance of p_j to the tangent plane of p_i) to the Euclidean length
/// used for the spanning tree, and when lambda != 0 a kNN edge whose tangent-plane distance is an
/// outlier among the neighbours of p_i (> Q3 + 1.5 IQR) is dropped, as Open3D does.
///
/// Differences from Open3D: the Euclidean tree comes from the kNN graph (max(k, 9) neighbours) plus
/// Boruvka bridges between its components (nearest pairs, exact by the cut property) instead of a Qhull
/// Delaunay tetrahedralisation, so any cloud of >= 1 point works (Open3D needs >= 4 points in general
/// position); every kNN edge enters the graph (Open3D skips kNN edges that are Delaunay but not tree
/// edges); when filtered edges leave the graph disconnected, each component is oriented from its own
/// lowest point (Open3D orients only the component of the global lowest point).
/// Deterministic for any num_threads (0 = library default).
/// @throws InvalidArgument when the cloud has no normals, k < 1, lambda is negative or not finite,
/// cos_alpha_tol is not finite, or a point is not finite.
void orient_normals_consistent_tangent_plane(PointCloud& cloud, int k, double lambda = 0.0,
                                             double cos_alpha_tol = 1.0, int num_threads = 0);

}  // namespace o3d::geometry
