/* SPDX-License-Identifier: MIT */
/**
 * @file camera.h
 * @brief Pinhole camera models and camera trajectories (o3d.camera).
 *
 * An intrinsic is a plain value struct with a frozen layout (six fields, never extended).
 * An extrinsic is a row-major 4x4 world-to-camera matrix. A trajectory is a handle holding a list of
 * (intrinsic, extrinsic) pairs: o3d.camera.PinholeCameraTrajectory.parameters.
 * Reading and writing them (Open3D's JSON layout, the .log format) is in io.h.
 *
 * **Out of memory:** any function here that allocates may also return O3D_ERROR_OUT_OF_MEMORY; the
 * per-function `@return` lists do not repeat it.
 */
#ifndef O3D_CAMERA_H
#define O3D_CAMERA_H

#include "o3d/common.h"
#include "o3d/types.h"

O3D_BEGIN_DECL

/** o3d.camera.PinholeCameraIntrinsic: image size and the focal lengths / principal point in pixels. */
typedef struct o3d_pinhole_intrinsic {
    int32_t width; /**< image width in pixels */
    int32_t height; /**< image height in pixels */
    double fx; /**< focal length in x, pixels */
    double fy; /**< focal length in y, pixels */
    double cx; /**< principal point x, pixels */
    double cy; /**< principal point y, pixels */
} o3d_pinhole_intrinsic_t;

/** Open3D's PinholeCameraIntrinsicParameters presets (O3D_INTRINSIC_*). */
typedef int32_t o3d_intrinsic_preset;
#define O3D_INTRINSIC_PRIMESENSE_DEFAULT 0         /**< 640x480, 525, 525, 319.5, 239.5 */
#define O3D_INTRINSIC_KINECT2_DEPTH_DEFAULT 1      /**< 512x424, 365.456, 365.456, 254.878, 205.395 */
#define O3D_INTRINSIC_KINECT2_COLOR_DEFAULT 2      /**< 1920x1080, 1059.9718, 1059.9718, 975.7193, 545.9533 */
/**
 * @brief Fill `out` with one of Open3D's PinholeCameraIntrinsicParameters presets.
 *
 * Threads: any thread.
 * @param out receives the intrinsic
 * @param preset O3D_INTRINSIC_*
 * @return O3D_OK, or O3D_ERROR_INVALID_ARGUMENT on a NULL pointer or an unknown preset.
 */
O3D_API o3d_status o3d_pinhole_intrinsic_set_preset(o3d_pinhole_intrinsic_t* out, o3d_intrinsic_preset preset);


/**
 * @brief New empty trajectory.
 *
 * Threads: any thread.
 * Ownership: `*out` is the caller's, to free with o3d_camera_trajectory_destroy(); left NULL on failure.
 * @param out receives the new handle (NULL on failure)
 * @return O3D_OK, or O3D_ERROR_INVALID_ARGUMENT on a NULL pointer.
 */
O3D_API o3d_status o3d_camera_trajectory_create(o3d_camera_trajectory_t** out);
/**
 * @brief Destroy. NULL is a no-op.
 *
 * Threads: needs exclusive access to `trajectory`: no other call may use it during or after.
 * @param trajectory the handle to destroy (NULL is a no-op)
 */
O3D_API void o3d_camera_trajectory_destroy(o3d_camera_trajectory_t* trajectory);
/**
 * @brief Number of camera poses.
 *
 * Threads: any thread; concurrent calls on the same handles are safe (all read-only).
 * @param out_n receives the count
 * @param trajectory the trajectory
 * @return O3D_OK, or O3D_ERROR_INVALID_ARGUMENT on a NULL pointer.
 */
O3D_API o3d_status o3d_camera_trajectory_size(size_t* out_n, const o3d_camera_trajectory_t* trajectory);
/**
 * @brief Intrinsic and extrinsic of pose `index` (either output may be NULL). Out of range → error.
 *
 * Threads: any thread; concurrent calls on the same handles are safe (all read-only).
 * @param out_intrinsic receives the intrinsic (may be NULL)
 * @param out_extrinsic receives the row-major 4x4 extrinsic (may be NULL)
 * @param trajectory the trajectory
 * @param index zero-based index (must be below the count)
 * @return O3D_OK, or O3D_ERROR_INVALID_ARGUMENT on a NULL `trajectory` or `index` out of range.
 */
O3D_API o3d_status o3d_camera_trajectory_get(o3d_pinhole_intrinsic_t* out_intrinsic, double out_extrinsic[16],
                                             const o3d_camera_trajectory_t* trajectory, size_t index);
/**
 * @brief Append a pose. The extrinsic's last row must be (0, 0, 0, 1).
 *
 * Threads: needs exclusive access to `trajectory`.
 * @param trajectory the trajectory
 * @param intrinsic the camera intrinsic
 * @param extrinsic row-major 4x4 world-to-camera matrix
 * @return O3D_OK, or O3D_ERROR_INVALID_ARGUMENT on a NULL pointer, non-finite values or an extrinsic whose last row
 *   is not (0, 0, 0, 1).
 */
O3D_API o3d_status o3d_camera_trajectory_append(o3d_camera_trajectory_t* trajectory,
                                                const o3d_pinhole_intrinsic_t* intrinsic,
                                                const double extrinsic[16]);
/**
 * @brief Remove all poses.
 *
 * Threads: needs exclusive access to `trajectory`.
 * @param trajectory the trajectory
 * @return O3D_OK, or O3D_ERROR_INVALID_ARGUMENT on a NULL pointer.
 */
O3D_API o3d_status o3d_camera_trajectory_clear(o3d_camera_trajectory_t* trajectory);

O3D_END_DECL

#endif /* O3D_CAMERA_H */
