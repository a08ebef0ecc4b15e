/* SPDX-License-Identifier: MIT */
/* A scene whose answer is known, shared by the C API tests that need RGB-D frames: the inside of a box room
 * with a smooth colour texture, ray-cast from any camera pose; and the row-major 4 x 4 rigid-motion helpers
 * that place the cameras and measure pose errors. */
#ifndef O3D_TEST_ROOM_H
#define O3D_TEST_ROOM_H
#include <stdint.h>

#include "o3d/o3d.h"

/* The room's corners (metres). */
extern const double o3d_test_room_lo[3], o3d_test_room_hi[3];

/* The wall texture at `p`: RGB in [0, 1], smooth, with several frequencies so odometry and ICP lock on. */
void o3d_test_room_texture(const double p[3], double rgb[3]);
/* Ray-cast the room from camera-to-world `pose` through `camera`: 8-bit RGB (3 * width * height) and the
 * depth in metres along z (width * height); either output may be NULL. */
void o3d_test_room_render(const double pose[16], const o3d_pinhole_intrinsic_t* camera, uint8_t* rgb, float* depth);

void o3d_test_mat_mul(const double a[16], const double b[16], double out[16]);
void o3d_test_rigid_inverse(const double m[16], double out[16]);
/* Camera-to-world pose at `centre` looking at `target` (x right, y down, z forward; world y points down). */
void o3d_test_look_at(const double centre[3], const double target[3], double m[16]);
/* Rotation by `deg` about `axis` (Rodrigues), then translation t. */
void o3d_test_motion(const double axis[3], double deg, const double t[3], double m[16]);
/* Rotation angle (degrees) of a * b^-1 and the distance between the two cameras' centres (a, b world-to-camera). */
void o3d_test_pose_error(const double a[16], const double b[16], double* deg, double* metres);

#endif
