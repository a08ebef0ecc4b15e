/* SPDX-License-Identifier: MIT */
/**
 * @file odometry.h
 * @brief RGB-D odometry (Open3D's o3d.pipelines.odometry): the rigid motion between two RGB-D frames by dense
 * photometric (Steinbruecker et al. 2011) or photometric + geometric (Park et al. 2017) alignment, coarse to
 * fine over image pyramids.
 *
 * The frames are Open3D's odometry input: an RGB-D image whose color is a 1-channel float intensity and whose
 * depth is 1-channel float metres (o3d_rgbd_image_create_from_color_and_depth with its default of converting
 * color to intensity), all four images of the intrinsic's size.
 */
#ifndef O3D_ODOMETRY_H
#define O3D_ODOMETRY_H

#include "o3d/camera.h"
#include "o3d/rgbd.h"
#include "o3d/types.h"

O3D_BEGIN_DECL

/** The error terms odometry minimizes (O3D_ODOMETRY_JACOBIAN_*). */
typedef int32_t o3d_odometry_jacobian;
#define O3D_ODOMETRY_JACOBIAN_COLOR_TERM 0  /**< intensity only (RGBDOdometryJacobianFromColorTerm) */
#define O3D_ODOMETRY_JACOBIAN_HYBRID_TERM 1 /**< intensity and depth (RGBDOdometryJacobianFromHybridTerm) */

/** OdometryOption's scalars; the iterations per pyramid level are a parameter of o3d_odometry_compute_rgbd. */
typedef struct o3d_odometry_options {
    uint32_t struct_size; /**< sizeof(o3d_odometry_options_t) */
    double depth_diff_max; /**< metres (> 0): two pixels whose depths differ more do not correspond; default 0.03 */
    double depth_min;      /**< metres: depth below is ignored; default 0.0 */
    double depth_max;      /**< metres: depth above is ignored; default 4.0 */
} o3d_odometry_options_t;

/**
 * @brief Fill defaults (Open3D's OdometryOption).
 *
 * Threads: any thread.
 * @param opts the struct to fill
 * @param struct_size sizeof the struct as the caller knows it (an older, smaller size is accepted)
 * @return O3D_OK, or O3D_ERROR_INVALID_ARGUMENT on a NULL pointer or a `struct_size` this library does not know.
 */
O3D_API o3d_status o3d_odometry_options_init(o3d_odometry_options_t* opts, uint32_t struct_size);

/**
 * @brief compute_rgbd_odometry: the motion taking `source` onto `target` (points of the source camera into the
 * target camera's frame), starting from `odo_init`.
 *
 * A pair that cannot be aligned (no pixel left that corresponds, or a singular system) is not an error:
 * `*out_success` is 0 and the transformation and information are the identity, as Open3D returns them.
 *
 * Threads: any thread; the images are only read. Parallel inside (o3d_set_num_threads); the result does not
 * depend on the thread count.
 * @param out_success receives 1 when the motion was found, else 0
 * @param out_transformation receives the 4x4 motion, row-major
 * @param out_information receives the 6x6 information matrix, row-major (Open3D's: of the point-to-point
 *   alignment at the result)
 * @param source the frame to move
 * @param target the frame it is moved onto
 * @param intrinsic the camera (its size must be the images')
 * @param odo_init 4x4 row-major initial motion (NULL: identity)
 * @param jacobian O3D_ODOMETRY_JACOBIAN_*
 * @param iterations_per_level Gauss-Newton iterations per pyramid level, coarsest first; its length is the
 *   number of levels (NULL: Open3D's 20, 10, 5)
 * @param num_levels how many entries `iterations_per_level` has (1..8; ignored when it is NULL)
 * @param opts options (NULL: o3d_odometry_options_init's defaults)
 * @return O3D_OK; O3D_ERROR_INVALID_ARGUMENT on a NULL pointer, images that are not float intensity and float
 *   depth of one size, an empty image, an intrinsic of another size or with fx, fy <= 0, a non-finite
 *   `odo_init`, a bad level count or iteration count, or bad options.
 */
O3D_API o3d_status o3d_odometry_compute_rgbd(o3d_bool* out_success, double out_transformation[16],
                                             double out_information[36], const o3d_rgbd_image_t* source,
                                             const o3d_rgbd_image_t* target, const o3d_pinhole_intrinsic_t* intrinsic,
                                             const double odo_init[16], o3d_odometry_jacobian jacobian,
                                             const int32_t* iterations_per_level, size_t num_levels,
                                             const o3d_odometry_options_t* opts);

O3D_END_DECL

#endif /* O3D_ODOMETRY_H */
