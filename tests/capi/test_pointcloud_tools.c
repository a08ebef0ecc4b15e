/* SPDX-License-Identifier: MIT */
/* C API point-cloud tools (pointcloud.h): happy paths, NULL / invalid arguments, buffer sizes. */
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <setjmp.h>
#include <cmocka.h>

#include <math.h>
#include <string.h>

#include "o3d/pointcloud.h"
#include "o3d_test_util.h"

#define INV O3D_ERROR_INVALID_ARGUMENT
#define SMALL O3D_ERROR_BUFFER_TOO_SMALL

/* 6 x 6 grid of spacing 0.1 on z = 0 (indices 0..35), then 2 far outliers (36, 37). */
#define GRID 36
#define NPTS 38
static o3d_pointcloud_t* make_grid(void) {
    double xyz[3 * NPTS];
    for (int i = 0; i < GRID; ++i) {
        xyz[3 * i] = 0.1 * (i / 6);
        xyz[3 * i + 1] = 0.1 * (i % 6);
        xyz[3 * i + 2] = 0.0;
    }
    const double far[6] = {5, 5, 5, -4, 3, 2};
    memcpy(xyz + 3 * GRID, far, sizeof far);
    o3d_pointcloud_t* pc = NULL;
    assert_int_equal(o3d_pointcloud_create(&pc), O3D_OK);
    assert_int_equal(o3d_pointcloud_set_array(pc, O3D_POINTCLOUD_POINTS, xyz, NPTS), O3D_OK);
    return pc;
}

static o3d_pointcloud_t* make_empty(void) {
    o3d_pointcloud_t* pc = NULL;
    assert_int_equal(o3d_pointcloud_create(&pc), O3D_OK);
    return pc;
}

static void expect_kept_grid(o3d_pointcloud_t* out, const int32_t* idx, size_t n) {
    size_t size = 0;
    assert_int_equal(n, GRID);
    for (int i = 0; i < GRID; ++i) assert_int_equal(idx[i], i);
    assert_int_equal(o3d_pointcloud_size(&size, out), O3D_OK);
    assert_int_equal(size, GRID);
}

static void test_statistical_outlier(void** state) {
    (void)state;
    o3d_pointcloud_t* pc = make_grid();
    o3d_pointcloud_t* out = NULL;
    int32_t idx[NPTS];
    size_t n = 0;
    assert_int_equal(o3d_pointcloud_remove_statistical_outlier(&out, idx, NPTS, &n, pc, 6, 2.0), O3D_OK);
    expect_kept_grid(out, idx, n);
    o3d_pointcloud_destroy(out);
    out = NULL;
    /* Indices skipped: count only. */
    assert_int_equal(o3d_pointcloud_remove_statistical_outlier(&out, NULL, 0, &n, pc, 6, 2.0), O3D_OK);
    assert_int_equal(n, GRID);
    o3d_pointcloud_destroy(out);
    out = NULL;
    O3D_ASSERT_FAILS(o3d_pointcloud_remove_statistical_outlier(&out, idx, GRID - 1, &n, pc, 6, 2.0), SMALL);
    assert_null(out);
    assert_int_equal(n, GRID);
    O3D_ASSERT_FAILS(o3d_pointcloud_remove_statistical_outlier(NULL, idx, NPTS, &n, pc, 6, 2.0), INV);
    O3D_ASSERT_FAILS(o3d_pointcloud_remove_statistical_outlier(&out, idx, NPTS, &n, NULL, 6, 2.0), INV);
    O3D_ASSERT_FAILS(o3d_pointcloud_remove_statistical_outlier(&out, idx, NPTS, NULL, pc, 6, 2.0), INV);
    O3D_ASSERT_FAILS(o3d_pointcloud_remove_statistical_outlier(&out, idx, NPTS, &n, pc, 0, 2.0), INV);
    O3D_ASSERT_FAILS(o3d_pointcloud_remove_statistical_outlier(&out, idx, NPTS, &n, pc, 6, 0.0), INV);
    O3D_ASSERT_FAILS(o3d_pointcloud_remove_statistical_outlier(&out, idx, NPTS, &n, pc, 6, NAN), INV);
    o3d_pointcloud_t* empty = make_empty();
    O3D_ASSERT_FAILS(o3d_pointcloud_remove_statistical_outlier(&out, idx, NPTS, &n, empty, 6, 2.0), INV);
    assert_null(out);
    o3d_pointcloud_destroy(empty);
    o3d_pointcloud_destroy(pc);
}

static void test_radius_outlier(void** state) {
    (void)state;
    o3d_pointcloud_t* pc = make_grid();
    o3d_pointcloud_t* out = NULL;
    int32_t idx[NPTS];
    size_t n = 0;
    assert_int_equal(o3d_pointcloud_remove_radius_outlier(&out, idx, NPTS, &n, pc, 2, 0.15), O3D_OK);
    expect_kept_grid(out, idx, n);
    o3d_pointcloud_destroy(out);
    out = NULL;
    O3D_ASSERT_FAILS(o3d_pointcloud_remove_radius_outlier(&out, idx, 3, &n, pc, 2, 0.15), SMALL);
    assert_null(out);
    O3D_ASSERT_FAILS(o3d_pointcloud_remove_radius_outlier(NULL, idx, NPTS, &n, pc, 2, 0.15), INV);
    O3D_ASSERT_FAILS(o3d_pointcloud_remove_radius_outlier(&out, idx, NPTS, &n, NULL, 2, 0.15), INV);
    O3D_ASSERT_FAILS(o3d_pointcloud_remove_radius_outlier(&out, idx, NPTS, NULL, pc, 2, 0.15), INV);
    O3D_ASSERT_FAILS(o3d_pointcloud_remove_radius_outlier(&out, idx, NPTS, &n, pc, 0, 0.15), INV);
    O3D_ASSERT_FAILS(o3d_pointcloud_remove_radius_outlier(&out, idx, NPTS, &n, pc, 2, 0.0), INV);
    O3D_ASSERT_FAILS(o3d_pointcloud_remove_radius_outlier(&out, idx, NPTS, &n, pc, 2, INFINITY), INV);
    o3d_pointcloud_t* empty = make_empty();
    O3D_ASSERT_FAILS(o3d_pointcloud_remove_radius_outlier(&out, idx, NPTS, &n, empty, 2, 0.15), INV);
    o3d_pointcloud_destroy(empty);
    o3d_pointcloud_destroy(pc);
}

static void test_crop_aabb(void** state) {
    (void)state;
    o3d_pointcloud_t* pc = make_grid();
    o3d_pointcloud_t* out = NULL;
    size_t size = 0;
    const double lo[3] = {0.0, 0.0, -1.0}, hi[3] = {0.2, 0.5, 0.0}; /* inclusive: rows 0..2 of the grid */
    assert_int_equal(o3d_pointcloud_crop_aabb(&out, pc, lo, hi, 0), O3D_OK);
    assert_int_equal(o3d_pointcloud_size(&size, out), O3D_OK);
    assert_int_equal(size, 18);
    o3d_pointcloud_destroy(out);
    assert_int_equal(o3d_pointcloud_crop_aabb(&out, pc, lo, hi, 1), O3D_OK);
    assert_int_equal(o3d_pointcloud_size(&size, out), O3D_OK);
    assert_int_equal(size, NPTS - 18);
    o3d_pointcloud_destroy(out);
    out = NULL;
    const double bad_hi[3] = {-1.0, 0.5, 0.0}, nan_hi[3] = {0.2, NAN, 0.0};
    O3D_ASSERT_FAILS(o3d_pointcloud_crop_aabb(&out, pc, lo, bad_hi, 0), INV);
    O3D_ASSERT_FAILS(o3d_pointcloud_crop_aabb(&out, pc, lo, nan_hi, 0), INV);
    O3D_ASSERT_FAILS(o3d_pointcloud_crop_aabb(NULL, pc, lo, hi, 0), INV);
    O3D_ASSERT_FAILS(o3d_pointcloud_crop_aabb(&out, NULL, lo, hi, 0), INV);
    O3D_ASSERT_FAILS(o3d_pointcloud_crop_aabb(&out, pc, NULL, hi, 0), INV);
    O3D_ASSERT_FAILS(o3d_pointcloud_crop_aabb(&out, pc, lo, NULL, 0), INV);
    assert_null(out);
    o3d_pointcloud_destroy(pc);
}

static void test_segment_plane(void** state) {
    (void)state;
    o3d_pointcloud_t* pc = make_grid();
    double plane[4] = {0}, plane2[4] = {0};
    int32_t idx[NPTS], idx2[NPTS];
    size_t n = 0, n2 = 0;
    assert_int_equal(o3d_pointcloud_segment_plane(plane, idx, NPTS, &n, pc, 0.01, 3, 100, 0.99999999, 7), O3D_OK);
    assert_int_equal(n, GRID);
    for (int i = 0; i < GRID; ++i) assert_int_equal(idx[i], i);
    assert_true(fabs(fabs(plane[2]) - 1.0) < 1e-12);
    assert_true(fabs(plane[3]) < 1e-12);
    assert_int_equal(o3d_pointcloud_segment_plane(plane2, idx2, NPTS, &n2, pc, 0.01, 3, 100, 0.99999999, 7), O3D_OK);
    assert_memory_equal(plane, plane2, sizeof plane);
    assert_int_equal(n2, n);
    assert_int_equal(o3d_pointcloud_segment_plane(plane2, NULL, 0, &n2, pc, 0.01, 3, 100, 0.99999999, 7), O3D_OK);
    assert_int_equal(n2, GRID);
    O3D_ASSERT_FAILS(o3d_pointcloud_segment_plane(plane, idx, 10, &n, pc, 0.01, 3, 100, 0.99, 7), SMALL);
    O3D_ASSERT_FAILS(o3d_pointcloud_segment_plane(plane, idx, NPTS, &n, NULL, 0.01, 3, 100, 0.99, 7), INV);
    O3D_ASSERT_FAILS(o3d_pointcloud_segment_plane(NULL, idx, NPTS, &n, pc, 0.01, 3, 100, 0.99, 7), INV);
    O3D_ASSERT_FAILS(o3d_pointcloud_segment_plane(plane, idx, NPTS, NULL, pc, 0.01, 3, 100, 0.99, 7), INV);
    O3D_ASSERT_FAILS(o3d_pointcloud_segment_plane(plane, idx, NPTS, &n, pc, NAN, 3, 100, 0.99, 7), INV);
    O3D_ASSERT_FAILS(o3d_pointcloud_segment_plane(plane, idx, NPTS, &n, pc, -1.0, 3, 100, 0.99, 7), INV);
    O3D_ASSERT_FAILS(o3d_pointcloud_segment_plane(plane, idx, NPTS, &n, pc, 0.01, 2, 100, 0.99, 7), INV);
    O3D_ASSERT_FAILS(o3d_pointcloud_segment_plane(plane, idx, NPTS, &n, pc, 0.01, 3, 0, 0.99, 7), INV);
    O3D_ASSERT_FAILS(o3d_pointcloud_segment_plane(plane, idx, NPTS, &n, pc, 0.01, 3, 100, 0.0, 7), INV);
    O3D_ASSERT_FAILS(o3d_pointcloud_segment_plane(plane, idx, NPTS, &n, pc, 0.01, 3, 100, NAN, 7), INV);
    O3D_ASSERT_FAILS(o3d_pointcloud_segment_plane(plane, idx, NPTS, &n, pc, 0.01, NPTS + 1, 100, 0.99, 7), INV);
    o3d_pointcloud_t* empty = make_empty();
    O3D_ASSERT_FAILS(o3d_pointcloud_segment_plane(plane, idx, NPTS, &n, empty, 0.01, 3, 100, 0.99, 7), INV);
    o3d_pointcloud_destroy(empty);
    o3d_pointcloud_destroy(pc);
}

static void test_cluster_dbscan(void** state) {
    (void)state;
    o3d_pointcloud_t* pc = make_grid();
    int32_t labels[NPTS];
    size_t n = 0;
    assert_int_equal(o3d_pointcloud_cluster_dbscan(labels, NPTS, &n, pc, 0.15, 3), O3D_OK);
    assert_int_equal(n, NPTS);
    for (int i = 0; i < GRID; ++i) assert_int_equal(labels[i], 0);
    assert_int_equal(labels[36], -1);
    assert_int_equal(labels[37], -1);
    assert_int_equal(o3d_pointcloud_cluster_dbscan(NULL, 0, &n, pc, 0.15, 3), O3D_OK);
    assert_int_equal(n, NPTS);
    O3D_ASSERT_FAILS(o3d_pointcloud_cluster_dbscan(labels, NPTS - 1, &n, pc, 0.15, 3), SMALL);
    O3D_ASSERT_FAILS(o3d_pointcloud_cluster_dbscan(labels, NPTS, &n, NULL, 0.15, 3), INV);
    O3D_ASSERT_FAILS(o3d_pointcloud_cluster_dbscan(labels, NPTS, NULL, pc, 0.15, 3), INV);
    O3D_ASSERT_FAILS(o3d_pointcloud_cluster_dbscan(labels, NPTS, &n, pc, 0.0, 3), INV);
    O3D_ASSERT_FAILS(o3d_pointcloud_cluster_dbscan(labels, NPTS, &n, pc, NAN, 3), INV);
    O3D_ASSERT_FAILS(o3d_pointcloud_cluster_dbscan(labels, NPTS, &n, pc, 0.15, -1), INV);
    O3D_ASSERT_FAILS(o3d_pointcloud_cluster_dbscan(NULL, 0, &n, pc, -0.15, 3), INV);
    o3d_pointcloud_t* empty = make_empty();
    O3D_ASSERT_FAILS(o3d_pointcloud_cluster_dbscan(labels, NPTS, &n, empty, 0.15, 3), INV);
    o3d_pointcloud_destroy(empty);
    o3d_pointcloud_destroy(pc);
}

static void test_mean_and_covariance(void** state) {
    (void)state;
    const double xyz[] = {1, 0, 0, -1, 0, 0, 0, 2, 0, 0, -2, 0, 0, 0, 3, 0, 0, -3};
    o3d_pointcloud_t* pc = NULL;
    assert_int_equal(o3d_pointcloud_create(&pc), O3D_OK);
    assert_int_equal(o3d_pointcloud_set_array(pc, O3D_POINTCLOUD_POINTS, xyz, 6), O3D_OK);
    double mean[3], cov[9];
    assert_int_equal(o3d_pointcloud_compute_mean_and_covariance(mean, cov, pc), O3D_OK);
    for (int i = 0; i < 3; ++i) assert_true(fabs(mean[i]) < 1e-15);
    const double expected[9] = {2.0 / 6, 0, 0, 0, 8.0 / 6, 0, 0, 0, 18.0 / 6};
    for (int i = 0; i < 9; ++i) assert_true(fabs(cov[i] - expected[i]) < 1e-12);
    O3D_ASSERT_FAILS(o3d_pointcloud_compute_mean_and_covariance(mean, cov, NULL), INV);
    O3D_ASSERT_FAILS(o3d_pointcloud_compute_mean_and_covariance(NULL, cov, pc), INV);
    O3D_ASSERT_FAILS(o3d_pointcloud_compute_mean_and_covariance(mean, NULL, pc), INV);
    o3d_pointcloud_t* empty = make_empty();
    O3D_ASSERT_FAILS(o3d_pointcloud_compute_mean_and_covariance(mean, cov, empty), INV);

    /* Mahalanobis: point (1,0,0) -> sqrt(1 / (1/3)) = sqrt(3); (0,2,0) -> sqrt(4 / (4/3)) = sqrt(3). */
    double d[6];
    size_t n = 0;
    assert_int_equal(o3d_pointcloud_compute_mahalanobis_distance(d, 6, &n, pc), O3D_OK);
    assert_int_equal(n, 6);
    for (int i = 0; i < 6; ++i) assert_true(fabs(d[i] - sqrt(3.0)) < 1e-12);
    assert_int_equal(o3d_pointcloud_compute_mahalanobis_distance(NULL, 0, &n, pc), O3D_OK);
    assert_int_equal(n, 6);
    O3D_ASSERT_FAILS(o3d_pointcloud_compute_mahalanobis_distance(d, 5, &n, pc), SMALL);
    O3D_ASSERT_FAILS(o3d_pointcloud_compute_mahalanobis_distance(d, 6, &n, NULL), INV);
    O3D_ASSERT_FAILS(o3d_pointcloud_compute_mahalanobis_distance(d, 6, NULL, pc), INV);
    O3D_ASSERT_FAILS(o3d_pointcloud_compute_mahalanobis_distance(d, 6, &n, empty), INV);
    o3d_pointcloud_destroy(empty);
    o3d_pointcloud_destroy(pc);
}

int main(void) {
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_statistical_outlier), cmocka_unit_test(test_radius_outlier),
        cmocka_unit_test(test_crop_aabb),           cmocka_unit_test(test_segment_plane),
        cmocka_unit_test(test_cluster_dbscan),      cmocka_unit_test(test_mean_and_covariance),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
