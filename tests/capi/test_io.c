/* SPDX-License-Identifier: MIT */
/* C API io.h: every function's success, NULL and invalid-argument paths (status plus a non-empty
 * message), memory round trips, options versioning, and the error codes of bad files. */
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

static o3d_pointcloud_t* make_cloud(size_t n, int normals, int colors) {
    o3d_pointcloud_t* pc = NULL;
    assert_int_equal(o3d_pointcloud_create(&pc), O3D_OK);
    double* xyz = malloc(3 * n * sizeof(double));
    assert_non_null(xyz);
    for (size_t i = 0; i < 3 * n; ++i) xyz[i] = 0.1 * (double)i - 7.3;
    assert_int_equal(o3d_pointcloud_set_array(pc, O3D_POINTCLOUD_POINTS, xyz, n), O3D_OK);
    if (normals) {
        for (size_t i = 0; i < 3 * n; ++i) xyz[i] = (i % 3 == 2) ? 1.0 : 0.0;
        assert_int_equal(o3d_pointcloud_set_array(pc, O3D_POINTCLOUD_NORMALS, xyz, n), O3D_OK);
    }
    if (colors) {
        for (size_t i = 0; i < 3 * n; ++i) xyz[i] = (double)(i % 256) / 255.0;
        assert_int_equal(o3d_pointcloud_set_array(pc, O3D_POINTCLOUD_COLORS, xyz, n), O3D_OK);
    }
    free(xyz);
    return pc;
}

static size_t cloud_size(const o3d_pointcloud_t* pc) {
    size_t n = 0;
    assert_int_equal(o3d_pointcloud_size(&n, pc), O3D_OK);
    return n;
}

static int32_t has_normals(const o3d_pointcloud_t* pc) {
    int32_t v = -1;
    assert_int_equal(o3d_pointcloud_has_array(&v, pc, O3D_POINTCLOUD_NORMALS), O3D_OK);
    return v;
}

static int32_t has_colors(const o3d_pointcloud_t* pc) {
    int32_t v = -1;
    assert_int_equal(o3d_pointcloud_has_array(&v, pc, O3D_POINTCLOUD_COLORS), O3D_OK);
    return v;
}

static void test_options_init(void** state) {
    (void)state;
    o3d_read_options_t r;
    memset(&r, 0x55, sizeof r);
    assert_int_equal(o3d_read_options_init(&r, sizeof r), O3D_OK);
    assert_int_equal(r.struct_size, sizeof r);
    assert_int_equal(r.remove_nan_points, 0);
    assert_int_equal(r.remove_infinite_points, 0);

    o3d_write_options_t w;
    memset(&w, 0x55, sizeof w);
    assert_int_equal(o3d_write_options_init(&w, sizeof w), O3D_OK);
    assert_int_equal(w.struct_size, sizeof w);
    assert_int_equal(w.write_ascii, 0);
    assert_int_equal(w.compressed, 0);

    /* An older, shorter struct: only its bytes are written. */
    memset(&w, 0x55, sizeof w);
    assert_int_equal(o3d_write_options_init(&w, 8), O3D_OK);
    assert_int_equal(w.struct_size, 8);
    assert_int_equal(w.write_ascii, 0);
    assert_int_equal(w.compressed, 0x55555555);

    O3D_ASSERT_FAILS(o3d_read_options_init(NULL, sizeof r), O3D_ERROR_INVALID_ARGUMENT);
    O3D_ASSERT_FAILS(o3d_write_options_init(NULL, sizeof w), O3D_ERROR_INVALID_ARGUMENT);
    O3D_ASSERT_FAILS(o3d_read_options_init(&r, 2), O3D_ERROR_INVALID_ARGUMENT);
    O3D_ASSERT_FAILS(o3d_write_options_init(&w, sizeof w + 4), O3D_ERROR_INVALID_ARGUMENT);
}

/* Every format and encoding through memory; the buffer is owned by the caller. */
static void test_memory_round_trip(void** state) {
    (void)state;
    o3d_pointcloud_t* in = make_cloud(50, 1, 1);
    const char* formats[] = {"ply", "pcd", "xyz", "xyzn", "xyzrgb", "pts"};
    for (size_t f = 0; f < 6; ++f) {
        for (int variant = 0; variant < 3; ++variant) {
            o3d_write_options_t w;
            assert_int_equal(o3d_write_options_init(&w, sizeof w), O3D_OK);
            w.write_ascii = variant == 1;
            w.compressed = variant == 2;
            o3d_buffer_t* buf = NULL;
            assert_int_equal(o3d_io_write_point_cloud_to_memory(&buf, in, formats[f], &w), O3D_OK);
            const uint8_t* data = NULL;
            size_t size = 0;
            assert_int_equal(o3d_buffer_view(&data, &size, buf), O3D_OK);
            assert_true(size > 0);
            o3d_pointcloud_t* out = NULL;
            assert_int_equal(o3d_io_read_point_cloud_from_memory(&out, data, size, formats[f], NULL), O3D_OK);
            assert_int_equal(cloud_size(out), 50);
            double p[150];
            size_t n = 0;
            assert_int_equal(o3d_pointcloud_get_array(p, 50, &n, out, O3D_POINTCLOUD_POINTS), O3D_OK);
            assert_int_equal(n, 50);
            assert_float_equal(p[149], 0.1 * 149 - 7.3, 1e-5);
            assert_int_equal(has_normals(out), f == 0 || f == 1 || f == 3);
            assert_int_equal(has_colors(out), f == 0 || f == 1 || f == 4 || f == 5);
            o3d_pointcloud_destroy(out);
            o3d_buffer_destroy(buf);
        }
    }
    o3d_pointcloud_destroy(in);
}

static void test_file_round_trip_and_auto_format(void** state) {
    (void)state;
    char path[256];
    snprintf(path, sizeof path, "/tmp/o3d_capi_io_%d.PLY", (int)getpid());
    o3d_pointcloud_t* in = make_cloud(20, 1, 0);
    assert_int_equal(o3d_io_write_point_cloud(path, in, NULL, NULL), O3D_OK);
    o3d_pointcloud_t* out = NULL;
    assert_int_equal(o3d_io_read_point_cloud(&out, path, "auto", NULL), O3D_OK);
    assert_int_equal(cloud_size(out), 20);
    assert_int_equal(has_normals(out), 1);
    o3d_pointcloud_destroy(out);
    out = NULL;
    assert_int_equal(o3d_io_read_point_cloud(&out, path, "", NULL), O3D_OK);
    o3d_pointcloud_destroy(out);
    remove(path);
    o3d_pointcloud_destroy(in);
}

static void test_read_options_remove_non_finite(void** state) {
    (void)state;
    const char text[] = "1 2 3\nnan 0 0\ninf 0 0\n4 5 6\n";
    o3d_read_options_t r;
    assert_int_equal(o3d_read_options_init(&r, sizeof r), O3D_OK);
    o3d_pointcloud_t* pc = NULL;
    assert_int_equal(o3d_io_read_point_cloud_from_memory(&pc, (const uint8_t*)text, strlen(text), "xyz", &r), O3D_OK);
    assert_int_equal(cloud_size(pc), 4);
    o3d_pointcloud_destroy(pc);
    r.remove_nan_points = 1;
    assert_int_equal(o3d_io_read_point_cloud_from_memory(&pc, (const uint8_t*)text, strlen(text), "xyz", &r), O3D_OK);
    assert_int_equal(cloud_size(pc), 3);
    o3d_pointcloud_destroy(pc);
    r.remove_infinite_points = 1;
    assert_int_equal(o3d_io_read_point_cloud_from_memory(&pc, (const uint8_t*)text, strlen(text), "xyz", &r), O3D_OK);
    assert_int_equal(cloud_size(pc), 2);
    o3d_pointcloud_destroy(pc);

    /* A caller built against a version whose struct ended after remove_nan_points. */
    struct {
        uint32_t struct_size;
        int32_t remove_nan_points;
    } old = {8, 1};
    assert_int_equal(o3d_io_read_point_cloud_from_memory(&pc, (const uint8_t*)text, strlen(text), "xyz",
                                                         (const o3d_read_options_t*)&old),
                     O3D_OK);
    assert_int_equal(cloud_size(pc), 3);
    o3d_pointcloud_destroy(pc);

    r.struct_size = 1000;
    pc = (o3d_pointcloud_t*)&r; /* must be reset to NULL on failure */
    O3D_ASSERT_FAILS(o3d_io_read_point_cloud_from_memory(&pc, (const uint8_t*)text, strlen(text), "xyz", &r),
                     O3D_ERROR_INVALID_ARGUMENT);
    assert_null(pc);
}

static void test_null_and_invalid_arguments(void** state) {
    (void)state;
    o3d_pointcloud_t* pc = make_cloud(3, 0, 0);
    o3d_pointcloud_t* out = NULL;
    o3d_buffer_t* buf = NULL;
    const uint8_t bytes[] = "1 2 3\n";

    O3D_ASSERT_FAILS(o3d_io_read_point_cloud(NULL, "x.ply", NULL, NULL), O3D_ERROR_INVALID_ARGUMENT);
    O3D_ASSERT_FAILS(o3d_io_read_point_cloud(&out, NULL, NULL, NULL), O3D_ERROR_INVALID_ARGUMENT);
    assert_null(out);
    O3D_ASSERT_FAILS(o3d_io_write_point_cloud(NULL, pc, NULL, NULL), O3D_ERROR_INVALID_ARGUMENT);
    O3D_ASSERT_FAILS(o3d_io_write_point_cloud("/tmp/o3d_capi_null.ply", NULL, NULL, NULL), O3D_ERROR_INVALID_ARGUMENT);
    O3D_ASSERT_FAILS(o3d_io_read_point_cloud_from_memory(NULL, bytes, 6, "xyz", NULL), O3D_ERROR_INVALID_ARGUMENT);
    O3D_ASSERT_FAILS(o3d_io_read_point_cloud_from_memory(&out, NULL, 6, "xyz", NULL), O3D_ERROR_INVALID_ARGUMENT);
    /* Memory has no extension: the format is required. */
    O3D_ASSERT_FAILS(o3d_io_read_point_cloud_from_memory(&out, bytes, 6, NULL, NULL), O3D_ERROR_INVALID_ARGUMENT);
    O3D_ASSERT_FAILS(o3d_io_read_point_cloud_from_memory(&out, bytes, 6, "auto", NULL), O3D_ERROR_INVALID_ARGUMENT);
    assert_null(out);
    O3D_ASSERT_FAILS(o3d_io_write_point_cloud_to_memory(NULL, pc, "ply", NULL), O3D_ERROR_INVALID_ARGUMENT);
    O3D_ASSERT_FAILS(o3d_io_write_point_cloud_to_memory(&buf, NULL, "ply", NULL), O3D_ERROR_INVALID_ARGUMENT);
    O3D_ASSERT_FAILS(o3d_io_write_point_cloud_to_memory(&buf, pc, NULL, NULL), O3D_ERROR_INVALID_ARGUMENT);
    assert_null(buf);

    o3d_write_options_t w = {2, 1, 0};
    O3D_ASSERT_FAILS(o3d_io_write_point_cloud_to_memory(&buf, pc, "ply", &w), O3D_ERROR_INVALID_ARGUMENT);
    O3D_ASSERT_FAILS(o3d_io_write_point_cloud("/tmp/o3d_capi_bad_opts.ply", pc, NULL, &w), O3D_ERROR_INVALID_ARGUMENT);

    /* Empty input with an explicit format is data, not an argument error: text formats give an
     * empty cloud, PLY has no header. */
    assert_int_equal(o3d_io_read_point_cloud_from_memory(&out, NULL, 0, "xyz", NULL), O3D_OK);
    assert_int_equal(cloud_size(out), 0);
    o3d_pointcloud_destroy(out);
    O3D_ASSERT_FAILS(o3d_io_read_point_cloud_from_memory(&out, NULL, 0, "ply", NULL), O3D_ERROR_PARSE);
    o3d_pointcloud_destroy(pc);
}

static void test_error_codes_of_bad_sources(void** state) {
    (void)state;
    o3d_pointcloud_t* out = NULL;
    O3D_ASSERT_FAILS(o3d_io_read_point_cloud(&out, "/nonexistent/o3d/cloud.pcd", NULL, NULL), O3D_ERROR_IO);
    assert_non_null(strstr(o3d_last_error_message(), "/nonexistent/o3d/cloud.pcd"));
    O3D_ASSERT_FAILS(o3d_io_read_point_cloud(&out, "/tmp/cloud.obj", NULL, NULL), O3D_ERROR_UNSUPPORTED);
    O3D_ASSERT_FAILS(o3d_io_read_point_cloud(&out, "/tmp/cloud.ply", "las", NULL), O3D_ERROR_UNSUPPORTED);
    const char bad[] = "ply\nformat ascii 1.0\nelement vertex 1000000\nproperty float x\nend_header\n1\n";
    O3D_ASSERT_FAILS(o3d_io_read_point_cloud_from_memory(&out, (const uint8_t*)bad, strlen(bad), "ply", NULL),
                     O3D_ERROR_PARSE);
    assert_non_null(strstr(o3d_last_error_message(), "<memory>"));
    assert_null(out);
    o3d_pointcloud_t* pc = make_cloud(2, 0, 0);
    O3D_ASSERT_FAILS(o3d_io_write_point_cloud("/nonexistent/o3d/out.ply", pc, NULL, NULL), O3D_ERROR_IO);
    o3d_pointcloud_destroy(pc);
}

static void test_shared_data_fragment(void** state) {
    (void)state;
    O3D_C_TEST_DATA_OR_SKIP(path, "open3d/fragment.pcd");
    o3d_pointcloud_t* pc = NULL;
    assert_int_equal(o3d_io_read_point_cloud(&pc, path, NULL, NULL), O3D_OK);
    assert_int_equal(cloud_size(pc), 113662);
    assert_int_equal(has_normals(pc), 1);
    assert_int_equal(has_colors(pc), 1);
    o3d_pointcloud_destroy(pc);
}

int main(void) {
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_options_init),
        cmocka_unit_test(test_memory_round_trip),
        cmocka_unit_test(test_file_round_trip_and_auto_format),
        cmocka_unit_test(test_read_options_remove_non_finite),
        cmocka_unit_test(test_null_and_invalid_arguments),
        cmocka_unit_test(test_error_codes_of_bad_sources),
        cmocka_unit_test(test_shared_data_fragment),
    };
    return cmocka_run_group_tests_name("o3d_io", tests, NULL, NULL);
}
