/* SPDX-License-Identifier: MIT */
/* Shared helpers of the cmocka C API tests. Include after <cmocka.h>. */
#ifndef O3D_TEST_UTIL_H
#define O3D_TEST_UTIL_H

#include <stddef.h>

/* Path of `relative` under $O3D_TEST_DATA (default ../shared/data), in a static buffer; NULL when absent. */
const char* o3d_test_data_path(const char* relative);
/* 1 when O3D_REQUIRE_TEST_DATA=1 (CI): a missing data file must fail, not skip. */
int o3d_test_data_required(void);

/* Row-major rotation by `deg` degrees about the z axis, then translation (tx, ty, tz); and its inverse. */
void o3d_test_motion_z(double deg, double tx, double ty, double tz, double m[16], double inv[16]);
/* Largest |a[i] - b[i]| over 16 entries (two 4 x 4 matrices). */
double o3d_test_max_abs_diff16(const double* a, const double* b);

/* Declare `var` as the data path, or skip (fail under O3D_REQUIRE_TEST_DATA=1) when it is missing. */
#define O3D_C_TEST_DATA_OR_SKIP(var, relative)                                  \
    const char* var = o3d_test_data_path(relative);                             \
    if (!var) {                                                                 \
        if (o3d_test_data_required()) fail_msg("missing test data %s", relative); \
        skip();                                                                 \
    }

/* Assert that `call` failed with `code` and left a non-empty message. */
#define O3D_ASSERT_FAILS(call, code)                              \
    do {                                                          \
        assert_int_equal((call), (code));                         \
        assert_int_equal(o3d_last_error_code(), (code));          \
        assert_true(o3d_last_error_message()[0] != '\0');         \
    } while (0)

#endif
