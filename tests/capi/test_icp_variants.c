/* SPDX-License-Identifier: MIT */
/* C API registration.h, ICP variants: colored, generalized and symmetric ICP through o3d_register_icp, robust
 * kernels (o3d_robust_kernel_weight and opts.kernel), the new option fields' defaults and versioning, and the
 * NULL / invalid-argument / missing-attribute paths (status plus a non-empty message). */
#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdlib.h>
#include <string.h>

#include <cmocka.h>

#include "o3d/o3d.h"
#include "o3d_test_util.h"

enum { WITH_NORMALS = 1, WITH_COLORS = 2 };

/* An asymmetric height field sampled by the R2 low-discrepancy sequence, with exact normals and an intensity
 * pattern, moved by `motion` (row-major 4x4, NULL: identity). */
static o3d_pointcloud_t* height_field(size_t n, const double motion[16], int attributes) {
    double* xyz = malloc(3 * n * sizeof(double));
    double* nrm = malloc(3 * n * sizeof(double));
    double* rgb = malloc(3 * n * sizeof(double));
    assert_non_null(xyz);
    assert_non_null(nrm);
    assert_non_null(rgb);
    for (size_t k = 0; k < n; ++k) {
        const double x = -1.0 + 2.0 * fmod(0.5 + k * 0.7548776662466927, 1.0);
        const double y = -0.7 + 1.9 * fmod(0.5 + k * 0.5698402909980532, 1.0);
        const double z = 0.3 * sin(2.0 * x) + 0.2 * cos(3.0 * y) + 0.15 * x * y + 0.1 * x * x;
        const double fx = 0.6 * cos(2.0 * x) + 0.15 * y + 0.2 * x, fy = -0.6 * sin(3.0 * y) + 0.15 * x;
        const double len = sqrt(fx * fx + fy * fy + 1.0);
        const double p[3] = {x, y, z}, nn[3] = {-fx / len, -fy / len, 1.0 / len};
        for (int r = 0; r < 3; ++r) {
            xyz[3 * k + r] = motion ? motion[4 * r] * p[0] + motion[4 * r + 1] * p[1] + motion[4 * r + 2] * p[2] +
                                          motion[4 * r + 3]
                                    : p[r];
            nrm[3 * k + r] = motion ? motion[4 * r] * nn[0] + motion[4 * r + 1] * nn[1] + motion[4 * r + 2] * nn[2]
                                    : nn[r];
        }
        const double i = 0.5 + 0.3 * sin(4.0 * x) * cos(3.0 * y);
        rgb[3 * k] = rgb[3 * k + 1] = rgb[3 * k + 2] = i;
    }
    o3d_pointcloud_t* pc = NULL;
    assert_int_equal(o3d_pointcloud_create(&pc), O3D_OK);
    assert_int_equal(o3d_pointcloud_set_array(pc, O3D_POINTCLOUD_POINTS, xyz, n), O3D_OK);
    if (attributes & WITH_NORMALS) assert_int_equal(o3d_pointcloud_set_array(pc, O3D_POINTCLOUD_NORMALS, nrm, n), O3D_OK);
    if (attributes & WITH_COLORS) assert_int_equal(o3d_pointcloud_set_array(pc, O3D_POINTCLOUD_COLORS, rgb, n), O3D_OK);
    free(xyz);
    free(nrm);
    free(rgb);
    return pc;
}

static void test_new_option_defaults_and_old_structs(void** state) {
    (void)state;
    o3d_icp_options_t o;
    memset(&o, 0xAB, sizeof o);
    assert_int_equal(o3d_icp_options_init(&o, sizeof o), O3D_OK);
    assert_int_equal(o.kernel, O3D_KERNEL_L2);
    assert_true(o.kernel_k == 1.0);
    assert_true(o.lambda_geometric == 0.968);
    assert_true(o.epsilon == 1e-3);
    /* A caller built before the kernel fields existed: the library fills them with the defaults. */
    o3d_icp_options_t old;
    memset(&old, 0xAB, sizeof old);
    assert_int_equal(o3d_icp_options_init(&old, (uint32_t)offsetof(o3d_icp_options_t, kernel)), O3D_OK);
    assert_int_equal(old.struct_size, offsetof(o3d_icp_options_t, kernel));
    assert_int_equal(old.kernel, (int32_t)0xABABABAB); /* untouched beyond struct_size */
    old.estimation = O3D_ESTIMATION_POINT_TO_PLANE;
    double m[16], inv[16];
    o3d_test_motion_z(3.0, 0.01, 0.0, 0.0, m, inv);
    o3d_pointcloud_t* target = height_field(1000, NULL, WITH_NORMALS);
    o3d_pointcloud_t* source = height_field(1000, inv, 0);
    o3d_registration_result_t* r = NULL;
    assert_int_equal(o3d_register_icp(&r, source, target, 0.2, NULL, &old), O3D_OK);
    o3d_registration_result_destroy(r);
    o3d_pointcloud_destroy(source);
    o3d_pointcloud_destroy(target);
}

static void icp_recovers(int32_t estimation, int32_t kernel, double k, int source_attributes, int target_attributes) {
    double m[16], inv[16];
    o3d_test_motion_z(5.0, 0.03, -0.02, 0.01, m, inv);
    o3d_pointcloud_t* target = height_field(3000, NULL, target_attributes);
    o3d_pointcloud_t* source = height_field(3000, inv, source_attributes);
    o3d_icp_options_t o;
    assert_int_equal(o3d_icp_options_init(&o, sizeof o), O3D_OK);
    o.estimation = estimation;
    o.kernel = kernel;
    o.kernel_k = k;
    o.relative_fitness = o.relative_rmse = 1e-12;
    o.max_iteration = 100;
    o3d_registration_result_t* r = NULL;
    assert_int_equal(o3d_register_icp(&r, source, target, 0.2, NULL, &o), O3D_OK);
    o3d_pointcloud_destroy(source);
    o3d_pointcloud_destroy(target);
    double t[16], fitness = 0, rmse = 1;
    assert_int_equal(o3d_registration_result_get_transformation(t, r), O3D_OK);
    assert_true(o3d_test_max_abs_diff16(t, m) < 1e-7);
    assert_int_equal(o3d_registration_result_get_fitness(&fitness, r), O3D_OK);
    assert_int_equal(o3d_registration_result_get_inlier_rmse(&rmse, r), O3D_OK);
    assert_true(fitness == 1.0);
    assert_true(rmse < 1e-7);
    o3d_registration_result_destroy(r);
}

static void test_colored_icp(void** state) {
    (void)state;
    /* Colored ICP reads the source's colors and the target's colors and normals only. */
    icp_recovers(O3D_ESTIMATION_COLORED, O3D_KERNEL_L2, 1.0, WITH_COLORS, WITH_COLORS | WITH_NORMALS);
    icp_recovers(O3D_ESTIMATION_COLORED, O3D_KERNEL_HUBER, 0.02, WITH_COLORS, WITH_COLORS | WITH_NORMALS);
}

static void test_generalized_icp(void** state) {
    (void)state;
    /* Bare points: covariances from 20-neighbour normals; with normals: from those. */
    icp_recovers(O3D_ESTIMATION_GENERALIZED, O3D_KERNEL_L2, 1.0, 0, 0);
    icp_recovers(O3D_ESTIMATION_GENERALIZED, O3D_KERNEL_CAUCHY, 0.5, WITH_NORMALS, WITH_NORMALS);
}

static void test_symmetric_icp(void** state) {
    (void)state;
    icp_recovers(O3D_ESTIMATION_SYMMETRIC, O3D_KERNEL_L2, 1.0, WITH_NORMALS, WITH_NORMALS);
    icp_recovers(O3D_ESTIMATION_SYMMETRIC, O3D_KERNEL_TUKEY, 0.05, WITH_NORMALS, WITH_NORMALS);
}

static void test_point_to_plane_with_kernels(void** state) {
    (void)state;
    icp_recovers(O3D_ESTIMATION_POINT_TO_PLANE, O3D_KERNEL_L1, -1.0, 0, WITH_NORMALS); /* L1 ignores k */
    icp_recovers(O3D_ESTIMATION_POINT_TO_PLANE, O3D_KERNEL_GM, 0.01, 0, WITH_NORMALS);
}

static void test_robust_kernel_weight(void** state) {
    (void)state;
    const double k = 0.5;
    const double residuals[] = {0.0, 0.2, -0.3, 0.5, 0.7, -2.0};
    for (size_t i = 0; i < sizeof residuals / sizeof residuals[0]; ++i) {
        const double r = residuals[i], a = fabs(r), q = r / k;
        double w = -1.0;
        assert_int_equal(o3d_robust_kernel_weight(&w, O3D_KERNEL_L2, k, r), O3D_OK);
        assert_true(w == 1.0);
        if (r != 0.0) {
            assert_int_equal(o3d_robust_kernel_weight(&w, O3D_KERNEL_L1, k, r), O3D_OK);
            assert_true(fabs(w - 1.0 / a) < 1e-15);
        }
        assert_int_equal(o3d_robust_kernel_weight(&w, O3D_KERNEL_HUBER, k, r), O3D_OK);
        assert_true(fabs(w - (a <= k ? 1.0 : k / a)) < 1e-15);
        assert_int_equal(o3d_robust_kernel_weight(&w, O3D_KERNEL_CAUCHY, k, r), O3D_OK);
        assert_true(fabs(w - 1.0 / (1.0 + q * q)) < 1e-15);
        assert_int_equal(o3d_robust_kernel_weight(&w, O3D_KERNEL_GM, k, r), O3D_OK);
        assert_true(fabs(w - k / ((k + r * r) * (k + r * r))) < 1e-15);
        assert_int_equal(o3d_robust_kernel_weight(&w, O3D_KERNEL_TUKEY, k, r), O3D_OK);
        assert_true(fabs(w - (a <= k ? (1.0 - q * q) * (1.0 - q * q) : 0.0)) < 1e-15);
    }
    double w = 0.0;
    assert_int_equal(o3d_robust_kernel_weight(&w, O3D_KERNEL_L1, 1.0, 0.0), O3D_OK);
    assert_true(isinf(w)); /* 1 / |0|, as Open3D's L1Loss */
    assert_int_equal(o3d_robust_kernel_weight(&w, O3D_KERNEL_L2, NAN, 3.0), O3D_OK); /* L2 ignores k */
    assert_int_equal(o3d_robust_kernel_weight(&w, O3D_KERNEL_CAUCHY, 1.0, INFINITY), O3D_OK);
    assert_true(w == 0.0);

    O3D_ASSERT_FAILS(o3d_robust_kernel_weight(NULL, O3D_KERNEL_HUBER, 1.0, 0.5), O3D_ERROR_INVALID_ARGUMENT);
    O3D_ASSERT_FAILS(o3d_robust_kernel_weight(&w, -1, 1.0, 0.5), O3D_ERROR_INVALID_ARGUMENT);
    O3D_ASSERT_FAILS(o3d_robust_kernel_weight(&w, 6, 1.0, 0.5), O3D_ERROR_INVALID_ARGUMENT);
    O3D_ASSERT_FAILS(o3d_robust_kernel_weight(&w, O3D_KERNEL_TUKEY, 1.0, NAN), O3D_ERROR_INVALID_ARGUMENT);
    const int32_t with_k[] = {O3D_KERNEL_HUBER, O3D_KERNEL_CAUCHY, O3D_KERNEL_GM, O3D_KERNEL_TUKEY};
    const double bad_k[] = {0.0, -1.0, NAN, INFINITY};
    for (size_t i = 0; i < 4; ++i)
        for (size_t j = 0; j < 4; ++j)
            O3D_ASSERT_FAILS(o3d_robust_kernel_weight(&w, with_k[i], bad_k[j], 0.5), O3D_ERROR_INVALID_ARGUMENT);
}

/* Every new field, out of range, makes o3d_register_icp fail with INVALID_ARGUMENT and leave *out NULL. */
static void test_invalid_new_fields(void** state) {
    (void)state;
    o3d_pointcloud_t* pc = height_field(500, NULL, WITH_NORMALS | WITH_COLORS);
    o3d_icp_options_t o;
    o3d_registration_result_t* r = (o3d_registration_result_t*)&o; /* must be reset to NULL */

#define EXPECT_REJECTED(field, value, estimation_)                                                  \
    do {                                                                                            \
        assert_int_equal(o3d_icp_options_init(&o, sizeof o), O3D_OK);                               \
        o.estimation = (estimation_);                                                               \
        o.field = (value);                                                                          \
        O3D_ASSERT_FAILS(o3d_register_icp(&r, pc, pc, 0.1, NULL, &o), O3D_ERROR_INVALID_ARGUMENT);  \
        assert_null(r);                                                                             \
    } while (0)

    EXPECT_REJECTED(estimation, 5, 5);
    EXPECT_REJECTED(estimation, -1, -1);
    EXPECT_REJECTED(kernel, 6, O3D_ESTIMATION_POINT_TO_PLANE);
    EXPECT_REJECTED(kernel, -1, O3D_ESTIMATION_COLORED);
    EXPECT_REJECTED(lambda_geometric, -0.01, O3D_ESTIMATION_COLORED);
    EXPECT_REJECTED(lambda_geometric, 1.01, O3D_ESTIMATION_COLORED);
    EXPECT_REJECTED(lambda_geometric, NAN, O3D_ESTIMATION_COLORED);
    EXPECT_REJECTED(epsilon, 0.0, O3D_ESTIMATION_GENERALIZED);
    EXPECT_REJECTED(epsilon, -1e-3, O3D_ESTIMATION_GENERALIZED);
    EXPECT_REJECTED(epsilon, NAN, O3D_ESTIMATION_GENERALIZED);
    EXPECT_REJECTED(epsilon, INFINITY, O3D_ESTIMATION_GENERALIZED);
    const int32_t with_k[] = {O3D_KERNEL_HUBER, O3D_KERNEL_CAUCHY, O3D_KERNEL_GM, O3D_KERNEL_TUKEY};
    const double bad_k[] = {0.0, -0.5, NAN};
    for (size_t i = 0; i < 4; ++i)
        for (size_t j = 0; j < 3; ++j) {
            assert_int_equal(o3d_icp_options_init(&o, sizeof o), O3D_OK);
            o.estimation = O3D_ESTIMATION_SYMMETRIC;
            o.kernel = with_k[i];
            o.kernel_k = bad_k[j];
            O3D_ASSERT_FAILS(o3d_register_icp(&r, pc, pc, 0.1, NULL, &o), O3D_ERROR_INVALID_ARGUMENT);
            assert_null(r);
        }
#undef EXPECT_REJECTED

    /* The edges of the ranges are fine. */
    assert_int_equal(o3d_icp_options_init(&o, sizeof o), O3D_OK);
    o.estimation = O3D_ESTIMATION_COLORED;
    o.lambda_geometric = 0.0;
    assert_int_equal(o3d_register_icp(&r, pc, pc, 0.1, NULL, &o), O3D_OK);
    o3d_registration_result_destroy(r);
    o.lambda_geometric = 1.0;
    assert_int_equal(o3d_register_icp(&r, pc, pc, 0.1, NULL, &o), O3D_OK);
    o3d_registration_result_destroy(r);
    o3d_pointcloud_destroy(pc);
}

/* What each estimation needs, missing: INVALID_ARGUMENT; and the NULL arguments. */
static void test_missing_attributes_and_null(void** state) {
    (void)state;
    o3d_pointcloud_t* full = height_field(500, NULL, WITH_NORMALS | WITH_COLORS);
    o3d_pointcloud_t* no_colors = height_field(500, NULL, WITH_NORMALS);
    o3d_pointcloud_t* no_normals = height_field(500, NULL, WITH_COLORS);
    o3d_pointcloud_t* bare = height_field(500, NULL, 0);
    o3d_icp_options_t o;
    o3d_registration_result_t* r = NULL;

    assert_int_equal(o3d_icp_options_init(&o, sizeof o), O3D_OK);
    o.estimation = O3D_ESTIMATION_COLORED;
    O3D_ASSERT_FAILS(o3d_register_icp(&r, no_colors, full, 0.1, NULL, &o), O3D_ERROR_INVALID_ARGUMENT);
    O3D_ASSERT_FAILS(o3d_register_icp(&r, full, no_colors, 0.1, NULL, &o), O3D_ERROR_INVALID_ARGUMENT);
    O3D_ASSERT_FAILS(o3d_register_icp(&r, full, no_normals, 0.1, NULL, &o), O3D_ERROR_INVALID_ARGUMENT);
    assert_null(r);
    assert_int_equal(o3d_register_icp(&r, no_normals, full, 0.1, NULL, &o), O3D_OK); /* source normals unused */
    o3d_registration_result_destroy(r);

    o.estimation = O3D_ESTIMATION_SYMMETRIC;
    O3D_ASSERT_FAILS(o3d_register_icp(&r, no_normals, full, 0.1, NULL, &o), O3D_ERROR_INVALID_ARGUMENT);
    O3D_ASSERT_FAILS(o3d_register_icp(&r, full, no_normals, 0.1, NULL, &o), O3D_ERROR_INVALID_ARGUMENT);
    assert_null(r);

    o.estimation = O3D_ESTIMATION_GENERALIZED; /* always finds its covariances */
    assert_int_equal(o3d_register_icp(&r, bare, bare, 0.1, NULL, &o), O3D_OK);
    o3d_registration_result_destroy(r);

    const int32_t estimations[] = {O3D_ESTIMATION_COLORED, O3D_ESTIMATION_GENERALIZED, O3D_ESTIMATION_SYMMETRIC};
    for (size_t i = 0; i < 3; ++i) {
        o.estimation = estimations[i];
        O3D_ASSERT_FAILS(o3d_register_icp(NULL, full, full, 0.1, NULL, &o), O3D_ERROR_INVALID_ARGUMENT);
        O3D_ASSERT_FAILS(o3d_register_icp(&r, NULL, full, 0.1, NULL, &o), O3D_ERROR_INVALID_ARGUMENT);
        O3D_ASSERT_FAILS(o3d_register_icp(&r, full, NULL, 0.1, NULL, &o), O3D_ERROR_INVALID_ARGUMENT);
        O3D_ASSERT_FAILS(o3d_register_icp(&r, full, full, NAN, NULL, &o), O3D_ERROR_INVALID_ARGUMENT);
        assert_null(r);
    }
    o3d_pointcloud_destroy(full);
    o3d_pointcloud_destroy(no_colors);
    o3d_pointcloud_destroy(no_normals);
    o3d_pointcloud_destroy(bare);
}

/* The same answer, bit for bit, on 1 and 2 threads, for every new estimation with a kernel. */
static void test_thread_count_does_not_change_bits(void** state) {
    (void)state;
    double m[16], inv[16];
    o3d_test_motion_z(4.0, 0.02, -0.01, 0.02, m, inv);
    o3d_pointcloud_t* target = height_field(4000, NULL, WITH_NORMALS | WITH_COLORS);
    o3d_pointcloud_t* source = height_field(3500, inv, WITH_NORMALS | WITH_COLORS);
    const int32_t estimations[] = {O3D_ESTIMATION_COLORED, O3D_ESTIMATION_GENERALIZED, O3D_ESTIMATION_SYMMETRIC};
    for (size_t i = 0; i < 3; ++i) {
        double t[2][16];
        for (int threads = 1; threads <= 2; ++threads) {
            o3d_icp_options_t o;
            assert_int_equal(o3d_icp_options_init(&o, sizeof o), O3D_OK);
            o.estimation = estimations[i];
            o.kernel = O3D_KERNEL_HUBER;
            o.kernel_k = 0.01;
            o.num_threads = threads;
            o3d_registration_result_t* r = NULL;
            assert_int_equal(o3d_register_icp(&r, source, target, 0.1, NULL, &o), O3D_OK);
            assert_int_equal(o3d_registration_result_get_transformation(t[threads - 1], r), O3D_OK);
            o3d_registration_result_destroy(r);
        }
        assert_memory_equal(t[0], t[1], sizeof t[0]);
    }
    o3d_pointcloud_destroy(source);
    o3d_pointcloud_destroy(target);
}

int main(void) {
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_new_option_defaults_and_old_structs),
        cmocka_unit_test(test_colored_icp),
        cmocka_unit_test(test_generalized_icp),
        cmocka_unit_test(test_symmetric_icp),
        cmocka_unit_test(test_point_to_plane_with_kernels),
        cmocka_unit_test(test_robust_kernel_weight),
        cmocka_unit_test(test_invalid_new_fields),
        cmocka_unit_test(test_missing_attributes_and_null),
        cmocka_unit_test(test_thread_count_does_not_change_bits),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
