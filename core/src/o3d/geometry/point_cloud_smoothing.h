// SPDX-License-Identifier: MIT
#pragma once
/// @file point_cloud_smoothing.h
/// @brief Point-cloud smoothing filters (Open3D 0.20's PointCloud.smooth_mls / smooth_laplacian /
/// smooth_taubin / smooth_bilateral). Each returns a new cloud; the input is never modified.
///
/// Common rules: every output point is computed from the previous state only (double buffers), so the
/// result does not depend on num_threads (0 = library default). An empty cloud gives an empty cloud
/// (attributes copied as they are), after the parameters have been validated. Attributes whose size does
/// not match the point count do not count (PointCloud's rule) and are copied as they are, except where a
/// function says otherwise.
#include "o3d/geometry/point_cloud.h"
#include "o3d/kdtree/kd_tree.h"

namespace o3d::geometry {

/// @brief Moving-least-squares-style smoothing: each point is projected onto the weighted PCA plane of its
/// neighbourhood (`param`, the point itself included). Weights are exp(-d^2 / h^2) with h = the search
/// radius (Radius, Hybrid) and uniform for Knn. A point with fewer than 3 neighbours is unchanged.
/// Colors and covariances are copied unchanged (covariances are not recomputed, as Open3D). When the cloud
/// has normals, each becomes its plane's unit normal (a point with < 3 neighbours, or whose neighbours all
/// coincide, keeps its normalised old normal) and the whole set is then oriented with
/// orient_normals_consistent_tangent_plane(k = 30, lambda = 0, cos_alpha_tol = 1), as Open3D does; a
/// cloud without normals gets none. Open3D returns a copy for a search parameter with neither a positive
/// radius nor a positive k, and turns a Hybrid with radius 0 (or max_nn 0) into a kNN (or radius) search;
/// here those parameters are errors.
/// @throws InvalidArgument on a bad search parameter (kdtree::validate) or a non-finite point.
PointCloud smooth_mls(const PointCloud& cloud, const kdtree::SearchParam& param, int num_threads = 0);

/// @brief Uniform graph-Laplacian smoothing: `iterations` times, x_i += lambda * (mean of the `knn` nearest
/// other points - x_i). The neighbours exclude the point itself (by index: a duplicate of it counts) and are
/// min(knn, N - 1) many; a single point is unchanged. The kNN graph is rebuilt from the current positions
/// before every pass, or built once from the input when `use_fixed_neighborhoods`. Normals, colors and
/// covariances are copied unchanged (as Open3D: the normals are not recomputed). 0 iterations give a copy.
/// Open3D returns a copy for knn <= 0 and NaN everywhere for a non-finite lambda; here both are errors.
/// @throws InvalidArgument on iterations < 0, knn < 1, a non-finite lambda or a non-finite point.
PointCloud smooth_laplacian(const PointCloud& cloud, int iterations, double lambda, int knn,
                            bool use_fixed_neighborhoods, int num_threads = 0);

/// @brief Taubin smoothing: per iteration one smooth_laplacian pass with `lambda`, then one with `mu`
/// (Open3D's defaults 0.5 and -0.53); without fixed neighbourhoods the kNN graph is rebuilt before each of
/// the two passes. Otherwise as smooth_laplacian.
/// @throws as smooth_laplacian, or on a non-finite mu.
PointCloud smooth_taubin(const PointCloud& cloud, int iterations, double lambda, double mu, int knn,
                         bool use_fixed_neighborhoods, int num_threads = 0);

/// @brief Bilateral smoothing (one pass): with n_i the unit normal of point i, each point becomes the
/// weighted mean of its neighbourhood (`param`, the point itself included) with weights
/// w_k = exp(-|p_i - p_k|^2 / (2 sigma_s^2)) * exp(-((p_i - p_k) . n_i)^2 / (2 sigma_r^2)).
/// A point with at most one neighbour, or with a zero normal, is unchanged. The input's normals are used
/// when it has them (normalised for the weights, copied unnormalised to the output); otherwise they are
/// estimated as Open3D's estimate_normals() default, kNN 30 (estimate_normals here, sign arbitrary), and
/// the output carries them. Colors and covariances are copied unchanged.
/// @throws InvalidArgument on a bad search parameter, sigma_s or sigma_r not finite and > 0, a non-finite
/// point, or a non-finite normal.
PointCloud smooth_bilateral(const PointCloud& cloud, const kdtree::SearchParam& param, double sigma_s,
                            double sigma_r, int num_threads = 0);

}  // namespace o3d::geometry
