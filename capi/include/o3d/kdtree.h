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
#include "o3d/pointcloud.h"

O3D_BEGIN_DECL

typedef struct o3d_kdtree o3d_kdtree_t;
/** Flat result of a batch search: for query i, neighbours offsets[i] .. offsets[i+1]-1. */
typedef struct o3d_search_result o3d_search_result_t;

/** @brief Build a tree over the points of `pc` (copied). An empty cloud gives an empty tree. */
O3D_API o3d_status o3d_kdtree_create_from_pointcloud(o3d_kdtree_t** out, const o3d_pointcloud_t* pc);
/** @brief Build a tree over `n` rows of `xyz` (copied). Non-finite coordinates → error. */
O3D_API o3d_status o3d_kdtree_create_from_points(o3d_kdtree_t** out, const double* xyz, size_t n);
/** @brief Destroy. NULL is a no-op. */
O3D_API void o3d_kdtree_destroy(o3d_kdtree_t* tree);
/** @brief Number of indexed points. */
O3D_API o3d_status o3d_kdtree_size(const o3d_kdtree_t* tree, size_t* out_n);

/**
 * @brief Search `num_queries` rows of `queries` with `param` (KNN, RADIUS or HYBRID), in parallel.
 * Neighbours of each query come sorted by increasing distance. num_threads 0 = default; the result
 * does not depend on it. **Ownership:** `*out` belongs to the caller (o3d_search_result_destroy).
 */
O3D_API o3d_status o3d_kdtree_search(const o3d_kdtree_t* tree, const double* queries, size_t num_queries,
                                     const o3d_search_param_t* param, int32_t num_threads,
                                     o3d_search_result_t** out);
/** @brief As o3d_kdtree_search with float32 queries. */
O3D_API o3d_status o3d_kdtree_search_f32(const o3d_kdtree_t* tree, const float* queries, size_t num_queries,
                                         const o3d_search_param_t* param, int32_t num_threads,
                                         o3d_search_result_t** out);

/** @brief Destroy. NULL is a no-op. */
O3D_API void o3d_search_result_destroy(o3d_search_result_t* result);
/** @brief Number of queries, and total number of neighbours over all queries. */
O3D_API o3d_status o3d_search_result_counts(const o3d_search_result_t* result, size_t* out_num_queries,
                                            size_t* out_total);
/**
 * @brief Borrowed views: `offsets` (num_queries + 1 values), `indices` and `distances2` (total values,
 * squared distances). **Ownership:** valid until o3d_search_result_destroy.
 */
O3D_API o3d_status o3d_search_result_view(const o3d_search_result_t* result, const int64_t** out_offsets,
                                          const int32_t** out_indices, const double** out_distances2);
/** @brief Copy the offsets (num_queries + 1 values) into `out`. */
O3D_API o3d_status o3d_search_result_get_offsets(const o3d_search_result_t* result, int64_t* out,
                                                 size_t capacity);
/** @brief Copy the neighbour indices (total values) into `out`. */
O3D_API o3d_status o3d_search_result_get_indices(const o3d_search_result_t* result, int32_t* out,
                                                 size_t capacity);
/** @brief Copy the squared distances (total values) into `out`. */
O3D_API o3d_status o3d_search_result_get_distances2(const o3d_search_result_t* result, double* out,
                                                    size_t capacity);

O3D_END_DECL

#endif /* O3D_KDTREE_H */
