/* SPDX-License-Identifier: MIT */
/* C API odometry.h. Checked: a frame against itself gives the identity exactly (no data needed), Open3D's result on
 * its RGBD test frames 0 -> 1 (recorded from the open3d 0.20 wheel, hybrid term, default options, PrimeSense
 * intrinsics: t = (-0.0010704978, 0.0232280983, 0.0014059205), 252387 correspondences on the information
 * diagonal), frames that do not overlap, and the error paths. */
#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>

#include <cmocka.h>

#include "o3d/o3d.h"
#include "o3d_test_util.h"

#define W 160
#define H 120

/* A float image from a function of the pixel. */
static o3d_image_t* float_image(float (*f)(int u, int v)) {
    float* px = malloc(sizeof(float) * W * H);
    for (int v = 0; v < H; ++v)
        for (int u = 0; u < W; ++u) px[v * W + u] = f(u, v);
    o3d_image_t* image = NULL;
    assert_int_equal(o3d_image_create_from_data(&image, W, H, 1, 4, (const uint8_t*)px, sizeof(float) * W * H), O3D_OK);
    free(px);
    return image;
}

static float textured(int u, int v) { return (float)(0.5 + 0.2 * sin(0.3 * u) * cos(0.25 * v) + 0.1 * sin(0.11 * (u + v))); }
static float slanted_depth(int u, int v) { return (float)(1.5 + 0.004 * u + 0.002 * v); }

static o3d_rgbd_image_t* synthetic_frame(void) {
    o3d_image_t* color = float_image(textured);
    o3d_image_t* depth = float_image(slanted_depth);
    o3d_rgbd_options_t o;
    assert_int_equal(o3d_rgbd_options_init(&o, sizeof o), O3D_OK);
    o.depth_scale = 1.0; /* float metres already */
    o3d_rgbd_image_t* rgbd = NULL;
    assert_int_equal(o3d_rgbd_image_create_from_color_and_depth(&rgbd, color, depth, &o), O3D_OK);
    o3d_image_destroy(color);
    o3d_image_destroy(depth);
    return rgbd;
}

static const o3d_pinhole_intrinsic_t kSmall = {W, H, 130.0, 130.0, 79.5, 59.5};

static void test_a_frame_onto_itself_is_the_identity(void** state) {
    (void)state;
    o3d_rgbd_image_t* frame = synthetic_frame();
    o3d_bool ok = 0;
    double t[16], info[36];
    for (o3d_odometry_jacobian j = O3D_ODOMETRY_JACOBIAN_COLOR_TERM; j <= O3D_ODOMETRY_JACOBIAN_HYBRID_TERM; ++j) {
        assert_int_equal(o3d_odometry_compute_rgbd(&ok, t, info, frame, frame, &kSmall, NULL, j, NULL, 0, NULL), O3D_OK);
        assert_true(ok);
        for (int i = 0; i < 16; ++i) assert_float_equal(t[i], (i % 5 == 0) ? 1.0 : 0.0, 1e-12);
        /* Every pixel but the border the smoothing and the pyramid eat corresponds. */
        assert_true(info[3 * 6 + 3] > 0.9 * W * H);
    }
    o3d_rgbd_image_destroy(frame);
}

static void test_open3d_frames_zero_to_one(void** state) {
    (void)state;
    o3d_rgbd_image_t* frames[2];
    for (int i = 0; i < 2; ++i) {
        char rel[64];
        o3d_image_t *color = NULL, *depth = NULL;
        snprintf(rel, sizeof rel, "open3d/RGBD/color/0000%d.jpg", i);
        O3D_C_TEST_DATA_OR_SKIP(color_path, rel);
        assert_int_equal(o3d_io_read_image(&color, color_path, NULL), O3D_OK);
        snprintf(rel, sizeof rel, "open3d/RGBD/depth/0000%d.png", i);
        O3D_C_TEST_DATA_OR_SKIP(depth_path, rel);
        assert_int_equal(o3d_io_read_image(&depth, depth_path, NULL), O3D_OK);
        assert_int_equal(o3d_rgbd_image_create_from_color_and_depth(&frames[i], color, depth, NULL), O3D_OK);
        o3d_image_destroy(color);
        o3d_image_destroy(depth);
    }
    const o3d_pinhole_intrinsic_t primesense = {640, 480, 525.0, 525.0, 319.5, 239.5};
    const int32_t iterations[3] = {20, 10, 5};
    o3d_bool ok = 0;
    double t[16], info[36];
    assert_int_equal(o3d_odometry_compute_rgbd(&ok, t, info, frames[0], frames[1], &primesense, NULL,
                                               O3D_ODOMETRY_JACOBIAN_HYBRID_TERM, iterations, 3, NULL), O3D_OK);
    assert_true(ok);
    assert_float_equal(t[3], -0.0010704978, 1e-5);
    assert_float_equal(t[7], 0.0232280983, 1e-5);
    assert_float_equal(t[11], 0.0014059205, 1e-5);
    assert_float_equal(info[3 * 6 + 3], 252387, 0.001 * 252387);
    /* Ignore everything beyond 0.3 m: nothing left to align, no solution, and no error. */
    o3d_odometry_options_t near;
    assert_int_equal(o3d_odometry_options_init(&near, sizeof near), O3D_OK);
    near.depth_max = 0.3;
    assert_int_equal(o3d_odometry_compute_rgbd(&ok, t, info, frames[0], frames[1], &primesense, NULL,
                                               O3D_ODOMETRY_JACOBIAN_HYBRID_TERM, NULL, 0, &near), O3D_OK);
    assert_false(ok);
    assert_float_equal(t[0], 1.0, 0);
    assert_float_equal(t[3], 0.0, 0);
    o3d_rgbd_image_destroy(frames[0]);
    o3d_rgbd_image_destroy(frames[1]);
}

static void test_errors(void** state) {
    (void)state;
    o3d_rgbd_image_t* frame = synthetic_frame();
    o3d_bool ok = 0;
    double t[16], info[36];
    const o3d_pinhole_intrinsic_t wrong_size = {W * 2, H * 2, 130.0, 130.0, 79.5, 59.5};
    O3D_ASSERT_FAILS(o3d_odometry_compute_rgbd(&ok, t, info, frame, frame, &wrong_size, NULL,
                                               O3D_ODOMETRY_JACOBIAN_COLOR_TERM, NULL, 0, NULL),
                     O3D_ERROR_INVALID_ARGUMENT);
    O3D_ASSERT_FAILS(o3d_odometry_compute_rgbd(&ok, t, info, frame, NULL, &kSmall, NULL,
                                               O3D_ODOMETRY_JACOBIAN_COLOR_TERM, NULL, 0, NULL),
                     O3D_ERROR_INVALID_ARGUMENT);
    O3D_ASSERT_FAILS(o3d_odometry_compute_rgbd(&ok, t, info, frame, frame, &kSmall, NULL, 7, NULL, 0, NULL),
                     O3D_ERROR_INVALID_ARGUMENT);
    const int32_t iterations[9] = {1, 1, 1, 1, 1, 1, 1, 1, 1};
    O3D_ASSERT_FAILS(o3d_odometry_compute_rgbd(&ok, t, info, frame, frame, &kSmall, NULL,
                                               O3D_ODOMETRY_JACOBIAN_COLOR_TERM, iterations, 9, NULL),
                     O3D_ERROR_INVALID_ARGUMENT);
    const double nan_init[16] = {NAN, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1};
    O3D_ASSERT_FAILS(o3d_odometry_compute_rgbd(&ok, t, info, frame, frame, &kSmall, nan_init,
                                               O3D_ODOMETRY_JACOBIAN_COLOR_TERM, NULL, 0, NULL),
                     O3D_ERROR_INVALID_ARGUMENT);
    /* An 8-bit color image is not odometry input. */
    o3d_image_t* rgb = NULL;
    o3d_image_t* depth = float_image(slanted_depth);
    assert_int_equal(o3d_image_create(&rgb, W, H, 3, 1), O3D_OK);
    o3d_rgbd_options_t o;
    assert_int_equal(o3d_rgbd_options_init(&o, sizeof o), O3D_OK);
    o.convert_rgb_to_intensity = 0;
    o.depth_scale = 1.0;
    o3d_rgbd_image_t* colored = NULL;
    assert_int_equal(o3d_rgbd_image_create_from_color_and_depth(&colored, rgb, depth, &o), O3D_OK);
    O3D_ASSERT_FAILS(o3d_odometry_compute_rgbd(&ok, t, info, colored, frame, &kSmall, NULL,
                                               O3D_ODOMETRY_JACOBIAN_COLOR_TERM, NULL, 0, NULL),
                     O3D_ERROR_INVALID_ARGUMENT);
    o3d_rgbd_image_destroy(colored);
    o3d_image_destroy(rgb);
    o3d_image_destroy(depth);
    o3d_rgbd_image_destroy(frame);
}

int main(void) {
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_a_frame_onto_itself_is_the_identity),
        cmocka_unit_test(test_open3d_frames_zero_to_one),
        cmocka_unit_test(test_errors),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
