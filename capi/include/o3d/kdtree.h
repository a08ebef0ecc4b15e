/* SPDX-License-Identifier: MIT */
/**
 * @file kdtree.h
 * @brief KD-tree over 3-D points (FLANN), with one-call batch knn / radius / hybrid queries.
 *
 * Mirrors o3d.geometry.KDTreeFlann. A tree copies the points it indexes, so it stays valid after
 * the cloud it was built from is changed or destroyed (handles may be destroyed in any order).
 *
 * **Thread safety:** searches take a const tree and may run concurrently.
 *
 * **Out of memory:** any function here that allocates may also return O3D_ERROR_OUT_OF_MEMORY; the
 * per-function `@return` lists do not repeat it.
 */
#ifndef O3D_KDTREE_H
#define O3D_KDTREE_H

#include "o3d/common.h"
#include "o3d/types.h"

O3D_BEGIN_DECL

/** Kinds of neighbourhood search (o3d.geometry.KDTreeSearchParam*; O3D_SEARCH_*). */
typedef int32_t o3d_search_kind;
#define O3D_SEARCH_KNN 0    /**< the `knn` nearest points */
#define O3D_SEARCH_RADIUS 1 /**< all points within `radius` */
#define O3D_SEARCH_HYBRID 2 /**< at most `knn` nearest points within `radius` */

/** Neighbourhood search parameter (KDTreeSearchParamKNN / Radius / Hybrid). */
typedef struct o3d_search_param {
    uint32_t struct_size; /**< sizeof(o3d_search_param_t), set by o3d_search_param_init */
    o3d_search_kind kind; /**< O3D_SEARCH_KNN, O3D_SEARCH_RADIUS or O3D_SEARCH_HYBRID; default KNN */
    o3d_count knn;        /**< neighbour count for KNN / HYBRID; default 30 */
    double radius;        /**< radius for RADIUS / HYBRID [units of the cloud]; default 0 */
} o3d_search_param_t;

/**
 * @brief Fill defaults (KNN, 30). `struct_size` must be sizeof(o3d_search_param_t) or a smaller, older size.
 *
 * Threads: any thread.
 * @param param the struct to fill
 * @param struct_size sizeof the struct as the caller knows it (an older, smaller size is accepted)
 * @return O3D_OK, or O3D_ERROR_INVALID_ARGUMENT on a NULL pointer or a `struct_size` this library does not know.
 */
O3D_API o3d_status o3d_search_param_init(o3d_search_param_t* param, uint32_t struct_size);


/**
 * @brief Build a tree over the points of `pc` (copied). An empty cloud gives an empty tree.
 *
 * Threads: any thread; concurrent calls on the same handles are safe (all read-only).
 * Ownership: `*out` is the caller's, to free with o3d_kdtree_destroy(); left NULL on failure.
 * @param out receives the new handle (NULL on failure)
 * @param pc the point cloud
 * @return O3D_OK, or O3D_ERROR_INVALID_ARGUMENT on a NULL pointer.
 */
O3D_API o3d_status o3d_kdtree_create_from_pointcloud(o3d_kdtree_t** out, const o3d_pointcloud_t* pc);
/**
 * @brief Build a tree over `n` rows of `xyz` (copied). Non-finite coordinates → error.
 *
 * Threads: any thread.
 * Ownership: `*out` is the caller's, to free with o3d_kdtree_destroy(); left NULL on failure.
 * @param out receives the new handle (NULL on failure)
 * @param xyz points, row-major n x 3 (may be NULL when n == 0)
 * @param n number of points (rows of 3 doubles) in `xyz`
 * @return O3D_OK, or O3D_ERROR_INVALID_ARGUMENT on a NULL pointer or non-finite coordinates.
 */
O3D_API o3d_status o3d_kdtree_create_from_points(o3d_kdtree_t** out, const double* xyz, size_t n);
/**
 * @brief Destroy. NULL is a no-op.
 *
 * Threads: needs exclusive access to `tree`: no other call may use it during or after.
 * @param tree the handle to destroy (NULL is a no-op)
 */
O3D_API void o3d_kdtree_destroy(o3d_kdtree_t* tree);
/**
 * @brief Number of indexed points.
 *
 * Threads: any thread; concurrent calls on the same handles are safe (all read-only).
 * @param out_n receives the count
 * @param tree the KD-tree
 * @return O3D_OK, or O3D_ERROR_INVALID_ARGUMENT on a NULL pointer.
 */
O3D_API o3d_status o3d_kdtree_size(size_t* out_n, const o3d_kdtree_t* tree);

/**
 * @brief Search `num_queries` rows of `queries` with `param` (KNN, RADIUS or HYBRID), in parallel.
 * Neighbours of each query come sorted by increasing distance. num_threads 0 = default; the result
 * does not depend on it.
 *
 * Threads: any thread; concurrent calls on the same handles are safe (all read-only).
 * Ownership: `*out` is the caller's, to free with o3d_search_result_destroy(); left NULL on failure.
 * @param out receives the new handle (NULL on failure)
 * @param tree the KD-tree
 * @param queries `num_queries` query rows, row-major (may be NULL when num_queries == 0)
 * @param num_queries number of query rows
 * @param param the neighbourhood search (NULL: KNN 30)
 * @param num_threads threads to use: 0 = the library default (o3d_set_num_threads), negative is invalid
 * @return O3D_OK, or O3D_ERROR_INVALID_ARGUMENT on a NULL pointer, a negative `num_threads`, a bad `param` (kind, knn
 *   < 1, radius <= 0 or NaN) or non-finite query coordinates.
 */
O3D_API o3d_status o3d_kdtree_search(o3d_search_result_t** out, const o3d_kdtree_t* tree, const double* queries,
                                     size_t num_queries, const o3d_search_param_t* param, int32_t num_threads);
/**
 * @brief As o3d_kdtree_search with float32 queries.
 *
 * Threads: any thread; concurrent calls on the same handles are safe (all read-only).
 * Ownership: `*out` is the caller's, to free with o3d_search_result_destroy(); left NULL on failure.
 * @param out receives the new handle (NULL on failure)
 * @param tree the KD-tree
 * @param queries `num_queries` query rows, row-major (may be NULL when num_queries == 0)
 * @param num_queries number of query rows
 * @param param the neighbourhood search (NULL: KNN 30)
 * @param num_threads threads to use: 0 = the library default (o3d_set_num_threads), negative is invalid
 * @return O3D_OK, or O3D_ERROR_INVALID_ARGUMENT on a NULL pointer, a negative `num_threads`, a bad `param` (kind, knn
 *   < 1, radius <= 0 or NaN) or non-finite query coordinates.
 */
O3D_API o3d_status o3d_kdtree_search_f32(o3d_search_result_t** out, const o3d_kdtree_t* tree, const float* queries,
                                         size_t num_queries, const o3d_search_param_t* param, int32_t num_threads);

/**
 * @brief Destroy. NULL is a no-op.
 *
 * Threads: needs exclusive access to `result`: no other call may use it during or after.
 * @param result the handle to destroy (NULL is a no-op)
 */
O3D_API void o3d_search_result_destroy(o3d_search_result_t* result);
/**
 * @brief Number of queries, and total number of neighbours over all queries.
 *
 * Threads: any thread; concurrent calls on the same handles are safe (all read-only).
 * @param out_num_queries receives the number of queries (may be NULL)
 * @param out_total receives the total number of neighbours (may be NULL)
 * @param result the result
 * @return O3D_OK, or O3D_ERROR_INVALID_ARGUMENT on a NULL `result`.
 */
O3D_API o3d_status o3d_search_result_counts(size_t* out_num_queries, size_t* out_total,
                                            const o3d_search_result_t* result);
/**
 * @brief Borrowed views: `offsets` (num_queries + 1 values), `indices` and `distances2` (total values,
 * squared distances).
 *
 * Threads: any thread; concurrent calls on the same handles are safe (all read-only).
 * Ownership: the views point into `result` (never to be freed); valid until o3d_search_result_destroy (a result never
 * changes).
 * @param out_offsets receives a pointer to the first value (NULL when the array is empty)
 * @param out_indices receives the indices view (may be NULL)
 * @param out_distances2 receives a pointer to the first value (NULL when the array is empty)
 * @param result the result
 * @return O3D_OK, or O3D_ERROR_INVALID_ARGUMENT on a NULL pointer.
 */
O3D_API o3d_status o3d_search_result_view(const int64_t** out_offsets, const int32_t** out_indices,
                                          const double** out_distances2, const o3d_search_result_t* result);
/**
 * @brief Copy the offsets (num_queries + 1 values) into `out`, which holds `capacity` values; `*out_n` always gets
 * the count.
 * `out` NULL only reports it.
 *
 * Threads: any thread; concurrent calls on the same handles are safe (all read-only).
 * @param out caller buffer of `capacity` items (NULL: only report the count)
 * @param capacity how many items the output buffer holds (ignored when it is NULL)
 * @param out_n receives the item count (always, also when the buffer is NULL or too small)
 * @param result the result
 * @return O3D_OK, or O3D_ERROR_INVALID_ARGUMENT on a NULL pointer; O3D_ERROR_BUFFER_TOO_SMALL when `capacity` is
 *   short (the count is still reported).
 */
O3D_API o3d_status o3d_search_result_get_offsets(int64_t* out, size_t capacity, size_t* out_n,
                                                 const o3d_search_result_t* result);
/**
 * @brief Copy the neighbour indices (total values) into `out`, which holds `capacity` values; `*out_n` always gets
 * the count.
 * `out` NULL only reports it.
 *
 * Threads: any thread; concurrent calls on the same handles are safe (all read-only).
 * @param out caller buffer of `capacity` items (NULL: only report the count)
 * @param capacity how many items the output buffer holds (ignored when it is NULL)
 * @param out_n receives the item count (always, also when the buffer is NULL or too small)
 * @param result the result
 * @return O3D_OK, or O3D_ERROR_INVALID_ARGUMENT on a NULL pointer; O3D_ERROR_BUFFER_TOO_SMALL when `capacity` is
 *   short (the count is still reported).
 */
O3D_API o3d_status o3d_search_result_get_indices(int32_t* out, size_t capacity, size_t* out_n,
                                                 const o3d_search_result_t* result);
/**
 * @brief Copy the squared distances (total values) into `out`, which holds `capacity` values; `*out_n` always gets
 * the count.
 * `out` NULL only reports it.
 *
 * Threads: any thread; concurrent calls on the same handles are safe (all read-only).
 * @param out caller buffer of `capacity` items (NULL: only report the count)
 * @param capacity how many items the output buffer holds (ignored when it is NULL)
 * @param out_n receives the item count (always, also when the buffer is NULL or too small)
 * @param result the result
 * @return O3D_OK, or O3D_ERROR_INVALID_ARGUMENT on a NULL pointer; O3D_ERROR_BUFFER_TOO_SMALL when `capacity` is
 *   short (the count is still reported).
 */
O3D_API o3d_status o3d_search_result_get_distances2(double* out, size_t capacity, size_t* out_n,
                                                    const o3d_search_result_t* result);

/* ---- Trees of any dimension (over features or rows of doubles) ---- */

/**
 * @brief A KD-tree over the descriptors of `feature` (copied), of dimension o3d_feature_dimension.
 * @see o3d.geometry.KDTreeFlann(feature)
 *
 * Threads: any thread; concurrent calls on the same handles are safe (all read-only).
 * Ownership: `*out` is the caller's, to free with o3d_kdtree_destroy(); left NULL on failure.
 * @param out receives the new handle (NULL on failure)
 * @param feature the feature
 * @return O3D_OK, or O3D_ERROR_INVALID_ARGUMENT on a NULL pointer.
 */
O3D_API o3d_status o3d_kdtree_create_from_feature(o3d_kdtree_t** out, const o3d_feature_t* feature);
/**
 * @brief A KD-tree over `n` points of `dimension` doubles each (row by row, copied).
 *
 * Threads: any thread.
 * Ownership: `*out` is the caller's, to free with o3d_kdtree_destroy(); left NULL on failure.
 * @param out receives the new handle (NULL on failure)
 * @param data `n` rows of `dimension` doubles, copied
 * @param dimension values per descriptor (point)
 * @param n number of points
 * @return O3D_OK, or O3D_ERROR_INVALID_ARGUMENT on a NULL pointer or non-finite values.
 */
O3D_API o3d_status o3d_kdtree_create_from_points_xd(o3d_kdtree_t** out, const double* data, size_t dimension,
                                                    size_t n);
/**
 * @brief Dimension of the indexed points (3 for trees over clouds).
 *
 * Threads: any thread; concurrent calls on the same handles are safe (all read-only).
 * @param out receives the result
 * @param tree the KD-tree
 * @return O3D_OK, or O3D_ERROR_INVALID_ARGUMENT on a NULL pointer.
 */
O3D_API o3d_status o3d_kdtree_dimension(size_t* out, const o3d_kdtree_t* tree);
/**
 * @brief As o3d_kdtree_search for a tree of any dimension: `queries` holds `num_queries` rows of
 * `dimension` doubles, which must equal the tree's. @see KDTreeFlann.search_knn_vector_xd
 *
 * Threads: any thread; concurrent calls on the same handles are safe (all read-only).
 * Ownership: `*out` is the caller's, to free with o3d_search_result_destroy(); left NULL on failure.
 * @param out receives the new handle (NULL on failure)
 * @param tree the KD-tree
 * @param queries `num_queries` query rows, row-major (may be NULL when num_queries == 0)
 * @param num_queries number of query rows
 * @param dimension values per descriptor (point)
 * @param param the neighbourhood search (NULL: KNN 30)
 * @param num_threads threads to use: 0 = the library default (o3d_set_num_threads), negative is invalid
 * @return O3D_OK, or O3D_ERROR_INVALID_ARGUMENT on a NULL pointer, a negative `num_threads`, a bad `param` (kind, knn
 *   < 1, radius <= 0 or NaN), non-finite query coordinates or a `dimension` other than the tree's.
 */
O3D_API o3d_status o3d_kdtree_search_xd(o3d_search_result_t** out, const o3d_kdtree_t* tree, const double* queries,
                                        size_t num_queries, size_t dimension, const o3d_search_param_t* param,
                                        int32_t num_threads);

O3D_END_DECL

#endif /* O3D_KDTREE_H */
