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
 *
 * **Out of memory:** any function here that allocates may also return O3D_ERROR_OUT_OF_MEMORY; the
 * per-function `@return` lists do not repeat it.
 */
#ifndef O3D_POINTCLOUD_H
#define O3D_POINTCLOUD_H

#include "o3d/common.h"
#include "o3d/types.h"
#include "o3d/boundingbox.h"
#include "o3d/camera.h"
#include "o3d/kdtree.h"

O3D_BEGIN_DECL


/**
 * @brief New empty cloud. @see o3d.geometry.PointCloud()
 *
 * Threads: any thread.
 * Ownership: `*out` is the caller's, to free with o3d_pointcloud_destroy(); left NULL on failure.
 * @param out receives the new handle (NULL on failure)
 * @return O3D_OK, or O3D_ERROR_INVALID_ARGUMENT on a NULL pointer.
 */
O3D_API o3d_status o3d_pointcloud_create(o3d_pointcloud_t** out);
/**
 * @brief Destroy. NULL is a no-op.
 *
 * Threads: needs exclusive access to `pc`: no other call may use it during or after.
 * @param pc the handle to destroy (NULL is a no-op)
 */
O3D_API void o3d_pointcloud_destroy(o3d_pointcloud_t* pc);
/**
 * @brief Deep copy.
 *
 * Threads: any thread; concurrent calls on the same handles are safe (all read-only).
 * Ownership: `*out` is the caller's, to free with o3d_pointcloud_destroy(); left NULL on failure.
 * @param out receives the new handle (NULL on failure)
 * @param src the handle to copy
 * @return O3D_OK, or O3D_ERROR_INVALID_ARGUMENT on a NULL pointer.
 */
O3D_API o3d_status o3d_pointcloud_clone(o3d_pointcloud_t** out, const o3d_pointcloud_t* src);

/**
 * @brief Number of points.
 *
 * Threads: any thread; concurrent calls on the same handles are safe (all read-only).
 * @param out_n receives the count
 * @param pc the point cloud
 * @return O3D_OK, or O3D_ERROR_INVALID_ARGUMENT on a NULL pointer.
 */
O3D_API o3d_status o3d_pointcloud_size(size_t* out_n, const o3d_pointcloud_t* pc);
/**
 * @brief Remove points, normals, colors and covariances.
 *
 * Threads: needs exclusive access to `pc`.
 * @param pc the point cloud
 * @return O3D_OK, or O3D_ERROR_INVALID_ARGUMENT on a NULL pointer.
 */
O3D_API o3d_status o3d_pointcloud_clear(o3d_pointcloud_t* pc);

/* ---- Arrays: the same functions for every geometry (docs/conventions.md, "Arrays") ----
 * `which` names the array; rows are counted in items (a point, a line, a descriptor), never in
 * values. Copy-outs take the caller's capacity in rows and always report the rows needed;
 * views are borrowed, valid until the next mutating call on the handle or its destruction. */
/** The arrays of a point cloud (O3D_POINTCLOUD_*). */
typedef int32_t o3d_pointcloud_array;
#define O3D_POINTCLOUD_POINTS 0 /**< N x 3 float64 */
#define O3D_POINTCLOUD_NORMALS 1 /**< N x 3, one per point */
#define O3D_POINTCLOUD_COLORS 2 /**< N x 3 RGB in [0,1], one per point */
#define O3D_POINTCLOUD_COVARIANCES 3 /**< N x 9, a row-major symmetric 3x3 per point (set_array rejects asymmetric ones) */

/**
 * @brief Whether array `which` counts (Open3D's has_*: present and of the matching size).
 *
 * Threads: any thread; concurrent calls on the same handles are safe (all read-only).
 * @param out receives 1 (true) or 0 (false)
 * @param pc the point cloud
 * @param which the array: one of this header's `which` constants
 * @return O3D_OK, or O3D_ERROR_INVALID_ARGUMENT on a NULL pointer or an unknown `which`.
 */
O3D_API o3d_status o3d_pointcloud_has_array(int32_t* out, const o3d_pointcloud_t* pc, o3d_pointcloud_array which);
/**
 * @brief Rows and columns (values per row) of array `which`: e.g. N x 3 for points, num x dimension for a
 * feature.
 *
 * Threads: any thread; concurrent calls on the same handles are safe (all read-only).
 * @param out_rows receives the rows (items)
 * @param out_cols receives the values per row
 * @param pc the point cloud
 * @param which the array: one of this header's `which` constants
 * @return O3D_OK, or O3D_ERROR_INVALID_ARGUMENT on a NULL pointer or an unknown `which`.
 */
O3D_API o3d_status o3d_pointcloud_array_shape(size_t* out_rows, size_t* out_cols, const o3d_pointcloud_t* pc, o3d_pointcloud_array which);
/**
 * @brief Replace array `which` with `rows` rows of `data`, copied once (`data` may be NULL when rows == 0).
 *
 * Threads: needs exclusive access to `pc`.
 * @param pc the point cloud
 * @param which the array: one of this header's `which` constants
 * @param data `rows` rows of values, copied once (NULL allowed when rows == 0)
 * @param rows number of rows in `data`
 * @return O3D_OK, or O3D_ERROR_INVALID_ARGUMENT on a NULL handle, an unknown `which`, NULL `data` with rows > 0, an
 *   unknown `which` (or one of the other type) or asymmetric covariances.
 */
O3D_API o3d_status o3d_pointcloud_set_array(o3d_pointcloud_t* pc, o3d_pointcloud_array which, const double* data, size_t rows);
/**
 * @brief As o3d_pointcloud_set_array from float32 values, converted in the one copy.
 *
 * Threads: needs exclusive access to `pc`.
 * @param pc the point cloud
 * @param which the array: one of this header's `which` constants
 * @param data `rows` rows of values, copied once (NULL allowed when rows == 0)
 * @param rows number of rows in `data`
 * @return O3D_OK, or O3D_ERROR_INVALID_ARGUMENT on a NULL handle, an unknown `which`, NULL `data` with rows > 0, an
 *   unknown `which` (or one of the other type), asymmetric covariances or an array that takes no float32.
 */
O3D_API o3d_status o3d_pointcloud_set_array_f32(o3d_pointcloud_t* pc, o3d_pointcloud_array which, const float* data, size_t rows);
/**
 * @brief Copy array `which` into `out`, which holds `capacity` rows; `*out_rows` always gets the rows
 * needed. `out` NULL only reports them.
 *
 * Threads: any thread; concurrent calls on the same handles are safe (all read-only).
 * @param out caller buffer of `capacity` rows (NULL: only report the row count)
 * @param capacity rows `out` holds
 * @param out_rows receives the rows of the array (always, also when `out` is NULL or too small)
 * @param pc the point cloud
 * @param which the array: one of this header's `which` constants
 * @return O3D_OK, or O3D_ERROR_INVALID_ARGUMENT on a NULL handle or `out_rows` or an unknown `which`;
 *   O3D_ERROR_BUFFER_TOO_SMALL when `capacity` is short (the count is still reported).
 */
O3D_API o3d_status o3d_pointcloud_get_array(double* out, size_t capacity, size_t* out_rows, const o3d_pointcloud_t* pc,
                                            o3d_pointcloud_array which);
/**
 * @brief Borrowed read-only view of array `which` (`*out_data` NULL when empty).
 *
 * Threads: any thread; concurrent calls on the same handles are safe (all read-only).
 * Ownership: `*out_data` points into `pc` (the library's memory, never to be freed): valid until the next mutating
 * call on `pc` or its destruction.
 * @param out_data receives the address of row 0 (NULL when the array is empty)
 * @param out_rows receives the row count
 * @param pc the point cloud
 * @param which the array: one of this header's `which` constants
 * @return O3D_OK, or O3D_ERROR_INVALID_ARGUMENT on a NULL handle, `out_data` or `out_rows` or an unknown `which`.
 */
O3D_API o3d_status o3d_pointcloud_array_view(const double** out_data, size_t* out_rows, const o3d_pointcloud_t* pc,
                                             o3d_pointcloud_array which);
/**
 * @brief Borrowed writable view of array `which`: as o3d_pointcloud_array_view; writing through it is a mutating
 * call.
 *
 * Threads: needs exclusive access to `pc`, also while the view is written through.
 * Ownership: `*out_data` points into `pc` (the library's memory, never to be freed): valid until the next mutating
 * call on `pc` or its destruction.
 * @param out_data receives the address of row 0 (NULL when the array is empty)
 * @param out_rows receives the row count
 * @param pc the point cloud
 * @param which the array: one of this header's `which` constants
 * @return O3D_OK, or O3D_ERROR_INVALID_ARGUMENT on a NULL handle, `out_data` or `out_rows` or an unknown `which`.
 */
O3D_API o3d_status o3d_pointcloud_array_mutable_view(double** out_data, size_t* out_rows, o3d_pointcloud_t* pc,
                                                     o3d_pointcloud_array which);

/**
 * @brief Concatenate `other` onto `pc` (Open3D `pcd += other`): normals/colors survive only when both
 * clouds have them (or `pc` is empty).
 *
 * Threads: needs exclusive access to `pc`; `other` is only read.
 * @param pc the point cloud
 * @param other the geometry appended (only read)
 * @return O3D_OK, or O3D_ERROR_INVALID_ARGUMENT on a NULL pointer.
 */
O3D_API o3d_status o3d_pointcloud_append(o3d_pointcloud_t* pc, const o3d_pointcloud_t* other);

/**
 * @brief Apply a row-major 4x4 transform to points (and rotate normals).
 *
 * Threads: needs exclusive access to `pc`.
 * @param pc the point cloud
 * @param transform row-major 4x4 transform
 * @return O3D_OK, or O3D_ERROR_INVALID_ARGUMENT on a NULL pointer.
 */
O3D_API o3d_status o3d_pointcloud_transform(o3d_pointcloud_t* pc, const double transform[16]);
/**
 * @brief Move the cloud: with `relative`, by `translation`; without, so that its center is at `translation`.
 *
 * Threads: needs exclusive access to `pc`.
 * @param pc the point cloud
 * @param translation the translation, or the new center
 * @param relative non-zero: add `translation`; 0: move the center there
 * @return O3D_OK, or O3D_ERROR_INVALID_ARGUMENT on a NULL pointer.
 */
O3D_API o3d_status o3d_pointcloud_translate(o3d_pointcloud_t* pc, const double translation[3], o3d_bool relative);
/**
 * @brief Rotate by row-major 3x3 `R` about `center` (NULL: the cloud's center).
 *
 * Threads: needs exclusive access to `pc`.
 * @param pc the point cloud
 * @param rotation row-major 3x3 rotation matrix
 * @param center the pivot (NULL: the geometry's center)
 * @return O3D_OK, or O3D_ERROR_INVALID_ARGUMENT on a NULL pointer.
 */
O3D_API o3d_status o3d_pointcloud_rotate(o3d_pointcloud_t* pc, const double rotation[9], const double center[3]);
/**
 * @brief Scale about `center` (NULL: the cloud's center).
 *
 * Threads: needs exclusive access to `pc`.
 * @param pc the point cloud
 * @param scale the scale factor
 * @param center the pivot (NULL: the geometry's center)
 * @return O3D_OK, or O3D_ERROR_INVALID_ARGUMENT on a NULL pointer.
 */
O3D_API o3d_status o3d_pointcloud_scale(o3d_pointcloud_t* pc, double scale, const double center[3]);

/**
 * @brief Component-wise minimum of the points ((0,0,0) for an empty cloud, as Open3D).
 *
 * Threads: any thread; concurrent calls on the same handles are safe (all read-only).
 * @param out receives the result
 * @param pc the point cloud
 * @return O3D_OK, or O3D_ERROR_INVALID_ARGUMENT on a NULL pointer.
 */
O3D_API o3d_status o3d_pointcloud_get_min_bound(double out[3], const o3d_pointcloud_t* pc);
/**
 * @brief Component-wise maximum of the points ((0,0,0) for an empty cloud).
 *
 * Threads: any thread; concurrent calls on the same handles are safe (all read-only).
 * @param out receives the result
 * @param pc the point cloud
 * @return O3D_OK, or O3D_ERROR_INVALID_ARGUMENT on a NULL pointer.
 */
O3D_API o3d_status o3d_pointcloud_get_max_bound(double out[3], const o3d_pointcloud_t* pc);
/**
 * @brief Mean of the points ((0,0,0) for an empty cloud).
 *
 * Threads: any thread; concurrent calls on the same handles are safe (all read-only).
 * @param out receives the result
 * @param pc the point cloud
 * @return O3D_OK, or O3D_ERROR_INVALID_ARGUMENT on a NULL pointer.
 */
O3D_API o3d_status o3d_pointcloud_get_center(double out[3], const o3d_pointcloud_t* pc);
/**
 * @brief Axis-aligned bounding box as min and max corners.
 *
 * Threads: any thread; concurrent calls on the same handles are safe (all read-only).
 * @param out_min receives the minimum corner
 * @param out_max receives the maximum corner
 * @param pc the point cloud
 * @return O3D_OK, or O3D_ERROR_INVALID_ARGUMENT on a NULL pointer.
 */
O3D_API o3d_status o3d_pointcloud_get_axis_aligned_bounding_box(double out_min[3], double out_max[3],
                                                                const o3d_pointcloud_t* pc);
/**
 * @brief Set every color to `rgb` (each in [0,1]).
 *
 * Threads: needs exclusive access to `pc`.
 * @param pc the point cloud
 * @param rgb the color, each channel in [0,1]
 * @return O3D_OK, or O3D_ERROR_INVALID_ARGUMENT on a NULL pointer.
 */
O3D_API o3d_status o3d_pointcloud_paint_uniform_color(o3d_pointcloud_t* pc, const double rgb[3]);
/**
 * @brief New cloud with the points at `indices` (or all others when invert != 0). Out-of-range → error.
 *
 * Threads: any thread; concurrent calls on the same handles are safe (all read-only).
 * Ownership: `*out` is the caller's, to free with o3d_pointcloud_destroy(); left NULL on failure.
 * @param out receives the new handle (NULL on failure)
 * @param pc the point cloud
 * @param indices the indices
 * @param n number of points (rows of 3 doubles) in `xyz`
 * @param invert non-zero selects the complement
 * @return O3D_OK, or O3D_ERROR_INVALID_ARGUMENT on a NULL pointer.
 */
O3D_API o3d_status o3d_pointcloud_select_by_index(o3d_pointcloud_t** out, const o3d_pointcloud_t* pc,
                                                  const int32_t* indices, size_t n, int32_t invert);
/**
 * @brief Drop points with a NaN (when `remove_nan`) or an infinite (when `remove_infinite`) coordinate.
 *
 * Threads: needs exclusive access to `pc`.
 * @param pc the point cloud
 * @param remove_nan non-zero drops points with a NaN coordinate
 * @param remove_infinite non-zero drops points with an infinite coordinate
 * @return O3D_OK, or O3D_ERROR_INVALID_ARGUMENT on a NULL pointer.
 */
O3D_API o3d_status o3d_pointcloud_remove_non_finite_points(o3d_pointcloud_t* pc, o3d_bool remove_nan,
                                                           o3d_bool remove_infinite);
/**
 * @brief Scale every normal to unit length.
 *
 * Threads: needs exclusive access to `pc`.
 * @param pc the point cloud
 * @return O3D_OK, or O3D_ERROR_INVALID_ARGUMENT on a NULL pointer.
 */
O3D_API o3d_status o3d_pointcloud_normalize_normals(o3d_pointcloud_t* pc);

/**
 * @brief Average points (normals, colors) per voxel of edge `voxel_size` > 0. @see voxel_down_sample
 *
 * Threads: any thread; concurrent calls on the same handles are safe (all read-only).
 * Ownership: `*out` is the caller's, to free with o3d_pointcloud_destroy(); left NULL on failure.
 * @param out receives the new handle (NULL on failure)
 * @param pc the point cloud
 * @param voxel_size voxel edge length (> 0)
 * @return O3D_OK, or O3D_ERROR_INVALID_ARGUMENT on a NULL pointer.
 */
O3D_API o3d_status o3d_pointcloud_voxel_down_sample(o3d_pointcloud_t** out, const o3d_pointcloud_t* pc,
                                                    double voxel_size);
/**
 * @brief Keep points 0, k, 2k, ... (every_k_points >= 1).
 *
 * Threads: any thread; concurrent calls on the same handles are safe (all read-only).
 * Ownership: `*out` is the caller's, to free with o3d_pointcloud_destroy(); left NULL on failure.
 * @param out receives the new handle (NULL on failure)
 * @param pc the point cloud
 * @param every_k_points the step (>= 1)
 * @return O3D_OK, or O3D_ERROR_INVALID_ARGUMENT on a NULL pointer.
 */
O3D_API o3d_status o3d_pointcloud_uniform_down_sample(o3d_pointcloud_t** out, const o3d_pointcloud_t* pc,
                                                      size_t every_k_points);
/**
 * @brief Keep floor(ratio * N) points chosen at random, in their original order. ratio in [0,1].
 * Same seed → same output, whatever the thread count.
 *
 * Threads: any thread; concurrent calls on the same handles are safe (all read-only).
 * Ownership: `*out` is the caller's, to free with o3d_pointcloud_destroy(); left NULL on failure.
 * @param out receives the new handle (NULL on failure)
 * @param pc the point cloud
 * @param sampling_ratio share of points to keep, in [0,1]
 * @param seed random seed: the same seed gives the same output
 * @return O3D_OK, or O3D_ERROR_INVALID_ARGUMENT on a NULL pointer.
 */
O3D_API o3d_status o3d_pointcloud_random_down_sample(o3d_pointcloud_t** out, const o3d_pointcloud_t* pc,
                                                     double sampling_ratio, uint64_t seed);
/**
 * @brief Farthest-point sampling of `num_samples` points, starting at `start_index`.
 *
 * Threads: any thread; concurrent calls on the same handles are safe (all read-only).
 * Ownership: `*out` is the caller's, to free with o3d_pointcloud_destroy(); left NULL on failure.
 * @param out receives the new handle (NULL on failure)
 * @param pc the point cloud
 * @param num_samples points to keep (at most the cloud's size)
 * @param start_index the first point chosen (below the cloud's size)
 * @return O3D_OK, or O3D_ERROR_INVALID_ARGUMENT on a NULL pointer.
 */
O3D_API o3d_status o3d_pointcloud_farthest_point_down_sample(o3d_pointcloud_t** out, const o3d_pointcloud_t* pc,
                                                             size_t num_samples, size_t start_index);


/**
 * @brief PCA normals over each point's neighbourhood (NULL param: KNN 30). When the cloud already
 * has normals, each new normal is flipped to agree with the old one. num_threads 0 = default.
 * Deterministic: the result does not depend on the thread count.
 *
 * Threads: needs exclusive access to `pc`.
 * @param pc the point cloud
 * @param param the neighbourhood search (NULL: KNN 30)
 * @param num_threads threads to use: 0 = the library default (o3d_set_num_threads), negative is invalid
 * @return O3D_OK, or O3D_ERROR_INVALID_ARGUMENT on a NULL pointer or a negative `num_threads`.
 */
O3D_API o3d_status o3d_pointcloud_estimate_normals(o3d_pointcloud_t* pc, const o3d_search_param_t* param,
                                                   int32_t num_threads);
/**
 * @brief Flip normals to have a non-negative dot product with `direction` (NULL: +Z).
 *
 * Threads: needs exclusive access to `pc`.
 * @param pc the point cloud
 * @param direction the direction (NULL: +Z)
 * @return O3D_OK, or O3D_ERROR_INVALID_ARGUMENT on a NULL pointer.
 */
O3D_API o3d_status o3d_pointcloud_orient_normals_to_align_with_direction(o3d_pointcloud_t* pc,
                                                                        const double direction[3]);
/**
 * @brief Flip normals to point towards `camera_location` (NULL: origin).
 *
 * Threads: needs exclusive access to `pc`.
 * @param pc the point cloud
 * @param camera_location the camera position
 * @return O3D_OK, or O3D_ERROR_INVALID_ARGUMENT on a NULL pointer.
 */
O3D_API o3d_status o3d_pointcloud_orient_normals_towards_camera_location(o3d_pointcloud_t* pc,
                                                                        const double camera_location[3]);
/**
 * @brief Distance from each point to its nearest other point, into `out` (capacity doubles).
 * `*out_n` always gets N.
 *
 * Threads: any thread; concurrent calls on the same handles are safe (all read-only).
 * @param out caller buffer of `capacity` items (NULL: only report the count)
 * @param capacity how many items the output buffer holds (ignored when it is NULL)
 * @param out_n receives the item count (always, also when the buffer is NULL or too small)
 * @param pc the point cloud
 * @param num_threads threads to use: 0 = the library default (o3d_set_num_threads), negative is invalid
 * @return O3D_OK, or O3D_ERROR_INVALID_ARGUMENT on a NULL pointer or a negative `num_threads`;
 *   O3D_ERROR_BUFFER_TOO_SMALL when `capacity` is short (the count is still reported).
 */
O3D_API o3d_status o3d_pointcloud_compute_nearest_neighbor_distance(double* out, size_t capacity, size_t* out_n,
                                                                   const o3d_pointcloud_t* pc, int32_t num_threads);
/**
 * @brief For each point of `source`, the distance to the closest point of `target`.
 *
 * Threads: any thread; concurrent calls on the same handles are safe (all read-only).
 * @param out caller buffer of `capacity` items (NULL: only report the count)
 * @param capacity how many items the output buffer holds (ignored when it is NULL)
 * @param out_n receives the item count (always, also when the buffer is NULL or too small)
 * @param source the source cloud (moved onto `target`)
 * @param target the target cloud
 * @param num_threads threads to use: 0 = the library default (o3d_set_num_threads), negative is invalid
 * @return O3D_OK, or O3D_ERROR_INVALID_ARGUMENT on a NULL pointer or a negative `num_threads`;
 *   O3D_ERROR_BUFFER_TOO_SMALL when `capacity` is short (the count is still reported).
 */
O3D_API o3d_status o3d_pointcloud_compute_point_cloud_distance(double* out, size_t capacity, size_t* out_n,
                                                               const o3d_pointcloud_t* source,
                                                               const o3d_pointcloud_t* target, int32_t num_threads);

/* ---- Point-cloud tools (o3d.geometry.PointCloud filters, segmentation, statistics) ----
 * Functions that also return indices write them to a caller buffer: `out_indices` holds `capacity`
 * int32 values, `*out_n` always gets the count (at most the cloud's size, so capacity = size always
 * fits), O3D_ERROR_BUFFER_TOO_SMALL when it does not fit; `out_indices` NULL skips them.
 * An empty cloud is an O3D_ERROR_INVALID_ARGUMENT for all of them. */

/**
 * @brief Statistical outlier removal: drop points whose mean distance to their `nb_neighbors` nearest
 * points is above the cloud's mean of that distance + `std_ratio` standard deviations.
 * Writes the kept cloud to `*out` and the kept indices (ascending). @see remove_statistical_outlier
 *
 * Threads: any thread; concurrent calls on the same handles are safe (all read-only).
 * Ownership: `*out` is the caller's, to free with o3d_pointcloud_destroy(); left NULL on failure.
 * @param out receives the new handle (NULL on failure)
 * @param out_indices receives the indices (`capacity` int32; NULL skips them)
 * @param capacity how many items the output buffer holds (ignored when it is NULL)
 * @param out_n receives the item count (always, also when the buffer is NULL or too small)
 * @param pc the point cloud
 * @param nb_neighbors neighbours averaged per point (>= 1)
 * @param std_ratio the threshold in standard deviations (> 0)
 * @return O3D_OK, or O3D_ERROR_INVALID_ARGUMENT on a NULL pointer; O3D_ERROR_BUFFER_TOO_SMALL when `capacity` is
 *   short (the count is still reported).
 */
O3D_API o3d_status o3d_pointcloud_remove_statistical_outlier(o3d_pointcloud_t** out, int32_t* out_indices,
                                                             size_t capacity, size_t* out_n,
                                                             const o3d_pointcloud_t* pc, int32_t nb_neighbors,
                                                             double std_ratio);
/**
 * @brief Radius outlier removal: keep points with at least `nb_points` other points within `radius`.
 * Writes the kept cloud and the kept indices (ascending). @see remove_radius_outlier
 *
 * Threads: any thread; concurrent calls on the same handles are safe (all read-only).
 * Ownership: `*out` is the caller's, to free with o3d_pointcloud_destroy(); left NULL on failure.
 * @param out receives the new handle (NULL on failure)
 * @param out_indices receives the indices (`capacity` int32; NULL skips them)
 * @param capacity how many items the output buffer holds (ignored when it is NULL)
 * @param out_n receives the item count (always, also when the buffer is NULL or too small)
 * @param pc the point cloud
 * @param nb_points minimum neighbours within `radius`
 * @param radius the radius (> 0)
 * @return O3D_OK, or O3D_ERROR_INVALID_ARGUMENT on a NULL pointer; O3D_ERROR_BUFFER_TOO_SMALL when `capacity` is
 *   short (the count is still reported).
 */
O3D_API o3d_status o3d_pointcloud_remove_radius_outlier(o3d_pointcloud_t** out, int32_t* out_indices, size_t capacity,
                                                        size_t* out_n, const o3d_pointcloud_t* pc, int32_t nb_points,
                                                        double radius);
/**
 * @brief New cloud with the points inside the box [min_bound, max_bound] (outside when invert != 0).
 *
 * Threads: any thread; concurrent calls on the same handles are safe (all read-only).
 * Ownership: `*out` is the caller's, to free with o3d_pointcloud_destroy(); left NULL on failure.
 * @param out receives the new handle (NULL on failure)
 * @param pc the point cloud
 * @param min_bound minimum corner (x, y, z)
 * @param max_bound maximum corner (x, y, z)
 * @param invert non-zero selects the complement
 * @return O3D_OK, or O3D_ERROR_INVALID_ARGUMENT on a NULL pointer.
 */
O3D_API o3d_status o3d_pointcloud_crop_aabb(o3d_pointcloud_t** out, const o3d_pointcloud_t* pc,
                                            const double min_bound[3], const double max_bound[3], int32_t invert);
/**
 * @brief RANSAC plane: `out_plane` gets (a, b, c, d) with a x + b y + c z + d = 0 and unit (a, b, c);
 * the inlier indices (ascending) go to `out_indices`. Same seed → same result on any thread count.
 * @see segment_plane
 *
 * Threads: any thread; concurrent calls on the same handles are safe (all read-only).
 * @param out_plane receives (a, b, c, d)
 * @param out_indices receives the indices (`capacity` int32; NULL skips them)
 * @param capacity how many items the output buffer holds (ignored when it is NULL)
 * @param out_n receives the item count (always, also when the buffer is NULL or too small)
 * @param pc the point cloud
 * @param distance_threshold maximum distance of an inlier to the plane
 * @param ransac_n points drawn per hypothesis (>= 3)
 * @param num_iterations RANSAC iterations
 * @param probability stop early at this confidence, in (0, 1]
 * @param seed random seed: the same seed gives the same output
 * @return O3D_OK, or O3D_ERROR_INVALID_ARGUMENT on a NULL pointer, an empty cloud, ransac_n < 3 or a bad threshold,
 *   iteration count or probability; O3D_ERROR_NOT_CONVERGED when every RANSAC sample was degenerate (collinear points);
 *   O3D_ERROR_BUFFER_TOO_SMALL when `capacity` is short (the count is still reported).
 */
O3D_API o3d_status o3d_pointcloud_segment_plane(double out_plane[4], int32_t* out_indices, size_t capacity,
                                                size_t* out_n, const o3d_pointcloud_t* pc, double distance_threshold,
                                                int32_t ransac_n, int32_t num_iterations, double probability,
                                                uint64_t seed);
/**
 * @brief DBSCAN: one label per point in `out_labels` (capacity values): clusters 0, 1, ... in order of
 * their lowest point index, -1 for noise. `*out_n` gets the point count. @see cluster_dbscan
 *
 * Threads: any thread; concurrent calls on the same handles are safe (all read-only).
 * @param out_labels receives one label per point (`capacity` int32; NULL: only report the count)
 * @param capacity how many items the output buffer holds (ignored when it is NULL)
 * @param out_n receives the item count (always, also when the buffer is NULL or too small)
 * @param pc the point cloud
 * @param eps the distance threshold (>= 0)
 * @param min_points minimum neighbours of a core point
 * @return O3D_OK, or O3D_ERROR_INVALID_ARGUMENT on a NULL pointer; O3D_ERROR_BUFFER_TOO_SMALL when `capacity` is
 *   short (the count is still reported).
 */
O3D_API o3d_status o3d_pointcloud_cluster_dbscan(int32_t* out_labels, size_t capacity, size_t* out_n,
                                                 const o3d_pointcloud_t* pc, double eps, int32_t min_points);
/**
 * @brief Mean (3) and covariance (row-major 3x3, divided by N) of the points. Empty cloud → error.
 *
 * Threads: any thread; concurrent calls on the same handles are safe (all read-only).
 * @param out_mean receives the mean
 * @param out_covariance receives the row-major 3x3 covariance
 * @param pc the point cloud
 * @return O3D_OK, or O3D_ERROR_INVALID_ARGUMENT on a NULL pointer.
 */
O3D_API o3d_status o3d_pointcloud_compute_mean_and_covariance(double out_mean[3], double out_covariance[9],
                                                              const o3d_pointcloud_t* pc);
/**
 * @brief Mahalanobis distance of each point to the cloud's distribution, into `out` (capacity doubles).
 *
 * Threads: any thread; concurrent calls on the same handles are safe (all read-only).
 * @param out caller buffer of `capacity` items (NULL: only report the count)
 * @param capacity how many items the output buffer holds (ignored when it is NULL)
 * @param out_n receives the item count (always, also when the buffer is NULL or too small)
 * @param pc the point cloud
 * @return O3D_OK, or O3D_ERROR_INVALID_ARGUMENT on a NULL pointer; O3D_ERROR_BUFFER_TOO_SMALL when `capacity` is
 *   short (the count is still reported).
 */
O3D_API o3d_status o3d_pointcloud_compute_mahalanobis_distance(double* out, size_t capacity, size_t* out_n,
                                                               const o3d_pointcloud_t* pc);

/* ---- Per-point covariances (o3d.geometry.PointCloud.covariances): N x 9, row-major 3x3 each ----
 * A cloud carries covariances only when their count equals the point count (has_covariances). As in
 * Open3D they follow the points through every operation that keeps a subset of the points
 * (select_by_index, crop_aabb / crop_obb, uniform/random/farthest down-sampling, outlier removal,
 * remove_non_finite_points), through append and clear, and rotate with transform/rotate (R C R^T);
 * voxel_down_sample, which averages points, drops them. */

/**
 * @brief Covariance of each point's neighbourhood (`param`: KNN, radius or hybrid; NULL: KNN 30 as
 * Open3D), divided by the neighbour count; fewer than 3 neighbours give the identity (Open3D).
 * @see PointCloud.estimate_covariances
 *
 * Threads: needs exclusive access to `pc`.
 * @param pc the point cloud
 * @param param the neighbourhood search (NULL: KNN 30)
 * @return O3D_OK, or O3D_ERROR_INVALID_ARGUMENT on a NULL pointer.
 */
O3D_API o3d_status o3d_pointcloud_estimate_covariances(o3d_pointcloud_t* pc, const o3d_search_param_t* param);

/* ---- Convex hull and hidden-point removal (Qhull) ---- */

/**
 * @brief Convex hull of the points (>= 4, not all coplanar unless joggle_inputs != 0, which makes Qhull
 * perturb the input ("QJ") so degenerate sets still give a hull). @see PointCloud.compute_convex_hull
 *
 * Threads: any thread; concurrent calls on the same handles are safe (all read-only).
 * Ownership: `*out_mesh` is the caller's, to free with o3d_trianglemesh_destroy(); left NULL on failure.
 * @param out_mesh receives the new handle (NULL on failure)
 * @param out_point_indices receives the indices of the hull vertices in the input (`capacity` values; NULL skips
 *   them)
 * @param capacity how many items the output buffer holds (ignored when it is NULL)
 * @param out_n receives the item count (always, also when the buffer is NULL or too small)
 * @param pc the point cloud
 * @param joggle_inputs non-zero lets Qhull perturb the input ("QJ") so degenerate sets still give a hull
 * @return O3D_OK, or O3D_ERROR_INVALID_ARGUMENT on a NULL pointer; O3D_ERROR_BUFFER_TOO_SMALL when `capacity` is
 *   short (the count is still reported).
 */
O3D_API o3d_status o3d_pointcloud_compute_convex_hull(o3d_trianglemesh_t** out_mesh, int32_t* out_point_indices,
                                                      size_t capacity, size_t* out_n, const o3d_pointcloud_t* pc,
                                                      int32_t joggle_inputs);
/**
 * @brief The points visible from `camera_location`: spherical flipping with radius `radius` (> 0,
 * Open3D's parameter: larger keeps more points) then the convex hull of the flipped points and the camera.
 * @see PointCloud.hidden_point_removal
 *
 * Threads: any thread; concurrent calls on the same handles are safe (all read-only).
 * Ownership: `*out_mesh` is the caller's, to free with o3d_trianglemesh_destroy(); left NULL on failure.
 * @param out_mesh receives the new handle (NULL on failure)
 * @param out_point_indices receives the indices of the hull vertices in the input (`capacity` values; NULL skips
 *   them)
 * @param capacity how many items the output buffer holds (ignored when it is NULL)
 * @param out_n receives the item count (always, also when the buffer is NULL or too small)
 * @param pc the point cloud
 * @param camera_location the camera position
 * @param radius the radius (> 0)
 * @return O3D_OK, or O3D_ERROR_INVALID_ARGUMENT on a NULL pointer; O3D_ERROR_BUFFER_TOO_SMALL when `capacity` is
 *   short (the count is still reported).
 */
O3D_API o3d_status o3d_pointcloud_hidden_point_removal(o3d_trianglemesh_t** out_mesh, int32_t* out_point_indices,
                                                       size_t capacity, size_t* out_n, const o3d_pointcloud_t* pc,
                                                       const double camera_location[3], double radius);

/* ---- Oriented bounding boxes ---- */

/**
 * @brief Oriented box of a cloud's points. @see PointCloud.get_oriented_bounding_box(robust)
 *
 * Threads: any thread; concurrent calls on the same handles are safe (all read-only).
 * @param out receives the result
 * @param pc the point cloud
 * @param robust non-zero joggles the input so degenerate (e.g. planar) point sets still give a box
 * @return O3D_OK, or O3D_ERROR_INVALID_ARGUMENT on a NULL pointer.
 */
O3D_API o3d_status o3d_pointcloud_get_oriented_bounding_box(o3d_obb_t* out, const o3d_pointcloud_t* pc, int32_t robust);
/**
 * @brief New cloud with the points inside `obb` (outside when invert != 0). @see PointCloud.crop
 *
 * Threads: any thread; concurrent calls on the same handles are safe (all read-only).
 * Ownership: `*out` is the caller's, to free with o3d_pointcloud_destroy(); left NULL on failure.
 * @param out receives the new handle (NULL on failure)
 * @param pc the point cloud
 * @param obb the oriented box
 * @param invert non-zero selects the complement
 * @return O3D_OK, or O3D_ERROR_INVALID_ARGUMENT on a NULL pointer.
 */
O3D_API o3d_status o3d_pointcloud_crop_obb(o3d_pointcloud_t** out, const o3d_pointcloud_t* pc, const o3d_obb_t* obb,
                                           int32_t invert);

/* ---- From depth and RGB-D images ---- */

/** PointCloud.create_from_depth_image keyword arguments. */
typedef struct o3d_depth_to_cloud_options {
    uint32_t struct_size;             /**< sizeof(o3d_depth_to_cloud_options_t) */
    double depth_scale;               /**< raw units per metre for uint16 depth; default 1000 */
    double depth_trunc;               /**< depths at or beyond this are dropped (metres); default 1000 */
    int32_t stride;                   /**< use every stride-th pixel in x and y; default 1 */
    o3d_bool project_valid_depth_only; /**< 0: invalid pixels give NaN points (organised cloud); default 1 */
} o3d_depth_to_cloud_options_t;

/**
 * @brief Fill defaults.
 *
 * Threads: any thread.
 * @param opts the struct to fill
 * @param struct_size sizeof the struct as the caller knows it (an older, smaller size is accepted)
 * @return O3D_OK, or O3D_ERROR_INVALID_ARGUMENT on a NULL pointer or a `struct_size` this library does not know.
 */
O3D_API o3d_status o3d_depth_to_cloud_options_init(o3d_depth_to_cloud_options_t* opts, uint32_t struct_size);

/**
 * @brief Back-project a depth image (uint16 raw or float32 metres; 1 channel) through `intrinsic`, then
 * to world coordinates with the inverse of `extrinsic` (row-major 4x4 world-to-camera; NULL: identity).
 * @see PointCloud.create_from_depth_image
 *
 * Threads: any thread; concurrent calls on the same handles are safe (all read-only).
 * Ownership: `*out` is the caller's, to free with o3d_pointcloud_destroy(); left NULL on failure.
 * @param out receives the new handle (NULL on failure)
 * @param depth the depth image
 * @param intrinsic the camera intrinsic
 * @param extrinsic row-major 4x4 world-to-camera matrix
 * @param opts options (NULL: the defaults of the matching `*_init`)
 * @return O3D_OK, or O3D_ERROR_INVALID_ARGUMENT on a NULL pointer or a bad `opts->struct_size`.
 */
O3D_API o3d_status o3d_pointcloud_create_from_depth_image(o3d_pointcloud_t** out, const o3d_image_t* depth,
                                                          const o3d_pinhole_intrinsic_t* intrinsic,
                                                          const double extrinsic[16],
                                                          const o3d_depth_to_cloud_options_t* opts);
/**
 * @brief As create_from_depth_image for an RGB-D image, with per-point colors.
 *
 * Threads: any thread; concurrent calls on the same handles are safe (all read-only).
 * Ownership: `*out` is the caller's, to free with o3d_pointcloud_destroy(); left NULL on failure.
 * @param out receives the new handle (NULL on failure)
 * @param rgbd the RGB-D image
 * @param intrinsic the camera intrinsic
 * @param extrinsic row-major 4x4 world-to-camera matrix
 * @param project_valid_depth_only non-zero drops pixels without valid depth; 0 keeps them as NaN points
 * @return O3D_OK, or O3D_ERROR_INVALID_ARGUMENT on a NULL pointer.
 */
O3D_API o3d_status o3d_pointcloud_create_from_rgbd_image(o3d_pointcloud_t** out, const o3d_rgbd_image_t* rgbd,
                                                         const o3d_pinhole_intrinsic_t* intrinsic,
                                                         const double extrinsic[16],
                                                         int32_t project_valid_depth_only);


/* ---- Normal orientation, duplicates and keypoints ---- */

/**
 * @brief Orient the normals consistently (Hoppe et al. 1992): a Riemannian graph of the points (the Euclidean
 * minimum spanning tree and the `k` nearest neighbours), weighted by how far neighbouring tangent planes disagree,
 * and a traversal of its minimum spanning tree that flips each normal to agree with its parent's.
 * @see PointCloud.orient_normals_consistent_tangent_plane
 *
 * Threads: needs exclusive access to `pc`.
 * @param pc the point cloud, with normals
 * @param k neighbours per point in the graph (>= 1)
 * @param lambda weight of the edge-direction penalty (Open3D 0.18's `lambda`; 0: Hoppe's weights only), finite, >= 0
 * @param cos_alpha_tol drops the graph edges i->j that leave p_i within this cosine of n_i
 *   (|n_i . (p_j - p_i)| / |p_j - p_i| > cos_alpha_tol; 1: keep all), finite
 * @return O3D_OK, or O3D_ERROR_INVALID_ARGUMENT on a NULL pointer, a cloud without normals, a non-finite point or
 *   an argument out of range.
 */
O3D_API o3d_status o3d_pointcloud_orient_normals_consistent_tangent_plane(o3d_pointcloud_t* pc, o3d_count k,
                                                                         double lambda, double cos_alpha_tol);
/**
 * @brief Remove points equal to an earlier point (coordinate for coordinate); their normals, colors and
 * covariances go with them. @see PointCloud.remove_duplicated_points
 *
 * Threads: needs exclusive access to `pc`.
 * @param pc the point cloud
 * @return O3D_OK, or O3D_ERROR_INVALID_ARGUMENT on a NULL pointer.
 */
O3D_API o3d_status o3d_pointcloud_remove_duplicated_points(o3d_pointcloud_t* pc);

/** o3d.geometry.keypoint.compute_iss_keypoints keyword arguments. */
typedef struct o3d_iss_options {
    uint32_t struct_size;  /**< sizeof(o3d_iss_options_t) */
    double salient_radius; /**< neighbourhood radius of the scatter matrix, >= 0; 0 (default): 6x the cloud resolution */
    double non_max_radius; /**< radius of the non-maximum suppression, >= 0; 0 (default): 4x the cloud resolution */
    double gamma_21;       /**< upper bound on lambda2 / lambda1, in (0, 1]; default 0.975 */
    double gamma_32;       /**< upper bound on lambda3 / lambda2, in (0, 1]; default 0.975 */
    o3d_count min_neighbors; /**< fewer neighbours than this: not a keypoint; default 5 */
    o3d_count num_threads; /**< 0 = library default; the result does not depend on it */
} o3d_iss_options_t;

/**
 * @brief Fill defaults (Open3D's).
 *
 * Threads: any thread.
 * @param opts the struct to fill
 * @param struct_size sizeof the struct as the caller knows it (an older, smaller size is accepted)
 * @return O3D_OK, or O3D_ERROR_INVALID_ARGUMENT on a NULL pointer or a `struct_size` this library does not know.
 */
O3D_API o3d_status o3d_iss_options_init(o3d_iss_options_t* opts, uint32_t struct_size);
/**
 * @brief Intrinsic Shape Signature keypoints (Zhong 2009): points whose neighbourhood scatter has three distinct
 * eigenvalues and the largest smallest eigenvalue within `non_max_radius`. @see keypoint.compute_iss_keypoints
 *
 * Threads: any thread; concurrent calls on the same handles are safe (all read-only).
 * Ownership: `*out` is the caller's, to free with o3d_pointcloud_destroy(); left NULL on failure.
 * @param out receives the new handle (NULL on failure): the keypoints, with their normals and colors
 * @param out_indices receives the keypoints' indices in `pc`, ascending (`capacity` values, at most the point
 *   count; NULL skips them)
 * @param capacity how many items the output buffer holds (ignored when it is NULL)
 * @param out_n receives the item count (always, also when the buffer is NULL or too small)
 * @param pc the point cloud
 * @param opts options (NULL: the defaults of the matching `*_init`)
 * @return O3D_OK, or O3D_ERROR_INVALID_ARGUMENT on a NULL pointer, a bad `opts->struct_size`, a non-finite point
 *   or an option out of range; O3D_ERROR_BUFFER_TOO_SMALL when `capacity` is short (the count is still reported;
 *   `*out` is left NULL).
 */
O3D_API o3d_status o3d_pointcloud_compute_iss_keypoints(o3d_pointcloud_t** out, int32_t* out_indices,
                                                        size_t capacity, size_t* out_n, const o3d_pointcloud_t* pc,
                                                        const o3d_iss_options_t* opts);


/* ---- Smoothing (Open3D 0.20's PointCloud.smooth_*) ---- */

/**
 * @brief Moving-least-squares-style smoothing: each point is projected onto the weighted PCA plane of its
 * neighbourhood (itself included; weights exp(-d^2 / r^2) for a radius or hybrid search, uniform for KNN); a point
 * with fewer than 3 neighbours is kept. Normals, when present, become the planes' normals, consistently oriented;
 * colors are kept. @see PointCloud.smooth_mls
 *
 * Threads: any thread; concurrent calls on the same handles are safe (all read-only).
 * Ownership: `*out` is the caller's, to free with o3d_pointcloud_destroy(); left NULL on failure.
 * @param out receives the new handle (NULL on failure)
 * @param pc the point cloud
 * @param param the neighbourhood search (NULL: Open3D's default, hybrid with radius 0.05 and 30 neighbours)
 * @return O3D_OK, or O3D_ERROR_INVALID_ARGUMENT on a NULL pointer, a bad search parameter or a non-finite point.
 */
O3D_API o3d_status o3d_pointcloud_smooth_mls(o3d_pointcloud_t** out, const o3d_pointcloud_t* pc,
                                             const o3d_search_param_t* param);
/**
 * @brief Graph-Laplacian smoothing: `iterations` times, x_i += lambda * (mean of its `knn` nearest other points
 * - x_i), every point from the previous iteration; the kNN graph is rebuilt each time unless
 * `use_fixed_neighborhoods`. Normals and colors are kept. @see PointCloud.smooth_laplacian
 *
 * Threads: any thread; concurrent calls on the same handles are safe (all read-only).
 * Ownership: `*out` is the caller's, to free with o3d_pointcloud_destroy(); left NULL on failure.
 * @param out receives the new handle (NULL on failure)
 * @param pc the point cloud
 * @param iterations number of iterations (0 returns a copy)
 * @param lambda the step (finite)
 * @param knn neighbours per point (>= 1)
 * @param use_fixed_neighborhoods build the kNN graph once, from the input
 * @return O3D_OK, or O3D_ERROR_INVALID_ARGUMENT on a NULL pointer, a negative count, knn 0, a non-finite lambda or point.
 */
O3D_API o3d_status o3d_pointcloud_smooth_laplacian(o3d_pointcloud_t** out, const o3d_pointcloud_t* pc,
                                                   o3d_count iterations, double lambda, o3d_count knn,
                                                   o3d_bool use_fixed_neighborhoods);
/**
 * @brief Taubin smoothing: per iteration a Laplacian pass with `lambda`, then one with `mu` (negative: it undoes
 * the shrinking). Otherwise as o3d_pointcloud_smooth_laplacian. @see PointCloud.smooth_taubin
 *
 * Threads: any thread; concurrent calls on the same handles are safe (all read-only).
 * Ownership: `*out` is the caller's, to free with o3d_pointcloud_destroy(); left NULL on failure.
 * @param out receives the new handle (NULL on failure)
 * @param pc the point cloud
 * @param iterations number of iterations (0 returns a copy)
 * @param lambda the shrinking step (finite)
 * @param mu the inflating step (finite)
 * @param knn neighbours per point (>= 1)
 * @param use_fixed_neighborhoods build the kNN graph once, from the input
 * @return O3D_OK, or O3D_ERROR_INVALID_ARGUMENT on a NULL pointer, a negative count, knn 0, a non-finite lambda, mu or point.
 */
O3D_API o3d_status o3d_pointcloud_smooth_taubin(o3d_pointcloud_t** out, const o3d_pointcloud_t* pc,
                                                o3d_count iterations, double lambda, double mu, o3d_count knn,
                                                o3d_bool use_fixed_neighborhoods);
/**
 * @brief Bilateral smoothing (one pass): each point becomes the average of its neighbours weighted by
 * exp(-d^2 / 2 sigma_s^2) * exp(-((p_i - p_k) . n_i)^2 / 2 sigma_r^2), n_i its unit normal (estimated from 30
 * neighbours when the cloud has none, and then kept). @see PointCloud.smooth_bilateral
 *
 * Threads: any thread; concurrent calls on the same handles are safe (all read-only).
 * Ownership: `*out` is the caller's, to free with o3d_pointcloud_destroy(); left NULL on failure.
 * @param out receives the new handle (NULL on failure)
 * @param pc the point cloud
 * @param param the neighbourhood search (NULL: Open3D's default, hybrid with radius 0.05 and 30 neighbours)
 * @param sigma_s the spatial standard deviation (finite, > 0)
 * @param sigma_r the standard deviation along the normal (finite, > 0)
 * @return O3D_OK, or O3D_ERROR_INVALID_ARGUMENT on a NULL pointer, a bad search parameter or sigma, a non-finite
 *   point or normal.
 */
O3D_API o3d_status o3d_pointcloud_smooth_bilateral(o3d_pointcloud_t** out, const o3d_pointcloud_t* pc,
                                                   const o3d_search_param_t* param, double sigma_s, double sigma_r);

/* ---- Bounding volumes, covariances, planar patches, traced down-sampling ---- */

/**
 * @brief The minimum-volume oriented box of the points (o3d_obb_create_from_points_minimal).
 * @see PointCloud.get_minimal_oriented_bounding_box
 *
 * Threads: any thread; concurrent calls on the same handles are safe (all read-only).
 * @param out receives the box
 * @param pc the point cloud
 * @param robust joggles the input so degenerate (e.g. planar) point sets still give a box
 * @return O3D_OK, or O3D_ERROR_INVALID_ARGUMENT on a NULL pointer, fewer than 4 points, a non-finite point or a
 *   flat cloud without `robust`.
 */
O3D_API o3d_status o3d_pointcloud_get_minimal_oriented_bounding_box(o3d_obb_t* out, const o3d_pointcloud_t* pc,
                                                                    o3d_bool robust);
/**
 * @brief The minimum-volume enclosing ellipsoid of the points (o3d_obe_create_from_points).
 * @see PointCloud.get_oriented_bounding_ellipsoid
 *
 * Threads: any thread; concurrent calls on the same handles are safe (all read-only).
 * @param out receives the ellipsoid
 * @param pc the point cloud
 * @param robust joggles the hull's input
 * @return O3D_OK, or O3D_ERROR_INVALID_ARGUMENT on a NULL pointer, fewer than 4 points, a non-finite point or a
 *   flat cloud.
 */
O3D_API o3d_status o3d_pointcloud_get_oriented_bounding_ellipsoid(o3d_obe_t* out, const o3d_pointcloud_t* pc,
                                                                  o3d_bool robust);
/**
 * @brief Each point's neighbourhood covariance (divided by the count, the point itself included; fewer than 3
 * neighbours give the identity), without changing the cloud: Open3D's static
 * PointCloud.estimate_point_covariances. Written as N row-major 3x3 matrices (9 doubles each); capacity and
 * count are in matrices.
 *
 * Threads: any thread; concurrent calls on the same handles are safe (all read-only).
 * @param out caller buffer of `capacity` matrices of 9 doubles (NULL: only report the count)
 * @param capacity how many items the output buffer holds (ignored when it is NULL)
 * @param out_n receives the item count (always, also when the buffer is NULL or too small)
 * @param pc the point cloud
 * @param param the neighbourhood search (NULL: KNN 30)
 * @param num_threads threads to use: 0 = the library default (o3d_set_num_threads), negative is invalid
 * @return O3D_OK, or O3D_ERROR_INVALID_ARGUMENT on a NULL `pc` or `out_n`, a bad search parameter, a non-finite
 *   point or a negative `num_threads`; O3D_ERROR_BUFFER_TOO_SMALL when `capacity` is short (the count is still
 *   reported).
 */
O3D_API o3d_status o3d_pointcloud_estimate_point_covariances(double* out, size_t capacity, size_t* out_n,
                                                             const o3d_pointcloud_t* pc,
                                                             const o3d_search_param_t* param, int32_t num_threads);

/** Options of o3d_pointcloud_detect_planar_patches (Open3D's keywords and defaults). */
typedef struct o3d_planar_patch_options {
    uint32_t struct_size;                /**< sizeof(o3d_planar_patch_options_t), set by the init */
    double normal_variance_threshold_deg; /**< largest spread of the normals in a patch, in (0, 90]; default 60 */
    double coplanarity_deg;              /**< flatness: a larger angle asks a flatter patch, in (0, 90]; default 75 */
    double outlier_ratio;                /**< largest share of outliers in a patch, in [0, 1); default 0.75 */
    double min_plane_edge_length;        /**< shortest long edge kept (0: 1% of the cloud's largest extent); default 0 */
    o3d_count min_num_points;            /**< fewest points in a patch (0: max(10, N / 1000)); default 0 */
    o3d_search_param_t search_param;     /**< the neighbourhood that grows patches; default KNN 30 */
    int32_t num_threads;                 /**< 0 = the library default; default 0 */
} o3d_planar_patch_options_t;

/**
 * @brief Fill Open3D's defaults.
 *
 * Threads: any thread.
 * @param opts the struct to fill
 * @param struct_size sizeof the struct as the caller knows it (an older, smaller size is accepted)
 * @return O3D_OK, or O3D_ERROR_INVALID_ARGUMENT on a NULL pointer or a `struct_size` this library does not know.
 */
O3D_API o3d_status o3d_planar_patch_options_init(o3d_planar_patch_options_t* opts, uint32_t struct_size);
/**
 * @brief Planar patches (Araujo & Oliveira 2020, Open3D's detect_planar_patches): an octree split by a
 * robust-statistics planarity test, then patches grown and merged; one oriented box per patch (column 2 of R the
 * patch normal), largest patch first. The cloud needs normals. Each box is written as 15 doubles in
 * o3d_obb_t's field order (center, R row-major, extent), so a buffer of o3d_obb_t can receive them; capacity and
 * count are in boxes.
 * @see PointCloud.detect_planar_patches
 *
 * Threads: any thread; concurrent calls on the same handles are safe (all read-only).
 * @param out caller buffer of `capacity` boxes of 15 doubles (NULL: only report the count)
 * @param capacity how many items the output buffer holds (ignored when it is NULL)
 * @param out_n receives the item count (always, also when the buffer is NULL or too small)
 * @param pc the point cloud (with normals)
 * @param opts options (NULL: the defaults of the matching `*_init`)
 * @return O3D_OK, or O3D_ERROR_INVALID_ARGUMENT on a NULL `pc` or `out_n`, a bad `opts->struct_size`, an empty
 *   cloud or one without normals, a non-finite point or normal, or an option out of range;
 *   O3D_ERROR_BUFFER_TOO_SMALL when `capacity` is short (the count is still reported).
 */
O3D_API o3d_status o3d_pointcloud_detect_planar_patches(double* out, size_t capacity, size_t* out_n,
                                                        const o3d_pointcloud_t* pc,
                                                        const o3d_planar_patch_options_t* opts);
/**
 * @brief Voxel down-sampling that remembers where each output point came from (Open3D's
 * voxel_down_sample_and_trace). Voxel (i, j, k) spans min_bound + voxel_size * [i, i+1) x ...; each occupied
 * voxel gives the mean point (normals and colors averaged; with `approximate_class`, the color becomes (c, c, c)
 * with c the most frequent integer part of the red channel). Output points come sorted by voxel (z, y, x).
 * `out_cubic_ids` gets 8 values per output point, one per octant of its voxel (bit 0, 1, 2 set when the point is
 * in the upper half along x, y, z): the largest input index in that octant, or -1. `out_original_indices` gets,
 * per output point, the input indices it averages, ascending. Points outside the bounds are kept.
 *
 * Threads: any thread; concurrent calls on the same handles are safe (all read-only).
 * Ownership: the three handles are the caller's (o3d_pointcloud_destroy, o3d_index_lists_destroy); all left NULL
 * on failure.
 * @param out receives the new handle (NULL on failure)
 * @param out_cubic_ids receives one list of 8 indices per output point (NULL on failure)
 * @param out_original_indices receives one list of input indices per output point (NULL on failure)
 * @param pc the point cloud
 * @param voxel_size the voxel edge (finite, > 0)
 * @param min_bound the grid's origin
 * @param max_bound the grid's far corner (>= min_bound)
 * @param approximate_class whether colors are classes (see above) instead of averages
 * @return O3D_OK, or O3D_ERROR_INVALID_ARGUMENT on a NULL pointer, a bad voxel size or bounds, a non-finite point
 *   or a voxel index beyond int32.
 */
O3D_API o3d_status o3d_pointcloud_voxel_down_sample_and_trace(o3d_pointcloud_t** out,
                                                              o3d_index_lists_t** out_cubic_ids,
                                                              o3d_index_lists_t** out_original_indices,
                                                              const o3d_pointcloud_t* pc, double voxel_size,
                                                              const double min_bound[3], const double max_bound[3],
                                                              o3d_bool approximate_class);


O3D_END_DECL

#endif /* O3D_POINTCLOUD_H */
