/* SPDX-License-Identifier: MIT */
/**
 * @file feature.h
 * @brief Per-point feature descriptors (FPFH), their files, KD-trees over them and feature matching.
 *
 * Mirrors o3d.pipelines.registration.Feature / compute_fpfh_feature / correspondences_from_features and
 * o3d.io.read_feature / write_feature. A feature holds `dimension` x `num` doubles stored column by
 * column, as Open3D's Eigen matrix: the descriptor of point i is the `dimension` doubles starting at
 * data + i * dimension.
 */
#ifndef O3D_FEATURE_H
#define O3D_FEATURE_H

#include "o3d/common.h"
#include "o3d/kdtree.h"
#include "o3d/pointcloud.h"

O3D_BEGIN_DECL

typedef struct o3d_feature o3d_feature_t;

/** @brief A `dimension` x `num` feature, all zeros. Both may be 0. */
O3D_API o3d_status o3d_feature_create(o3d_feature_t** out, size_t dimension, size_t num);
/**
 * @brief A feature holding a copy of `dimension * num` doubles (descriptor i at data + i * dimension).
 * Non-finite values are an error.
 */
O3D_API o3d_status o3d_feature_create_from_data(o3d_feature_t** out, const double* data, size_t dimension,
                                                size_t num);
/** @brief Destroy. NULL is a no-op. */
O3D_API void o3d_feature_destroy(o3d_feature_t* feature);
/** @brief Deep copy. */
O3D_API o3d_status o3d_feature_clone(o3d_feature_t** out, const o3d_feature_t* feature);
/** @brief Descriptor length (33 for FPFH). */
O3D_API o3d_status o3d_feature_dimension(const o3d_feature_t* feature, size_t* out);
/** @brief Number of descriptors (points). */
O3D_API o3d_status o3d_feature_num(const o3d_feature_t* feature, size_t* out);
/** @brief Resize to `dimension` x `num`; Open3D's Feature.resize. Kept values stay where they were
 *  when `dimension` is unchanged; new values are zero. */
O3D_API o3d_status o3d_feature_resize(o3d_feature_t* feature, size_t dimension, size_t num);
/**
 * @brief Borrowed, writable view of the `dimension * num` doubles (NULL when empty).
 * **Ownership:** valid until the feature is resized or destroyed.
 */
O3D_API o3d_status o3d_feature_data(o3d_feature_t* feature, double** out_data);
/** @brief Copy the `dimension * num` doubles into `out` (capacity doubles). */
O3D_API o3d_status o3d_feature_get_data(const o3d_feature_t* feature, double* out, size_t capacity);
/**
 * @brief The descriptors of points `indices` (in that order), or of every other point when invert != 0
 * (ascending). An index out of range is an error.
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
 */
O3D_API o3d_status o3d_correspondences_from_features(const o3d_feature_t* source, const o3d_feature_t* target,
                                                     int32_t mutual_filter, double mutual_consistency_ratio,
                                                     int32_t num_threads, int32_t* out, size_t capacity,
                                                     size_t* out_n);

/**
 * @brief Read a feature file in Open3D's binary layout: int32 dimension, int32 num, then num x dimension
 * float64 (descriptor by descriptor). Truncated or inconsistent files → O3D_ERROR_PARSE.
 */
O3D_API o3d_status o3d_io_read_feature(o3d_feature_t** out, const char* path);
/** @brief Write `feature` in the layout o3d_io_read_feature reads. */
O3D_API o3d_status o3d_io_write_feature(const char* path, const o3d_feature_t* feature);

/**
 * @brief A KD-tree over the descriptors of `feature` (copied), of dimension o3d_feature_dimension.
 * @see o3d.geometry.KDTreeFlann(feature)
 */
O3D_API o3d_status o3d_kdtree_create_from_feature(o3d_kdtree_t** out, const o3d_feature_t* feature);
/** @brief A KD-tree over `n` points of `dimension` doubles each (row by row, copied). */
O3D_API o3d_status o3d_kdtree_create_from_points_xd(o3d_kdtree_t** out, const double* data, size_t dimension,
                                                    size_t n);
/** @brief Dimension of the indexed points (3 for trees over clouds). */
O3D_API o3d_status o3d_kdtree_dimension(const o3d_kdtree_t* tree, size_t* out);
/**
 * @brief As o3d_kdtree_search for a tree of any dimension: `queries` holds `num_queries` rows of
 * `dimension` doubles, which must equal the tree's. @see KDTreeFlann.search_knn_vector_xd
 */
O3D_API o3d_status o3d_kdtree_search_xd(const o3d_kdtree_t* tree, const double* queries, size_t num_queries,
                                        size_t dimension, const o3d_search_param_t* param, int32_t num_threads,
                                        o3d_search_result_t** out);

O3D_END_DECL

#endif /* O3D_FEATURE_H */
