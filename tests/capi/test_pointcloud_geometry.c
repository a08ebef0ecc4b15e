/* SPDX-License-Identifier: MIT */
/* C API point-cloud geometry (pointcloud.h: smoothing, minimal boxes and ellipsoids, static covariances, planar
 * patches, voxel_down_sample_and_trace; boundingbox.h: the point-array constructors): analytic answers on synthetic
 * clouds through the ABI, copy-out buffers and index lists, NULL / bad input. */
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <setjmp.h>
#include <cmocka.h>

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "o3d/o3d.h"
#include "o3d_test_util.h"

#define INV O3D_ERROR_INVALID_ARGUMENT

/* A deterministic value in [-1, 1) (an LCG, so the test needs no seeding). */
static double jitter(uint64_t* state) {
    *state = *state * 6364136223846793005ULL + 1442695040888963407ULL;
    return (double)(*state >> 11) / (double)(1ULL << 52) - 1.0;
}

static o3d_pointcloud_t* cloud_of(const double* xyz, size_t n, const double* normals) {
    o3d_pointcloud_t* pc = NULL;
    assert_int_equal(o3d_pointcloud_create(&pc), O3D_OK);
    assert_int_equal(o3d_pointcloud_set_array(pc, O3D_POINTCLOUD_POINTS, xyz, n), O3D_OK);
    if (normals) assert_int_equal(o3d_pointcloud_set_array(pc, O3D_POINTCLOUD_NORMALS, normals, n), O3D_OK);
    return pc;
}

/* A 20 x 20 grid on z = 0 with spacing 0.01 and noise of +-0.002 in z. */
static o3d_pointcloud_t* noisy_plane(double noise) {
    double xyz[3 * 400];
    uint64_t st = 7;
    for (int i = 0; i < 400; ++i) {
        xyz[3 * i] = 0.01 * (i % 20);
        xyz[3 * i + 1] = 0.01 * (i / 20);
        xyz[3 * i + 2] = noise * jitter(&st);
    }
    return cloud_of(xyz, 400, NULL);
}

static double max_abs_z(const o3d_pointcloud_t* pc) {
    const double* p = NULL;
    size_t n = 0;
    assert_int_equal(o3d_pointcloud_array_view(&p, &n, pc, O3D_POINTCLOUD_POINTS), O3D_OK);
    double worst = 0.0;
    for (size_t i = 0; i < n; ++i) worst = fmax(worst, fabs(p[3 * i + 2]));
    return worst;
}

/* Every smoothing filter flattens a noisy plane; Laplacian and Taubin keep a line's points on the line. */
static void test_smoothing_flattens_a_noisy_plane(void** state) {
    (void)state;
    o3d_pointcloud_t* pc = noisy_plane(0.002);
    const double before = max_abs_z(pc);
    o3d_search_param_t param;
    assert_int_equal(o3d_search_param_init(&param, sizeof param), O3D_OK);
    param.kind = O3D_SEARCH_HYBRID;
    param.radius = 0.035;
    param.knn = 30;
    o3d_pointcloud_t* out = NULL;
    assert_int_equal(o3d_pointcloud_smooth_mls(&out, pc, &param), O3D_OK);
    assert_true(max_abs_z(out) < 0.5 * before);
    o3d_pointcloud_destroy(out);
    assert_int_equal(o3d_pointcloud_smooth_laplacian(&out, pc, 10, 0.5, 8, 0), O3D_OK);
    assert_true(max_abs_z(out) < 0.5 * before);
    o3d_pointcloud_destroy(out);
    assert_int_equal(o3d_pointcloud_smooth_taubin(&out, pc, 10, 0.5, -0.53, 8, 1), O3D_OK);
    assert_true(max_abs_z(out) < before);
    o3d_pointcloud_destroy(out);
    assert_int_equal(o3d_pointcloud_smooth_bilateral(&out, pc, &param, 0.02, 0.01), O3D_OK);
    assert_true(max_abs_z(out) < before);
    o3d_pointcloud_destroy(out);
    /* 0 iterations is a copy. */
    assert_int_equal(o3d_pointcloud_smooth_laplacian(&out, pc, 0, 0.5, 8, 0), O3D_OK);
    assert_true(max_abs_z(out) == before);
    o3d_pointcloud_destroy(out);
    /* Bad input. */
    O3D_ASSERT_FAILS(o3d_pointcloud_smooth_laplacian(&out, pc, 1, 0.5, 0, 0), INV);
    assert_null(out);
    O3D_ASSERT_FAILS(o3d_pointcloud_smooth_laplacian(&out, pc, -1, 0.5, 8, 0), INV);
    O3D_ASSERT_FAILS(o3d_pointcloud_smooth_taubin(&out, pc, 1, 0.5, NAN, 8, 0), INV);
    O3D_ASSERT_FAILS(o3d_pointcloud_smooth_bilateral(&out, pc, NULL, 0.0, 0.01), INV);
    O3D_ASSERT_FAILS(o3d_pointcloud_smooth_mls(&out, NULL, NULL), INV);
    O3D_ASSERT_FAILS(o3d_pointcloud_smooth_mls(NULL, pc, NULL), INV);
    o3d_pointcloud_destroy(pc);

    double line[3 * 50];
    for (int i = 0; i < 50; ++i) {
        line[3 * i] = 0.1 * i * i / 50.0;
        line[3 * i + 1] = 2.0 * line[3 * i];
        line[3 * i + 2] = -line[3 * i];
    }
    pc = cloud_of(line, 50, NULL);
    assert_int_equal(o3d_pointcloud_smooth_taubin(&out, pc, 5, 0.5, -0.53, 6, 0), O3D_OK);
    const double* p = NULL;
    size_t n = 0;
    assert_int_equal(o3d_pointcloud_array_view(&p, &n, out, O3D_POINTCLOUD_POINTS), O3D_OK);
    for (size_t i = 0; i < n; ++i) {
        assert_true(fabs(p[3 * i + 1] - 2.0 * p[3 * i]) < 1e-12);
        assert_true(fabs(p[3 * i + 2] + p[3 * i]) < 1e-12);
    }
    o3d_pointcloud_destroy(out);
    o3d_pointcloud_destroy(pc);
}

/* The minimal box of a rotated box's corners and samples is that box; the ellipsoid of a sampled ellipsoid is it. */
static void test_minimal_box_and_ellipsoid(void** state) {
    (void)state;
    const double c = cos(0.4), s = sin(0.4), half[3] = {1.5, 1.0, 0.25}, t[3] = {3.0, -1.0, 2.0};
    double xyz[3 * 208];
    size_t n = 0;
    uint64_t st = 11;
    for (int k = 0; k < 208; ++k) { /* 8 corners, then points inside */
        double u[3];
        for (int d = 0; d < 3; ++d) u[d] = k < 8 ? ((k >> d) & 1 ? 1.0 : -1.0) : jitter(&st);
        const double x = half[0] * u[0], y = half[1] * u[1], z = half[2] * u[2];
        xyz[3 * n] = c * x - s * y + t[0];
        xyz[3 * n + 1] = s * x + c * y + t[1];
        xyz[3 * n + 2] = z + t[2];
        ++n;
    }
    o3d_obb_t box;
    assert_int_equal(o3d_obb_create_from_points_minimal(&box, xyz, n, 0), O3D_OK);
    assert_true(fabs(box.extent[0] * box.extent[1] * box.extent[2] - 8.0 * half[0] * half[1] * half[2]) < 1e-6);
    for (int d = 0; d < 3; ++d) assert_true(fabs(box.center[d] - t[d]) < 1e-6);
    o3d_pointcloud_t* pc = cloud_of(xyz, n, NULL);
    o3d_obb_t box2;
    assert_int_equal(o3d_pointcloud_get_minimal_oriented_bounding_box(&box2, pc, 0), O3D_OK);
    assert_memory_equal(&box, &box2, sizeof box);
    /* The PCA box is never smaller than the minimal one. */
    o3d_obb_t pca;
    assert_int_equal(o3d_pointcloud_get_oriented_bounding_box(&pca, pc, 0), O3D_OK);
    assert_true(pca.extent[0] * pca.extent[1] * pca.extent[2] >= box.extent[0] * box.extent[1] * box.extent[2] - 1e-9);
    o3d_pointcloud_destroy(pc);

    /* 500 points on the ellipsoid with semi-axes (2, 1, 0.5) about (1, 2, 3). */
    double e[3 * 500];
    const double golden = 3.14159265358979323846 * (3.0 - sqrt(5.0));
    for (int i = 0; i < 500; ++i) {
        const double z = 1.0 - 2.0 * (i + 0.5) / 500.0, r = sqrt(1.0 - z * z), phi = golden * i;
        e[3 * i] = 1.0 + 2.0 * r * cos(phi);
        e[3 * i + 1] = 2.0 + 1.0 * r * sin(phi);
        e[3 * i + 2] = 3.0 + 0.5 * z;
    }
    o3d_obe_t fit;
    assert_int_equal(o3d_obe_create_from_points(&fit, e, 500, 0), O3D_OK);
    for (int d = 0; d < 3; ++d) assert_true(fabs(fit.center[d] - (double)(d + 1)) < 1e-2);
    const double vol = fit.radii[0] * fit.radii[1] * fit.radii[2];
    assert_true(fabs(vol - 1.0) < 0.02); /* 2 * 1 * 0.5 */
    pc = cloud_of(e, 500, NULL);
    o3d_obe_t fit2;
    assert_int_equal(o3d_pointcloud_get_oriented_bounding_ellipsoid(&fit2, pc, 0), O3D_OK);
    assert_memory_equal(&fit, &fit2, sizeof fit);
    o3d_pointcloud_destroy(pc);
    /* Flat and short inputs are refused. */
    const double flat[12] = {0, 0, 0, 1, 0, 0, 0, 1, 0, 1, 1, 0};
    O3D_ASSERT_FAILS(o3d_obb_create_from_points_minimal(&box, flat, 4, 0), INV);
    O3D_ASSERT_FAILS(o3d_obe_create_from_points(&fit, flat, 4, 0), INV);
    O3D_ASSERT_FAILS(o3d_obb_create_from_points_minimal(&box, flat, 3, 1), INV);
    O3D_ASSERT_FAILS(o3d_obe_create_from_points(NULL, e, 500, 0), INV);
}

/* Four points at the corners of a unit square in z = 0 and one above: the covariance of all five (KNN 5) is the
 * same for every point, known in closed form; the cloud keeps no covariances. */
static void test_static_point_covariances(void** state) {
    (void)state;
    const double xyz[15] = {0, 0, 0, 1, 0, 0, 0, 1, 0, 1, 1, 0, 0.5, 0.5, 1.0};
    o3d_pointcloud_t* pc = cloud_of(xyz, 5, NULL);
    o3d_search_param_t param;
    assert_int_equal(o3d_search_param_init(&param, sizeof param), O3D_OK);
    param.knn = 5;
    double cov[9 * 5];
    size_t n = 0;
    assert_int_equal(o3d_pointcloud_estimate_point_covariances(cov, 5, &n, pc, &param, 0), O3D_OK);
    assert_int_equal(n, 5);
    /* mean (0.5, 0.5, 0.2); var x = var y = (4 * 0.25 + 0) / 5 = 0.2; var z = (4 * 0.04 + 0.64) / 5 = 0.16;
     * cov xy = (4 * (+-0.25)) / 5 = 0 (two +0.25, two -0.25); cov xz = sum (x - 0.5)(z - 0.2) / 5 = 0. */
    const double want[9] = {0.2, 0, 0, 0, 0.2, 0, 0, 0, 0.16};
    for (size_t i = 0; i < 5; ++i)
        for (int k = 0; k < 9; ++k) assert_true(fabs(cov[9 * i + k] - want[k]) < 1e-12);
    int32_t has = 1;
    assert_int_equal(o3d_pointcloud_has_array(&has, pc, O3D_POINTCLOUD_COVARIANCES), O3D_OK);
    assert_int_equal(has, 0);
    O3D_ASSERT_FAILS(o3d_pointcloud_estimate_point_covariances(cov, 4, &n, pc, &param, 0), O3D_ERROR_BUFFER_TOO_SMALL);
    assert_int_equal(n, 5);
    O3D_ASSERT_FAILS(o3d_pointcloud_estimate_point_covariances(cov, 5, &n, pc, &param, -1), INV);
    O3D_ASSERT_FAILS(o3d_pointcloud_estimate_point_covariances(cov, 5, NULL, pc, &param, 0), INV);
    o3d_pointcloud_destroy(pc);
}

/* Two perpendicular planes (a floor and a wall), sampled with normals: two patches whose normals are the planes'. */
static void test_planar_patches_of_floor_and_wall(void** state) {
    (void)state;
    enum { SIDE = 40 };
    double* xyz = malloc(3 * 2 * SIDE * SIDE * sizeof(double));
    double* nrm = malloc(3 * 2 * SIDE * SIDE * sizeof(double));
    size_t n = 0;
    uint64_t st = 3;
    for (int plane = 0; plane < 2; ++plane)
        for (int i = 0; i < SIDE; ++i)
            for (int j = 0; j < SIDE; ++j, ++n) {
                const double a = 0.05 * i + 0.01, b = 0.05 * j + 0.01, w = 0.001 * jitter(&st);
                double* p = xyz + 3 * n;
                double* q = nrm + 3 * n;
                if (plane == 0) { /* floor z = 0 over x, y in (0, 2) */
                    p[0] = a; p[1] = b; p[2] = w;
                    q[0] = 0; q[1] = 0; q[2] = 1;
                } else { /* wall x = 0 over y in (0, 2), z in (0, 2) */
                    p[0] = w; p[1] = a; p[2] = b + 0.05;
                    q[0] = 1; q[1] = 0; q[2] = 0;
                }
            }
    o3d_pointcloud_t* pc = cloud_of(xyz, n, nrm);
    double boxes[15 * 16];
    size_t count = 0;
    assert_int_equal(o3d_pointcloud_detect_planar_patches(boxes, 16, &count, pc, NULL), O3D_OK);
    assert_int_equal(count, 2);
    int saw_floor = 0, saw_wall = 0;
    for (size_t i = 0; i < count; ++i) {
        const o3d_obb_t* box = (const o3d_obb_t*)(boxes + 15 * i);
        const double nz[3] = {box->R[2], box->R[5], box->R[8]}; /* column 2: the normal */
        if (fabs(fabs(nz[2]) - 1.0) < 1e-3) {
            saw_floor = 1;
            assert_true(fabs(box->center[2]) < 0.01);
        }
        if (fabs(fabs(nz[0]) - 1.0) < 1e-3) {
            saw_wall = 1;
            assert_true(fabs(box->center[0]) < 0.01);
        }
        assert_true(box->extent[2] < 0.01); /* thin along the normal */
    }
    assert_true(saw_floor && saw_wall);
    /* Options: a minimum edge longer than the planes leaves none; a bad ratio is refused. */
    o3d_planar_patch_options_t opts;
    assert_int_equal(o3d_planar_patch_options_init(&opts, sizeof opts), O3D_OK);
    assert_true(opts.normal_variance_threshold_deg == 60.0 && opts.coplanarity_deg == 75.0);
    assert_true(opts.outlier_ratio == 0.75 && opts.search_param.knn == 30);
    opts.min_plane_edge_length = 5.0;
    assert_int_equal(o3d_pointcloud_detect_planar_patches(NULL, 0, &count, pc, &opts), O3D_OK);
    assert_int_equal(count, 0);
    opts.min_plane_edge_length = 0.0;
    opts.outlier_ratio = 1.5;
    O3D_ASSERT_FAILS(o3d_pointcloud_detect_planar_patches(NULL, 0, &count, pc, &opts), INV);
    o3d_pointcloud_destroy(pc);
    /* Without normals: a clear error. */
    pc = cloud_of(xyz, n, NULL);
    O3D_ASSERT_FAILS(o3d_pointcloud_detect_planar_patches(NULL, 0, &count, pc, NULL), INV);
    o3d_pointcloud_destroy(pc);
    free(xyz);
    free(nrm);
}

/* Six points in two voxels of edge 1 from (0, 0, 0): two output points, their means, the traced indices and the
 * octants of the cubic ids. */
static void test_voxel_down_sample_and_trace(void** state) {
    (void)state;
    const double xyz[18] = {0.2, 0.2, 0.2, 0.7, 0.2, 0.2, 0.3, 0.8, 0.9, /* voxel (0,0,0) */
                            1.2, 0.1, 0.1, 1.9, 0.9, 0.9, 1.1, 0.1, 0.6}; /* voxel (1,0,0) */
    o3d_pointcloud_t* pc = cloud_of(xyz, 6, NULL);
    const double lo[3] = {0, 0, 0}, hi[3] = {2, 1, 1};
    o3d_pointcloud_t* out = NULL;
    o3d_index_lists_t *cubic = NULL, *traced = NULL;
    assert_int_equal(o3d_pointcloud_voxel_down_sample_and_trace(&out, &cubic, &traced, pc, 1.0, lo, hi, 0), O3D_OK);
    const double* p = NULL;
    size_t n = 0;
    assert_int_equal(o3d_pointcloud_array_view(&p, &n, out, O3D_POINTCLOUD_POINTS), O3D_OK);
    assert_int_equal(n, 2);
    const double mean0[3] = {0.4, 0.4, 1.3 / 3.0}, mean1[3] = {4.2 / 3.0, 1.1 / 3.0, 1.6 / 3.0};
    for (int d = 0; d < 3; ++d) {
        assert_true(fabs(p[d] - mean0[d]) < 1e-12);
        assert_true(fabs(p[3 + d] - mean1[d]) < 1e-12);
    }
    int64_t off[3];
    int32_t val[16];
    size_t got = 0;
    assert_int_equal(o3d_index_lists_get_offsets(off, 3, &got, traced), O3D_OK);
    assert_int_equal(got, 3);
    assert_int_equal(o3d_index_lists_get_values(val, 16, &got, traced), O3D_OK);
    assert_int_equal(got, 6);
    const int32_t want_traced[6] = {0, 1, 2, 3, 4, 5};
    assert_int_equal(off[1], 3);
    assert_memory_equal(val, want_traced, sizeof want_traced);
    /* Octant bits: x (1), y (2), z (4) set in the upper half. Voxel 0: point 0 in octant 0, point 1 in 1, point 2
     * in 6; voxel 1: point 3 in 0, point 4 in 7, point 5 in 4. */
    assert_int_equal(o3d_index_lists_get_values(val, 16, &got, cubic), O3D_OK);
    assert_int_equal(got, 16);
    const int32_t want_cubic[16] = {0, 1, -1, -1, -1, -1, 2, -1, 3, -1, -1, -1, 5, -1, -1, 4};
    assert_memory_equal(val, want_cubic, sizeof want_cubic);
    o3d_pointcloud_destroy(out);
    o3d_index_lists_destroy(cubic);
    o3d_index_lists_destroy(traced);
    /* Bad input leaves all three outputs NULL. */
    out = (o3d_pointcloud_t*)1;
    O3D_ASSERT_FAILS(o3d_pointcloud_voxel_down_sample_and_trace(&out, &cubic, &traced, pc, 0.0, lo, hi, 0), INV);
    assert_null(out);
    assert_null(cubic);
    assert_null(traced);
    O3D_ASSERT_FAILS(o3d_pointcloud_voxel_down_sample_and_trace(&out, &cubic, &traced, pc, 1.0, hi, lo, 0), INV);
    O3D_ASSERT_FAILS(o3d_pointcloud_voxel_down_sample_and_trace(&out, NULL, &traced, pc, 1.0, lo, hi, 0), INV);
    o3d_pointcloud_destroy(pc);
}

int main(void) {
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_smoothing_flattens_a_noisy_plane),
        cmocka_unit_test(test_minimal_box_and_ellipsoid),
        cmocka_unit_test(test_static_point_covariances),
        cmocka_unit_test(test_planar_patches_of_floor_and_wall),
        cmocka_unit_test(test_voxel_down_sample_and_trace),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
