/* SPDX-License-Identifier: MIT */
/* C API image.h and the image part of io.h: creation and views, the copy-out convention, filters,
 * pyramid step, flips and conversions with analytic answers, numbers recorded from Open3D 0.20 on the
 * shared RGB-D frame (tools/reference/record_image.py), memory and file round trips, and every NULL,
 * bad-size, bad-format and malformed-file path (status plus a non-empty message). */
#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include <cmocka.h>

#include "o3d/o3d.h"
#include "o3d_test_util.h"

static int32_t prop(o3d_status (*f)(int32_t*, const o3d_image_t*), const o3d_image_t* im) {
    int32_t v = -1;
    assert_int_equal(f(&v, im), O3D_OK);
    return v;
}

static const float* float_view(const o3d_image_t* im, size_t* count) {
    const uint8_t* data = NULL;
    size_t size = 0;
    assert_int_equal(o3d_image_array_view(&data, &size, im, O3D_IMAGE_DATA), O3D_OK);
    *count = size / sizeof(float);
    return (const float*)data;
}

static o3d_image_t* float_image(int32_t w, int32_t h, const float* values) {
    o3d_image_t* im = NULL;
    assert_int_equal(o3d_image_create_from_data(&im, w, h, 1, 4, (const uint8_t*)values, (size_t)w * h * 4), O3D_OK);
    return im;
}

static void test_create_and_views(void** state) {
    (void)state;
    o3d_image_t* im = NULL;
    assert_int_equal(o3d_image_create(&im, 5, 3, 3, 2), O3D_OK);
    assert_int_equal(prop(o3d_image_width, im), 5);
    assert_int_equal(prop(o3d_image_height, im), 3);
    assert_int_equal(prop(o3d_image_num_channels, im), 3);
    assert_int_equal(prop(o3d_image_bytes_per_channel, im), 2);
    const uint8_t* view = NULL;
    size_t size = 0;
    assert_int_equal(o3d_image_array_view(&view, &size, im, O3D_IMAGE_DATA), O3D_OK);
    assert_int_equal(size, 5 * 3 * 3 * 2);
    for (size_t i = 0; i < size; ++i) assert_int_equal(view[i], 0);
    uint8_t* mut = NULL;
    assert_int_equal(o3d_image_array_mutable_view(&mut, &size, im, O3D_IMAGE_DATA), O3D_OK);
    for (size_t i = 0; i < size; ++i) mut[i] = (uint8_t)i;

    /* Copy-out: query, too small, exact. */
    size_t needed = 0;
    assert_int_equal(o3d_image_get_array(NULL, 0, &needed, im, O3D_IMAGE_DATA), O3D_OK);
    assert_int_equal(needed, 90);
    uint8_t buf[90];
    O3D_ASSERT_FAILS(o3d_image_get_array(buf, 89, &needed, im, O3D_IMAGE_DATA), O3D_ERROR_BUFFER_TOO_SMALL);
    assert_int_equal(needed, 90);
    assert_int_equal(o3d_image_get_array(buf, sizeof buf, &needed, im, O3D_IMAGE_DATA), O3D_OK);
    for (size_t i = 0; i < 90; ++i) assert_int_equal(buf[i], (uint8_t)i);

    /* Clone is deep. */
    o3d_image_t* copy = NULL;
    assert_int_equal(o3d_image_clone(&copy, im), O3D_OK);
    mut[0] = 200;
    assert_int_equal(o3d_image_get_array(buf, sizeof buf, &needed, copy, O3D_IMAGE_DATA), O3D_OK);
    assert_int_equal(buf[0], 0);
    o3d_image_destroy(copy);

    /* From data: the size must match exactly. */
    o3d_image_t* d = NULL;
    assert_int_equal(o3d_image_create_from_data(&d, 3, 2, 1, 1, buf, 6), O3D_OK);
    assert_int_equal(o3d_image_get_array(buf + 10, 6, &needed, d, O3D_IMAGE_DATA), O3D_OK);
    assert_memory_equal(buf + 10, buf, 6);
    o3d_image_destroy(d);
    d = (o3d_image_t*)1;
    O3D_ASSERT_FAILS(o3d_image_create_from_data(&d, 3, 2, 1, 1, buf, 7), O3D_ERROR_INVALID_ARGUMENT);
    assert_null(d);
    O3D_ASSERT_FAILS(o3d_image_create_from_data(&d, 3, 2, 1, 1, buf, 5), O3D_ERROR_INVALID_ARGUMENT);
    O3D_ASSERT_FAILS(o3d_image_create_from_data(&d, 3, 2, 1, 1, NULL, 6), O3D_ERROR_INVALID_ARGUMENT);
    o3d_image_destroy(im);
    o3d_image_destroy(NULL);
}

static void test_bad_arguments(void** state) {
    (void)state;
    o3d_image_t* im = (o3d_image_t*)1;
    O3D_ASSERT_FAILS(o3d_image_create(&im, 0, 3, 1, 1), O3D_ERROR_INVALID_ARGUMENT);
    assert_null(im);
    O3D_ASSERT_FAILS(o3d_image_create(&im, 3, -2, 1, 1), O3D_ERROR_INVALID_ARGUMENT);
    O3D_ASSERT_FAILS(o3d_image_create(&im, 3, 3, 2, 1), O3D_ERROR_INVALID_ARGUMENT);
    O3D_ASSERT_FAILS(o3d_image_create(&im, 3, 3, 5, 1), O3D_ERROR_INVALID_ARGUMENT);
    O3D_ASSERT_FAILS(o3d_image_create(&im, 3, 3, 1, 3), O3D_ERROR_INVALID_ARGUMENT);
    O3D_ASSERT_FAILS(o3d_image_create(&im, 2147483647, 2147483647, 4, 4), O3D_ERROR_INVALID_ARGUMENT);
    O3D_ASSERT_FAILS(o3d_image_create(NULL, 3, 3, 1, 1), O3D_ERROR_INVALID_ARGUMENT);

    int32_t v = 0;
    const uint8_t* view = NULL;
    uint8_t* mut = NULL;
    size_t size = 0;
    O3D_ASSERT_FAILS(o3d_image_width(&v, NULL), O3D_ERROR_INVALID_ARGUMENT);
    O3D_ASSERT_FAILS(o3d_image_height(&v, NULL), O3D_ERROR_INVALID_ARGUMENT);
    O3D_ASSERT_FAILS(o3d_image_num_channels(&v, NULL), O3D_ERROR_INVALID_ARGUMENT);
    O3D_ASSERT_FAILS(o3d_image_bytes_per_channel(&v, NULL), O3D_ERROR_INVALID_ARGUMENT);
    O3D_ASSERT_FAILS(o3d_image_array_view(&view, &size, NULL, O3D_IMAGE_DATA), O3D_ERROR_INVALID_ARGUMENT);
    O3D_ASSERT_FAILS(o3d_image_array_mutable_view(&mut, &size, NULL, O3D_IMAGE_DATA), O3D_ERROR_INVALID_ARGUMENT);
    O3D_ASSERT_FAILS(o3d_image_get_array(NULL, 0, &size, NULL, O3D_IMAGE_DATA), O3D_ERROR_INVALID_ARGUMENT);
    o3d_image_t* out = NULL;
    O3D_ASSERT_FAILS(o3d_image_clone(&out, NULL), O3D_ERROR_INVALID_ARGUMENT);
    O3D_ASSERT_FAILS(o3d_image_filter(&out, NULL, O3D_IMAGE_FILTER_GAUSSIAN3), O3D_ERROR_INVALID_ARGUMENT);
    O3D_ASSERT_FAILS(o3d_image_downsample(&out, NULL), O3D_ERROR_INVALID_ARGUMENT);
    O3D_ASSERT_FAILS(o3d_image_flip_vertical(&out, NULL), O3D_ERROR_INVALID_ARGUMENT);
    O3D_ASSERT_FAILS(o3d_image_flip_horizontal(&out, NULL), O3D_ERROR_INVALID_ARGUMENT);
    O3D_ASSERT_FAILS(o3d_image_create_float_image(&out, NULL, O3D_IMAGE_CONVERT_EQUAL), O3D_ERROR_INVALID_ARGUMENT);
    O3D_ASSERT_FAILS(o3d_image_convert_depth_to_float(&out, NULL, 1000.0, 3.0), O3D_ERROR_INVALID_ARGUMENT);

    assert_int_equal(o3d_image_create(&im, 4, 4, 1, 1), O3D_OK);
    O3D_ASSERT_FAILS(o3d_image_width(NULL, im), O3D_ERROR_INVALID_ARGUMENT);
    O3D_ASSERT_FAILS(o3d_image_array_view(NULL, &size, im, O3D_IMAGE_DATA), O3D_ERROR_INVALID_ARGUMENT);
    O3D_ASSERT_FAILS(o3d_image_array_view(&view, NULL, im, O3D_IMAGE_DATA), O3D_ERROR_INVALID_ARGUMENT);
    O3D_ASSERT_FAILS(o3d_image_filter(NULL, im, O3D_IMAGE_FILTER_GAUSSIAN3), O3D_ERROR_INVALID_ARGUMENT);
    /* Filters and the pyramid step need 1-channel float32. */
    out = (o3d_image_t*)1;
    O3D_ASSERT_FAILS(o3d_image_filter(&out, im, O3D_IMAGE_FILTER_GAUSSIAN3), O3D_ERROR_INVALID_ARGUMENT);
    assert_null(out);
    O3D_ASSERT_FAILS(o3d_image_downsample(&out, im), O3D_ERROR_INVALID_ARGUMENT);
    O3D_ASSERT_FAILS(o3d_image_convert_depth_to_float(&out, im, 1000.0, 3.0), O3D_ERROR_INVALID_ARGUMENT);
    O3D_ASSERT_FAILS(o3d_image_create_float_image(&out, im, 2), O3D_ERROR_INVALID_ARGUMENT);
    o3d_image_t* f = NULL;
    assert_int_equal(o3d_image_create_float_image(&f, im, O3D_IMAGE_CONVERT_EQUAL), O3D_OK);
    O3D_ASSERT_FAILS(o3d_image_filter(&out, f, 5), O3D_ERROR_INVALID_ARGUMENT);
    O3D_ASSERT_FAILS(o3d_image_filter(&out, f, -1), O3D_ERROR_INVALID_ARGUMENT);
    o3d_image_t* depth = NULL;
    assert_int_equal(o3d_image_create(&depth, 4, 4, 1, 2), O3D_OK);
    O3D_ASSERT_FAILS(o3d_image_convert_depth_to_float(&out, depth, 0.0, 3.0), O3D_ERROR_INVALID_ARGUMENT);
    O3D_ASSERT_FAILS(o3d_image_convert_depth_to_float(&out, depth, NAN, 3.0), O3D_ERROR_INVALID_ARGUMENT);
    O3D_ASSERT_FAILS(o3d_image_convert_depth_to_float(&out, depth, 1000.0, NAN), O3D_ERROR_INVALID_ARGUMENT);
    o3d_image_t* thin = NULL;
    assert_int_equal(o3d_image_create(&thin, 1, 4, 1, 4), O3D_OK);
    O3D_ASSERT_FAILS(o3d_image_downsample(&out, thin), O3D_ERROR_INVALID_ARGUMENT);
    o3d_image_destroy(thin);
    o3d_image_destroy(depth);
    o3d_image_destroy(f);
    o3d_image_destroy(im);
}

static void test_filters_analytic(void** state) {
    (void)state;
    /* f = 0.5 u + 0.25 v on 12 x 10: Sobel dx = 8 x 0.5 inside, 4 x 0.5 on the left/right border. */
    float ramp[120];
    for (int v = 0; v < 10; ++v)
        for (int u = 0; u < 12; ++u) ramp[v * 12 + u] = 0.5f * (float)u + 0.25f * (float)v;
    o3d_image_t* im = float_image(12, 10, ramp);
    o3d_image_t* dx = NULL;
    o3d_image_t* dy = NULL;
    assert_int_equal(o3d_image_filter(&dx, im, O3D_IMAGE_FILTER_SOBEL3_DX), O3D_OK);
    assert_int_equal(o3d_image_filter(&dy, im, O3D_IMAGE_FILTER_SOBEL3_DY), O3D_OK);
    size_t n = 0;
    const float* gx = float_view(dx, &n);
    assert_int_equal(n, 120);
    const float* gy = float_view(dy, &n);
    for (int v = 0; v < 10; ++v)
        for (int u = 0; u < 12; ++u) {
            assert_true(gx[v * 12 + u] == ((u == 0 || u == 11) ? 2.0f : 4.0f));
            assert_true(gy[v * 12 + u] == ((v == 0 || v == 9) ? 1.0f : 2.0f));
        }
    /* Gaussians keep a constant. */
    float constant[120];
    for (int i = 0; i < 120; ++i) constant[i] = 2.5f;
    o3d_image_t* c = float_image(12, 10, constant);
    for (int32_t t = O3D_IMAGE_FILTER_GAUSSIAN3; t <= O3D_IMAGE_FILTER_GAUSSIAN7; ++t) {
        o3d_image_t* g = NULL;
        assert_int_equal(o3d_image_filter(&g, c, t), O3D_OK);
        const float* p = float_view(g, &n);
        for (size_t i = 0; i < n; ++i) assert_true(p[i] == 2.5f);
        o3d_image_destroy(g);
    }
    /* Pyramid step: 2x2 means, floor(size / 2). */
    o3d_image_t* half = NULL;
    assert_int_equal(o3d_image_downsample(&half, im), O3D_OK);
    assert_int_equal(prop(o3d_image_width, half), 6);
    assert_int_equal(prop(o3d_image_height, half), 5);
    const float* h = float_view(half, &n);
    /* block (1, 2): u 2..3, v 4..5 -> 0.5 * 2.5 + 0.25 * 4.5 */
    assert_true(h[2 * 6 + 1] == 0.5f * 2.5f + 0.25f * 4.5f);
    /* Flips. */
    o3d_image_t* fv = NULL;
    o3d_image_t* fh = NULL;
    assert_int_equal(o3d_image_flip_vertical(&fv, im), O3D_OK);
    assert_int_equal(o3d_image_flip_horizontal(&fh, im), O3D_OK);
    const float* pv = float_view(fv, &n);
    const float* ph = float_view(fh, &n);
    for (int v = 0; v < 10; ++v)
        for (int u = 0; u < 12; ++u) {
            assert_true(pv[v * 12 + u] == ramp[(9 - v) * 12 + u]);
            assert_true(ph[v * 12 + u] == ramp[v * 12 + 11 - u]);
        }
    o3d_image_destroy(fv);
    o3d_image_destroy(fh);
    o3d_image_destroy(half);
    o3d_image_destroy(c);
    o3d_image_destroy(dx);
    o3d_image_destroy(dy);
    o3d_image_destroy(im);
}

static void test_conversions(void** state) {
    (void)state;
    const uint8_t rgb[6] = {30, 60, 90, 255, 0, 0};
    o3d_image_t* im = NULL;
    assert_int_equal(o3d_image_create_from_data(&im, 2, 1, 3, 1, rgb, sizeof rgb), O3D_OK);
    o3d_image_t* eq = NULL;
    o3d_image_t* wt = NULL;
    assert_int_equal(o3d_image_create_float_image(&eq, im, O3D_IMAGE_CONVERT_EQUAL), O3D_OK);
    assert_int_equal(o3d_image_create_float_image(&wt, im, O3D_IMAGE_CONVERT_WEIGHTED), O3D_OK);
    assert_int_equal(prop(o3d_image_num_channels, eq), 1);
    assert_int_equal(prop(o3d_image_bytes_per_channel, eq), 4);
    size_t n = 0;
    const float* e = float_view(eq, &n);
    const float* w = float_view(wt, &n);
    assert_float_equal(e[0], 60.0 / 255.0, 1e-7);
    assert_float_equal(w[1], 0.299, 1e-7);
    /* Depth: Open3D 0.20 (record_image.py), scale 1000, trunc 3: at or beyond 3 m -> 0. */
    const uint16_t raw[8] = {0, 1, 2999, 3000, 3001, 65535, 1234, 777};
    const float expected[8] = {0.0f, 0.00100000005f, 2.99900007f, 0.0f, 0.0f, 0.0f, 1.23399997f, 0.77700001f};
    o3d_image_t* depth = NULL;
    assert_int_equal(o3d_image_create_from_data(&depth, 8, 1, 1, 2, (const uint8_t*)raw, sizeof raw), O3D_OK);
    o3d_image_t* m = NULL;
    assert_int_equal(o3d_image_convert_depth_to_float(&m, depth, 1000.0, 3.0), O3D_OK);
    const float* d = float_view(m, &n);
    assert_int_equal(n, 8);
    for (int i = 0; i < 8; ++i) assert_true(d[i] == expected[i]);
    o3d_image_destroy(m);
    o3d_image_destroy(depth);
    o3d_image_destroy(eq);
    o3d_image_destroy(wt);
    o3d_image_destroy(im);
}

static void test_io_round_trips(void** state) {
    (void)state;
    static const struct {
        const char* format;
        int32_t channels, bytes;
    } cases[] = {{"png", 1, 1}, {"png", 1, 2}, {"png", 3, 1}, {"png", 3, 2}, {"png", 4, 1},
                 {"png", 4, 2}, {"pgm", 1, 1}, {"pgm", 1, 2}, {"ppm", 3, 1}, {"ppm", 3, 2}};
    uint8_t data[13 * 7 * 4 * 2];
    for (size_t i = 0; i < sizeof data; ++i) data[i] = (uint8_t)(i * 37 + 11);
    char path[256];
    for (size_t k = 0; k < sizeof cases / sizeof cases[0]; ++k) {
        const size_t size = (size_t)13 * 7 * cases[k].channels * cases[k].bytes;
        o3d_image_t* im = NULL;
        assert_int_equal(o3d_image_create_from_data(&im, 13, 7, cases[k].channels, cases[k].bytes, data, size), O3D_OK);
        o3d_buffer_t* buf = NULL;
        assert_int_equal(o3d_io_write_image_to_memory(&buf, im, cases[k].format, -1), O3D_OK);
        const uint8_t* bytes = NULL;
        size_t nbytes = 0;
        assert_int_equal(o3d_buffer_view(&bytes, &nbytes, buf), O3D_OK);
        o3d_image_t* back = NULL;
        assert_int_equal(o3d_io_read_image_from_memory(&back, bytes, nbytes, cases[k].format), O3D_OK);
        assert_int_equal(prop(o3d_image_num_channels, back), cases[k].channels);
        assert_int_equal(prop(o3d_image_bytes_per_channel, back), cases[k].bytes);
        const uint8_t* got = NULL;
        size_t got_size = 0;
        assert_int_equal(o3d_image_array_view(&got, &got_size, back, O3D_IMAGE_DATA), O3D_OK);
        assert_int_equal(got_size, size);
        assert_memory_equal(got, data, size);
        o3d_image_destroy(back);
        o3d_buffer_destroy(buf);

        snprintf(path, sizeof path, "/tmp/o3d_capi_image_%d_%zu.%s", (int)getpid(), k, cases[k].format);
        assert_int_equal(o3d_io_write_image(path, im, NULL, -1), O3D_OK);
        assert_int_equal(o3d_io_read_image(&back, path, "auto"), O3D_OK);
        assert_int_equal(o3d_image_array_view(&got, &got_size, back, O3D_IMAGE_DATA), O3D_OK);
        assert_memory_equal(got, data, size);
        o3d_image_destroy(back);
        remove(path);
        o3d_image_destroy(im);
    }
    /* JPEG: lossy, smaller at lower quality. */
    uint8_t smooth[32 * 16 * 3];
    for (int i = 0; i < 32 * 16 * 3; ++i) smooth[i] = (uint8_t)((i / 3) % 32 * 4 + (i % 3) * 20);
    o3d_image_t* im = NULL;
    assert_int_equal(o3d_image_create_from_data(&im, 32, 16, 3, 1, smooth, sizeof smooth), O3D_OK);
    o3d_buffer_t* hi = NULL;
    o3d_buffer_t* lo = NULL;
    assert_int_equal(o3d_io_write_image_to_memory(&hi, im, "jpg", 95), O3D_OK);
    assert_int_equal(o3d_io_write_image_to_memory(&lo, im, "jpeg", 5), O3D_OK);
    const uint8_t* hb = NULL;
    const uint8_t* lb = NULL;
    size_t hn = 0, ln = 0;
    assert_int_equal(o3d_buffer_view(&hb, &hn, hi), O3D_OK);
    assert_int_equal(o3d_buffer_view(&lb, &ln, lo), O3D_OK);
    assert_true(ln < hn);
    o3d_image_t* back = NULL;
    assert_int_equal(o3d_io_read_image_from_memory(&back, hb, hn, "jpg"), O3D_OK);
    assert_int_equal(prop(o3d_image_width, back), 32);
    assert_int_equal(prop(o3d_image_num_channels, back), 3);
    o3d_image_destroy(back);
    o3d_buffer_destroy(hi);
    o3d_buffer_destroy(lo);
    o3d_image_destroy(im);
}

static void test_io_errors(void** state) {
    (void)state;
    o3d_image_t* im = NULL;
    o3d_image_t* out = (o3d_image_t*)1;
    o3d_buffer_t* buf = (o3d_buffer_t*)1;
    assert_int_equal(o3d_image_create(&im, 4, 4, 1, 4), O3D_OK);
    O3D_ASSERT_FAILS(o3d_io_write_image_to_memory(&buf, im, "png", -1), O3D_ERROR_INVALID_ARGUMENT); /* float */
    assert_null(buf);
    o3d_image_destroy(im);
    assert_int_equal(o3d_image_create(&im, 4, 4, 4, 1), O3D_OK);
    O3D_ASSERT_FAILS(o3d_io_write_image_to_memory(&buf, im, "jpg", -1), O3D_ERROR_INVALID_ARGUMENT);
    O3D_ASSERT_FAILS(o3d_io_write_image_to_memory(&buf, im, "pgm", -1), O3D_ERROR_INVALID_ARGUMENT);
    O3D_ASSERT_FAILS(o3d_io_write_image_to_memory(&buf, im, "bmp", -1), O3D_ERROR_UNSUPPORTED);
    O3D_ASSERT_FAILS(o3d_io_write_image_to_memory(&buf, im, NULL, -1), O3D_ERROR_INVALID_ARGUMENT);
    O3D_ASSERT_FAILS(o3d_io_write_image_to_memory(NULL, im, "png", -1), O3D_ERROR_INVALID_ARGUMENT);
    O3D_ASSERT_FAILS(o3d_io_write_image_to_memory(&buf, NULL, "png", -1), O3D_ERROR_INVALID_ARGUMENT);
    O3D_ASSERT_FAILS(o3d_io_write_image("/nonexistent/o3d/x.png", im, NULL, -1), O3D_ERROR_IO);
    O3D_ASSERT_FAILS(o3d_io_write_image(NULL, im, "png", -1), O3D_ERROR_INVALID_ARGUMENT);
    O3D_ASSERT_FAILS(o3d_io_write_image("/tmp/x.png", NULL, "png", -1), O3D_ERROR_INVALID_ARGUMENT);
    o3d_image_destroy(im);
    assert_int_equal(o3d_image_create(&im, 4, 4, 3, 1), O3D_OK);
    O3D_ASSERT_FAILS(o3d_io_write_image_to_memory(&buf, im, "jpg", 0), O3D_ERROR_INVALID_ARGUMENT);
    O3D_ASSERT_FAILS(o3d_io_write_image_to_memory(&buf, im, "jpg", 101), O3D_ERROR_INVALID_ARGUMENT);
    o3d_image_destroy(im);

    O3D_ASSERT_FAILS(o3d_io_read_image(&out, "/nonexistent/o3d/x.png", NULL), O3D_ERROR_IO);
    assert_null(out);
    O3D_ASSERT_FAILS(o3d_io_read_image(&out, NULL, NULL), O3D_ERROR_INVALID_ARGUMENT);
    O3D_ASSERT_FAILS(o3d_io_read_image(NULL, "/tmp/x.png", NULL), O3D_ERROR_INVALID_ARGUMENT);
    O3D_ASSERT_FAILS(o3d_io_read_image(&out, "/tmp/x.gif", NULL), O3D_ERROR_UNSUPPORTED);
    const uint8_t junk[] = "P5\n4 4\n255\nabc";
    O3D_ASSERT_FAILS(o3d_io_read_image_from_memory(&out, junk, sizeof junk - 1, "pgm"), O3D_ERROR_PARSE);
    assert_non_null(strstr(o3d_last_error_message(), "truncated"));
    O3D_ASSERT_FAILS(o3d_io_read_image_from_memory(&out, junk, sizeof junk - 1, "png"), O3D_ERROR_PARSE);
    O3D_ASSERT_FAILS(o3d_io_read_image_from_memory(&out, junk, sizeof junk - 1, "jpg"), O3D_ERROR_PARSE);
    O3D_ASSERT_FAILS(o3d_io_read_image_from_memory(&out, junk, sizeof junk - 1, NULL), O3D_ERROR_INVALID_ARGUMENT);
    O3D_ASSERT_FAILS(o3d_io_read_image_from_memory(&out, NULL, 10, "png"), O3D_ERROR_INVALID_ARGUMENT);
    O3D_ASSERT_FAILS(o3d_io_read_image_from_memory(&out, NULL, 0, "png"), O3D_ERROR_PARSE);
    /* A lying header: 50000 x 50000 16-bit over 4 bytes. */
    const uint8_t lying[] = "P5 50000 50000 65535\n\x01\x02\x03\x04";
    O3D_ASSERT_FAILS(o3d_io_read_image_from_memory(&out, lying, sizeof lying - 1, "pgm"), O3D_ERROR_PARSE);
    assert_null(out);
}

static void test_shared_rgbd_frame(void** state) {
    (void)state;
    O3D_C_TEST_DATA_OR_SKIP(depth_path, "open3d/RGBD/depth/00000.png");
    o3d_image_t* depth = NULL;
    assert_int_equal(o3d_io_read_image(&depth, depth_path, NULL), O3D_OK);
    assert_int_equal(prop(o3d_image_width, depth), 640);
    assert_int_equal(prop(o3d_image_height, depth), 480);
    assert_int_equal(prop(o3d_image_num_channels, depth), 1);
    assert_int_equal(prop(o3d_image_bytes_per_channel, depth), 2);
    o3d_image_t* m = NULL;
    assert_int_equal(o3d_image_convert_depth_to_float(&m, depth, 1000.0, 3.0), O3D_OK);
    /* Open3D 0.20 (record_image.py): Gaussian7 and Sobel3Dx of the depth in metres at (320, 240), (100, 200). */
    o3d_image_t* g = NULL;
    o3d_image_t* s = NULL;
    assert_int_equal(o3d_image_filter(&g, m, O3D_IMAGE_FILTER_GAUSSIAN7), O3D_OK);
    assert_int_equal(o3d_image_filter(&s, m, O3D_IMAGE_FILTER_SOBEL3_DX), O3D_OK);
    size_t n = 0;
    const float* gp = float_view(g, &n);
    assert_int_equal(n, 640 * 480);
    const float* sp = float_view(s, &n);
    assert_true(gp[240 * 640 + 320] == 2.1990757f);
    assert_true(gp[200 * 640 + 100] == 1.37385213f);
    assert_true(sp[240 * 640 + 320] == -0.0679998398f);
    assert_true(sp[200 * 640 + 100] == -0.0209999084f);
    o3d_image_destroy(g);
    o3d_image_destroy(s);
    o3d_image_destroy(m);
    o3d_image_destroy(depth);

    O3D_C_TEST_DATA_OR_SKIP(color_path, "open3d/RGBD/color/00000.jpg");
    o3d_image_t* color = NULL;
    assert_int_equal(o3d_io_read_image(&color, color_path, "jpg"), O3D_OK);
    assert_int_equal(prop(o3d_image_num_channels, color), 3);
    assert_int_equal(prop(o3d_image_bytes_per_channel, color), 1);
    o3d_image_t* gray = NULL;
    assert_int_equal(o3d_image_create_float_image(&gray, color, O3D_IMAGE_CONVERT_WEIGHTED), O3D_OK);
    const float* gr = float_view(gray, &n);
    assert_true(gr[200 * 640 + 100] == 0.787388206f);
    assert_true(gr[479 * 640 + 639] == 0.384239197f);
    o3d_image_destroy(gray);
    o3d_image_destroy(color);
}

int main(void) {
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_create_and_views), cmocka_unit_test(test_bad_arguments),
        cmocka_unit_test(test_filters_analytic), cmocka_unit_test(test_conversions),
        cmocka_unit_test(test_io_round_trips),   cmocka_unit_test(test_io_errors),
        cmocka_unit_test(test_shared_rgbd_frame),
    };
    return cmocka_run_group_tests_name("o3d_image", tests, NULL, NULL);
}
