/* SPDX-License-Identifier: MIT */
/* C API rgbd.h: RGB-D images, the dataset readers and back-projection (analytic on synthetic depth; the real
 * frame RGBD/{color,depth}/00000 against Open3D 0.20.0, numbers printed by tools/reference/record_rgbd.py),
 * plus options versioning and the NULL / format / size / non-rigid paths. */
#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include <cmocka.h>

#include "o3d/o3d.h"
#include "o3d_test_util.h"

static o3d_image_t* make_image(int w, int h, int channels, int bytes, const void* data) {
    o3d_image_t* image = NULL;
    assert_int_equal(o3d_image_create_from_data(&image, w, h, channels, bytes, (const uint8_t*)data,
                                                (size_t)w * h * channels * bytes),
                     O3D_OK);
    return image;
}

static float float_at(const o3d_image_t* image, int index) {
    const uint8_t* data = NULL;
    size_t size = 0;
    assert_int_equal(o3d_image_array_view(&data, &size, image, O3D_IMAGE_DATA), O3D_OK);
    assert_true((size_t)(index + 1) * 4 <= size);
    float v;
    memcpy(&v, data + 4 * index, 4);
    return v;
}

static void test_options_init(void** state) {
    (void)state;
    o3d_rgbd_options_t r;
    assert_int_equal(o3d_rgbd_options_init(&r, sizeof r), O3D_OK);
    assert_true(r.struct_size == sizeof r && r.depth_scale == 1000.0 && r.depth_trunc == 3.0);
    assert_int_equal(r.convert_rgb_to_intensity, 1);
    o3d_depth_to_cloud_options_t d;
    assert_int_equal(o3d_depth_to_cloud_options_init(&d, sizeof d), O3D_OK);
    assert_true(d.depth_scale == 1000.0 && d.depth_trunc == 1000.0);
    assert_int_equal(d.stride, 1);
    assert_int_equal(d.project_valid_depth_only, 1);
    O3D_ASSERT_FAILS(o3d_rgbd_options_init(NULL, sizeof r), O3D_ERROR_INVALID_ARGUMENT);
    O3D_ASSERT_FAILS(o3d_rgbd_options_init(&r, sizeof r + 8), O3D_ERROR_INVALID_ARGUMENT);
    O3D_ASSERT_FAILS(o3d_depth_to_cloud_options_init(&d, 2), O3D_ERROR_INVALID_ARGUMENT);
}

static void test_color_and_depth(void** state) {
    (void)state;
    const uint16_t raw[6] = {0, 1000, 2999, 3000, 65535, 1500};
    uint8_t rgb[18];
    for (int i = 0; i < 18; ++i) rgb[i] = (uint8_t)(29 * i + 3);
    o3d_image_t* depth = make_image(3, 2, 1, 2, raw);
    o3d_image_t* color = make_image(3, 2, 3, 1, rgb);

    o3d_rgbd_image_t* rgbd = NULL;
    assert_int_equal(o3d_rgbd_image_create_from_color_and_depth(&rgbd, color, depth, NULL), O3D_OK);
    o3d_image_t* d = NULL;
    o3d_image_t* c = NULL;
    assert_int_equal(o3d_rgbd_image_get_depth(&d, rgbd), O3D_OK);
    assert_int_equal(o3d_rgbd_image_get_color(&c, rgbd), O3D_OK);
    const float expected[6] = {0.0f, 1.0f, 2999.0f / 1000.0f, 0.0f, 0.0f, 1.5f};
    for (int i = 0; i < 6; ++i) assert_true(float_at(d, i) == expected[i]);
    int32_t channels = 0, bytes = 0;
    assert_int_equal(o3d_image_num_channels(&channels, c), O3D_OK);
    assert_int_equal(o3d_image_bytes_per_channel(&bytes, c), O3D_OK);
    assert_int_equal(channels, 1);
    assert_int_equal(bytes, 4);
    for (int i = 0; i < 6; ++i)
        assert_true(fabs(float_at(c, i) - (0.299 * rgb[3 * i] + 0.587 * rgb[3 * i + 1] + 0.114 * rgb[3 * i + 2]) /
                                              255.0) < 1e-6);
    o3d_image_destroy(d);
    o3d_image_destroy(c);
    o3d_rgbd_image_destroy(rgbd);

    /* An older, shorter options struct (without convert_rgb_to_intensity) keeps the default 1. */
    o3d_rgbd_options_t opts;
    assert_int_equal(o3d_rgbd_options_init(&opts, (uint32_t)offsetof(o3d_rgbd_options_t, convert_rgb_to_intensity)),
                     O3D_OK);
    opts.convert_rgb_to_intensity = 0; /* beyond struct_size: not read */
    assert_int_equal(o3d_rgbd_image_create_from_color_and_depth(&rgbd, color, depth, &opts), O3D_OK);
    assert_int_equal(o3d_rgbd_image_get_color(&c, rgbd), O3D_OK);
    assert_int_equal(o3d_image_num_channels(&channels, c), O3D_OK);
    assert_int_equal(channels, 1);
    o3d_image_destroy(c);
    o3d_rgbd_image_destroy(rgbd);

    assert_int_equal(o3d_rgbd_options_init(&opts, sizeof opts), O3D_OK);
    opts.depth_scale = 500.0;
    opts.depth_trunc = 200.0;
    opts.convert_rgb_to_intensity = 0;
    assert_int_equal(o3d_rgbd_image_create_from_color_and_depth(&rgbd, color, depth, &opts), O3D_OK);
    assert_int_equal(o3d_rgbd_image_get_depth(&d, rgbd), O3D_OK);
    assert_true(float_at(d, 1) == 2.0f && float_at(d, 4) == 65535.0f / 500.0f);
    assert_int_equal(o3d_rgbd_image_get_color(&c, rgbd), O3D_OK);
    const uint8_t* data = NULL;
    size_t size = 0;
    assert_int_equal(o3d_image_array_view(&data, &size, c, O3D_IMAGE_DATA), O3D_OK);
    assert_int_equal(size, 18);
    assert_memory_equal(data, rgb, 18);
    o3d_image_destroy(d);
    o3d_image_destroy(c);
    o3d_rgbd_image_destroy(rgbd);

    /* Errors: NULLs (out cleared), size mismatch, bad formats, bad options. */
    o3d_image_t* small = make_image(2, 3, 3, 1, rgb);
    rgbd = (o3d_rgbd_image_t*)depth;
    O3D_ASSERT_FAILS(o3d_rgbd_image_create_from_color_and_depth(&rgbd, small, depth, NULL), O3D_ERROR_INVALID_ARGUMENT);
    assert_null(rgbd);
    O3D_ASSERT_FAILS(o3d_rgbd_image_create_from_color_and_depth(NULL, color, depth, NULL), O3D_ERROR_INVALID_ARGUMENT);
    O3D_ASSERT_FAILS(o3d_rgbd_image_create_from_color_and_depth(&rgbd, NULL, depth, NULL), O3D_ERROR_INVALID_ARGUMENT);
    O3D_ASSERT_FAILS(o3d_rgbd_image_create_from_color_and_depth(&rgbd, color, NULL, NULL), O3D_ERROR_INVALID_ARGUMENT);
    O3D_ASSERT_FAILS(o3d_rgbd_image_create_from_color_and_depth(&rgbd, color, color, NULL), O3D_ERROR_INVALID_ARGUMENT);
    opts.depth_scale = NAN;
    O3D_ASSERT_FAILS(o3d_rgbd_image_create_from_color_and_depth(&rgbd, color, depth, &opts), O3D_ERROR_INVALID_ARGUMENT);
    opts.struct_size = 1000;
    O3D_ASSERT_FAILS(o3d_rgbd_image_create_from_color_and_depth(&rgbd, color, depth, &opts), O3D_ERROR_INVALID_ARGUMENT);
    O3D_ASSERT_FAILS(o3d_rgbd_image_get_color(&c, NULL), O3D_ERROR_INVALID_ARGUMENT);
    O3D_ASSERT_FAILS(o3d_rgbd_image_get_depth(NULL, NULL), O3D_ERROR_INVALID_ARGUMENT);
    o3d_rgbd_image_destroy(NULL);
    o3d_image_destroy(small);
    o3d_image_destroy(color);
    o3d_image_destroy(depth);
}

static void test_dataset_formats(void** state) {
    (void)state;
    /* Raw samples and Open3D's depths: record_rgbd.py "SUN / NYU on raw samples" (a subset). */
    const uint16_t raw[6] = {8, 55992, 0x4400, 0x1204, 0x8000, 0xff03};
    const float sun[6] = {0.0010000000474974513f, 6.999000072479248f, 2.1760001182556152f, 0.0f,
                          4.0960001945495605f, 0.0f};
    const float nyu[6] = {0.0f, 0.0f, 0.34299999475479126f, 6.955999851226807f, 0.36399999260902405f,
                          5.054999828338623f};
    uint8_t rgb[18] = {0};
    o3d_image_t* depth = make_image(6, 1, 1, 2, raw);
    o3d_image_t* color = make_image(6, 1, 3, 1, rgb);
    o3d_rgbd_image_t* rgbd = NULL;
    o3d_image_t* d = NULL;
    assert_int_equal(o3d_rgbd_image_create_from_dataset_format(&rgbd, O3D_RGBD_FORMAT_SUN, color, depth, 1), O3D_OK);
    assert_int_equal(o3d_rgbd_image_get_depth(&d, rgbd), O3D_OK);
    for (int i = 0; i < 6; ++i) assert_true(float_at(d, i) == sun[i]);
    o3d_image_destroy(d);
    o3d_rgbd_image_destroy(rgbd);
    assert_int_equal(o3d_rgbd_image_create_from_dataset_format(&rgbd, O3D_RGBD_FORMAT_NYU, color, depth, 0), O3D_OK);
    assert_int_equal(o3d_rgbd_image_get_depth(&d, rgbd), O3D_OK);
    for (int i = 0; i < 6; ++i) assert_true(float_at(d, i) == nyu[i]);
    o3d_image_destroy(d);
    o3d_rgbd_image_destroy(rgbd);
    /* The caller's depth image is untouched. */
    const uint8_t* data = NULL;
    size_t size = 0;
    assert_int_equal(o3d_image_array_view(&data, &size, depth, O3D_IMAGE_DATA), O3D_OK);
    assert_memory_equal(data, raw, sizeof raw);

    assert_int_equal(o3d_rgbd_image_create_from_dataset_format(&rgbd, O3D_RGBD_FORMAT_TUM, color, depth, 1), O3D_OK);
    assert_int_equal(o3d_rgbd_image_get_depth(&d, rgbd), O3D_OK);
    assert_true(float_at(d, 0) == 8.0f / 5000.0f);
    assert_true(float_at(d, 1) == 0.0f);  /* 11.2 m > 4 m */
    o3d_image_destroy(d);
    o3d_rgbd_image_destroy(rgbd);
    assert_int_equal(o3d_rgbd_image_create_from_dataset_format(&rgbd, O3D_RGBD_FORMAT_REDWOOD, color, depth, 1),
                     O3D_OK);
    o3d_rgbd_image_destroy(rgbd);

    O3D_ASSERT_FAILS(o3d_rgbd_image_create_from_dataset_format(&rgbd, 4, color, depth, 1), O3D_ERROR_INVALID_ARGUMENT);
    assert_null(rgbd);
    O3D_ASSERT_FAILS(o3d_rgbd_image_create_from_dataset_format(&rgbd, -1, color, depth, 1), O3D_ERROR_INVALID_ARGUMENT);
    O3D_ASSERT_FAILS(o3d_rgbd_image_create_from_dataset_format(&rgbd, O3D_RGBD_FORMAT_SUN, NULL, depth, 1),
                     O3D_ERROR_INVALID_ARGUMENT);
    O3D_ASSERT_FAILS(o3d_rgbd_image_create_from_dataset_format(&rgbd, O3D_RGBD_FORMAT_NYU, color, color, 1),
                     O3D_ERROR_INVALID_ARGUMENT);
    o3d_image_destroy(color);
    o3d_image_destroy(depth);
}

/* 4 x 3 float depth in metres; pixel (1, 0) invalid (0) and (3, 2) NaN. */
static const float kDepth[12] = {1.0f, 0.0f, 1.5f, 2.0f, 2.5f, 3.0f, 3.5f, 4.0f, 4.5f, 5.0f, 5.5f, NAN};
static const o3d_pinhole_intrinsic_t kIntrinsic = {4, 3, 2.0, 2.5, 1.5, 0.75};

static void test_back_projection_synthetic(void** state) {
    (void)state;
    o3d_image_t* depth = make_image(4, 3, 1, 4, kDepth);
    /* world-to-camera: rotation by 90 degrees about z, then a translation. */
    const double extrinsic[16] = {0, -1, 0, 1.0, 1, 0, 0, -2.0, 0, 0, 1, 0.5, 0, 0, 0, 1};
    o3d_pointcloud_t* pc = NULL;
    assert_int_equal(o3d_pointcloud_create_from_depth_image(&pc, depth, &kIntrinsic, extrinsic, NULL), O3D_OK);
    size_t n = 0;
    const double* xyz = NULL;
    assert_int_equal(o3d_pointcloud_array_view(&xyz, &n, pc, O3D_POINTCLOUD_POINTS), O3D_OK);
    assert_int_equal(n, 10);
    size_t k = 0;
    for (int v = 0; v < 3; ++v)
        for (int u = 0; u < 4; ++u) {
            const double z = kDepth[4 * v + u];
            if (!(z > 0)) continue;
            const double cam[3] = {(u - kIntrinsic.cx) * z / kIntrinsic.fx, (v - kIntrinsic.cy) * z / kIntrinsic.fy, z};
            /* extrinsic * world == camera point */
            const double* w = xyz + 3 * k++;
            for (int r = 0; r < 3; ++r) {
                const double back = extrinsic[4 * r] * w[0] + extrinsic[4 * r + 1] * w[1] +
                                    extrinsic[4 * r + 2] * w[2] + extrinsic[4 * r + 3];
                assert_true(fabs(back - cam[r]) < 1e-12);
            }
        }
    o3d_pointcloud_destroy(pc);

    /* Organised with stride 2: pixels (0,0) (2,0) (0,2) (2,2); truncation at 4.75 m drops (2,2) = 5.5 m. */
    o3d_depth_to_cloud_options_t opts;
    assert_int_equal(o3d_depth_to_cloud_options_init(&opts, sizeof opts), O3D_OK);
    opts.stride = 2;
    opts.depth_trunc = 4.75;
    opts.project_valid_depth_only = 0;
    assert_int_equal(o3d_pointcloud_create_from_depth_image(&pc, depth, &kIntrinsic, NULL, &opts), O3D_OK);
    assert_int_equal(o3d_pointcloud_array_view(&xyz, &n, pc, O3D_POINTCLOUD_POINTS), O3D_OK);
    assert_int_equal(n, 4);
    assert_true(xyz[0] == (0 - 1.5) * 1.0 / 2.0 && xyz[1] == (0 - 0.75) * 1.0 / 2.5 && xyz[2] == 1.0);
    assert_true(xyz[3] == (2 - 1.5) * 1.5 / 2.0 && xyz[5] == 1.5);
    assert_true(xyz[6] == (0 - 1.5) * 4.5 / 2.0 && xyz[7] == (2 - 0.75) * 4.5 / 2.5 && xyz[8] == 4.5);
    assert_true(isnan(xyz[9]) && isnan(xyz[10]) && isnan(xyz[11]));
    o3d_pointcloud_destroy(pc);

    /* Errors. */
    const double projective[16] = {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0.1, 1};
    const double singular[16] = {1, 0, 0, 0, 0, 0, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1};
    pc = (o3d_pointcloud_t*)depth;
    O3D_ASSERT_FAILS(o3d_pointcloud_create_from_depth_image(&pc, depth, &kIntrinsic, projective, NULL),
                     O3D_ERROR_INVALID_ARGUMENT);
    assert_null(pc);
    O3D_ASSERT_FAILS(o3d_pointcloud_create_from_depth_image(&pc, depth, &kIntrinsic, singular, NULL),
                     O3D_ERROR_INVALID_ARGUMENT);
    O3D_ASSERT_FAILS(o3d_pointcloud_create_from_depth_image(NULL, depth, &kIntrinsic, NULL, NULL),
                     O3D_ERROR_INVALID_ARGUMENT);
    O3D_ASSERT_FAILS(o3d_pointcloud_create_from_depth_image(&pc, NULL, &kIntrinsic, NULL, NULL),
                     O3D_ERROR_INVALID_ARGUMENT);
    O3D_ASSERT_FAILS(o3d_pointcloud_create_from_depth_image(&pc, depth, NULL, NULL, NULL), O3D_ERROR_INVALID_ARGUMENT);
    opts.stride = 0;
    O3D_ASSERT_FAILS(o3d_pointcloud_create_from_depth_image(&pc, depth, &kIntrinsic, NULL, &opts),
                     O3D_ERROR_INVALID_ARGUMENT);
    o3d_pinhole_intrinsic_t bad = kIntrinsic;
    bad.fy = 0.0;
    O3D_ASSERT_FAILS(o3d_pointcloud_create_from_depth_image(&pc, depth, &bad, NULL, NULL), O3D_ERROR_INVALID_ARGUMENT);
    uint8_t rgb[36] = {0};
    o3d_image_t* color = make_image(4, 3, 3, 1, rgb);
    O3D_ASSERT_FAILS(o3d_pointcloud_create_from_depth_image(&pc, color, &kIntrinsic, NULL, NULL),
                     O3D_ERROR_INVALID_ARGUMENT);
    O3D_ASSERT_FAILS(o3d_pointcloud_create_from_rgbd_image(&pc, NULL, &kIntrinsic, NULL, 1), O3D_ERROR_INVALID_ARGUMENT);
    o3d_rgbd_image_t* rgbd = NULL;
    o3d_rgbd_options_t ro;
    assert_int_equal(o3d_rgbd_options_init(&ro, sizeof ro), O3D_OK);
    ro.depth_scale = 1.0;
    ro.depth_trunc = 100.0;
    assert_int_equal(o3d_rgbd_image_create_from_color_and_depth(&rgbd, color, depth, &ro), O3D_OK);
    O3D_ASSERT_FAILS(o3d_pointcloud_create_from_rgbd_image(&pc, rgbd, NULL, NULL, 1), O3D_ERROR_INVALID_ARGUMENT);
    O3D_ASSERT_FAILS(o3d_pointcloud_create_from_rgbd_image(&pc, rgbd, &kIntrinsic, projective, 1),
                     O3D_ERROR_INVALID_ARGUMENT);
    assert_int_equal(o3d_pointcloud_create_from_rgbd_image(&pc, rgbd, &kIntrinsic, NULL, 1), O3D_OK);
    int32_t has = 0;
    assert_int_equal(o3d_pointcloud_has_array(&has, pc, O3D_POINTCLOUD_COLORS), O3D_OK);
    assert_int_equal(has, 1);
    o3d_pointcloud_destroy(pc);
    o3d_rgbd_image_destroy(rgbd);
    o3d_image_destroy(color);
    o3d_image_destroy(depth);
}

static void test_back_projection_real_frame(void** state) {
    (void)state;
    /* o3d_test_data_path returns a static buffer: use each path before asking for the next. */
    o3d_image_t* color = NULL;
    o3d_image_t* depth = NULL;
    O3D_C_TEST_DATA_OR_SKIP(color_path, "open3d/RGBD/color/00000.jpg");
    assert_int_equal(o3d_io_read_image(&color, color_path, NULL), O3D_OK);
    O3D_C_TEST_DATA_OR_SKIP(depth_path, "open3d/RGBD/depth/00000.png");
    assert_int_equal(o3d_io_read_image(&depth, depth_path, NULL), O3D_OK);
    o3d_pinhole_intrinsic_t ps;
    assert_int_equal(o3d_pinhole_intrinsic_set_preset(&ps, O3D_INTRINSIC_PRIMESENSE_DEFAULT), O3D_OK);
    o3d_rgbd_options_t opts;
    assert_int_equal(o3d_rgbd_options_init(&opts, sizeof opts), O3D_OK);
    opts.convert_rgb_to_intensity = 0;
    o3d_rgbd_image_t* rgbd = NULL;
    assert_int_equal(o3d_rgbd_image_create_from_color_and_depth(&rgbd, color, depth, &opts), O3D_OK);
    o3d_pointcloud_t* pc = NULL;
    assert_int_equal(o3d_pointcloud_create_from_rgbd_image(&pc, rgbd, &ps, NULL, 1), O3D_OK);

    /* Open3D: rgbd_rgb_count, _centroid, _point[1000], _color_mean, _color[1000]. */
    size_t n = 0, nc = 0;
    const double* xyz = NULL;
    const double* rgb = NULL;
    assert_int_equal(o3d_pointcloud_array_view(&xyz, &n, pc, O3D_POINTCLOUD_POINTS), O3D_OK);
    assert_int_equal(o3d_pointcloud_array_view(&rgb, &nc, pc, O3D_POINTCLOUD_COLORS), O3D_OK);
    assert_int_equal(n, 267129);
    assert_int_equal(nc, n);
    const double centroid[3] = {-0.04790395589573783, -0.05202429268729524, 1.793887336424306};
    const double color_mean[3] = {0.8401963096483908, 0.7798637494595275, 0.7436728924169724};
    const double p1000[3] = {-0.1562895173118228, -0.9655694836661929, 2.247999906539917};
    const double c1000[3] = {0.5607843137254902, 0.5764705882352941, 0.5803921568627451};
    double sum[3] = {0, 0, 0}, csum[3] = {0, 0, 0};
    for (size_t i = 0; i < n; ++i)
        for (int r = 0; r < 3; ++r) {
            sum[r] += xyz[3 * i + r];
            csum[r] += rgb[3 * i + r];
        }
    for (int r = 0; r < 3; ++r) {
        assert_true(fabs(sum[r] / n - centroid[r]) < 1e-12);
        assert_true(fabs(csum[r] / n - color_mean[r]) < 1e-12);
        assert_true(fabs(xyz[3 * 1000 + r] - p1000[r]) < 1e-15);
        assert_true(rgb[3 * 1000 + r] == c1000[r]);
    }
    o3d_pointcloud_destroy(pc);

    /* Organised: every pixel, NaN where the depth is 0 (Open3D: rgbd_organised_count, 40071 NaN). */
    assert_int_equal(o3d_pointcloud_create_from_rgbd_image(&pc, rgbd, &ps, NULL, 0), O3D_OK);
    assert_int_equal(o3d_pointcloud_array_view(&xyz, &n, pc, O3D_POINTCLOUD_POINTS), O3D_OK);
    assert_int_equal(n, 307200);
    size_t nan_count = 0;
    for (size_t i = 0; i < n; ++i) nan_count += isnan(xyz[3 * i]) ? 1 : 0;
    assert_int_equal(nan_count, 40071);
    o3d_pointcloud_destroy(pc);

    /* The raw depth PNG directly: Open3D's depth_count and depth_point[123456]. */
    assert_int_equal(o3d_pointcloud_create_from_depth_image(&pc, depth, &ps, NULL, NULL), O3D_OK);
    assert_int_equal(o3d_pointcloud_array_view(&xyz, &n, pc, O3D_POINTCLOUD_POINTS), O3D_OK);
    assert_int_equal(n, 267129);
    const double p123456[3] = {0.043559999465942384, -0.04770857084365118, 2.177999973297119};
    for (int r = 0; r < 3; ++r) assert_true(fabs(xyz[3 * 123456 + r] - p123456[r]) < 1e-15);
    o3d_pointcloud_destroy(pc);

    o3d_rgbd_image_destroy(rgbd);
    o3d_image_destroy(color);
    o3d_image_destroy(depth);
}

int main(void) {
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_options_init),
        cmocka_unit_test(test_color_and_depth),
        cmocka_unit_test(test_dataset_formats),
        cmocka_unit_test(test_back_projection_synthetic),
        cmocka_unit_test(test_back_projection_real_frame),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
