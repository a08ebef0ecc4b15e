/* SPDX-License-Identifier: MIT */
/* C API camera.h and the camera part of io.h: presets, trajectories (row-major extrinsics), Open3D's JSON
 * files and .log files, round trips, and the NULL / malformed / non-rigid paths.
 * Reference extrinsics: Open3D 0.20.0, printed by tools/reference/record_rgbd.py (section "camera"). */
#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include <cmocka.h>

#include "o3d/o3d.h"
#include "o3d_test_util.h"

static void temp_path(char* buf, size_t size, const char* name) {
    snprintf(buf, size, "/tmp/o3d_capi_camera_%d_%s", (int)getpid(), name);
}

static void write_text(const char* path, const char* text) {
    FILE* f = fopen(path, "wb");
    assert_non_null(f);
    fputs(text, f);
    fclose(f);
}

static void assert_intrinsic_equal(const o3d_pinhole_intrinsic_t* a, const o3d_pinhole_intrinsic_t* b) {
    assert_int_equal(a->width, b->width);
    assert_int_equal(a->height, b->height);
    assert_true(a->fx == b->fx && a->fy == b->fy && a->cx == b->cx && a->cy == b->cy);
}

static void test_presets(void** state) {
    (void)state;
    o3d_pinhole_intrinsic_t in;
    assert_int_equal(o3d_pinhole_intrinsic_set_preset(&in, O3D_INTRINSIC_PRIMESENSE_DEFAULT), O3D_OK);
    const o3d_pinhole_intrinsic_t ps = {640, 480, 525.0, 525.0, 319.5, 239.5};
    assert_intrinsic_equal(&in, &ps);
    assert_int_equal(o3d_pinhole_intrinsic_set_preset(&in, O3D_INTRINSIC_KINECT2_DEPTH_DEFAULT), O3D_OK);
    const o3d_pinhole_intrinsic_t k2d = {512, 424, 365.456, 365.456, 254.878, 205.395};
    assert_intrinsic_equal(&in, &k2d);
    assert_int_equal(o3d_pinhole_intrinsic_set_preset(&in, O3D_INTRINSIC_KINECT2_COLOR_DEFAULT), O3D_OK);
    const o3d_pinhole_intrinsic_t k2c = {1920, 1080, 1059.9718, 1059.9718, 975.7193, 545.9533};
    assert_intrinsic_equal(&in, &k2c);
    O3D_ASSERT_FAILS(o3d_pinhole_intrinsic_set_preset(&in, 3), O3D_ERROR_INVALID_ARGUMENT);
    O3D_ASSERT_FAILS(o3d_pinhole_intrinsic_set_preset(&in, -1), O3D_ERROR_INVALID_ARGUMENT);
    O3D_ASSERT_FAILS(o3d_pinhole_intrinsic_set_preset(NULL, 0), O3D_ERROR_INVALID_ARGUMENT);
}

static void rotation_z(double angle, double tx, double ty, double tz, double m[16]) {
    const double c = cos(angle), s = sin(angle);
    const double v[16] = {c, -s, 0, tx, s, c, 0, ty, 0, 0, 1, tz, 0, 0, 0, 1};
    memcpy(m, v, sizeof v);
}

static void test_trajectory_handle(void** state) {
    (void)state;
    o3d_camera_trajectory_t* t = NULL;
    assert_int_equal(o3d_camera_trajectory_create(&t), O3D_OK);
    size_t n = 99;
    assert_int_equal(o3d_camera_trajectory_size(&n, t), O3D_OK);
    assert_int_equal(n, 0);
    const o3d_pinhole_intrinsic_t in = {320, 240, 300.5, 301.25, 159.5, 119.5};
    double e[16], back[16];
    rotation_z(0.4, 1.0, -2.0, 0.5, e);
    assert_int_equal(o3d_camera_trajectory_append(t, &in, e), O3D_OK);
    rotation_z(-1.1, 0.0, 0.25, 3.0, e);
    assert_int_equal(o3d_camera_trajectory_append(t, &in, e), O3D_OK);
    assert_int_equal(o3d_camera_trajectory_size(&n, t), O3D_OK);
    assert_int_equal(n, 2);
    o3d_pinhole_intrinsic_t got;
    assert_int_equal(o3d_camera_trajectory_get(&got, back, t, 1), O3D_OK);
    assert_intrinsic_equal(&got, &in);
    assert_memory_equal(back, e, sizeof e);  /* row-major in, row-major out */
    assert_int_equal(o3d_camera_trajectory_get(NULL, NULL, t, 0), O3D_OK);

    /* Errors: range, NULLs, a last row other than (0, 0, 0, 1), NaN. */
    O3D_ASSERT_FAILS(o3d_camera_trajectory_get(&got, back, t, 2), O3D_ERROR_INVALID_ARGUMENT);
    O3D_ASSERT_FAILS(o3d_camera_trajectory_get(&got, back, NULL, 0), O3D_ERROR_INVALID_ARGUMENT);
    O3D_ASSERT_FAILS(o3d_camera_trajectory_size(&n, NULL), O3D_ERROR_INVALID_ARGUMENT);
    O3D_ASSERT_FAILS(o3d_camera_trajectory_size(NULL, t), O3D_ERROR_INVALID_ARGUMENT);
    O3D_ASSERT_FAILS(o3d_camera_trajectory_append(NULL, &in, e), O3D_ERROR_INVALID_ARGUMENT);
    O3D_ASSERT_FAILS(o3d_camera_trajectory_append(t, NULL, e), O3D_ERROR_INVALID_ARGUMENT);
    O3D_ASSERT_FAILS(o3d_camera_trajectory_append(t, &in, NULL), O3D_ERROR_INVALID_ARGUMENT);
    double projective[16];
    memcpy(projective, e, sizeof e);
    projective[14] = 0.5;
    O3D_ASSERT_FAILS(o3d_camera_trajectory_append(t, &in, projective), O3D_ERROR_INVALID_ARGUMENT);
    memcpy(projective, e, sizeof e);
    projective[3] = NAN;
    O3D_ASSERT_FAILS(o3d_camera_trajectory_append(t, &in, projective), O3D_ERROR_INVALID_ARGUMENT);
    o3d_pinhole_intrinsic_t bad = in;
    bad.fx = INFINITY;
    O3D_ASSERT_FAILS(o3d_camera_trajectory_append(t, &bad, e), O3D_ERROR_INVALID_ARGUMENT);
    assert_int_equal(o3d_camera_trajectory_size(&n, t), O3D_OK);
    assert_int_equal(n, 2);  /* failed appends add nothing */

    assert_int_equal(o3d_camera_trajectory_clear(t), O3D_OK);
    assert_int_equal(o3d_camera_trajectory_size(&n, t), O3D_OK);
    assert_int_equal(n, 0);
    O3D_ASSERT_FAILS(o3d_camera_trajectory_clear(NULL), O3D_ERROR_INVALID_ARGUMENT);
    O3D_ASSERT_FAILS(o3d_camera_trajectory_create(NULL), O3D_ERROR_INVALID_ARGUMENT);
    o3d_camera_trajectory_destroy(t);
    o3d_camera_trajectory_destroy(NULL);
}

static void assert_near16(const double* m, const double* ref, double tol) {
    for (int k = 0; k < 16; ++k) assert_true(fabs(m[k] - ref[k]) <= tol);
}

static void test_read_open3d_files(void** state) {
    (void)state;
    O3D_C_TEST_DATA_OR_SKIP(intrinsic_path, "open3d/camera_primesense.json");
    o3d_pinhole_intrinsic_t in;
    assert_int_equal(o3d_io_read_pinhole_camera_intrinsic(&in, intrinsic_path), O3D_OK);
    const o3d_pinhole_intrinsic_t ps = {640, 480, 525.0, 525.0, 319.5, 239.5};
    assert_intrinsic_equal(&in, &ps);

    O3D_C_TEST_DATA_OR_SKIP(json_path, "open3d/camera_trajectory.json");
    o3d_camera_trajectory_t* t = NULL;
    assert_int_equal(o3d_io_read_pinhole_camera_trajectory(&t, json_path, NULL), O3D_OK);
    size_t n = 0;
    assert_int_equal(o3d_camera_trajectory_size(&n, t), O3D_OK);
    assert_int_equal(n, 31);
    double e[16];
    assert_int_equal(o3d_camera_trajectory_get(&in, e, t, 1), O3D_OK);
    const double e1[16] = {0.9992879577710159,   -0.006715136819757545, 0.0371279462308972, -2.3078035383191513,
                           0.016150876271446853, 0.9654520063147016,    -0.260079935209508, -1.2035828634030123,
                           -0.03409877782995854, 0.2604943961785155,    0.9648730190600698, 1.125458179216736,
                           0.0,                  0.0,                   0.0,                1.0};
    assert_near16(e, e1, 0.0);
    assert_int_equal(in.width, 1920);
    o3d_camera_trajectory_destroy(t);

    O3D_C_TEST_DATA_OR_SKIP(log_path, "open3d/RGBD/trajectory.log");
    assert_int_equal(o3d_io_read_pinhole_camera_trajectory(&t, log_path, "log"), O3D_OK);
    assert_int_equal(o3d_camera_trajectory_size(&n, t), O3D_OK);
    assert_int_equal(n, 5);
    assert_int_equal(o3d_camera_trajectory_get(&in, e, t, 4), O3D_OK);
    assert_intrinsic_equal(&in, &ps);  /* .log carries no intrinsic: PrimeSense default */
    const double e4[16] = {-0.2589186421085548, 0.0,  -0.9658991338481787,  1.9684600200041038,
                           0.07016430847656363, -0.997358120495347,   -0.018808224211631922, 0.7304114882103011,
                           -0.9633473447229031, -0.07264144465791822, 0.2582346102545956,    -0.795113314908377,
                           0.0,                 0.0,                  0.0,                   1.0};
    assert_near16(e, e4, 1e-14);
    o3d_camera_trajectory_destroy(t);
}

static void test_round_trips(void** state) {
    (void)state;
    char path[256];
    const o3d_pinhole_intrinsic_t in = {321, 243, 500.125, 499.875, 160.25, 121.75};
    double e[16], back[16];
    rotation_z(0.8, -1.0 / 3.0, 2.5, 0.125, e);

    temp_path(path, sizeof path, "intrinsic.json");
    assert_int_equal(o3d_io_write_pinhole_camera_intrinsic(path, &in), O3D_OK);
    o3d_pinhole_intrinsic_t got;
    assert_int_equal(o3d_io_read_pinhole_camera_intrinsic(&got, path), O3D_OK);
    assert_intrinsic_equal(&got, &in);
    remove(path);

    temp_path(path, sizeof path, "params.json");
    assert_int_equal(o3d_io_write_pinhole_camera_parameters(path, &in, e), O3D_OK);
    assert_int_equal(o3d_io_read_pinhole_camera_parameters(&got, back, path), O3D_OK);
    assert_intrinsic_equal(&got, &in);
    assert_memory_equal(back, e, sizeof e);
    assert_int_equal(o3d_io_read_pinhole_camera_parameters(NULL, NULL, path), O3D_OK);
    remove(path);

    o3d_camera_trajectory_t* t = NULL;
    assert_int_equal(o3d_camera_trajectory_create(&t), O3D_OK);
    assert_int_equal(o3d_camera_trajectory_append(t, &in, e), O3D_OK);
    rotation_z(-2.0, 4.0, 0.0, -1.0, e);
    assert_int_equal(o3d_camera_trajectory_append(t, &in, e), O3D_OK);

    temp_path(path, sizeof path, "traj.json");
    assert_int_equal(o3d_io_write_pinhole_camera_trajectory(path, t, NULL), O3D_OK);
    o3d_camera_trajectory_t* json = NULL;
    assert_int_equal(o3d_io_read_pinhole_camera_trajectory(&json, path, "json"), O3D_OK);
    assert_int_equal(o3d_camera_trajectory_get(&got, back, json, 1), O3D_OK);
    assert_intrinsic_equal(&got, &in);
    assert_memory_equal(back, e, sizeof e);  /* JSON keeps every bit */
    o3d_camera_trajectory_destroy(json);
    remove(path);

    temp_path(path, sizeof path, "traj.log");
    assert_int_equal(o3d_io_write_pinhole_camera_trajectory(path, t, "auto"), O3D_OK);
    o3d_camera_trajectory_t* log = NULL;
    assert_int_equal(o3d_io_read_pinhole_camera_trajectory(&log, path, NULL), O3D_OK);
    size_t n = 0;
    assert_int_equal(o3d_camera_trajectory_size(&n, log), O3D_OK);
    assert_int_equal(n, 2);
    assert_int_equal(o3d_camera_trajectory_get(&got, back, log, 1), O3D_OK);
    assert_near16(back, e, 1e-14);  /* inverted on write and on read */
    assert_int_equal(got.width, 640);
    o3d_camera_trajectory_destroy(log);
    remove(path);
    o3d_camera_trajectory_destroy(t);
}

static void test_io_errors(void** state) {
    (void)state;
    char path[256];
    o3d_pinhole_intrinsic_t in = {640, 480, 525.0, 525.0, 319.5, 239.5};
    double e[16];
    o3d_camera_trajectory_t* t = (o3d_camera_trajectory_t*)&in; /* must be cleared on failure */

    O3D_ASSERT_FAILS(o3d_io_read_pinhole_camera_intrinsic(&in, "/nonexistent/o3d/camera.json"), O3D_ERROR_IO);
    O3D_ASSERT_FAILS(o3d_io_read_pinhole_camera_trajectory(&t, "/nonexistent/o3d/t.json", NULL), O3D_ERROR_IO);
    assert_null(t);
    O3D_ASSERT_FAILS(o3d_io_read_pinhole_camera_trajectory(&t, "/tmp/o3d_t.txt", NULL), O3D_ERROR_UNSUPPORTED);
    O3D_ASSERT_FAILS(o3d_io_read_pinhole_camera_trajectory(&t, "/tmp/o3d_t.json", "xml"), O3D_ERROR_UNSUPPORTED);

    temp_path(path, sizeof path, "bad.json");
    write_text(path, "{\"width\": 640, \"height\": 480, \"intrinsic_matrix\": [1, 2, 3]}");
    O3D_ASSERT_FAILS(o3d_io_read_pinhole_camera_intrinsic(&in, path), O3D_ERROR_PARSE);
    write_text(path, "{\"width\": 640, ");
    O3D_ASSERT_FAILS(o3d_io_read_pinhole_camera_intrinsic(&in, path), O3D_ERROR_PARSE);
    O3D_ASSERT_FAILS(o3d_io_read_pinhole_camera_parameters(&in, e, path), O3D_ERROR_PARSE);
    O3D_ASSERT_FAILS(o3d_io_read_pinhole_camera_trajectory(&t, path, NULL), O3D_ERROR_PARSE);
    remove(path);
    temp_path(path, sizeof path, "bad.log");
    write_text(path, "0 0 1\n1 0 0 0\n0 1 0 0\n0 0 1\n");
    O3D_ASSERT_FAILS(o3d_io_read_pinhole_camera_trajectory(&t, path, NULL), O3D_ERROR_PARSE);
    assert_null(t);
    remove(path);

    O3D_ASSERT_FAILS(o3d_io_read_pinhole_camera_intrinsic(&in, NULL), O3D_ERROR_INVALID_ARGUMENT);
    O3D_ASSERT_FAILS(o3d_io_read_pinhole_camera_intrinsic(NULL, "/tmp/x.json"), O3D_ERROR_INVALID_ARGUMENT);
    O3D_ASSERT_FAILS(o3d_io_write_pinhole_camera_intrinsic(NULL, &in), O3D_ERROR_INVALID_ARGUMENT);
    O3D_ASSERT_FAILS(o3d_io_write_pinhole_camera_intrinsic("/tmp/x.json", NULL), O3D_ERROR_INVALID_ARGUMENT);
    O3D_ASSERT_FAILS(o3d_io_read_pinhole_camera_parameters(&in, e, NULL), O3D_ERROR_INVALID_ARGUMENT);
    O3D_ASSERT_FAILS(o3d_io_write_pinhole_camera_parameters("/tmp/x.json", &in, NULL), O3D_ERROR_INVALID_ARGUMENT);
    O3D_ASSERT_FAILS(o3d_io_read_pinhole_camera_trajectory(NULL, "/tmp/x.json", NULL), O3D_ERROR_INVALID_ARGUMENT);
    O3D_ASSERT_FAILS(o3d_io_read_pinhole_camera_trajectory(&t, NULL, NULL), O3D_ERROR_INVALID_ARGUMENT);
    O3D_ASSERT_FAILS(o3d_io_write_pinhole_camera_trajectory("/tmp/x.json", NULL, NULL), O3D_ERROR_INVALID_ARGUMENT);

    /* Non-finite values cannot be written as JSON; a singular extrinsic has no .log pose. */
    temp_path(path, sizeof path, "nan.json");
    in.cx = NAN;
    O3D_ASSERT_FAILS(o3d_io_write_pinhole_camera_intrinsic(path, &in), O3D_ERROR_INVALID_ARGUMENT);
    in.cx = 319.5;
    rotation_z(0.0, 0.0, 0.0, 0.0, e);
    e[5] = 0.0;  /* singular, but rigid layout */
    assert_int_equal(o3d_camera_trajectory_create(&t), O3D_OK);
    assert_int_equal(o3d_camera_trajectory_append(t, &in, e), O3D_OK);
    temp_path(path, sizeof path, "singular.log");
    O3D_ASSERT_FAILS(o3d_io_write_pinhole_camera_trajectory(path, t, NULL), O3D_ERROR_INVALID_ARGUMENT);
    O3D_ASSERT_FAILS(o3d_io_write_pinhole_camera_trajectory("/nonexistent/o3d/t.json", t, NULL), O3D_ERROR_IO);
    o3d_camera_trajectory_destroy(t);
    remove(path);
}

int main(void) {
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_presets),
        cmocka_unit_test(test_trajectory_handle),
        cmocka_unit_test(test_read_open3d_files),
        cmocka_unit_test(test_round_trips),
        cmocka_unit_test(test_io_errors),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
