/* SPDX-License-Identifier: MIT */
/* C API registration.h: results through handles, options versioning, cancellation, and every
 * function's NULL / invalid-argument paths (status plus a non-empty message). */
#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdlib.h>
#include <string.h>

#include <cmocka.h>

#include "o3d/o3d.h"
#include "o3d_test_util.h"

/* An asymmetric height field sampled by the R2 low-discrepancy sequence, with exact normals. */
static o3d_pointcloud_t* height_field(size_t n, const double motion[16]) {
    double* xyz = malloc(3 * n * sizeof(double));
    double* nrm = malloc(3 * n * sizeof(double));
    assert_non_null(xyz);
    assert_non_null(nrm);
    for (size_t k = 0; k < n; ++k) {
        const double x = -1.0 + 2.0 * fmod(0.5 + k * 0.7548776662466927, 1.0);
        const double y = -0.7 + 1.9 * fmod(0.5 + k * 0.5698402909980532, 1.0);
        const double z = 0.3 * sin(2.0 * x) + 0.2 * cos(3.0 * y) + 0.15 * x * y + 0.1 * x * x;
        const double fx = 0.6 * cos(2.0 * x) + 0.15 * y + 0.2 * x, fy = -0.6 * sin(3.0 * y) + 0.15 * x;
        const double len = sqrt(fx * fx + fy * fy + 1.0);
        const double p[3] = {x, y, z};
        for (int r = 0; r < 3; ++r)
            xyz[3 * k + r] = motion ? motion[4 * r] * p[0] + motion[4 * r + 1] * p[1] + motion[4 * r + 2] * p[2] +
                                          motion[4 * r + 3]
                                    : p[r];
        nrm[3 * k] = -fx / len;
        nrm[3 * k + 1] = -fy / len;
        nrm[3 * k + 2] = 1.0 / len;
    }
    o3d_pointcloud_t* pc = NULL;
    assert_int_equal(o3d_pointcloud_create(&pc), O3D_OK);
    assert_int_equal(o3d_pointcloud_set_array(pc, O3D_POINTCLOUD_POINTS, xyz, n), O3D_OK);
    assert_int_equal(o3d_pointcloud_set_array(pc, O3D_POINTCLOUD_NORMALS, nrm, n), O3D_OK);
    free(xyz);
    free(nrm);
    return pc;
}

static o3d_pointcloud_t* cloud_of(const double* xyz, size_t n) {
    o3d_pointcloud_t* pc = NULL;
    assert_int_equal(o3d_pointcloud_create(&pc), O3D_OK);
    assert_int_equal(o3d_pointcloud_set_array(pc, O3D_POINTCLOUD_POINTS, xyz, n), O3D_OK);
    return pc;
}

static void test_options_init_defaults(void** state) {
    (void)state;
    o3d_icp_options_t o;
    memset(&o, 0xAB, sizeof o);
    assert_int_equal(o3d_icp_options_init(&o, sizeof o), O3D_OK);
    assert_int_equal(o.struct_size, sizeof o);
    assert_int_equal(o.estimation, O3D_ESTIMATION_POINT_TO_POINT);
    assert_int_equal(o.with_scaling, 0);
    assert_true(o.relative_fitness == 1e-6);
    assert_true(o.relative_rmse == 1e-6);
    assert_int_equal(o.max_iteration, 30);
    assert_int_equal(o.num_threads, 0);
    assert_null(o.progress);
    assert_null(o.user_data);
    O3D_ASSERT_FAILS(o3d_icp_options_init(NULL, sizeof o), O3D_ERROR_INVALID_ARGUMENT);
    O3D_ASSERT_FAILS(o3d_icp_options_init(&o, 0), O3D_ERROR_INVALID_ARGUMENT);
    O3D_ASSERT_FAILS(o3d_icp_options_init(&o, sizeof o + 8), O3D_ERROR_INVALID_ARGUMENT);
}

static void icp_recovers(int32_t estimation) {
    double m[16], inv[16];
    o3d_test_motion_z(5.0, 0.03, -0.02, 0.01, m, inv);
    o3d_pointcloud_t* target = height_field(3000, NULL);
    o3d_pointcloud_t* source = height_field(3000, inv);
    o3d_icp_options_t o;
    assert_int_equal(o3d_icp_options_init(&o, sizeof o), O3D_OK);
    o.estimation = estimation;
    o.relative_fitness = o.relative_rmse = 1e-12;
    o.max_iteration = 100;
    o3d_registration_result_t* r = NULL;
    assert_int_equal(o3d_register_icp(&r, source, target, 0.2, NULL, &o), O3D_OK);
    /* Handles are independent: the result outlives its inputs. */
    o3d_pointcloud_destroy(source);
    o3d_pointcloud_destroy(target);
    double t[16], fitness = 0, rmse = 1;
    assert_int_equal(o3d_registration_result_get_transformation(t, r), O3D_OK);
    assert_true(o3d_test_max_abs_diff16(t, m) < 1e-9);
    assert_int_equal(o3d_registration_result_get_fitness(&fitness, r), O3D_OK);
    assert_int_equal(o3d_registration_result_get_inlier_rmse(&rmse, r), O3D_OK);
    assert_true(fitness == 1.0);
    assert_true(rmse < 1e-9);
    size_t n = 0;
    assert_int_equal(o3d_registration_result_get_correspondence_set(NULL, 0, &n, r), O3D_OK);
    assert_int_equal(n, 3000);
    o3d_registration_result_destroy(r);
}

static void test_icp_point_to_point(void** state) {
    (void)state;
    icp_recovers(O3D_ESTIMATION_POINT_TO_POINT);
}

static void test_icp_point_to_plane(void** state) {
    (void)state;
    icp_recovers(O3D_ESTIMATION_POINT_TO_PLANE);
}

static int32_t cancel_on_second_call(double fraction, void* user_data) {
    int* calls = user_data;
    ++*calls;
    assert_true(fraction > 0.0 && fraction <= 1.0);
    return *calls >= 2;
}

static void test_icp_cancel(void** state) {
    (void)state;
    double m[16], inv[16];
    o3d_test_motion_z(5.0, 0.03, -0.02, 0.01, m, inv);
    o3d_pointcloud_t* target = height_field(1000, NULL);
    o3d_pointcloud_t* source = height_field(1000, inv);
    o3d_icp_options_t o;
    o3d_icp_options_init(&o, sizeof o);
    o.relative_fitness = o.relative_rmse = 0.0; /* never converge: only the callback can stop it early */
    int calls = 0;
    o.progress = cancel_on_second_call;
    o.user_data = &calls;
    o3d_registration_result_t* r = (o3d_registration_result_t*)&calls; /* must be reset to NULL */
    O3D_ASSERT_FAILS(o3d_register_icp(&r, source, target, 0.2, NULL, &o), O3D_ERROR_CANCELLED);
    assert_null(r);
    assert_int_equal(calls, 2);
    o3d_pointcloud_destroy(source);
    o3d_pointcloud_destroy(target);
}

static void test_icp_thread_count_does_not_change_bits(void** state) {
    (void)state;
    double m[16], inv[16];
    o3d_test_motion_z(4.0, 0.02, 0.01, -0.01, m, inv);
    o3d_pointcloud_t* target = height_field(5000, NULL);
    o3d_pointcloud_t* source = height_field(4000, inv);
    double t[2][16], rmse[2];
    for (int k = 0; k < 2; ++k) {
        o3d_icp_options_t o;
        o3d_icp_options_init(&o, sizeof o);
        o.estimation = O3D_ESTIMATION_POINT_TO_PLANE;
        o.num_threads = k + 1;
        o3d_registration_result_t* r = NULL;
        assert_int_equal(o3d_register_icp(&r, source, target, 0.1, NULL, &o), O3D_OK);
        o3d_registration_result_get_transformation(t[k], r);
        o3d_registration_result_get_inlier_rmse(&rmse[k], r);
        o3d_registration_result_destroy(r);
    }
    assert_memory_equal(t[0], t[1], sizeof t[0]);
    assert_memory_equal(&rmse[0], &rmse[1], sizeof rmse[0]);
    o3d_pointcloud_destroy(source);
    o3d_pointcloud_destroy(target);
}

static void test_icp_old_options_struct(void** state) {
    (void)state;
    /* A caller compiled before `progress` existed passes a shorter struct: the rest takes defaults. */
    o3d_pointcloud_t* target = height_field(500, NULL);
    o3d_icp_options_t o;
    o3d_icp_options_init(&o, sizeof o);
    o.struct_size = (uint32_t)offsetof(o3d_icp_options_t, progress);
    o.progress = (o3d_progress_callback)(uintptr_t)1; /* garbage beyond struct_size must be ignored */
    o3d_registration_result_t* r = NULL;
    assert_int_equal(o3d_register_icp(&r, target, target, 0.1, NULL, &o), O3D_OK);
    o3d_registration_result_destroy(r);
    o3d_pointcloud_destroy(target);
}

static void test_evaluate_and_correspondences(void** state) {
    (void)state;
    const double tgt[] = {0, 0, 0, 1, 0, 0, 0, 1, 0};
    const double src[] = {0, 0, 0.1, 1, 0, 0.2, 5, 5, 5, 0, 1, 0.6};
    o3d_pointcloud_t* target = cloud_of(tgt, 3);
    o3d_pointcloud_t* source = cloud_of(src, 4);
    const double down[16] = {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, -0.3, 0, 0, 0, 1};
    o3d_registration_result_t* r = NULL;
    assert_int_equal(o3d_evaluate_registration(&r, source, target, 0.5, down), O3D_OK);
    double fitness, rmse, t[16];
    o3d_registration_result_get_fitness(&fitness, r);
    o3d_registration_result_get_inlier_rmse(&rmse, r);
    o3d_registration_result_get_transformation(t, r);
    assert_true(fitness == 0.75);
    assert_true(fabs(rmse - sqrt((0.04 + 0.01 + 0.09) / 3.0)) < 1e-15);
    assert_memory_equal(t, down, sizeof down);

    size_t n = 0;
    int32_t pairs[8] = {0};
    O3D_ASSERT_FAILS(o3d_registration_result_get_correspondence_set(pairs, 2, &n, r), O3D_ERROR_BUFFER_TOO_SMALL);
    assert_int_equal(n, 3);
    assert_int_equal(o3d_registration_result_get_correspondence_set(pairs, 4, &n, r), O3D_OK);
    const int32_t expected[6] = {0, 0, 1, 1, 3, 2};
    assert_memory_equal(pairs, expected, sizeof expected);
    o3d_registration_result_destroy(r);

    /* NULL transformation means identity: only the first two source points pair. */
    assert_int_equal(o3d_evaluate_registration(&r, source, target, 0.5, NULL), O3D_OK);
    o3d_registration_result_get_fitness(&fitness, r);
    assert_true(fitness == 0.5);
    o3d_registration_result_destroy(r);
    o3d_pointcloud_destroy(source);
    o3d_pointcloud_destroy(target);
}

static void test_information_matrix(void** state) {
    (void)state;
    const double tgt[] = {0.5, -1.0, 2.0, 1.5, 0.25, -0.75};
    const double src[] = {0.5, -1.0, 2.05, 9, 9, 9};
    o3d_pointcloud_t* target = cloud_of(tgt, 2);
    o3d_pointcloud_t* source = cloud_of(src, 2);
    double info[36];
    assert_int_equal(o3d_get_information_matrix_from_point_clouds(info, source, target, 0.1, NULL), O3D_OK);
    /* One pair, q = (0.5, -1, 2): G = [-[q]x | I], info = G^T G. */
    const double x = 0.5, y = -1.0, z = 2.0;
    const double expected[36] = {y * y + z * z, -x * y, -x * z, 0, -z, y,
                                 -x * y, x * x + z * z, -y * z, z, 0, -x,
                                 -x * z, -y * z, x * x + y * y, -y, x, 0,
                                 0, z, -y, 1, 0, 0,
                                 -z, 0, x, 0, 1, 0,
                                 y, -x, 0, 0, 0, 1};
    for (int i = 0; i < 36; ++i) assert_true(fabs(info[i] - expected[i]) < 1e-12);
    o3d_pointcloud_destroy(source);
    o3d_pointcloud_destroy(target);
}

static void test_invalid_arguments(void** state) {
    (void)state;
    const double xyz[] = {0, 0, 0, 1, 0, 0, 0, 1, 0};
    o3d_pointcloud_t* pc = cloud_of(xyz, 3);
    o3d_pointcloud_t* empty = NULL;
    assert_int_equal(o3d_pointcloud_create(&empty), O3D_OK);
    o3d_registration_result_t* r = NULL;
    double bad_init[16] = {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1};
    bad_init[3] = NAN;
    double info[36], t[16], d;
    o3d_icp_options_t o;

    O3D_ASSERT_FAILS(o3d_register_icp(NULL, pc, pc, 0.1, NULL, NULL), O3D_ERROR_INVALID_ARGUMENT);
    O3D_ASSERT_FAILS(o3d_register_icp(&r, NULL, pc, 0.1, NULL, NULL), O3D_ERROR_INVALID_ARGUMENT);
    O3D_ASSERT_FAILS(o3d_register_icp(&r, pc, NULL, 0.1, NULL, NULL), O3D_ERROR_INVALID_ARGUMENT);
    O3D_ASSERT_FAILS(o3d_register_icp(&r, empty, pc, 0.1, NULL, NULL), O3D_ERROR_INVALID_ARGUMENT);
    O3D_ASSERT_FAILS(o3d_register_icp(&r, pc, empty, 0.1, NULL, NULL), O3D_ERROR_INVALID_ARGUMENT);
    O3D_ASSERT_FAILS(o3d_register_icp(&r, pc, pc, 0.0, NULL, NULL), O3D_ERROR_INVALID_ARGUMENT);
    O3D_ASSERT_FAILS(o3d_register_icp(&r, pc, pc, -1.0, NULL, NULL), O3D_ERROR_INVALID_ARGUMENT);
    O3D_ASSERT_FAILS(o3d_register_icp(&r, pc, pc, NAN, NULL, NULL), O3D_ERROR_INVALID_ARGUMENT);
    O3D_ASSERT_FAILS(o3d_register_icp(&r, pc, pc, 0.1, bad_init, NULL), O3D_ERROR_INVALID_ARGUMENT);
    o3d_icp_options_init(&o, sizeof o);
    o.max_iteration = -1;
    O3D_ASSERT_FAILS(o3d_register_icp(&r, pc, pc, 0.1, NULL, &o), O3D_ERROR_INVALID_ARGUMENT);
    o3d_icp_options_init(&o, sizeof o);
    o.estimation = 7;
    O3D_ASSERT_FAILS(o3d_register_icp(&r, pc, pc, 0.1, NULL, &o), O3D_ERROR_INVALID_ARGUMENT);
    o3d_icp_options_init(&o, sizeof o);
    o.estimation = O3D_ESTIMATION_POINT_TO_PLANE; /* pc has no normals */
    O3D_ASSERT_FAILS(o3d_register_icp(&r, pc, pc, 0.1, NULL, &o), O3D_ERROR_INVALID_ARGUMENT);
    o3d_icp_options_init(&o, sizeof o);
    o.num_threads = -1;
    O3D_ASSERT_FAILS(o3d_register_icp(&r, pc, pc, 0.1, NULL, &o), O3D_ERROR_INVALID_ARGUMENT);
    o3d_icp_options_init(&o, sizeof o);
    o.relative_rmse = NAN;
    O3D_ASSERT_FAILS(o3d_register_icp(&r, pc, pc, 0.1, NULL, &o), O3D_ERROR_INVALID_ARGUMENT);
    o.struct_size = 2;
    O3D_ASSERT_FAILS(o3d_register_icp(&r, pc, pc, 0.1, NULL, &o), O3D_ERROR_INVALID_ARGUMENT);
    assert_null(r);

    O3D_ASSERT_FAILS(o3d_evaluate_registration(NULL, pc, pc, 0.1, NULL), O3D_ERROR_INVALID_ARGUMENT);
    O3D_ASSERT_FAILS(o3d_evaluate_registration(&r, NULL, pc, 0.1, NULL), O3D_ERROR_INVALID_ARGUMENT);
    O3D_ASSERT_FAILS(o3d_evaluate_registration(&r, pc, NULL, 0.1, NULL), O3D_ERROR_INVALID_ARGUMENT);
    O3D_ASSERT_FAILS(o3d_evaluate_registration(&r, empty, pc, 0.1, NULL), O3D_ERROR_INVALID_ARGUMENT);
    O3D_ASSERT_FAILS(o3d_evaluate_registration(&r, pc, pc, NAN, NULL), O3D_ERROR_INVALID_ARGUMENT);
    O3D_ASSERT_FAILS(o3d_evaluate_registration(&r, pc, pc, 0.1, bad_init), O3D_ERROR_INVALID_ARGUMENT);
    assert_null(r);

    O3D_ASSERT_FAILS(o3d_get_information_matrix_from_point_clouds(info, NULL, pc, 0.1, NULL),
                     O3D_ERROR_INVALID_ARGUMENT);
    O3D_ASSERT_FAILS(o3d_get_information_matrix_from_point_clouds(info, pc, NULL, 0.1, NULL),
                     O3D_ERROR_INVALID_ARGUMENT);
    O3D_ASSERT_FAILS(o3d_get_information_matrix_from_point_clouds(NULL, pc, pc, 0.1, NULL),
                     O3D_ERROR_INVALID_ARGUMENT);
    O3D_ASSERT_FAILS(o3d_get_information_matrix_from_point_clouds(info, pc, empty, 0.1, NULL),
                     O3D_ERROR_INVALID_ARGUMENT);
    O3D_ASSERT_FAILS(o3d_get_information_matrix_from_point_clouds(info, pc, pc, -2.0, NULL),
                     O3D_ERROR_INVALID_ARGUMENT);
    O3D_ASSERT_FAILS(o3d_get_information_matrix_from_point_clouds(info, pc, pc, 0.1, bad_init),
                     O3D_ERROR_INVALID_ARGUMENT);

    assert_int_equal(o3d_evaluate_registration(&r, pc, pc, 0.1, NULL), O3D_OK);
    size_t n;
    O3D_ASSERT_FAILS(o3d_registration_result_get_transformation(t, NULL), O3D_ERROR_INVALID_ARGUMENT);
    O3D_ASSERT_FAILS(o3d_registration_result_get_transformation(NULL, r), O3D_ERROR_INVALID_ARGUMENT);
    O3D_ASSERT_FAILS(o3d_registration_result_get_fitness(&d, NULL), O3D_ERROR_INVALID_ARGUMENT);
    O3D_ASSERT_FAILS(o3d_registration_result_get_fitness(NULL, r), O3D_ERROR_INVALID_ARGUMENT);
    O3D_ASSERT_FAILS(o3d_registration_result_get_inlier_rmse(&d, NULL), O3D_ERROR_INVALID_ARGUMENT);
    O3D_ASSERT_FAILS(o3d_registration_result_get_inlier_rmse(NULL, r), O3D_ERROR_INVALID_ARGUMENT);
    O3D_ASSERT_FAILS(o3d_registration_result_get_correspondence_set(NULL, 0, &n, NULL), O3D_ERROR_INVALID_ARGUMENT);
    O3D_ASSERT_FAILS(o3d_registration_result_get_correspondence_set(NULL, 0, NULL, r), O3D_ERROR_INVALID_ARGUMENT);
    o3d_registration_result_destroy(r);
    o3d_registration_result_destroy(NULL);
    o3d_pointcloud_destroy(empty);
    o3d_pointcloud_destroy(pc);
}

int main(void) {
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_options_init_defaults),
        cmocka_unit_test(test_icp_point_to_point),
        cmocka_unit_test(test_icp_point_to_plane),
        cmocka_unit_test(test_icp_cancel),
        cmocka_unit_test(test_icp_thread_count_does_not_change_bits),
        cmocka_unit_test(test_icp_old_options_struct),
        cmocka_unit_test(test_evaluate_and_correspondences),
        cmocka_unit_test(test_information_matrix),
        cmocka_unit_test(test_invalid_arguments),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
