/* SPDX-License-Identifier: MIT */
/**
 * @file registration.h
 * @brief Local refinement (ICP: point-to-point, point-to-plane, colored, generalized, symmetric, with
 * robust kernels), global registration (RANSAC with correspondence checkers, Fast Global Registration),
 * evaluation and the information matrix.
 *
 * Mirrors o3d.pipelines.registration. Transformations are row-major 4x4 (16 doubles).
 * Sums are reduced in a fixed order, so results do not depend on the thread count; randomized calls
 * (RANSAC, FGR) give the same result for the same seed on any thread count.
 *
 * **Out of memory:** any function here that allocates may also return O3D_ERROR_OUT_OF_MEMORY; the
 * per-function `@return` lists do not repeat it.
 */
#ifndef O3D_REGISTRATION_H
#define O3D_REGISTRATION_H

#include "o3d/common.h"
#include "o3d/types.h"
#include "o3d/feature.h"
#include "o3d/pointcloud.h"

O3D_BEGIN_DECL

/** Transformation estimation methods (O3D_ESTIMATION_*). */
typedef int32_t o3d_estimation;
#define O3D_ESTIMATION_POINT_TO_POINT 0 /**< TransformationEstimationPointToPoint */
#define O3D_ESTIMATION_POINT_TO_PLANE 1 /**< TransformationEstimationPointToPlane (target needs normals) */
/** TransformationEstimationForColoredICP (Park et al. 2017): both clouds need colors, the target normals. */
#define O3D_ESTIMATION_COLORED 2
/** TransformationEstimationForGeneralizedICP (Segal et al. 2009): per-point covariances are taken from the
 *  clouds when present, else built from their normals, else estimated from 20 neighbours. */
#define O3D_ESTIMATION_GENERALIZED 3
/** TransformationEstimationSymmetric (Rusinkiewicz 2019, symmetric point-to-plane): both clouds need normals. */
#define O3D_ESTIMATION_SYMMETRIC 4

/** Robust kernels (M-estimators) weighting each residual r; k is the kernel's scale (O3D_KERNEL_*). */
typedef int32_t o3d_robust_kernel;
#define O3D_KERNEL_L2 0     /**< L2Loss: w = 1 */
#define O3D_KERNEL_L1 1     /**< L1Loss: w = 1 / |r| */
#define O3D_KERNEL_HUBER 2  /**< HuberLoss(k): w = 1 if |r| <= k else k / |r| */
#define O3D_KERNEL_CAUCHY 3 /**< CauchyLoss(k): w = 1 / (1 + (r / k)^2) */
#define O3D_KERNEL_GM 4     /**< GMLoss(k) (Geman-McClure): w = k / (k + r^2)^2 */
#define O3D_KERNEL_TUKEY 5  /**< TukeyLoss(k): w = (1 - (r / k)^2)^2 if |r| <= k else 0 */

/** ICP options: estimation method and ICPConvergenceCriteria. */
typedef struct o3d_icp_options {
    uint32_t struct_size;        /**< sizeof(o3d_icp_options_t) */
    o3d_estimation estimation;   /**< O3D_ESTIMATION_*; default POINT_TO_POINT */
    o3d_bool with_scaling;       /**< point-to-point only (ignored for point-to-plane): also estimate a scale; default 0 */
    double relative_fitness;     /**< >= 0; stop when fitness changes less than this; default 1e-6 */
    double relative_rmse;        /**< >= 0; stop when inlier RMSE changes less than this; default 1e-6 */
    o3d_count max_iteration;     /**< iteration limit; default 30 */
    o3d_count num_threads;       /**< 0 = library default */
    o3d_progress_callback progress; /**< called after each iteration with (iteration+1)/max_iteration; may be NULL */
    void* user_data;             /**< passed to `progress` */
    o3d_robust_kernel kernel;    /**< O3D_KERNEL_*, for point-to-plane, colored, generalized, symmetric; default L2 */
    double kernel_k;             /**< the kernel's k (> 0; unused by L2 and L1); default 1.0 */
    double lambda_geometric;     /**< colored ICP: weight of the geometric term, in [0, 1]; default 0.968 */
    double epsilon;              /**< generalized ICP: covariance regularisation (> 0); default 1e-3 */
} o3d_icp_options_t;

/**
 * @brief Fill defaults (Open3D's).
 *
 * Threads: any thread.
 * @param opts the struct to fill
 * @param struct_size sizeof the struct as the caller knows it (an older, smaller size is accepted)
 * @return O3D_OK, or O3D_ERROR_INVALID_ARGUMENT on a NULL pointer or a `struct_size` this library does not know;
 *   O3D_ERROR_CANCELLED when the progress callback returns non-zero.
 */
O3D_API o3d_status o3d_icp_options_init(o3d_icp_options_t* opts, uint32_t struct_size);

/**
 * @brief The weight the robust `kernel` (O3D_KERNEL_*) with scale `k` gives to `residual`. @see RobustKernel.weight
 *
 * Threads: any thread.
 * @param out receives the result
 * @param kernel O3D_KERNEL_*
 * @param k the kernel's scale
 * @param residual the residual r
 * @return O3D_OK, or O3D_ERROR_INVALID_ARGUMENT on a NULL pointer.
 */
O3D_API o3d_status o3d_robust_kernel_weight(double* out, o3d_robust_kernel kernel, double k, double residual);


/**
 * @brief Iterative closest point from `source` onto `target`, starting at `init` (NULL: identity), with
 * any estimation (opts.estimation). Pairs farther apart than `max_correspondence_distance` are ignored.
 * @see o3d.pipelines.registration.registration_icp, registration_colored_icp,
 * registration_generalized_icp, registration_symmetric_icp
 *
 * Threads: any thread; `source`, `target` and the features are only read; the progress callback runs on the calling
 * thread.
 * Ownership: `*out` is the caller's, to free with o3d_registration_result_destroy(); left NULL on failure.
 * @param out receives the new handle (NULL on failure)
 * @param source the source cloud (moved onto `target`)
 * @param target the target cloud
 * @param max_correspondence_distance pairs farther apart are ignored (> 0)
 * @param init row-major 4x4 initial transformation (NULL: identity)
 * @param opts options (NULL: the defaults of the matching `*_init`)
 * @return O3D_OK, or O3D_ERROR_INVALID_ARGUMENT on a NULL pointer or a bad `opts->struct_size`; O3D_ERROR_CANCELLED
 *   when the progress callback returns non-zero.
 */
O3D_API o3d_status o3d_register_icp(o3d_registration_result_t** out, const o3d_pointcloud_t* source,
                                    const o3d_pointcloud_t* target, double max_correspondence_distance,
                                    const double init[16], const o3d_icp_options_t* opts);
/**
 * @brief Fitness, inlier RMSE and correspondences of `source` moved by `transformation` (NULL: identity).
 *
 * Threads: any thread; concurrent calls on the same handles are safe (all read-only).
 * Ownership: `*out` is the caller's, to free with o3d_registration_result_destroy(); left NULL on failure.
 * @param out receives the new handle (NULL on failure)
 * @param source the source cloud (moved onto `target`)
 * @param target the target cloud
 * @param max_correspondence_distance pairs farther apart are ignored (> 0)
 * @param transformation row-major 4x4 transformation of the source (NULL: identity)
 * @return O3D_OK, or O3D_ERROR_INVALID_ARGUMENT on a NULL pointer.
 */
O3D_API o3d_status o3d_evaluate_registration(o3d_registration_result_t** out, const o3d_pointcloud_t* source,
                                             const o3d_pointcloud_t* target, double max_correspondence_distance,
                                             const double transformation[16]);
/**
 * @brief The 6x6 information matrix (row-major, 36 doubles) of the correspondences under `transformation`.
 *
 * Threads: any thread; concurrent calls on the same handles are safe (all read-only).
 * @param out receives the result
 * @param source the source cloud (moved onto `target`)
 * @param target the target cloud
 * @param max_correspondence_distance pairs farther apart are ignored (> 0)
 * @param transformation row-major 4x4 transformation of the source (NULL: identity)
 * @return O3D_OK, or O3D_ERROR_INVALID_ARGUMENT on a NULL pointer.
 */
O3D_API o3d_status o3d_get_information_matrix_from_point_clouds(double out[36], const o3d_pointcloud_t* source,
                                                                const o3d_pointcloud_t* target,
                                                                double max_correspondence_distance,
                                                                const double transformation[16]);

/**
 * @brief Destroy. NULL is a no-op.
 *
 * Threads: needs exclusive access to `result`: no other call may use it during or after.
 * @param result the handle to destroy (NULL is a no-op)
 */
O3D_API void o3d_registration_result_destroy(o3d_registration_result_t* result);
/**
 * @brief Row-major 4x4 transformation.
 *
 * Threads: any thread; concurrent calls on the same handles are safe (all read-only).
 * @param out receives the result
 * @param result the result
 * @return O3D_OK, or O3D_ERROR_INVALID_ARGUMENT on a NULL pointer.
 */
O3D_API o3d_status o3d_registration_result_get_transformation(double out[16], const o3d_registration_result_t* result);
/**
 * @brief Inlier count / number of source points.
 *
 * Threads: any thread; concurrent calls on the same handles are safe (all read-only).
 * @param out receives the result
 * @param result the result
 * @return O3D_OK, or O3D_ERROR_INVALID_ARGUMENT on a NULL pointer.
 */
O3D_API o3d_status o3d_registration_result_get_fitness(double* out, const o3d_registration_result_t* result);
/**
 * @brief RMS distance of the inlier pairs.
 *
 * Threads: any thread; concurrent calls on the same handles are safe (all read-only).
 * @param out receives the result
 * @param result the result
 * @return O3D_OK, or O3D_ERROR_INVALID_ARGUMENT on a NULL pointer.
 */
O3D_API o3d_status o3d_registration_result_get_inlier_rmse(double* out, const o3d_registration_result_t* result);
/**
 * @brief Copy the correspondences as (source index, target index) pairs: `out` holds `capacity` pairs
 * (2 * capacity int32). `*out_n` always gets the pair count.
 *
 * Threads: any thread; concurrent calls on the same handles are safe (all read-only).
 * @param out caller buffer of `capacity` items (NULL: only report the count)
 * @param capacity how many items the output buffer holds (ignored when it is NULL)
 * @param out_n receives the item count (always, also when the buffer is NULL or too small)
 * @param result the result
 * @return O3D_OK, or O3D_ERROR_INVALID_ARGUMENT on a NULL pointer; O3D_ERROR_BUFFER_TOO_SMALL when `capacity` is
 *   short (the count is still reported).
 */
O3D_API o3d_status o3d_registration_result_get_correspondence_set(int32_t* out, size_t capacity, size_t* out_n,
                                                                  const o3d_registration_result_t* result);

/** Correspondence checkers: prune RANSAC hypotheses early (Open3D's CorrespondenceChecker*; O3D_CHECKER_*). */
typedef int32_t o3d_correspondence_checker_kind;
#define O3D_CHECKER_EDGE_LENGTH 0 /**< BasedOnEdgeLength(similarity_threshold in (0, 1]; default 0.9) */
#define O3D_CHECKER_DISTANCE 1    /**< BasedOnDistance(distance_threshold > 0) */
#define O3D_CHECKER_NORMAL 2      /**< BasedOnNormal(normal_angle_threshold, radians, > 0): both clouds need normals */

/** A correspondence checker (CorrespondenceChecker*): its kind and threshold; fill with o3d_correspondence_checker_init. */
typedef struct o3d_correspondence_checker {
    uint32_t struct_size; /**< sizeof(o3d_correspondence_checker_t) */
    o3d_correspondence_checker_kind kind; /**< O3D_CHECKER_* */
    double threshold;     /**< similarity, distance or angle (see the kinds); must be finite and > 0 */
} o3d_correspondence_checker_t;

/**
 * @brief Fill a checker of `kind`: threshold 0.9 for EDGE_LENGTH, 0.075 for DISTANCE, 0.5236 (30 deg) for NORMAL.
 *
 * Threads: any thread.
 * @param checker the struct to fill
 * @param struct_size sizeof the struct as the caller knows it (an older, smaller size is accepted)
 * @param kind O3D_CHECKER_*
 * @return O3D_OK, or O3D_ERROR_INVALID_ARGUMENT on a NULL pointer or a `struct_size` this library does not know.
 */
O3D_API o3d_status o3d_correspondence_checker_init(o3d_correspondence_checker_t* checker, uint32_t struct_size,
                                                   o3d_correspondence_checker_kind kind);
/**
 * @brief Does the hypothesis pass `checker`? `corres` holds `num_corres` (source, target) index pairs;
 * `transformation` (NULL: identity) moves the source. `*out_passed` gets 1 or 0. @see CorrespondenceChecker.Check
 *
 * Threads: any thread; concurrent calls on the same handles are safe (all read-only).
 * @param out_passed receives 1 (passes) or 0
 * @param checker the checker
 * @param source the source cloud (moved onto `target`)
 * @param target the target cloud
 * @param corres num_corres (source index, target index) pairs, 2 int32 each
 * @param num_corres number of pairs in `corres`
 * @param transformation row-major 4x4 transformation of the source (NULL: identity)
 * @return O3D_OK, or O3D_ERROR_INVALID_ARGUMENT on a NULL pointer.
 */
O3D_API o3d_status o3d_correspondence_checker_check(int32_t* out_passed, const o3d_correspondence_checker_t* checker,
                                                    const o3d_pointcloud_t* source, const o3d_pointcloud_t* target,
                                                    const int32_t* corres, size_t num_corres,
                                                    const double transformation[16]);

/** RANSAC options: estimation, ransac_n and RANSACConvergenceCriteria, seed, threads, progress. */
typedef struct o3d_ransac_options {
    uint32_t struct_size;     /**< sizeof(o3d_ransac_options_t) */
    o3d_estimation estimation; /**< O3D_ESTIMATION_POINT_TO_POINT (default) or POINT_TO_PLANE */
    o3d_bool with_scaling;    /**< point-to-point: also estimate a scale; default 0 */
    o3d_count ransac_n;       /**< correspondences drawn per hypothesis, >= 3; default 3 */
    o3d_count max_iteration;  /**< RANSACConvergenceCriteria.max_iteration; default 100000 */
    double confidence;        /**< RANSACConvergenceCriteria.confidence, in [0, 1]; default 0.999 */
    o3d_bool mutual_filter;   /**< feature matching only: keep mutual nearest pairs; default 0 */
    o3d_bool use_seed;        /**< 1: draw from `seed`, the same result on any thread count; 0 (default): take a seed from the global generator (o3d_random_seed) */
    uint64_t seed;            /**< used when use_seed = 1 */
    o3d_count num_threads;    /**< 0 = library default; the result does not depend on it */
    o3d_progress_callback progress; /**< fraction of max_iteration done (jumps to 1 when confident); may be NULL */
    void* user_data;          /**< passed to `progress` */
} o3d_ransac_options_t;

/**
 * @brief Fill defaults (Open3D's).
 *
 * Threads: any thread.
 * @param opts the struct to fill
 * @param struct_size sizeof the struct as the caller knows it (an older, smaller size is accepted)
 * @return O3D_OK, or O3D_ERROR_INVALID_ARGUMENT on a NULL pointer or a `struct_size` this library does not know;
 *   O3D_ERROR_CANCELLED when the progress callback returns non-zero.
 */
O3D_API o3d_status o3d_ransac_options_init(o3d_ransac_options_t* opts, uint32_t struct_size);


/**
 * @brief RANSAC over feature correspondences (nearest target descriptor of each source descriptor, see
 * o3d_correspondences_from_features): each hypothesis fits `ransac_n` drawn pairs, must pass every
 * checker, and is scored by the share of pairs within `max_correspondence_distance` after the move.
 * `checkers` holds `num_checkers` entries (may be NULL when 0).
 * @see o3d.pipelines.registration.registration_ransac_based_on_feature_matching
 *
 * Threads: any thread; `source`, `target` and the features are only read; the progress callback runs on the calling
 * thread.
 * Ownership: `*out` is the caller's, to free with o3d_registration_result_destroy(); left NULL on failure.
 * @param out receives the new handle (NULL on failure)
 * @param source the source cloud (moved onto `target`)
 * @param target the target cloud
 * @param source_feature descriptors of `source`, one per point
 * @param target_feature descriptors of `target`, one per point
 * @param max_correspondence_distance pairs farther apart are ignored (> 0)
 * @param checkers num_checkers checkers (may be NULL when num_checkers == 0)
 * @param num_checkers number of checkers
 * @param opts options (NULL: the defaults of the matching `*_init`)
 * @return O3D_OK, or O3D_ERROR_INVALID_ARGUMENT on a NULL pointer or a bad `opts->struct_size`; O3D_ERROR_CANCELLED
 *   when the progress callback returns non-zero.
 */
O3D_API o3d_status o3d_register_ransac_based_on_feature_matching(
    o3d_registration_result_t** out, const o3d_pointcloud_t* source, const o3d_pointcloud_t* target,
    const o3d_feature_t* source_feature, const o3d_feature_t* target_feature, double max_correspondence_distance,
    const o3d_correspondence_checker_t* checkers, size_t num_checkers, const o3d_ransac_options_t* opts);
/**
 * @brief RANSAC over given (source, target) pairs (`num_corres` pairs, 2 int32 each). opts.mutual_filter is ignored.
 * @see o3d.pipelines.registration.registration_ransac_based_on_correspondence
 *
 * Threads: any thread; `source`, `target` and the features are only read; the progress callback runs on the calling
 * thread.
 * Ownership: `*out` is the caller's, to free with o3d_registration_result_destroy(); left NULL on failure.
 * @param out receives the new handle (NULL on failure)
 * @param source the source cloud (moved onto `target`)
 * @param target the target cloud
 * @param corres num_corres (source index, target index) pairs, 2 int32 each
 * @param num_corres number of pairs in `corres`
 * @param max_correspondence_distance pairs farther apart are ignored (> 0)
 * @param checkers num_checkers checkers (may be NULL when num_checkers == 0)
 * @param num_checkers number of checkers
 * @param opts options (NULL: the defaults of the matching `*_init`)
 * @return O3D_OK, or O3D_ERROR_INVALID_ARGUMENT on a NULL pointer or a bad `opts->struct_size`; O3D_ERROR_CANCELLED
 *   when the progress callback returns non-zero.
 */
O3D_API o3d_status o3d_register_ransac_based_on_correspondence(
    o3d_registration_result_t** out, const o3d_pointcloud_t* source, const o3d_pointcloud_t* target,
    const int32_t* corres, size_t num_corres, double max_correspondence_distance,
    const o3d_correspondence_checker_t* checkers, size_t num_checkers, const o3d_ransac_options_t* opts);

/** FastGlobalRegistrationOption, plus seed, threads and progress. */
typedef struct o3d_fgr_options {
    uint32_t struct_size;               /**< sizeof(o3d_fgr_options_t) */
    double division_factor;             /**< > 1: mu is divided by it each annealing step; default 1.4 */
    o3d_bool use_absolute_scale;        /**< 1: distances in the clouds' units; 0 (default): normalised scale */
    o3d_bool decrease_mu;               /**< anneal mu (graduated non-convexity); default 1 */
    double maximum_correspondence_distance; /**< > 0; default 0.025 */
    o3d_count iteration_number;         /**< iterations; default 64 */
    double tuple_scale;                 /**< in (0, 1]: edge-length similarity of the tuple test; default 0.95 */
    o3d_count maximum_tuple_count;      /**< tuples kept at most; default 1000 */
    o3d_bool tuple_test;                /**< apply the tuple test; default 1 */
    o3d_bool use_seed;                  /**< 1: draw the random tuples from `seed`, the same result on any thread count; 0 (default): take a seed from the global generator (o3d_random_seed) */
    uint64_t seed; /**< used when use_seed = 1 */
    o3d_count num_threads;              /**< 0 = library default; the result does not depend on it */
    o3d_progress_callback progress;     /**< fraction of iteration_number done; may be NULL */
    void* user_data; /**< passed to `progress` */
} o3d_fgr_options_t;

/**
 * @brief Fill defaults (Open3D's).
 *
 * Threads: any thread.
 * @param opts the struct to fill
 * @param struct_size sizeof the struct as the caller knows it (an older, smaller size is accepted)
 * @return O3D_OK, or O3D_ERROR_INVALID_ARGUMENT on a NULL pointer or a `struct_size` this library does not know;
 *   O3D_ERROR_CANCELLED when the progress callback returns non-zero.
 */
O3D_API o3d_status o3d_fgr_options_init(o3d_fgr_options_t* opts, uint32_t struct_size);
/**
 * @brief Fast Global Registration (Zhou, Park, Koltun 2016) on mutual feature matches.
 * @see o3d.pipelines.registration.registration_fgr_based_on_feature_matching
 *
 * Threads: any thread; `source`, `target` and the features are only read; the progress callback runs on the calling
 * thread.
 * Ownership: `*out` is the caller's, to free with o3d_registration_result_destroy(); left NULL on failure.
 * @param out receives the new handle (NULL on failure)
 * @param source the source cloud (moved onto `target`)
 * @param target the target cloud
 * @param source_feature descriptors of `source`, one per point
 * @param target_feature descriptors of `target`, one per point
 * @param opts options (NULL: the defaults of the matching `*_init`)
 * @return O3D_OK, or O3D_ERROR_INVALID_ARGUMENT on a NULL pointer or a bad `opts->struct_size`; O3D_ERROR_CANCELLED
 *   when the progress callback returns non-zero.
 */
O3D_API o3d_status o3d_register_fgr_based_on_feature_matching(o3d_registration_result_t** out,
                                                              const o3d_pointcloud_t* source,
                                                              const o3d_pointcloud_t* target,
                                                              const o3d_feature_t* source_feature,
                                                              const o3d_feature_t* target_feature,
                                                              const o3d_fgr_options_t* opts);
/**
 * @brief Fast Global Registration on given (source, target) pairs.
 * @see o3d.pipelines.registration.registration_fgr_based_on_correspondence
 *
 * Threads: any thread; `source`, `target` and the features are only read; the progress callback runs on the calling
 * thread.
 * Ownership: `*out` is the caller's, to free with o3d_registration_result_destroy(); left NULL on failure.
 * @param out receives the new handle (NULL on failure)
 * @param source the source cloud (moved onto `target`)
 * @param target the target cloud
 * @param corres num_corres (source index, target index) pairs, 2 int32 each
 * @param num_corres number of pairs in `corres`
 * @param opts options (NULL: the defaults of the matching `*_init`)
 * @return O3D_OK, or O3D_ERROR_INVALID_ARGUMENT on a NULL pointer or a bad `opts->struct_size`; O3D_ERROR_CANCELLED
 *   when the progress callback returns non-zero.
 */
O3D_API o3d_status o3d_register_fgr_based_on_correspondence(o3d_registration_result_t** out,
                                                            const o3d_pointcloud_t* source,
                                                            const o3d_pointcloud_t* target, const int32_t* corres,
                                                            size_t num_corres, const o3d_fgr_options_t* opts);

O3D_END_DECL

#endif /* O3D_REGISTRATION_H */
