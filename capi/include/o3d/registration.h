/* SPDX-License-Identifier: MIT */
/**
 * @file registration.h
 * @brief ICP (point-to-point with optional scaling, point-to-plane), evaluation, information matrix.
 *
 * Mirrors o3d.pipelines.registration. Transformations are row-major 4x4 (16 doubles).
 * Sums are reduced in a fixed order, so results do not depend on the thread count.
 */
#ifndef O3D_REGISTRATION_H
#define O3D_REGISTRATION_H

#include "o3d/common.h"
#include "o3d/pointcloud.h"

O3D_BEGIN_DECL

/** Transformation estimation methods. */
#define O3D_ESTIMATION_POINT_TO_POINT 0 /**< TransformationEstimationPointToPoint */
#define O3D_ESTIMATION_POINT_TO_PLANE 1 /**< TransformationEstimationPointToPlane (target needs normals) */

/** ICP options: estimation method and ICPConvergenceCriteria. */
typedef struct o3d_icp_options {
    uint32_t struct_size;        /**< sizeof(o3d_icp_options_t) */
    int32_t estimation;          /**< O3D_ESTIMATION_*; default POINT_TO_POINT */
    int32_t with_scaling;        /**< point-to-point only (ignored for point-to-plane): also estimate a scale; default 0 */
    double relative_fitness;     /**< >= 0; stop when fitness changes less than this; default 1e-6 */
    double relative_rmse;        /**< >= 0; stop when inlier RMSE changes less than this; default 1e-6 */
    int32_t max_iteration;       /**< >= 0; default 30 */
    int32_t num_threads;         /**< >= 0; 0 = library default */
    o3d_progress_callback progress; /**< called after each iteration with (iteration+1)/max_iteration; may be NULL */
    void* user_data;             /**< passed to `progress` */
} o3d_icp_options_t;

/** @brief Fill defaults (Open3D's). */
O3D_API o3d_status o3d_icp_options_init(o3d_icp_options_t* opts, uint32_t struct_size);

/** Result of a registration: transformation, fitness, inlier_rmse, correspondence_set. */
typedef struct o3d_registration_result o3d_registration_result_t;

/**
 * @brief Iterative closest point from `source` onto `target`, starting at `init` (NULL: identity).
 * Pairs farther apart than `max_correspondence_distance` are ignored.
 * @see o3d.pipelines.registration.registration_icp
 * **Ownership:** `*out` belongs to the caller (o3d_registration_result_destroy).
 */
O3D_API o3d_status o3d_register_icp(o3d_registration_result_t** out, const o3d_pointcloud_t* source,
                                    const o3d_pointcloud_t* target, double max_correspondence_distance,
                                    const double init[16], const o3d_icp_options_t* opts);
/** @brief Fitness, inlier RMSE and correspondences of `source` moved by `transformation` (NULL: identity). */
O3D_API o3d_status o3d_evaluate_registration(o3d_registration_result_t** out, const o3d_pointcloud_t* source,
                                             const o3d_pointcloud_t* target, double max_correspondence_distance,
                                             const double transformation[16]);
/** @brief The 6x6 information matrix (row-major, 36 doubles) of the correspondences under `transformation`. */
O3D_API o3d_status o3d_get_information_matrix_from_point_clouds(const o3d_pointcloud_t* source,
                                                                const o3d_pointcloud_t* target,
                                                                double max_correspondence_distance,
                                                                const double transformation[16], double out[36]);

/** @brief Destroy. NULL is a no-op. */
O3D_API void o3d_registration_result_destroy(o3d_registration_result_t* result);
/** @brief Row-major 4x4 transformation. */
O3D_API o3d_status o3d_registration_result_get_transformation(const o3d_registration_result_t* result,
                                                              double out[16]);
/** @brief Inlier count / number of source points. */
O3D_API o3d_status o3d_registration_result_get_fitness(const o3d_registration_result_t* result, double* out);
/** @brief RMS distance of the inlier pairs. */
O3D_API o3d_status o3d_registration_result_get_inlier_rmse(const o3d_registration_result_t* result, double* out);
/**
 * @brief Copy the correspondences as (source index, target index) pairs: `out` holds `capacity` pairs
 * (2 * capacity int32). `*out_n` always gets the pair count.
 */
O3D_API o3d_status o3d_registration_result_get_correspondence_set(const o3d_registration_result_t* result,
                                                                  int32_t* out, size_t capacity, size_t* out_n);

O3D_END_DECL

#endif /* O3D_REGISTRATION_H */
