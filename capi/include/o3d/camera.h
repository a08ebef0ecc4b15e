/* SPDX-License-Identifier: MIT */
/**
 * @file camera.h
 * @brief Pinhole camera models and camera trajectories (o3d.camera).
 *
 * An intrinsic is a plain value struct with a frozen layout (six fields, never extended).
 * An extrinsic is a row-major 4x4 world-to-camera matrix. A trajectory is a handle holding a list of
 * (intrinsic, extrinsic) pairs: o3d.camera.PinholeCameraTrajectory.parameters.
 * Reading and writing them (Open3D's JSON layout, the .log format) is in io.h.
 */
#ifndef O3D_CAMERA_H
#define O3D_CAMERA_H

#include "o3d/common.h"
#include "o3d/types.h"

O3D_BEGIN_DECL

/** o3d.camera.PinholeCameraIntrinsic: image size and the focal lengths / principal point in pixels. */
typedef struct o3d_pinhole_intrinsic {
    int32_t width;
    int32_t height;
    double fx;
    double fy;
    double cx;
    double cy;
} o3d_pinhole_intrinsic_t;

#define O3D_INTRINSIC_PRIMESENSE_DEFAULT 0         /**< 640x480, 525, 525, 319.5, 239.5 */
#define O3D_INTRINSIC_KINECT2_DEPTH_DEFAULT 1      /**< 512x424, 365.456, 365.456, 254.878, 205.395 */
#define O3D_INTRINSIC_KINECT2_COLOR_DEFAULT 2      /**< 1920x1080, 1059.9718, 1059.9718, 975.7193, 545.9533 */
/** @brief Fill `out` with one of Open3D's PinholeCameraIntrinsicParameters presets. */
O3D_API o3d_status o3d_pinhole_intrinsic_set_preset(o3d_pinhole_intrinsic_t* out, int32_t preset);


/** @brief New empty trajectory. */
O3D_API o3d_status o3d_camera_trajectory_create(o3d_camera_trajectory_t** out);
/** @brief Destroy. NULL is a no-op. */
O3D_API void o3d_camera_trajectory_destroy(o3d_camera_trajectory_t* trajectory);
/** @brief Number of camera poses. */
O3D_API o3d_status o3d_camera_trajectory_size(size_t* out_n, const o3d_camera_trajectory_t* trajectory);
/** @brief Intrinsic and extrinsic of pose `index` (either output may be NULL). Out of range → error. */
O3D_API o3d_status o3d_camera_trajectory_get(o3d_pinhole_intrinsic_t* out_intrinsic, double out_extrinsic[16],
                                             const o3d_camera_trajectory_t* trajectory, size_t index);
/** @brief Append a pose. The extrinsic's last row must be (0, 0, 0, 1). */
O3D_API o3d_status o3d_camera_trajectory_append(o3d_camera_trajectory_t* trajectory,
                                                const o3d_pinhole_intrinsic_t* intrinsic,
                                                const double extrinsic[16]);
/** @brief Remove all poses. */
O3D_API o3d_status o3d_camera_trajectory_clear(o3d_camera_trajectory_t* trajectory);

O3D_END_DECL

#endif /* O3D_CAMERA_H */
