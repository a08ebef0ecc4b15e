/* SPDX-License-Identifier: MIT */
#include "o3d_test_util.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#ifndef M_PI
#define M_PI 3.14159265358979323846
#endif

const char* o3d_test_data_path(const char* relative) {
    static char buf[4096];
    const char* root = getenv("O3D_TEST_DATA");
    if (!root || !*root) root = O3D_TEST_DATA_DEFAULT;
    snprintf(buf, sizeof buf, "%s/%s", root, relative);
    return access(buf, R_OK) == 0 ? buf : NULL;
}

int o3d_test_data_required(void) {
    const char* env = getenv("O3D_REQUIRE_TEST_DATA");
    return env && strcmp(env, "1") == 0;
}

void o3d_test_motion_z(double deg, double tx, double ty, double tz, double m[16], double inv[16]) {
    const double c = cos(deg * M_PI / 180.0), s = sin(deg * M_PI / 180.0);
    const double fwd[16] = {c, -s, 0, tx, s, c, 0, ty, 0, 0, 1, tz, 0, 0, 0, 1};
    const double bwd[16] = {c, s, 0, -(c * tx + s * ty), -s, c, 0, -(-s * tx + c * ty), 0, 0, 1, -tz, 0, 0, 0, 1};
    memcpy(m, fwd, sizeof fwd);
    memcpy(inv, bwd, sizeof bwd);
}

double o3d_test_max_abs_diff16(const double* a, const double* b) {
    double m = 0.0;
    for (int i = 0; i < 16; ++i) m = fmax(m, fabs(a[i] - b[i]));
    return m;
}
