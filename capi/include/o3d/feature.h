/* SPDX-License-Identifier: MIT */
/**
 * @file feature.h
 * @brief Per-point feature descriptors (FPFH), their files, KD-trees over them and feature matching.
 *
 * Mirrors o3d.pipelines.registration.Feature / compute_fpfh_feature / correspondences_from_features and
 * o3d.io.read_feature / write_feature. A feature holds `dimension` x `num` doubles stored column by
 * column, as Open3D's Eigen matrix: the descriptor of point i is the `dimension` doubles starting at
 * data + i * dimension.
 *
 * **Out of memory:** any function here that allocates may also return O3D_ERROR_OUT_OF_MEMORY; the
 * per-function `@return` lists do not repeat it.
 */
#ifndef O3D_FEATURE_H
#define O3D_FEATURE_H

#include "o3d/common.h"
#include "o3d/types.h"
#include "o3d/kdtree.h"

O3D_BEGIN_DECL


/**
 * @brief A `dimension` x `num` feature, all zeros. Both may be 0.
 *
 * Threads: any thread.
 * Ownership: `*out` is the caller's, to free with o3d_feature_destroy(); left NULL on failure.
 * @param out receives the new handle (NULL on failure)
 * @param dimension values per descriptor (point)
 * @param num number of descriptors (points)
 * @return O3D_OK, or O3D_ERROR_INVALID_ARGUMENT on a NULL pointer.
 */
O3D_API o3d_status o3d_feature_create(o3d_feature_t** out, size_t dimension, size_t num);
/**
 * @brief A feature holding a copy of `dimension * num` doubles (descriptor i at data + i * dimension).
 * Non-finite values are an error.
 *
 * Threads: any thread.
 * Ownership: `*out` is the caller's, to free with o3d_feature_destroy(); left NULL on failure.
 * @param out receives the new handle (NULL on failure)
 * @param data the input values, copied
 * @param dimension values per descriptor (point)
 * @param num number of descriptors (points)
 * @return O3D_OK, or O3D_ERROR_INVALID_ARGUMENT on a NULL pointer.
 */
O3D_API o3d_status o3d_feature_create_from_data(o3d_feature_t** out, const double* data, size_t dimension,
                                                size_t num);
/**
 * @brief Destroy. NULL is a no-op.
 *
 * Threads: needs exclusive access to `feature`: no other call may use it during or after.
 * @param feature the handle to destroy (NULL is a no-op)
 */
O3D_API void o3d_feature_destroy(o3d_feature_t* feature);
/**
 * @brief Deep copy.
 *
 * Threads: any thread; concurrent calls on the same handles are safe (all read-only).
 * Ownership: `*out` is the caller's, to free with o3d_feature_destroy(); left NULL on failure.
 * @param out receives the new handle (NULL on failure)
 * @param feature the feature
 * @return O3D_OK, or O3D_ERROR_INVALID_ARGUMENT on a NULL pointer.
 */
O3D_API o3d_status o3d_feature_clone(o3d_feature_t** out, const o3d_feature_t* feature);
/**
 * @brief Descriptor length (33 for FPFH).
 *
 * Threads: any thread; concurrent calls on the same handles are safe (all read-only).
 * @param out receives the result
 * @param feature the feature
 * @return O3D_OK, or O3D_ERROR_INVALID_ARGUMENT on a NULL pointer.
 */
O3D_API o3d_status o3d_feature_dimension(size_t* out, const o3d_feature_t* feature);
/**
 * @brief Number of descriptors (points).
 *
 * Threads: any thread; concurrent calls on the same handles are safe (all read-only).
 * @param out receives the result
 * @param feature the feature
 * @return O3D_OK, or O3D_ERROR_INVALID_ARGUMENT on a NULL pointer.
 */
O3D_API o3d_status o3d_feature_num(size_t* out, const o3d_feature_t* feature);
/**
 * @brief Resize to `dimension` x `num`; Open3D's Feature.resize. Kept values stay where they were
 * when `dimension` is unchanged; new values are zero.
 *
 * Threads: needs exclusive access to `feature`.
 * @param feature the feature
 * @param dimension values per descriptor (point)
 * @param num number of descriptors (points)
 * @return O3D_OK, or O3D_ERROR_INVALID_ARGUMENT on a NULL pointer.
 */
O3D_API o3d_status o3d_feature_resize(o3d_feature_t* feature, size_t dimension, size_t num);
/* ---- Arrays: the same functions for every geometry (docs/conventions.md, "Arrays") ----
 * `which` names the array; rows are counted in items (a point, a line, a descriptor), never in
 * values. Copy-outs take the caller's capacity in rows and always report the rows needed;
 * views are borrowed, valid until the next mutating call on the handle or its destruction. */
/** The arrays of a feature (O3D_FEATURE_*). */
typedef int32_t o3d_feature_array;
#define O3D_FEATURE_DATA 0 /**< num x dimension float64: row i is the descriptor of point i; set_array keeps the dimension */

/**
 * @brief Whether array `which` counts (Open3D's has_*: present and of the matching size).
 *
 * Threads: any thread; concurrent calls on the same handles are safe (all read-only).
 * @param out receives 1 (true) or 0 (false)
 * @param feature the feature
 * @param which the array: one of this header's `which` constants
 * @return O3D_OK, or O3D_ERROR_INVALID_ARGUMENT on a NULL pointer or an unknown `which`.
 */
O3D_API o3d_status o3d_feature_has_array(int32_t* out, const o3d_feature_t* feature, o3d_feature_array which);
/**
 * @brief Rows and columns (values per row) of array `which`: e.g. N x 3 for points, num x dimension for a
 * feature.
 *
 * Threads: any thread; concurrent calls on the same handles are safe (all read-only).
 * @param out_rows receives the rows (items)
 * @param out_cols receives the values per row
 * @param feature the feature
 * @param which the array: one of this header's `which` constants
 * @return O3D_OK, or O3D_ERROR_INVALID_ARGUMENT on a NULL pointer or an unknown `which`.
 */
O3D_API o3d_status o3d_feature_array_shape(size_t* out_rows, size_t* out_cols, const o3d_feature_t* feature, o3d_feature_array which);
/**
 * @brief Replace array `which` with `rows` rows of `data`, copied once (`data` may be NULL when rows == 0).
 *
 * Threads: needs exclusive access to `feature`.
 * @param feature the feature
 * @param which the array: one of this header's `which` constants
 * @param data `rows` rows of values, copied once (NULL allowed when rows == 0)
 * @param rows number of rows in `data`
 * @return O3D_OK, or O3D_ERROR_INVALID_ARGUMENT on a NULL handle, an unknown `which`, NULL `data` with rows > 0 or an
 *   unknown `which` (or one of the other type).
 */
O3D_API o3d_status o3d_feature_set_array(o3d_feature_t* feature, o3d_feature_array which, const double* data, size_t rows);
/**
 * @brief As o3d_feature_set_array from float32 values, converted in the one copy.
 *
 * Threads: needs exclusive access to `feature`.
 * @param feature the feature
 * @param which the array: one of this header's `which` constants
 * @param data `rows` rows of values, copied once (NULL allowed when rows == 0)
 * @param rows number of rows in `data`
 * @return O3D_OK, or O3D_ERROR_INVALID_ARGUMENT on a NULL handle, an unknown `which`, NULL `data` with rows > 0, an
 *   unknown `which` (or one of the other type) or an array that takes no float32.
 */
O3D_API o3d_status o3d_feature_set_array_f32(o3d_feature_t* feature, o3d_feature_array which, const float* data, size_t rows);
/**
 * @brief Copy array `which` into `out`, which holds `capacity` rows; `*out_rows` always gets the rows
 * needed. `out` NULL only reports them.
 *
 * Threads: any thread; concurrent calls on the same handles are safe (all read-only).
 * @param out caller buffer of `capacity` rows (NULL: only report the row count)
 * @param capacity rows `out` holds
 * @param out_rows receives the rows of the array (always, also when `out` is NULL or too small)
 * @param feature the feature
 * @param which the array: one of this header's `which` constants
 * @return O3D_OK, or O3D_ERROR_INVALID_ARGUMENT on a NULL handle or `out_rows` or an unknown `which`;
 *   O3D_ERROR_BUFFER_TOO_SMALL when `capacity` is short (the count is still reported).
 */
O3D_API o3d_status o3d_feature_get_array(double* out, size_t capacity, size_t* out_rows, const o3d_feature_t* feature,
                                         o3d_feature_array which);
/**
 * @brief Borrowed read-only view of array `which` (`*out_data` NULL when empty).
 *
 * Threads: any thread; concurrent calls on the same handles are safe (all read-only).
 * Ownership: `*out_data` points into `feature` (the library's memory, never to be freed): valid until the next
 * mutating call on `feature` or its destruction.
 * @param out_data receives the address of row 0 (NULL when the array is empty)
 * @param out_rows receives the row count
 * @param feature the feature
 * @param which the array: one of this header's `which` constants
 * @return O3D_OK, or O3D_ERROR_INVALID_ARGUMENT on a NULL handle, `out_data` or `out_rows` or an unknown `which`.
 */
O3D_API o3d_status o3d_feature_array_view(const double** out_data, size_t* out_rows, const o3d_feature_t* feature,
                                          o3d_feature_array which);
/**
 * @brief Borrowed writable view of array `which`: as o3d_feature_array_view; writing through it is a mutating call.
 *
 * Threads: needs exclusive access to `feature`, also while the view is written through.
 * Ownership: `*out_data` points into `feature` (the library's memory, never to be freed): valid until the next
 * mutating call on `feature` or its destruction.
 * @param out_data receives the address of row 0 (NULL when the array is empty)
 * @param out_rows receives the row count
 * @param feature the feature
 * @param which the array: one of this header's `which` constants
 * @return O3D_OK, or O3D_ERROR_INVALID_ARGUMENT on a NULL handle, `out_data` or `out_rows` or an unknown `which`.
 */
O3D_API o3d_status o3d_feature_array_mutable_view(double** out_data, size_t* out_rows, o3d_feature_t* feature,
                                                  o3d_feature_array which);

/**
 * @brief The descriptors of points `indices` (in that order), or of every other point when invert != 0
 * (ascending). An index out of range is an error.
 *
 * Threads: any thread; concurrent calls on the same handles are safe (all read-only).
 * Ownership: `*out` is the caller's, to free with o3d_feature_destroy(); left NULL on failure.
 * @param out receives the new handle (NULL on failure)
 * @param feature the feature
 * @param indices the indices
 * @param n number of points (rows of 3 doubles) in `xyz`
 * @param invert non-zero selects the complement
 * @return O3D_OK, or O3D_ERROR_INVALID_ARGUMENT on a NULL pointer.
 */
O3D_API o3d_status o3d_feature_select_by_index(o3d_feature_t** out, const o3d_feature_t* feature,
                                               const int64_t* indices, size_t n, int32_t invert);

/**
 * @brief Fast Point Feature Histograms (Rusu et al. 2009), 33 x N; the cloud needs normals.
 * `param` (NULL: KNN 30) selects each point's neighbourhood; Open3D's tutorial uses HYBRID radius 0.25,
 * max_nn 100 on a 0.05 voxel grid. With `indices` (n_indices > 0) only those points get a descriptor
 * (neighbourhoods still come from the whole cloud), as Open3D: each distinct index once, columns in
 * ascending index order; an index out of range is an error. num_threads 0 = default; the result does
 * not depend on it. Each 11-bin sub-histogram sums to 200 (Open3D 0.20 adds the point's own SPFH).
 * @see o3d.pipelines.registration.compute_fpfh_feature
 *
 * Threads: any thread; concurrent calls on the same handles are safe (all read-only).
 * Ownership: `*out` is the caller's, to free with o3d_feature_destroy(); left NULL on failure.
 * @param out receives the new handle (NULL on failure)
 * @param pc the point cloud
 * @param param the neighbourhood search (NULL: KNN 30)
 * @param indices the indices
 * @param n_indices number of `indices` (0: every point)
 * @param num_threads threads to use: 0 = the library default (o3d_set_num_threads), negative is invalid
 * @return O3D_OK, or O3D_ERROR_INVALID_ARGUMENT on a NULL pointer or a negative `num_threads`.
 */
O3D_API o3d_status o3d_compute_fpfh_feature(o3d_feature_t** out, const o3d_pointcloud_t* pc,
                                            const o3d_search_param_t* param, const int64_t* indices,
                                            size_t n_indices, int32_t num_threads);

/**
 * @brief For each source descriptor its nearest target descriptor (L2), as (source, target) pairs in
 * ascending source order. With mutual_filter != 0 only pairs that are also nearest the other way are
 * kept, unless fewer than `mutual_consistency_ratio` * num(source) survive, in which case all pairs are
 * returned (Open3D's rule). At most num(source) pairs: `out` holds `capacity` pairs (2 * capacity int32),
 * `*out_n` always gets the count. Dimensions must agree. num_threads 0 = default.
 * @see o3d.pipelines.registration.correspondences_from_features
 *
 * Threads: any thread; concurrent calls on the same handles are safe (all read-only).
 * @param out caller buffer of `capacity` items (NULL: only report the count)
 * @param capacity how many items the output buffer holds (ignored when it is NULL)
 * @param out_n receives the item count (always, also when the buffer is NULL or too small)
 * @param source the source cloud (moved onto `target`)
 * @param target the target cloud
 * @param mutual_filter non-zero keeps only mutual nearest pairs
 * @param mutual_consistency_ratio the share of mutual pairs below which all pairs are kept
 * @param num_threads threads to use: 0 = the library default (o3d_set_num_threads), negative is invalid
 * @return O3D_OK, or O3D_ERROR_INVALID_ARGUMENT on a NULL pointer or a negative `num_threads`;
 *   O3D_ERROR_BUFFER_TOO_SMALL when `capacity` is short (the count is still reported).
 */
O3D_API o3d_status o3d_correspondences_from_features(int32_t* out, size_t capacity, size_t* out_n,
                                                     const o3d_feature_t* source, const o3d_feature_t* target,
                                                     int32_t mutual_filter, double mutual_consistency_ratio,
                                                     int32_t num_threads);



O3D_END_DECL

#endif /* O3D_FEATURE_H */
