/* SPDX-License-Identifier: MIT */
/* The box room and rigid-motion helpers of o3d_test_room.h. */
#include "o3d_test_room.h"

#include <math.h>
#include <string.h>

#ifndef M_PI
#define M_PI 3.14159265358979323846
#endif

const double o3d_test_room_lo[3] = {-1.2, -1.0, -1.0}, o3d_test_room_hi[3] = {1.2, 1.0, 1.6};

void o3d_test_room_texture(const double p[3], double rgb[3]) {
    rgb[0] = 0.5 + 0.2 * sin(5.0 * p[0] + 2.0 * p[2]) * cos(4.0 * p[1]) + 0.15 * sin(11.0 * p[2] + 3.0 * p[1]);
    rgb[1] = 0.5 + 0.2 * cos(4.5 * p[1] + 1.0) * sin(5.5 * p[2] - p[0]) + 0.15 * cos(10.0 * p[0] - 4.0 * p[1]);
    rgb[2] = 0.5 + 0.25 * sin(3.0 * (p[0] + p[1] + p[2])) + 0.15 * cos(12.0 * p[1] - 5.0 * p[2] + 3.0 * p[0]);
}

void o3d_test_mat_mul(const double a[16], const double b[16], double out[16]) {
    double t[16];
    for (int r = 0; r < 4; ++r)
        for (int c = 0; c < 4; ++c) {
            t[4 * r + c] = 0;
            for (int k = 0; k < 4; ++k) t[4 * r + c] += a[4 * r + k] * b[4 * k + c];
        }
    memcpy(out, t, sizeof t);
}

void o3d_test_rigid_inverse(const double m[16], double out[16]) {
    memset(out, 0, 16 * sizeof(double));
    for (int r = 0; r < 3; ++r) {
        for (int c = 0; c < 3; ++c) out[4 * r + c] = m[4 * c + r];
        for (int c = 0; c < 3; ++c) out[4 * r + 3] -= m[4 * c + r] * m[4 * c + 3];
    }
    out[15] = 1;
}

static void normalize(double v[3]) {
    const double n = sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
    for (int i = 0; i < 3; ++i) v[i] /= n;
}

static void cross(const double a[3], const double b[3], double out[3]) {
    out[0] = a[1] * b[2] - a[2] * b[1];
    out[1] = a[2] * b[0] - a[0] * b[2];
    out[2] = a[0] * b[1] - a[1] * b[0];
}

/* Camera-to-world pose at `centre` looking at `target` (x right, y down, z forward; world y points down). */
void o3d_test_look_at(const double centre[3], const double target[3], double m[16]) {
    double z[3] = {target[0] - centre[0], target[1] - centre[1], target[2] - centre[2]}, x[3], y[3];
    const double up[3] = {0, 1, 0};
    normalize(z);
    cross(up, z, x);
    normalize(x);
    cross(z, x, y);
    memset(m, 0, 16 * sizeof(double));
    for (int r = 0; r < 3; ++r) {
        m[4 * r + 0] = x[r];
        m[4 * r + 1] = y[r];
        m[4 * r + 2] = z[r];
        m[4 * r + 3] = centre[r];
    }
    m[15] = 1;
}

/* Rotation by `deg` about `axis` (Rodrigues), then translation t. */
void o3d_test_motion(const double axis_in[3], double deg, const double t[3], double m[16]) {
    double k[3] = {axis_in[0], axis_in[1], axis_in[2]};
    normalize(k);
    const double a = deg * M_PI / 180, c = cos(a), s = sin(a);
    memset(m, 0, 16 * sizeof(double));
    for (int r = 0; r < 3; ++r)
        for (int q = 0; q < 3; ++q) m[4 * r + q] = (1 - c) * k[r] * k[q] + (r == q ? c : 0);
    m[1] -= s * k[2]; m[2] += s * k[1];
    m[4] += s * k[2]; m[6] -= s * k[0];
    m[8] -= s * k[1]; m[9] += s * k[0];
    for (int r = 0; r < 3; ++r) m[4 * r + 3] = t[r];
    m[15] = 1;
}

/* Rotation angle (degrees) of a * b^-1 and the distance between the two cameras' centres. */
void o3d_test_pose_error(const double a[16], const double b[16], double* deg, double* metres) {
    double ib[16], e[16], ia[16];
    o3d_test_rigid_inverse(b, ib);
    o3d_test_mat_mul(a, ib, e);
    double tr = (e[0] + e[5] + e[10] - 1) / 2;
    tr = tr > 1 ? 1 : tr < -1 ? -1 : tr;
    *deg = acos(tr) * 180 / M_PI;
    o3d_test_rigid_inverse(a, ia);
    *metres = sqrt(pow(ia[3] - ib[3], 2) + pow(ia[7] - ib[7], 2) + pow(ia[11] - ib[11], 2));
}

void o3d_test_room_render(const double pose[16], const o3d_pinhole_intrinsic_t* camera, uint8_t* rgb, float* depth) {
    for (int v = 0; v < camera->height; ++v)
        for (int u = 0; u < camera->width; ++u) {
            const double dc[3] = {(u - camera->cx) / camera->fx, (v - camera->cy) / camera->fy, 1.0};
            double d[3], t = INFINITY, p[3], col[3];
            for (int r = 0; r < 3; ++r) d[r] = pose[4 * r] * dc[0] + pose[4 * r + 1] * dc[1] + pose[4 * r + 2] * dc[2];
            for (int a = 0; a < 3; ++a)
                if (d[a] != 0) {
                    const double ta = ((d[a] > 0 ? o3d_test_room_hi[a] : o3d_test_room_lo[a]) - pose[4 * a + 3]) / d[a];
                    if (ta < t) t = ta;
                }
            for (int r = 0; r < 3; ++r) p[r] = pose[4 * r + 3] + t * d[r];
            o3d_test_room_texture(p, col);
            if (rgb)
                for (int k = 0; k < 3; ++k) rgb[3 * (v * camera->width + u) + k] = (uint8_t)lround(255.0 * col[k]);
            if (depth) depth[v * camera->width + u] = (float)t; /* the camera ray has z = 1: t is the depth */
        }
}
