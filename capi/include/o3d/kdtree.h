/* SPDX-License-Identifier: MIT */
/**
 * @file kdtree.h
 * @brief KD-tree over 3-D points (FLANN), with one-call batch knn / radius / hybrid queries.
 *
 * Mirrors o3d.geometry.KDTreeFlann. A tree copies the points it indexes, so it stays valid after
 * the cloud it was built from is changed or destroyed (handles may be destroyed in any order).
 *
 * **Thread safety:** searches take a const tree and may run concurrently.
 */
#ifndef O3D_KDTREE_H
#define O3D_KDTREE_H

#include "o3d/common.h"
#include "o3d/types.h"

O3D_BEGIN_DECL

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


/** @brief Build a tree over the points of `pc` (copied). An empty cloud gives an empty tree. */
O3D_API o3d_status o3d_kdtree_create_from_pointcloud(o3d_kdtree_t** out, const o3d_pointcloud_t* pc);
/** @brief Build a tree over `n` rows of `xyz` (copied). Non-finite coordinates → error. */
O3D_API o3d_status o3d_kdtree_create_from_points(o3d_kdtree_t** out, const double* xyz, size_t n);
/** @brief Destroy. NULL is a no-op. */
O3D_API void o3d_kdtree_destroy(o3d_kdtree_t* tree);
/** @brief Number of indexed points. */
O3D_API o3d_status o3d_kdtree_size(size_t* out_n, const o3d_kdtree_t* tree);

/**
 * @brief Search `num_queries` rows of `queries` with `param` (KNN, RADIUS or HYBRID), in parallel.
 * Neighbours of each query come sorted by increasing distance. num_threads 0 = default; the result
 * does not depend on it. **Ownership:** `*out` belongs to the caller (o3d_search_result_destroy).
 */
O3D_API o3d_status o3d_kdtree_search(o3d_search_result_t** out, const o3d_kdtree_t* tree, const double* queries,
                                     size_t num_queries, const o3d_search_param_t* param, int32_t num_threads);
/** @brief As o3d_kdtree_search with float32 queries. */
O3D_API o3d_status o3d_kdtree_search_f32(o3d_search_result_t** out, const o3d_kdtree_t* tree, const float* queries,
                                         size_t num_queries, const o3d_search_param_t* param, int32_t num_threads);

/** @brief Destroy. NULL is a no-op. */
O3D_API void o3d_search_result_destroy(o3d_search_result_t* result);
/** @brief Number of queries, and total number of neighbours over all queries. */
O3D_API o3d_status o3d_search_result_counts(size_t* out_num_queries, size_t* out_total,
                                            const o3d_search_result_t* result);
/**
 * @brief Borrowed views: `offsets` (num_queries + 1 values), `indices` and `distances2` (total values,
 * squared distances). **Ownership:** valid until o3d_search_result_destroy.
 */
O3D_API o3d_status o3d_search_result_view(const int64_t** out_offsets, const int32_t** out_indices,
                                          const double** out_distances2, const o3d_search_result_t* result);
/**
 * @brief Copy the offsets (num_queries + 1 values) into `out`, which holds `capacity` values; `*out_n` always gets the count.
 * `out` NULL only reports it. @return O3D_ERROR_BUFFER_TOO_SMALL when capacity is short,
 * O3D_ERROR_INVALID_ARGUMENT on a NULL result or out_n.
 */
O3D_API o3d_status o3d_search_result_get_offsets(int64_t* out, size_t capacity, size_t* out_n,
                                                 const o3d_search_result_t* result);
/**
 * @brief Copy the neighbour indices (total values) into `out`, which holds `capacity` values; `*out_n` always gets the count.
 * `out` NULL only reports it. @return O3D_ERROR_BUFFER_TOO_SMALL when capacity is short,
 * O3D_ERROR_INVALID_ARGUMENT on a NULL result or out_n.
 */
O3D_API o3d_status o3d_search_result_get_indices(int32_t* out, size_t capacity, size_t* out_n,
                                                 const o3d_search_result_t* result);
/**
 * @brief Copy the squared distances (total values) into `out`, which holds `capacity` values; `*out_n` always gets the count.
 * `out` NULL only reports it. @return O3D_ERROR_BUFFER_TOO_SMALL when capacity is short,
 * O3D_ERROR_INVALID_ARGUMENT on a NULL result or out_n.
 */
O3D_API o3d_status o3d_search_result_get_distances2(double* out, size_t capacity, size_t* out_n,
                                                    const o3d_search_result_t* result);

/* ---- Trees of any dimension (over features or rows of doubles) ---- */

/**
 * @brief A KD-tree over the descriptors of `feature` (copied), of dimension o3d_feature_dimension.
 * @see o3d.geometry.KDTreeFlann(feature)
 */
O3D_API o3d_status o3d_kdtree_create_from_feature(o3d_kdtree_t** out, const o3d_feature_t* feature);
/** @brief A KD-tree over `n` points of `dimension` doubles each (row by row, copied). */
O3D_API o3d_status o3d_kdtree_create_from_points_xd(o3d_kdtree_t** out, const double* data, size_t dimension,
                                                    size_t n);
/** @brief Dimension of the indexed points (3 for trees over clouds). */
O3D_API o3d_status o3d_kdtree_dimension(size_t* out, const o3d_kdtree_t* tree);
/**
 * @brief As o3d_kdtree_search for a tree of any dimension: `queries` holds `num_queries` rows of
 * `dimension` doubles, which must equal the tree's. @see KDTreeFlann.search_knn_vector_xd
 */
O3D_API o3d_status o3d_kdtree_search_xd(o3d_search_result_t** out, const o3d_kdtree_t* tree, const double* queries,
                                        size_t num_queries, size_t dimension, const o3d_search_param_t* param,
                                        int32_t num_threads);

O3D_END_DECL

#endif /* O3D_KDTREE_H */
