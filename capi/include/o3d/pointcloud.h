/* SPDX-License-Identifier: MIT */
/**
 * @file pointcloud.h
 * @brief Point clouds: points, normals, colors (float64, N x 3, row-major; colors in [0,1]).
 *
 * Mirrors o3d.geometry.PointCloud. Matrices are row-major (4x4 = 16 doubles, 3x3 = 9 doubles).
 * Arrays are (N x 3) row-major; counts are in points (rows), not in doubles.
 *
 * **Ownership:** a handle written through `o3d_pointcloud_t** out` belongs to the caller, who
 * destroys it with o3d_pointcloud_destroy(). Views (`*_view`) are borrowed: valid until the next
 * mutating call on the cloud or its destruction. On failure `*out` is left NULL.
 *
 * **Thread safety:** see common.h. Calls taking `const o3d_pointcloud_t*` may run concurrently.
 */
#ifndef O3D_POINTCLOUD_H
#define O3D_POINTCLOUD_H

#include "o3d/common.h"

O3D_BEGIN_DECL

typedef struct o3d_pointcloud o3d_pointcloud_t;

/** @brief New empty cloud. @see o3d.geometry.PointCloud() */
O3D_API o3d_status o3d_pointcloud_create(o3d_pointcloud_t** out);
/** @brief Destroy. NULL is a no-op. */
O3D_API void o3d_pointcloud_destroy(o3d_pointcloud_t* pc);
/** @brief Deep copy. */
O3D_API o3d_status o3d_pointcloud_clone(o3d_pointcloud_t** out, const o3d_pointcloud_t* src);

/** @brief Number of points. */
O3D_API o3d_status o3d_pointcloud_size(const o3d_pointcloud_t* pc, size_t* out_n);
/** @brief 1 if the cloud has points, else 0. */
O3D_API o3d_status o3d_pointcloud_has_points(const o3d_pointcloud_t* pc, int32_t* out);
/** @brief 1 if the cloud has one normal per point, else 0. */
O3D_API o3d_status o3d_pointcloud_has_normals(const o3d_pointcloud_t* pc, int32_t* out);
/** @brief 1 if the cloud has one color per point, else 0. */
O3D_API o3d_status o3d_pointcloud_has_colors(const o3d_pointcloud_t* pc, int32_t* out);
/** @brief Remove points, normals and colors. */
O3D_API o3d_status o3d_pointcloud_clear(o3d_pointcloud_t* pc);

/**
 * @brief Replace the points with `n` rows of `xyz` (copied once). `xyz` may be NULL when n == 0.
 * Normals and colors are kept as they are (Open3D semantics: they count only when their size matches).
 */
O3D_API o3d_status o3d_pointcloud_set_points(o3d_pointcloud_t* pc, const double* xyz, size_t n);
/** @brief As o3d_pointcloud_set_points, from float32 input (converted in the single copy). */
O3D_API o3d_status o3d_pointcloud_set_points_f32(o3d_pointcloud_t* pc, const float* xyz, size_t n);
O3D_API o3d_status o3d_pointcloud_set_normals(o3d_pointcloud_t* pc, const double* xyz, size_t n);
O3D_API o3d_status o3d_pointcloud_set_normals_f32(o3d_pointcloud_t* pc, const float* xyz, size_t n);
/** @brief Colors as RGB in [0,1]. */
O3D_API o3d_status o3d_pointcloud_set_colors(o3d_pointcloud_t* pc, const double* rgb, size_t n);
O3D_API o3d_status o3d_pointcloud_set_colors_f32(o3d_pointcloud_t* pc, const float* rgb, size_t n);

/**
 * @brief Copy the points into `out` (room for `capacity` rows). `*out_n` always gets the count.
 * With `out` NULL only the count is reported. @return O3D_ERROR_BUFFER_TOO_SMALL if capacity < count.
 */
O3D_API o3d_status o3d_pointcloud_get_points(const o3d_pointcloud_t* pc, double* out, size_t capacity,
                                             size_t* out_n);
O3D_API o3d_status o3d_pointcloud_get_normals(const o3d_pointcloud_t* pc, double* out, size_t capacity,
                                              size_t* out_n);
O3D_API o3d_status o3d_pointcloud_get_colors(const o3d_pointcloud_t* pc, double* out, size_t capacity,
                                             size_t* out_n);

/**
 * @brief Borrowed read-only view of the points (`*out_n` rows of 3 doubles; NULL when empty).
 * **Ownership:** borrowed; valid until the next mutating call on `pc` or its destruction.
 */
O3D_API o3d_status o3d_pointcloud_points_view(const o3d_pointcloud_t* pc, const double** out_data,
                                              size_t* out_n);
O3D_API o3d_status o3d_pointcloud_normals_view(const o3d_pointcloud_t* pc, const double** out_data,
                                               size_t* out_n);
O3D_API o3d_status o3d_pointcloud_colors_view(const o3d_pointcloud_t* pc, const double** out_data,
                                              size_t* out_n);
/**
 * @brief Borrowed writable view of the points, for in-place edits (numpy `np.asarray(pcd.points)`).
 * **Ownership:** as o3d_pointcloud_points_view. Writing through it is a mutating call.
 */
O3D_API o3d_status o3d_pointcloud_points_mutable_view(o3d_pointcloud_t* pc, double** out_data, size_t* out_n);
O3D_API o3d_status o3d_pointcloud_normals_mutable_view(o3d_pointcloud_t* pc, double** out_data,
                                                       size_t* out_n);
O3D_API o3d_status o3d_pointcloud_colors_mutable_view(o3d_pointcloud_t* pc, double** out_data, size_t* out_n);

/**
 * @brief Concatenate `other` onto `pc` (Open3D `pcd += other`): normals/colors survive only when both
 * clouds have them (or `pc` is empty).
 */
O3D_API o3d_status o3d_pointcloud_append(o3d_pointcloud_t* pc, const o3d_pointcloud_t* other);

/** @brief Apply a row-major 4x4 transform to points (and rotate normals). */
O3D_API o3d_status o3d_pointcloud_transform(o3d_pointcloud_t* pc, const double transform[16]);
/** @brief relative != 0: add `t`; relative == 0: move the center to `t`. */
O3D_API o3d_status o3d_pointcloud_translate(o3d_pointcloud_t* pc, const double translation[3], int32_t relative);
/** @brief Rotate by row-major 3x3 `R` about `center` (NULL: the cloud's center). */
O3D_API o3d_status o3d_pointcloud_rotate(o3d_pointcloud_t* pc, const double rotation[9], const double center[3]);
/** @brief Scale about `center` (NULL: the cloud's center). */
O3D_API o3d_status o3d_pointcloud_scale(o3d_pointcloud_t* pc, double scale, const double center[3]);

/** @brief Component-wise minimum of the points ((0,0,0) for an empty cloud, as Open3D). */
O3D_API o3d_status o3d_pointcloud_get_min_bound(const o3d_pointcloud_t* pc, double out[3]);
O3D_API o3d_status o3d_pointcloud_get_max_bound(const o3d_pointcloud_t* pc, double out[3]);
/** @brief Mean of the points ((0,0,0) for an empty cloud). */
O3D_API o3d_status o3d_pointcloud_get_center(const o3d_pointcloud_t* pc, double out[3]);
/** @brief Axis-aligned bounding box as min and max corners. */
O3D_API o3d_status o3d_pointcloud_get_axis_aligned_bounding_box(const o3d_pointcloud_t* pc, double out_min[3],
                                                                double out_max[3]);
/** @brief Set every color to `rgb` (each in [0,1]). */
O3D_API o3d_status o3d_pointcloud_paint_uniform_color(o3d_pointcloud_t* pc, const double rgb[3]);
/** @brief New cloud with the points at `indices` (or all others when invert != 0). Out-of-range → error. */
O3D_API o3d_status o3d_pointcloud_select_by_index(o3d_pointcloud_t** out, const o3d_pointcloud_t* pc,
                                                  const int32_t* indices, size_t n, int32_t invert);
/** @brief Drop points with a NaN (remove_nan != 0) or an infinite (remove_infinite != 0) coordinate. */
O3D_API o3d_status o3d_pointcloud_remove_non_finite_points(o3d_pointcloud_t* pc, int32_t remove_nan,
                                                           int32_t remove_infinite);
/** @brief Scale every normal to unit length. */
O3D_API o3d_status o3d_pointcloud_normalize_normals(o3d_pointcloud_t* pc);

/** @brief Average points (normals, colors) per voxel of edge `voxel_size` > 0. @see voxel_down_sample */
O3D_API o3d_status o3d_pointcloud_voxel_down_sample(o3d_pointcloud_t** out, const o3d_pointcloud_t* pc,
                                                    double voxel_size);
/** @brief Keep points 0, k, 2k, ... (every_k_points >= 1). */
O3D_API o3d_status o3d_pointcloud_uniform_down_sample(o3d_pointcloud_t** out, const o3d_pointcloud_t* pc,
                                                      size_t every_k_points);
/**
 * @brief Keep floor(ratio * N) points chosen at random, in their original order. ratio in [0,1].
 * Same seed → same output, whatever the thread count.
 */
O3D_API o3d_status o3d_pointcloud_random_down_sample(o3d_pointcloud_t** out, const o3d_pointcloud_t* pc,
                                                     double sampling_ratio, uint64_t seed);
/** @brief Farthest-point sampling of `num_samples` points, starting at `start_index`. */
O3D_API o3d_status o3d_pointcloud_farthest_point_down_sample(o3d_pointcloud_t** out, const o3d_pointcloud_t* pc,
                                                             size_t num_samples, size_t start_index);

/** Kinds of neighbourhood search (o3d.geometry.KDTreeSearchParam*). */
#define O3D_SEARCH_KNN 0    /**< the `knn` nearest points */
#define O3D_SEARCH_RADIUS 1 /**< all points within `radius` */
#define O3D_SEARCH_HYBRID 2 /**< at most `knn` nearest points within `radius` */

/** Neighbourhood search parameter (KDTreeSearchParamKNN / Radius / Hybrid). */
typedef struct o3d_search_param {
    uint32_t struct_size; /**< sizeof(o3d_search_param_t), set by o3d_search_param_init */
    int32_t kind;         /**< O3D_SEARCH_KNN, O3D_SEARCH_RADIUS or O3D_SEARCH_HYBRID; default KNN */
    int32_t knn;          /**< neighbour count for KNN / HYBRID; default 30 */
    double radius;        /**< radius for RADIUS / HYBRID [units of the cloud]; default 0 */
} o3d_search_param_t;

/** @brief Fill defaults (KNN, 30). `struct_size` must be sizeof(o3d_search_param_t) or a smaller, older size. */
O3D_API o3d_status o3d_search_param_init(o3d_search_param_t* param, uint32_t struct_size);

/**
 * @brief PCA normals over each point's neighbourhood (NULL param: KNN 30). When the cloud already
 * has normals, each new normal is flipped to agree with the old one. num_threads 0 = default.
 * Deterministic: the result does not depend on the thread count.
 */
O3D_API o3d_status o3d_pointcloud_estimate_normals(o3d_pointcloud_t* pc, const o3d_search_param_t* param,
                                                   int32_t num_threads);
/** @brief Flip normals to have a non-negative dot product with `direction` (NULL: +Z). */
O3D_API o3d_status o3d_pointcloud_orient_normals_to_align_with_direction(o3d_pointcloud_t* pc,
                                                                        const double direction[3]);
/** @brief Flip normals to point towards `camera_location` (NULL: origin). */
O3D_API o3d_status o3d_pointcloud_orient_normals_towards_camera_location(o3d_pointcloud_t* pc,
                                                                        const double camera_location[3]);
/**
 * @brief Distance from each point to its nearest other point, into `out` (capacity doubles).
 * `*out_n` always gets N. @return O3D_ERROR_BUFFER_TOO_SMALL if capacity < N.
 */
O3D_API o3d_status o3d_pointcloud_compute_nearest_neighbor_distance(const o3d_pointcloud_t* pc, double* out,
                                                                   size_t capacity, size_t* out_n,
                                                                   int32_t num_threads);
/** @brief For each point of `source`, the distance to the closest point of `target`. */
O3D_API o3d_status o3d_pointcloud_compute_point_cloud_distance(const o3d_pointcloud_t* source,
                                                               const o3d_pointcloud_t* target, double* out,
                                                               size_t capacity, size_t* out_n,
                                                               int32_t num_threads);

/* ---- Point-cloud tools (o3d.geometry.PointCloud filters, segmentation, statistics) ----
 * Functions that also return indices write them to a caller buffer: `out_indices` holds `capacity`
 * int32 values, `*out_n` always gets the count (at most the cloud's size, so capacity = size always
 * fits), O3D_ERROR_BUFFER_TOO_SMALL when it does not fit; `out_indices` NULL skips them.
 * An empty cloud is an O3D_ERROR_INVALID_ARGUMENT for all of them. */

/**
 * @brief Statistical outlier removal: drop points whose mean distance to their `nb_neighbors` nearest
 * points is above the cloud's mean of that distance + `std_ratio` standard deviations.
 * Writes the kept cloud to `*out` and the kept indices (ascending). @see remove_statistical_outlier
 */
O3D_API o3d_status o3d_pointcloud_remove_statistical_outlier(o3d_pointcloud_t** out, const o3d_pointcloud_t* pc,
                                                             int32_t nb_neighbors, double std_ratio,
                                                             int32_t* out_indices, size_t capacity, size_t* out_n);
/**
 * @brief Radius outlier removal: keep points with at least `nb_points` other points within `radius`.
 * Writes the kept cloud and the kept indices (ascending). @see remove_radius_outlier
 */
O3D_API o3d_status o3d_pointcloud_remove_radius_outlier(o3d_pointcloud_t** out, const o3d_pointcloud_t* pc,
                                                        int32_t nb_points, double radius, int32_t* out_indices,
                                                        size_t capacity, size_t* out_n);
/** @brief New cloud with the points inside the box [min_bound, max_bound] (outside when invert != 0). */
O3D_API o3d_status o3d_pointcloud_crop_aabb(o3d_pointcloud_t** out, const o3d_pointcloud_t* pc,
                                            const double min_bound[3], const double max_bound[3], int32_t invert);
/**
 * @brief RANSAC plane: `out_plane` gets (a, b, c, d) with a x + b y + c z + d = 0 and unit (a, b, c);
 * the inlier indices (ascending) go to `out_indices`. Same seed → same result on any thread count.
 * @see segment_plane
 */
O3D_API o3d_status o3d_pointcloud_segment_plane(const o3d_pointcloud_t* pc, double distance_threshold,
                                                int32_t ransac_n, int32_t num_iterations, double probability,
                                                uint64_t seed, double out_plane[4], int32_t* out_indices,
                                                size_t capacity, size_t* out_n);
/**
 * @brief DBSCAN: one label per point in `out_labels` (capacity values): clusters 0, 1, ... in order of
 * their lowest point index, -1 for noise. `*out_n` gets the point count. @see cluster_dbscan
 */
O3D_API o3d_status o3d_pointcloud_cluster_dbscan(const o3d_pointcloud_t* pc, double eps, int32_t min_points,
                                                 int32_t* out_labels, size_t capacity, size_t* out_n);
/** @brief Mean (3) and covariance (row-major 3x3, divided by N) of the points. Empty cloud → error. */
O3D_API o3d_status o3d_pointcloud_compute_mean_and_covariance(const o3d_pointcloud_t* pc, double out_mean[3],
                                                              double out_covariance[9]);
/** @brief Mahalanobis distance of each point to the cloud's distribution, into `out` (capacity doubles). */
O3D_API o3d_status o3d_pointcloud_compute_mahalanobis_distance(const o3d_pointcloud_t* pc, double* out,
                                                               size_t capacity, size_t* out_n);

/* ---- Per-point covariances (o3d.geometry.PointCloud.covariances): N x 9, row-major 3x3 each ----
 * A cloud carries covariances only when their count equals the point count (has_covariances). As in
 * Open3D they follow the points through every operation that keeps a subset of the points
 * (select_by_index, crop_aabb / crop_obb, uniform/random/farthest down-sampling, outlier removal,
 * remove_non_finite_points), through append and clear, and rotate with transform/rotate (R C R^T);
 * voxel_down_sample, which averages points, drops them. */

/** @brief 1 when the cloud has one covariance per point, else 0. */
O3D_API o3d_status o3d_pointcloud_has_covariances(const o3d_pointcloud_t* pc, int32_t* out);
/** @brief Replace the covariances with `n` row-major 3x3 matrices (n x 9 doubles, copied). */
O3D_API o3d_status o3d_pointcloud_set_covariances(o3d_pointcloud_t* pc, const double* data, size_t n);
/** @brief Copy the covariances out (capacity matrices; `*out_n` always gets the count). */
O3D_API o3d_status o3d_pointcloud_get_covariances(const o3d_pointcloud_t* pc, double* out, size_t capacity,
                                                  size_t* out_n);
/** @brief Borrowed read-only view of the covariances (n x 9 doubles). */
O3D_API o3d_status o3d_pointcloud_covariances_view(const o3d_pointcloud_t* pc, const double** out_data,
                                                   size_t* out_n);
/**
 * @brief Covariance of each point's neighbourhood (`param`: KNN, radius or hybrid; NULL: KNN 30 as
 * Open3D), divided by the neighbour count; fewer than 3 neighbours give the identity (Open3D).
 * @see PointCloud.estimate_covariances
 */
O3D_API o3d_status o3d_pointcloud_estimate_covariances(o3d_pointcloud_t* pc, const o3d_search_param_t* param);

O3D_END_DECL

#endif /* O3D_POINTCLOUD_H */
