/* SPDX-License-Identifier: MIT */
/* C API feature.h: feature handles, FPFH (analytic plane, Open3D's numbers on the stored scan), feature
 * files, feature matching, KD-trees of any dimension; NULL and invalid arguments for every function. */
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <setjmp.h>
#include <cmocka.h>

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "o3d/feature.h"
#include "o3d/io.h"
#include "o3d_test_util.h"

#define INV O3D_ERROR_INVALID_ARGUMENT

/* A 4 x 3 feature: descriptor i holds 10 i + (0, 1, 2, 3). */
/* rows reported by the array functions (descriptors) */
static size_t g_rows;

static o3d_feature_t* small_feature(void) {
    double data[12];
    for (int i = 0; i < 12; ++i) data[i] = 10.0 * (i / 4) + (i % 4);
    o3d_feature_t* f = NULL;
    assert_int_equal(o3d_feature_create_from_data(&f, data, 4, 3), O3D_OK);
    return f;
}

/* A 12 x 12 grid in z = 1 spaced 0.1, all normals +z. */
static o3d_pointcloud_t* plane(void) {
    double xyz[3 * 144], nrm[3 * 144];
    for (int i = 0; i < 144; ++i) {
        xyz[3 * i] = 0.1 * (i % 12);
        xyz[3 * i + 1] = 0.1 * (i / 12);
        xyz[3 * i + 2] = 1.0;
        nrm[3 * i] = nrm[3 * i + 1] = 0.0;
        nrm[3 * i + 2] = 1.0;
    }
    o3d_pointcloud_t* pc = NULL;
    assert_int_equal(o3d_pointcloud_create(&pc), O3D_OK);
    assert_int_equal(o3d_pointcloud_set_array(pc, O3D_POINTCLOUD_POINTS, xyz, 144), O3D_OK);
    assert_int_equal(o3d_pointcloud_set_array(pc, O3D_POINTCLOUD_NORMALS, nrm, 144), O3D_OK);
    return pc;
}

static void test_feature_handles(void** state) {
    (void)state;
    o3d_feature_t* f = small_feature();
    size_t dim = 0, num = 0;
    assert_int_equal(o3d_feature_dimension(&dim, f), O3D_OK);
    assert_int_equal(o3d_feature_num(&num, f), O3D_OK);
    assert_int_equal(dim, 4);
    assert_int_equal(num, 3);
    double* view = NULL;
    assert_int_equal(o3d_feature_array_mutable_view(&view, &g_rows, f, O3D_FEATURE_DATA), O3D_OK);
    assert_true(view[4 * 2 + 3] == 23.0); /* descriptor 2, value 3 */
    view[0] = -1.0;                       /* writable */

    o3d_feature_t* copy = NULL;
    assert_int_equal(o3d_feature_clone(&copy, f), O3D_OK);
    o3d_feature_destroy(f); /* the clone is independent */
    double all[12];
    assert_int_equal(o3d_feature_get_array(all, 3, &g_rows, copy, O3D_FEATURE_DATA), O3D_OK);
    assert_true(all[0] == -1.0 && all[11] == 23.0);
    O3D_ASSERT_FAILS(o3d_feature_get_array(all, 2, &g_rows, copy, O3D_FEATURE_DATA), O3D_ERROR_BUFFER_TOO_SMALL);

    /* Resize keeps the kept descriptors when the dimension stays, new values are zero. */
    assert_int_equal(o3d_feature_resize(copy, 4, 5), O3D_OK);
    double grown[20];
    assert_int_equal(o3d_feature_get_array(grown, 5, &g_rows, copy, O3D_FEATURE_DATA), O3D_OK);
    assert_true(grown[11] == 23.0 && grown[12] == 0.0 && grown[19] == 0.0);
    assert_int_equal(o3d_feature_resize(copy, 4, 2), O3D_OK);
    assert_int_equal(o3d_feature_num(&num, copy), O3D_OK);
    assert_int_equal(num, 2);

    /* Selection in the given order, or the complement ascending. */
    o3d_feature_t* sel = NULL;
    const int64_t pick[3] = {1, 0, 1};
    assert_int_equal(o3d_feature_select_by_index(&sel, copy, pick, 3, 0), O3D_OK);
    double s[12];
    assert_int_equal(o3d_feature_get_array(s, 3, &g_rows, sel, O3D_FEATURE_DATA), O3D_OK);
    assert_true(s[0] == 10.0 && s[4] == -1.0 && s[8] == 10.0);
    o3d_feature_destroy(sel);
    assert_int_equal(o3d_feature_select_by_index(&sel, copy, pick, 1, 1), O3D_OK);
    assert_int_equal(o3d_feature_num(&num, sel), O3D_OK);
    assert_int_equal(num, 1);
    assert_int_equal(o3d_feature_get_array(s, 1, &g_rows, sel, O3D_FEATURE_DATA), O3D_OK);
    assert_true(s[0] == -1.0);
    o3d_feature_destroy(sel);

    o3d_feature_t* zeros = NULL;
    assert_int_equal(o3d_feature_create(&zeros, 33, 2), O3D_OK);
    double z[66];
    assert_int_equal(o3d_feature_get_array(z, 2, &g_rows, zeros, O3D_FEATURE_DATA), O3D_OK);
    for (int i = 0; i < 66; ++i) assert_true(z[i] == 0.0);
    o3d_feature_destroy(zeros);
    assert_int_equal(o3d_feature_create(&zeros, 0, 0), O3D_OK);
    assert_int_equal(o3d_feature_array_mutable_view(&view, &g_rows, zeros, O3D_FEATURE_DATA), O3D_OK);
    assert_null(view);
    assert_int_equal(o3d_feature_get_array(NULL, 0, &g_rows, zeros, O3D_FEATURE_DATA), O3D_OK);
    o3d_feature_destroy(zeros);
    o3d_feature_destroy(copy);
    o3d_feature_destroy(NULL);
}

static void test_fpfh(void** state) {
    (void)state;
    o3d_pointcloud_t* pc = plane();
    o3d_search_param_t p;
    assert_int_equal(o3d_search_param_init(&p, sizeof p), O3D_OK);
    p.kind = O3D_SEARCH_HYBRID;
    p.radius = 0.25;
    p.knn = 30;
    o3d_feature_t* f = NULL;
    assert_int_equal(o3d_compute_fpfh_feature(&f, pc, &p, NULL, 0, 0), O3D_OK);
    size_t dim, num;
    assert_int_equal(o3d_feature_dimension(&dim, f), O3D_OK);
    assert_int_equal(o3d_feature_num(&num, f), O3D_OK);
    assert_int_equal(dim, 33);
    assert_int_equal(num, 144);
    double* v;
    assert_int_equal(o3d_feature_array_mutable_view(&v, &g_rows, f, O3D_FEATURE_DATA), O3D_OK);
    /* One normal on a plane: every pair feature is (0, 0, 0), bins 5, 16, 27, each 100 + 100. */
    for (size_t i = 0; i < num; ++i)
        for (int b = 0; b < 33; ++b)
            assert_true(fabs(v[33 * i + b] - ((b == 5 || b == 16 || b == 27) ? 200.0 : 0.0)) < 1e-9);

    const int64_t pick[3] = {100, 7, 7};
    o3d_feature_t* sub = NULL;
    assert_int_equal(o3d_compute_fpfh_feature(&sub, pc, &p, pick, 3, 2), O3D_OK);
    assert_int_equal(o3d_feature_num(&num, sub), O3D_OK);
    assert_int_equal(num, 2); /* unique, ascending: 7, 100 */
    o3d_feature_destroy(sub);

    O3D_ASSERT_FAILS(o3d_compute_fpfh_feature(NULL, pc, &p, NULL, 0, 0), INV);
    O3D_ASSERT_FAILS(o3d_compute_fpfh_feature(&sub, NULL, &p, NULL, 0, 0), INV);
    assert_null(sub);
    O3D_ASSERT_FAILS(o3d_compute_fpfh_feature(&sub, pc, &p, NULL, 2, 0), INV);
    const int64_t out_of_range[1] = {144};
    O3D_ASSERT_FAILS(o3d_compute_fpfh_feature(&sub, pc, &p, out_of_range, 1, 0), INV);
    O3D_ASSERT_FAILS(o3d_compute_fpfh_feature(&sub, pc, &p, NULL, 0, -1), INV);
    p.radius = NAN;
    O3D_ASSERT_FAILS(o3d_compute_fpfh_feature(&sub, pc, &p, NULL, 0, 0), INV);
    o3d_pointcloud_t* bare = NULL;
    assert_int_equal(o3d_pointcloud_create(&bare), O3D_OK);
    const double xyz[6] = {0, 0, 0, 1, 0, 0};
    assert_int_equal(o3d_pointcloud_set_array(bare, O3D_POINTCLOUD_POINTS, xyz, 2), O3D_OK);
    O3D_ASSERT_FAILS(o3d_compute_fpfh_feature(&sub, bare, NULL, NULL, 0, 0), INV); /* no normals */
    assert_null(sub);
    o3d_pointcloud_destroy(bare);
    o3d_feature_destroy(f);
    o3d_pointcloud_destroy(pc);
}

/* Open3D's compute_fpfh_feature on the stored scan (tools/reference/record_fpfh.py, hybrid_bin0_column_0). */
static void test_fpfh_reference(void** state) {
    (void)state;
    O3D_C_TEST_DATA_OR_SKIP(path, "open3d/Feature/cloud_bin_0.pcd");
    o3d_pointcloud_t* pc = NULL;
    assert_int_equal(o3d_io_read_point_cloud(&pc, path, NULL, NULL), O3D_OK);
    o3d_search_param_t p;
    assert_int_equal(o3d_search_param_init(&p, sizeof p), O3D_OK);
    p.kind = O3D_SEARCH_HYBRID;
    p.radius = 0.25;
    p.knn = 100;
    o3d_feature_t* f = NULL;
    assert_int_equal(o3d_compute_fpfh_feature(&f, pc, &p, NULL, 0, 2), O3D_OK);
    double* v;
    assert_int_equal(o3d_feature_array_mutable_view(&v, &g_rows, f, O3D_FEATURE_DATA), O3D_OK);
    assert_true(fabs(v[0] - 6.725477174570882) < 1e-9);
    assert_true(fabs(v[5] - 101.19109442668875) < 1e-9);
    assert_true(fabs(v[32] - 7.55456455788651) < 1e-9);
    o3d_feature_destroy(f);
    o3d_pointcloud_destroy(pc);
}

static void test_feature_files(void** state) {
    (void)state;
    O3D_C_TEST_DATA_OR_SKIP(path, "open3d/Feature/cloud_bin_0.fpfh.bin");
    o3d_feature_t* f = NULL;
    assert_int_equal(o3d_io_read_feature(&f, path), O3D_OK);
    size_t dim, num;
    assert_int_equal(o3d_feature_dimension(&dim, f), O3D_OK);
    assert_int_equal(o3d_feature_num(&num, f), O3D_OK);
    assert_int_equal(dim, 33);
    assert_int_equal(num, 3903);
    double* v;
    assert_int_equal(o3d_feature_array_mutable_view(&v, &g_rows, f, O3D_FEATURE_DATA), O3D_OK);
    assert_true(v[0] == 6.711965560913086); /* record_fpfh.py: stored0_column_0[0] */

    char tmp[128];
    snprintf(tmp, sizeof tmp, "/tmp/o3d_capi_feature_%d_\xc3\xbc.bin", (int)getpid()); /* UTF-8 name */
    assert_int_equal(o3d_io_write_feature(tmp, f), O3D_OK);
    o3d_feature_t* back = NULL;
    assert_int_equal(o3d_io_read_feature(&back, tmp), O3D_OK);
    double* w;
    assert_int_equal(o3d_feature_array_mutable_view(&w, &g_rows, back, O3D_FEATURE_DATA), O3D_OK);
    assert_memory_equal(v, w, 33 * 3903 * sizeof(double));
    o3d_feature_destroy(back);

    FILE* cut = fopen(tmp, "wb");
    const int32_t header[2] = {33, 10};
    fwrite(header, sizeof header, 1, cut);
    fwrite(v, sizeof(double), 33, cut); /* 1 of 10 descriptors */
    fclose(cut);
    O3D_ASSERT_FAILS(o3d_io_read_feature(&back, tmp), O3D_ERROR_PARSE);
    assert_null(back);
    remove(tmp);
    O3D_ASSERT_FAILS(o3d_io_read_feature(&back, tmp), O3D_ERROR_IO);
    O3D_ASSERT_FAILS(o3d_io_read_feature(NULL, tmp), INV);
    O3D_ASSERT_FAILS(o3d_io_read_feature(&back, NULL), INV);
    O3D_ASSERT_FAILS(o3d_io_write_feature(NULL, f), INV);
    O3D_ASSERT_FAILS(o3d_io_write_feature(tmp, NULL), INV);
    O3D_ASSERT_FAILS(o3d_io_write_feature("/nonexistent_dir_o3d/f.bin", f), O3D_ERROR_IO);
    o3d_feature_destroy(f);
}

static void test_correspondences(void** state) {
    (void)state;
    /* Sources 0 and 2 both prefer target 1, whose nearest source is 0. */
    const double src[8] = {0.0, 0.0, 10.0, 0.0, 0.2, 0.1, 5.1, 5.0};
    const double tgt[6] = {5.0, 5.0, 0.1, 0.0, 9.0, 1.0};
    o3d_feature_t *s = NULL, *t = NULL;
    assert_int_equal(o3d_feature_create_from_data(&s, src, 2, 4), O3D_OK);
    assert_int_equal(o3d_feature_create_from_data(&t, tgt, 2, 3), O3D_OK);
    int32_t pairs[8];
    size_t n = 0;
    assert_int_equal(o3d_correspondences_from_features(pairs, 4, &n, s, t, 0, 0.1, 0), O3D_OK);
    assert_int_equal(n, 4);
    const int32_t expected[8] = {0, 1, 1, 2, 2, 1, 3, 0};
    assert_memory_equal(pairs, expected, sizeof expected);
    assert_int_equal(o3d_correspondences_from_features(pairs, 4, &n, s, t, 1, 0.5, 2), O3D_OK);
    assert_int_equal(n, 3);
    const int32_t mutual[6] = {0, 1, 1, 2, 3, 0};
    assert_memory_equal(pairs, mutual, sizeof mutual);
    assert_int_equal(o3d_correspondences_from_features(NULL, 0, &n, s, t, 1, 1.0, 0), O3D_OK);
    assert_int_equal(n, 4); /* too few mutual pairs: all of them (Open3D's rule) */
    O3D_ASSERT_FAILS(o3d_correspondences_from_features(pairs, 3, &n, s, t, 0, 0.1, 0), O3D_ERROR_BUFFER_TOO_SMALL);
    assert_int_equal(n, 4);

    O3D_ASSERT_FAILS(o3d_correspondences_from_features(pairs, 4, &n, NULL, t, 0, 0.1, 0), INV);
    O3D_ASSERT_FAILS(o3d_correspondences_from_features(pairs, 4, &n, s, NULL, 0, 0.1, 0), INV);
    O3D_ASSERT_FAILS(o3d_correspondences_from_features(pairs, 4, &n, s, t, 1, NAN, 0), INV);
    O3D_ASSERT_FAILS(o3d_correspondences_from_features(pairs, 4, &n, s, t, 1, 2.0, 0), INV);
    O3D_ASSERT_FAILS(o3d_correspondences_from_features(pairs, 4, &n, s, t, 0, 0.1, -1), INV);
    o3d_feature_t* other = small_feature(); /* dimension 4 */
    O3D_ASSERT_FAILS(o3d_correspondences_from_features(pairs, 4, &n, s, other, 0, 0.1, 0), INV);
    o3d_feature_t* empty = NULL;
    assert_int_equal(o3d_feature_create(&empty, 2, 0), O3D_OK);
    O3D_ASSERT_FAILS(o3d_correspondences_from_features(pairs, 4, &n, s, empty, 0, 0.1, 0), INV);
    o3d_feature_destroy(empty);
    o3d_feature_destroy(other);
    o3d_feature_destroy(s);
    o3d_feature_destroy(t);
}

static void test_kdtree_xd(void** state) {
    (void)state;
    O3D_C_TEST_DATA_OR_SKIP(path, "open3d/Feature/cloud_bin_1.fpfh.bin");
    o3d_feature_t* f = NULL;
    assert_int_equal(o3d_io_read_feature(&f, path), O3D_OK);
    o3d_kdtree_t* tree = NULL;
    assert_int_equal(o3d_kdtree_create_from_feature(&tree, f), O3D_OK);
    size_t dim = 0, n = 0;
    assert_int_equal(o3d_kdtree_dimension(&dim, tree), O3D_OK);
    assert_int_equal(o3d_kdtree_size(&n, tree), O3D_OK);
    assert_int_equal(dim, 33);
    assert_int_equal(n, 3458);

    /* search_knn_vector_xd: each descriptor finds itself (or an identical one) at distance 0. */
    double* v;
    assert_int_equal(o3d_feature_array_mutable_view(&v, &g_rows, f, O3D_FEATURE_DATA), O3D_OK);
    o3d_search_param_t p;
    assert_int_equal(o3d_search_param_init(&p, sizeof p), O3D_OK);
    p.knn = 3;
    o3d_search_result_t* r = NULL;
    assert_int_equal(o3d_kdtree_search_xd(&r, tree, v, 3458, 33, &p, 0), O3D_OK);
    const int64_t* off;
    const int32_t* idx;
    const double* d2;
    assert_int_equal(o3d_search_result_view(&off, &idx, &d2, r), O3D_OK);
    assert_int_equal(off[3458], 3 * 3458);
    for (int q = 0; q < 3458; ++q) {
        assert_true(d2[3 * q] == 0.0);
        assert_true(d2[3 * q] <= d2[3 * q + 1] && d2[3 * q + 1] <= d2[3 * q + 2]);
    }
    o3d_search_result_destroy(r);

    /* A 33-D tree cannot take 3-D queries, nor queries of another dimension. */
    r = NULL;
    O3D_ASSERT_FAILS(o3d_kdtree_search(&r, tree, v, 1, &p, 0), INV);
    const float vf[3] = {0, 0, 0};
    O3D_ASSERT_FAILS(o3d_kdtree_search_f32(&r, tree, vf, 1, &p, 0), INV);
    O3D_ASSERT_FAILS(o3d_kdtree_search_xd(&r, tree, v, 1, 32, &p, 0), INV);
    O3D_ASSERT_FAILS(o3d_kdtree_search_xd(&r, tree, NULL, 1, 33, &p, 0), INV);
    O3D_ASSERT_FAILS(o3d_kdtree_search_xd(&r, tree, v, 1, 33, &p, -1), INV);
    O3D_ASSERT_FAILS(o3d_kdtree_search_xd(NULL, tree, v, 1, 33, &p, 0), INV);
    O3D_ASSERT_FAILS(o3d_kdtree_search_xd(&r, NULL, v, 1, 33, &p, 0), INV);
    p.knn = 0;
    O3D_ASSERT_FAILS(o3d_kdtree_search_xd(&r, tree, v, 1, 33, &p, 0), INV);
    assert_null(r);
    o3d_kdtree_destroy(tree);

    /* Rows of any dimension; 3-D rows make an ordinary tree that both searches take. */
    const double line[5] = {0.0, 1.0, 2.0, 3.0, 4.0};
    assert_int_equal(o3d_kdtree_create_from_points_xd(&tree, line, 1, 5), O3D_OK);
    const double q1 = 2.7;
    p.knn = 1;
    assert_int_equal(o3d_kdtree_search_xd(&r, tree, &q1, 1, 1, &p, 0), O3D_OK);
    assert_int_equal(o3d_search_result_view(&off, &idx, &d2, r), O3D_OK);
    assert_int_equal(idx[0], 3);
    o3d_search_result_destroy(r);
    o3d_kdtree_destroy(tree);
    const double xyz[9] = {0, 0, 0, 1, 0, 0, 0, 5, 0};
    assert_int_equal(o3d_kdtree_create_from_points_xd(&tree, xyz, 3, 3), O3D_OK);
    assert_int_equal(o3d_kdtree_dimension(&dim, tree), O3D_OK);
    assert_int_equal(dim, 3);
    const double q3[3] = {0.9, 0.1, 0.0};
    assert_int_equal(o3d_kdtree_search(&r, tree, q3, 1, &p, 0), O3D_OK);
    assert_int_equal(o3d_search_result_view(&off, &idx, &d2, r), O3D_OK);
    assert_int_equal(idx[0], 1);
    o3d_search_result_destroy(r);
    assert_int_equal(o3d_kdtree_search_xd(&r, tree, q3, 1, 3, &p, 0), O3D_OK);
    assert_int_equal(o3d_search_result_view(&off, &idx, &d2, r), O3D_OK);
    assert_int_equal(idx[0], 1);
    o3d_search_result_destroy(r);
    O3D_ASSERT_FAILS(o3d_kdtree_search_xd(&r, tree, q3, 1, 2, &p, 0), INV);
    o3d_kdtree_destroy(tree);

    tree = NULL;
    O3D_ASSERT_FAILS(o3d_kdtree_create_from_points_xd(&tree, xyz, 0, 3), INV);
    O3D_ASSERT_FAILS(o3d_kdtree_create_from_points_xd(&tree, NULL, 3, 3), INV);
    O3D_ASSERT_FAILS(o3d_kdtree_create_from_points_xd(NULL, xyz, 3, 3), INV);
    const double nan_row[2] = {1.0, NAN};
    O3D_ASSERT_FAILS(o3d_kdtree_create_from_points_xd(&tree, nan_row, 2, 1), INV);
    O3D_ASSERT_FAILS(o3d_kdtree_create_from_feature(&tree, NULL), INV);
    O3D_ASSERT_FAILS(o3d_kdtree_create_from_feature(NULL, f), INV);
    assert_null(tree);
    O3D_ASSERT_FAILS(o3d_kdtree_dimension(&dim, NULL), INV);
    assert_int_equal(o3d_kdtree_create_from_feature(&tree, f), O3D_OK);
    O3D_ASSERT_FAILS(o3d_kdtree_dimension(NULL, tree), INV);
    o3d_kdtree_destroy(tree);
    o3d_feature_destroy(f);
}

static void test_bad_arguments(void** state) {
    (void)state;
    o3d_feature_t* f = small_feature();
    o3d_feature_t* out = NULL;
    size_t n;
    double* view;
    double buf[12];
    O3D_ASSERT_FAILS(o3d_feature_create(NULL, 3, 3), INV);
    O3D_ASSERT_FAILS(o3d_feature_create(&out, SIZE_MAX / 2, 3), O3D_ERROR_OUT_OF_MEMORY);
    assert_null(out);
    O3D_ASSERT_FAILS(o3d_feature_create_from_data(NULL, buf, 1, 1), INV);
    O3D_ASSERT_FAILS(o3d_feature_create_from_data(&out, NULL, 4, 3), INV);
    const double bad[2] = {1.0, INFINITY};
    O3D_ASSERT_FAILS(o3d_feature_create_from_data(&out, bad, 2, 1), INV);
    assert_null(out);
    O3D_ASSERT_FAILS(o3d_feature_clone(NULL, f), INV);
    O3D_ASSERT_FAILS(o3d_feature_clone(&out, NULL), INV);
    assert_null(out);
    O3D_ASSERT_FAILS(o3d_feature_dimension(&n, NULL), INV);
    O3D_ASSERT_FAILS(o3d_feature_dimension(NULL, f), INV);
    O3D_ASSERT_FAILS(o3d_feature_num(&n, NULL), INV);
    O3D_ASSERT_FAILS(o3d_feature_num(NULL, f), INV);
    O3D_ASSERT_FAILS(o3d_feature_resize(NULL, 1, 1), INV);
    O3D_ASSERT_FAILS(o3d_feature_resize(f, SIZE_MAX / 2, 3), O3D_ERROR_OUT_OF_MEMORY);
    O3D_ASSERT_FAILS(o3d_feature_array_mutable_view(&view, &g_rows, NULL, O3D_FEATURE_DATA), INV);
    O3D_ASSERT_FAILS(o3d_feature_array_mutable_view(NULL, &g_rows, f, O3D_FEATURE_DATA), INV);
    O3D_ASSERT_FAILS(o3d_feature_array_view((const double**)&view, &g_rows, f, 7), INV); /* unknown which */
    O3D_ASSERT_FAILS(o3d_feature_get_array(buf, 3, &g_rows, NULL, O3D_FEATURE_DATA), INV);
    O3D_ASSERT_FAILS(o3d_feature_get_array(buf, 3, NULL, f, O3D_FEATURE_DATA), INV);
    const int64_t idx[2] = {0, 3};
    O3D_ASSERT_FAILS(o3d_feature_select_by_index(NULL, f, idx, 1, 0), INV);
    O3D_ASSERT_FAILS(o3d_feature_select_by_index(&out, NULL, idx, 1, 0), INV);
    O3D_ASSERT_FAILS(o3d_feature_select_by_index(&out, f, NULL, 1, 0), INV);
    O3D_ASSERT_FAILS(o3d_feature_select_by_index(&out, f, idx, 2, 0), INV); /* 3 is out of range */
    O3D_ASSERT_FAILS(o3d_feature_select_by_index(&out, f, idx, 2, 1), INV);
    const int64_t negative[1] = {-1};
    O3D_ASSERT_FAILS(o3d_feature_select_by_index(&out, f, negative, 1, 0), INV);
    assert_null(out);
    /* The feature is untouched by the failures. */
    assert_int_equal(o3d_feature_num(&n, f), O3D_OK);
    assert_int_equal(n, 3);
    o3d_feature_destroy(f);
}

int main(void) {
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_feature_handles), cmocka_unit_test(test_fpfh),
        cmocka_unit_test(test_fpfh_reference),  cmocka_unit_test(test_feature_files),
        cmocka_unit_test(test_correspondences), cmocka_unit_test(test_kdtree_xd),
        cmocka_unit_test(test_bad_arguments),
    };
    return cmocka_run_group_tests_name("o3d_feature", tests, NULL, NULL);
}
