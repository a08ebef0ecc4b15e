/* SPDX-License-Identifier: MIT */
/* C API registration.h, global part: correspondence checkers, RANSAC, FGR and the random seed. Known
 * transforms recovered, reproducibility by seed on any thread count, cancellation, and every function's
 * NULL / invalid-argument paths (status plus a non-empty message). */
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

#ifndef M_PI
#define M_PI 3.14159265358979323846
#endif

enum { kPoints = 600 };

/* Rotation by `deg` about the axis (ax, ay, az), then translation t: row-major 4x4. */
static void rigid(double deg, double ax, double ay, double az, const double t[3], double m[16]) {
    const double len = sqrt(ax * ax + ay * ay + az * az);
    const double x = ax / len, y = ay / len, z = az / len;
    const double c = cos(deg * M_PI / 180.0), s = sin(deg * M_PI / 180.0), k = 1.0 - c;
    const double r[9] = {c + x * x * k,     x * y * k - z * s, x * z * k + y * s, y * x * k + z * s, c + y * y * k,
                         y * z * k - x * s, z * x * k - y * s, z * y * k + x * s, c + z * z * k};
    for (int i = 0; i < 3; ++i) {
        for (int j = 0; j < 3; ++j) m[4 * i + j] = r[3 * i + j];
        m[4 * i + 3] = t[i];
    }
    m[12] = m[13] = m[14] = 0.0;
    m[15] = 1.0;
}

static const double kT[3] = {0.5, -0.3, 0.8};

/* An asymmetric height field sampled by the R2 sequence, with normals. */
static o3d_pointcloud_t* height_field(size_t n) {
    double* xyz = malloc(3 * n * sizeof(double));
    double* nrm = malloc(3 * n * sizeof(double));
    assert_non_null(xyz);
    assert_non_null(nrm);
    for (size_t k = 0; k < n; ++k) {
        const double x = -1.0 + 2.0 * fmod(0.5 + k * 0.7548776662466927, 1.0);
        const double y = -0.7 + 1.9 * fmod(0.5 + k * 0.5698402909980532, 1.0);
        const double fx = 0.6 * cos(2.0 * x) + 0.15 * y + 0.2 * x, fy = -0.6 * sin(3.0 * y) + 0.15 * x;
        const double len = sqrt(fx * fx + fy * fy + 1.0);
        xyz[3 * k] = x;
        xyz[3 * k + 1] = y;
        xyz[3 * k + 2] = 0.3 * sin(2.0 * x) + 0.2 * cos(3.0 * y) + 0.15 * x * y + 0.1 * x * x;
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

static o3d_pointcloud_t* moved(const o3d_pointcloud_t* pc, const double m[16]) {
    o3d_pointcloud_t* out = NULL;
    assert_int_equal(o3d_pointcloud_clone(&out, pc), O3D_OK);
    assert_int_equal(o3d_pointcloud_transform(out, m), O3D_OK);
    return out;
}

/* (i, i) pairs, every other one replaced by (i, a deterministic wrong index). */
static int32_t* half_outliers(size_t n) {
    int32_t* c = malloc(2 * n * sizeof(int32_t));
    assert_non_null(c);
    uint32_t state = 12345u;
    for (size_t i = 0; i < n; ++i) {
        c[2 * i] = (int32_t)i;
        state = state * 1664525u + 1013904223u;
        c[2 * i + 1] = (i % 2) ? (int32_t)((i + 1 + state % (n - 1)) % n) : (int32_t)i;
    }
    return c;
}

static double max_abs_diff(const double a[16], const double b[16]) {
    double m = 0.0;
    for (int i = 0; i < 16; ++i) m = fmax(m, fabs(a[i] - b[i]));
    return m;
}

typedef struct {
    double transformation[16];
    double fitness, rmse;
    size_t pairs;
    int32_t* corres;
} Result;

static Result take(o3d_registration_result_t* r) {
    Result out;
    memset(&out, 0, sizeof out);
    assert_int_equal(o3d_registration_result_get_transformation(out.transformation, r), O3D_OK);
    assert_int_equal(o3d_registration_result_get_fitness(&out.fitness, r), O3D_OK);
    assert_int_equal(o3d_registration_result_get_inlier_rmse(&out.rmse, r), O3D_OK);
    assert_int_equal(o3d_registration_result_get_correspondence_set(NULL, 0, &out.pairs, r), O3D_OK);
    out.corres = malloc((2 * out.pairs + 1) * sizeof(int32_t));
    assert_non_null(out.corres);
    assert_int_equal(o3d_registration_result_get_correspondence_set(out.corres, out.pairs, &out.pairs, r), O3D_OK);
    o3d_registration_result_destroy(r);
    return out;
}

static int bitwise_equal(const Result* a, const Result* b) {
    return memcmp(a->transformation, b->transformation, sizeof a->transformation) == 0 &&
           memcmp(&a->fitness, &b->fitness, sizeof(double)) == 0 && memcmp(&a->rmse, &b->rmse, sizeof(double)) == 0 &&
           a->pairs == b->pairs && memcmp(a->corres, b->corres, 2 * a->pairs * sizeof(int32_t)) == 0;
}

/* Features that identify each point: its coordinates in the source frame (exact matches). */
static o3d_feature_t* coordinate_feature(const o3d_pointcloud_t* pc) {
    const double* xyz = NULL;
    size_t n = 0;
    assert_int_equal(o3d_pointcloud_array_view(&xyz, &n, pc, O3D_POINTCLOUD_POINTS), O3D_OK);
    o3d_feature_t* f = NULL;
    assert_int_equal(o3d_feature_create_from_data(&f, xyz, 3, n), O3D_OK);
    return f;
}

/* ---------------------------------------------------------------------------------------------- */

static void test_checker_init_defaults(void** state) {
    (void)state;
    o3d_correspondence_checker_t c;
    assert_int_equal(o3d_correspondence_checker_init(&c, sizeof c, O3D_CHECKER_EDGE_LENGTH), O3D_OK);
    assert_int_equal(c.struct_size, sizeof c);
    assert_int_equal(c.kind, O3D_CHECKER_EDGE_LENGTH);
    assert_true(c.threshold == 0.9);
    assert_int_equal(o3d_correspondence_checker_init(&c, sizeof c, O3D_CHECKER_DISTANCE), O3D_OK);
    assert_true(c.threshold == 0.075);
    assert_int_equal(o3d_correspondence_checker_init(&c, sizeof c, O3D_CHECKER_NORMAL), O3D_OK);
    assert_true(fabs(c.threshold - M_PI / 6) < 1e-4);
    O3D_ASSERT_FAILS(o3d_correspondence_checker_init(NULL, sizeof c, O3D_CHECKER_DISTANCE),
                     O3D_ERROR_INVALID_ARGUMENT);
    O3D_ASSERT_FAILS(o3d_correspondence_checker_init(&c, sizeof c, 7), O3D_ERROR_INVALID_ARGUMENT);
    O3D_ASSERT_FAILS(o3d_correspondence_checker_init(&c, 2, O3D_CHECKER_DISTANCE), O3D_ERROR_INVALID_ARGUMENT);
    O3D_ASSERT_FAILS(o3d_correspondence_checker_init(&c, sizeof c + 8, O3D_CHECKER_DISTANCE),
                     O3D_ERROR_INVALID_ARGUMENT);
}

static void test_checker_check(void** state) {
    (void)state;
    const double src[9] = {0, 0, 0, 1, 0, 0, 1, 1, 0};
    const double dst[9] = {0.5, 0, 0, 1.5, 0, 0, 1.5, 1, 0.05};
    const double shift[16] = {1, 0, 0, 0.5, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1};
    const int32_t corres[6] = {0, 0, 1, 1, 2, 2};
    o3d_pointcloud_t* s = NULL;
    o3d_pointcloud_t* t = NULL;
    assert_int_equal(o3d_pointcloud_create(&s), O3D_OK);
    assert_int_equal(o3d_pointcloud_create(&t), O3D_OK);
    assert_int_equal(o3d_pointcloud_set_array(s, O3D_POINTCLOUD_POINTS, src, 3), O3D_OK);
    assert_int_equal(o3d_pointcloud_set_array(t, O3D_POINTCLOUD_POINTS, dst, 3), O3D_OK);
    o3d_correspondence_checker_t distance, edge, normal;
    assert_int_equal(o3d_correspondence_checker_init(&distance, sizeof distance, O3D_CHECKER_DISTANCE), O3D_OK);
    assert_int_equal(o3d_correspondence_checker_init(&edge, sizeof edge, O3D_CHECKER_EDGE_LENGTH), O3D_OK);
    assert_int_equal(o3d_correspondence_checker_init(&normal, sizeof normal, O3D_CHECKER_NORMAL), O3D_OK);

    /* Distance: 0.5 apart unmoved; after the shift only the third pair is 0.05 off (< 0.075). */
    int32_t passed = -1;
    assert_int_equal(o3d_correspondence_checker_check(&passed, &distance, s, t, corres, 3, NULL), O3D_OK);
    assert_int_equal(passed, 0);
    assert_int_equal(o3d_correspondence_checker_check(&passed, &distance, s, t, corres, 3, shift), O3D_OK);
    assert_int_equal(passed, 1);
    distance.threshold = 0.04;
    assert_int_equal(o3d_correspondence_checker_check(&passed, &distance, s, t, corres, 3, shift), O3D_OK);
    assert_int_equal(passed, 0);
    assert_int_equal(o3d_correspondence_checker_check(&passed, &distance, s, t, corres, 2, shift), O3D_OK);
    assert_int_equal(passed, 1);
    /* Edge length ignores the transformation; edges agree to within 0.9. */
    assert_int_equal(o3d_correspondence_checker_check(&passed, &edge, s, t, corres, 3, NULL), O3D_OK);
    assert_int_equal(passed, 1);

    /* Invalid arguments. */
    O3D_ASSERT_FAILS(o3d_correspondence_checker_check(&passed, NULL, s, t, corres, 3, NULL),
                     O3D_ERROR_INVALID_ARGUMENT);
    O3D_ASSERT_FAILS(o3d_correspondence_checker_check(&passed, &edge, NULL, t, corres, 3, NULL),
                     O3D_ERROR_INVALID_ARGUMENT);
    O3D_ASSERT_FAILS(o3d_correspondence_checker_check(&passed, &edge, s, NULL, corres, 3, NULL),
                     O3D_ERROR_INVALID_ARGUMENT);
    O3D_ASSERT_FAILS(o3d_correspondence_checker_check(&passed, &edge, s, t, NULL, 3, NULL),
                     O3D_ERROR_INVALID_ARGUMENT);
    O3D_ASSERT_FAILS(o3d_correspondence_checker_check(NULL, &edge, s, t, corres, 3, NULL),
                     O3D_ERROR_INVALID_ARGUMENT);
    const int32_t out_of_range[6] = {0, 0, 1, 1, 2, 3};
    O3D_ASSERT_FAILS(o3d_correspondence_checker_check(&passed, &edge, s, t, out_of_range, 3, NULL),
                     O3D_ERROR_INVALID_ARGUMENT);
    /* The normal checker needs normals on both clouds. */
    O3D_ASSERT_FAILS(o3d_correspondence_checker_check(&passed, &normal, s, t, corres, 3, NULL),
                     O3D_ERROR_INVALID_ARGUMENT);
    o3d_correspondence_checker_t bad = edge;
    bad.kind = 42;
    O3D_ASSERT_FAILS(o3d_correspondence_checker_check(&passed, &bad, s, t, corres, 3, NULL),
                     O3D_ERROR_INVALID_ARGUMENT);
    const double thresholds[4] = {0.0, -1.0, NAN, 1.5}; /* 1.5: edge similarity must be <= 1 */
    for (int i = 0; i < 4; ++i) {
        bad = edge;
        bad.threshold = thresholds[i];
        O3D_ASSERT_FAILS(o3d_correspondence_checker_check(&passed, &bad, s, t, corres, 3, NULL),
                         O3D_ERROR_INVALID_ARGUMENT);
    }
    bad = distance;
    bad.threshold = 0.0;
    O3D_ASSERT_FAILS(o3d_correspondence_checker_check(&passed, &bad, s, t, corres, 3, NULL),
                     O3D_ERROR_INVALID_ARGUMENT);
    bad = edge;
    bad.struct_size = 3;
    O3D_ASSERT_FAILS(o3d_correspondence_checker_check(&passed, &bad, s, t, corres, 3, NULL),
                     O3D_ERROR_INVALID_ARGUMENT);
    double nan_shift[16];
    memcpy(nan_shift, shift, sizeof nan_shift);
    nan_shift[3] = NAN;
    O3D_ASSERT_FAILS(o3d_correspondence_checker_check(&passed, &distance, s, t, corres, 3, nan_shift),
                     O3D_ERROR_INVALID_ARGUMENT);
    o3d_pointcloud_destroy(s);
    o3d_pointcloud_destroy(t);
}

static void test_options_init(void** state) {
    (void)state;
    o3d_ransac_options_t r;
    assert_int_equal(o3d_ransac_options_init(&r, sizeof r), O3D_OK);
    assert_int_equal(r.struct_size, sizeof r);
    assert_int_equal(r.estimation, O3D_ESTIMATION_POINT_TO_POINT);
    assert_int_equal(r.ransac_n, 3);
    assert_int_equal(r.max_iteration, 100000);
    assert_true(r.confidence == 0.999);
    assert_int_equal(r.mutual_filter, 0);
    assert_int_equal(r.use_seed, 0);
    assert_null(r.progress);
    O3D_ASSERT_FAILS(o3d_ransac_options_init(NULL, sizeof r), O3D_ERROR_INVALID_ARGUMENT);
    O3D_ASSERT_FAILS(o3d_ransac_options_init(&r, 0), O3D_ERROR_INVALID_ARGUMENT);
    O3D_ASSERT_FAILS(o3d_ransac_options_init(&r, sizeof r + 4), O3D_ERROR_INVALID_ARGUMENT);

    o3d_fgr_options_t f;
    assert_int_equal(o3d_fgr_options_init(&f, sizeof f), O3D_OK);
    assert_int_equal(f.struct_size, sizeof f);
    assert_true(f.division_factor == 1.4);
    assert_int_equal(f.use_absolute_scale, 0);
    assert_int_equal(f.decrease_mu, 1);
    assert_true(f.maximum_correspondence_distance == 0.025);
    assert_int_equal(f.iteration_number, 64);
    assert_true(f.tuple_scale == 0.95);
    assert_int_equal(f.maximum_tuple_count, 1000);
    assert_int_equal(f.tuple_test, 1);
    assert_int_equal(f.use_seed, 0);
    O3D_ASSERT_FAILS(o3d_fgr_options_init(NULL, sizeof f), O3D_ERROR_INVALID_ARGUMENT);
    O3D_ASSERT_FAILS(o3d_fgr_options_init(&f, 1), O3D_ERROR_INVALID_ARGUMENT);
    assert_int_equal(o3d_random_seed(0), O3D_OK);
    assert_int_equal(o3d_random_seed(UINT64_MAX), O3D_OK);
}

static void test_ransac_recovers_exact_transform(void** state) {
    (void)state;
    double m[16];
    rigid(70.0, 0.4, -1.0, 0.6, kT, m);
    o3d_pointcloud_t* s = height_field(kPoints);
    o3d_pointcloud_t* t = moved(s, m);
    int32_t* corres = half_outliers(kPoints);
    o3d_correspondence_checker_t checkers[2];
    assert_int_equal(o3d_correspondence_checker_init(&checkers[0], sizeof checkers[0], O3D_CHECKER_EDGE_LENGTH),
                     O3D_OK);
    assert_int_equal(o3d_correspondence_checker_init(&checkers[1], sizeof checkers[1], O3D_CHECKER_NORMAL), O3D_OK);
    o3d_ransac_options_t o;
    assert_int_equal(o3d_ransac_options_init(&o, sizeof o), O3D_OK);
    o.use_seed = 1;
    o.seed = 3;
    o3d_registration_result_t* r = NULL;
    assert_int_equal(o3d_register_ransac_based_on_correspondence(&r, s, t, corres, kPoints, 0.01, checkers, 2, &o),
                     O3D_OK);
    Result got = take(r);
    assert_true(max_abs_diff(got.transformation, m) < 1e-9);
    assert_true(got.fitness == 1.0);
    assert_int_equal(got.pairs, kPoints);
    free(got.corres);

    /* Feature matching on descriptors that identify every point. */
    o3d_feature_t* fs = coordinate_feature(s);
    o3d_feature_t* ft = coordinate_feature(s);
    for (int mutual = 0; mutual < 2; ++mutual) {
        o.mutual_filter = mutual;
        assert_int_equal(o3d_register_ransac_based_on_feature_matching(&r, s, t, fs, ft, 0.01, NULL, 0, &o), O3D_OK);
        got = take(r);
        assert_true(max_abs_diff(got.transformation, m) < 1e-9);
        assert_true(got.fitness == 1.0);
        free(got.corres);
    }
    o3d_feature_destroy(fs);
    o3d_feature_destroy(ft);
    free(corres);
    o3d_pointcloud_destroy(s);
    o3d_pointcloud_destroy(t);
}

static void test_ransac_reproducible(void** state) {
    (void)state;
    double m[16];
    rigid(50.0, 1.0, 0.2, -0.3, kT, m);
    o3d_pointcloud_t* s = height_field(1500);
    o3d_pointcloud_t* t = moved(s, m);
    /* Jitter the target so that the chosen hypothesis shows in the bits. */
    double* xyz = NULL;
    size_t n = 0;
    assert_int_equal(o3d_pointcloud_array_mutable_view(&xyz, &n, t, O3D_POINTCLOUD_POINTS), O3D_OK);
    for (size_t i = 0; i < 3 * n; ++i) xyz[i] += 0.004 * (fmod(i * 0.6180339887, 1.0) - 0.5);
    int32_t* corres = half_outliers(n);
    o3d_ransac_options_t o;
    assert_int_equal(o3d_ransac_options_init(&o, sizeof o), O3D_OK);
    o.use_seed = 1;
    o.seed = 99;
    Result runs[3];
    const int32_t threads[3] = {1, 2, 2};
    for (int k = 0; k < 3; ++k) {
        o.num_threads = threads[k];
        o3d_registration_result_t* r = NULL;
        assert_int_equal(o3d_register_ransac_based_on_correspondence(&r, s, t, corres, n, 0.02, NULL, 0, &o), O3D_OK);
        runs[k] = take(r);
    }
    assert_true(bitwise_equal(&runs[0], &runs[1]));
    assert_true(bitwise_equal(&runs[1], &runs[2]));

    /* Unseeded calls repeat after the same global seed, and consecutive ones differ. */
    o.use_seed = 0;
    Result global[3];
    for (int k = 0; k < 3; ++k) {
        if (k != 1) assert_int_equal(o3d_random_seed(2024), O3D_OK);
        o3d_registration_result_t* r = NULL;
        assert_int_equal(o3d_register_ransac_based_on_correspondence(&r, s, t, corres, n, 0.02, NULL, 0, &o), O3D_OK);
        global[k] = take(r);
    }
    assert_true(bitwise_equal(&global[0], &global[2]));
    assert_false(bitwise_equal(&global[0], &global[1]));
    for (int k = 0; k < 3; ++k) {
        free(runs[k].corres);
        free(global[k].corres);
    }
    free(corres);
    o3d_pointcloud_destroy(s);
    o3d_pointcloud_destroy(t);
}

static int32_t cancel_on_second(double fraction, void* user_data) {
    (void)fraction;
    int* calls = (int*)user_data;
    return ++*calls >= 2;
}

static void test_cancel(void** state) {
    (void)state;
    double m[16];
    rigid(30.0, 0.0, 0.0, 1.0, kT, m);
    o3d_pointcloud_t* s = height_field(kPoints);
    o3d_pointcloud_t* t = moved(s, m);
    int32_t* corres = half_outliers(kPoints);
    int calls = 0;
    o3d_ransac_options_t o;
    assert_int_equal(o3d_ransac_options_init(&o, sizeof o), O3D_OK);
    o.confidence = 1.0; /* never confident: several progress reports */
    o.max_iteration = 2000;
    o.progress = cancel_on_second;
    o.user_data = &calls;
    o3d_registration_result_t* r = (o3d_registration_result_t*)&calls; /* must be reset to NULL */
    O3D_ASSERT_FAILS(o3d_register_ransac_based_on_correspondence(&r, s, t, corres, kPoints, 0.01, NULL, 0, &o),
                     O3D_ERROR_CANCELLED);
    assert_null(r);
    assert_int_equal(calls, 2);

    calls = 0;
    o3d_fgr_options_t f;
    assert_int_equal(o3d_fgr_options_init(&f, sizeof f), O3D_OK);
    f.progress = cancel_on_second;
    f.user_data = &calls;
    O3D_ASSERT_FAILS(o3d_register_fgr_based_on_correspondence(&r, s, t, corres, kPoints, &f), O3D_ERROR_CANCELLED);
    assert_null(r);
    assert_int_equal(calls, 2);
    free(corres);
    o3d_pointcloud_destroy(s);
    o3d_pointcloud_destroy(t);
}

static void test_ransac_invalid_arguments(void** state) {
    (void)state;
    o3d_pointcloud_t* s = height_field(50);
    o3d_pointcloud_t* t = height_field(50);
    o3d_pointcloud_t* empty = NULL;
    assert_int_equal(o3d_pointcloud_create(&empty), O3D_OK);
    o3d_pointcloud_t* bare = NULL; /* points without normals */
    const double* xyz = NULL;
    size_t n = 0;
    assert_int_equal(o3d_pointcloud_array_view(&xyz, &n, s, O3D_POINTCLOUD_POINTS), O3D_OK);
    assert_int_equal(o3d_pointcloud_create(&bare), O3D_OK);
    assert_int_equal(o3d_pointcloud_set_array(bare, O3D_POINTCLOUD_POINTS, xyz, n), O3D_OK);
    int32_t* corres = half_outliers(50);
    o3d_ransac_options_t ok;
    assert_int_equal(o3d_ransac_options_init(&ok, sizeof ok), O3D_OK);
    o3d_correspondence_checker_t normal;
    assert_int_equal(o3d_correspondence_checker_init(&normal, sizeof normal, O3D_CHECKER_NORMAL), O3D_OK);
    o3d_registration_result_t* r = NULL;
    const int E = O3D_ERROR_INVALID_ARGUMENT;

    O3D_ASSERT_FAILS(o3d_register_ransac_based_on_correspondence(NULL, s, t, corres, 50, 0.1, NULL, 0, &ok), E);
    O3D_ASSERT_FAILS(o3d_register_ransac_based_on_correspondence(&r, NULL, t, corres, 50, 0.1, NULL, 0, &ok), E);
    O3D_ASSERT_FAILS(o3d_register_ransac_based_on_correspondence(&r, s, NULL, corres, 50, 0.1, NULL, 0, &ok), E);
    O3D_ASSERT_FAILS(o3d_register_ransac_based_on_correspondence(&r, s, t, NULL, 50, 0.1, NULL, 0, &ok), E);
    O3D_ASSERT_FAILS(o3d_register_ransac_based_on_correspondence(&r, s, t, corres, 50, 0.1, NULL, 2, &ok), E);
    O3D_ASSERT_FAILS(o3d_register_ransac_based_on_correspondence(&r, empty, t, corres, 0, 0.1, NULL, 0, &ok), E);
    O3D_ASSERT_FAILS(o3d_register_ransac_based_on_correspondence(&r, s, empty, corres, 0, 0.1, NULL, 0, &ok), E);
    const double distances[4] = {NAN, 0.0, -1.0, INFINITY};
    for (int i = 0; i < 4; ++i)
        O3D_ASSERT_FAILS(
            o3d_register_ransac_based_on_correspondence(&r, s, t, corres, 50, distances[i], NULL, 0, &ok), E);
    o3d_ransac_options_t o = ok;
    o.ransac_n = 2;
    O3D_ASSERT_FAILS(o3d_register_ransac_based_on_correspondence(&r, s, t, corres, 50, 0.1, NULL, 0, &o), E);
    const double confidences[3] = {-0.1, 1.5, NAN};
    for (int i = 0; i < 3; ++i) {
        o = ok;
        o.confidence = confidences[i];
        O3D_ASSERT_FAILS(o3d_register_ransac_based_on_correspondence(&r, s, t, corres, 50, 0.1, NULL, 0, &o), E);
    }
    o = ok;
    o.max_iteration = -1;
    O3D_ASSERT_FAILS(o3d_register_ransac_based_on_correspondence(&r, s, t, corres, 50, 0.1, NULL, 0, &o), E);
    o = ok;
    o.estimation = 9;
    O3D_ASSERT_FAILS(o3d_register_ransac_based_on_correspondence(&r, s, t, corres, 50, 0.1, NULL, 0, &o), E);
    o = ok;
    o.num_threads = -1;
    O3D_ASSERT_FAILS(o3d_register_ransac_based_on_correspondence(&r, s, t, corres, 50, 0.1, NULL, 0, &o), E);
    o = ok;
    o.struct_size = 2;
    O3D_ASSERT_FAILS(o3d_register_ransac_based_on_correspondence(&r, s, t, corres, 50, 0.1, NULL, 0, &o), E);
    o = ok;
    o.estimation = O3D_ESTIMATION_POINT_TO_PLANE; /* the target needs normals */
    O3D_ASSERT_FAILS(o3d_register_ransac_based_on_correspondence(&r, s, bare, corres, 50, 0.1, NULL, 0, &o), E);
    O3D_ASSERT_FAILS(o3d_register_ransac_based_on_correspondence(&r, bare, t, corres, 50, 0.1, &normal, 1, &ok), E);
    o3d_correspondence_checker_t bad = normal;
    bad.kind = -1;
    O3D_ASSERT_FAILS(o3d_register_ransac_based_on_correspondence(&r, s, t, corres, 50, 0.1, &bad, 1, &ok), E);
    bad = normal;
    bad.threshold = 0.0;
    O3D_ASSERT_FAILS(o3d_register_ransac_based_on_correspondence(&r, s, t, corres, 50, 0.1, &bad, 1, &ok), E);
    o3d_correspondence_checker_t mixed[2] = {normal, normal};
    mixed[1].struct_size = 8; /* entries must share checkers[0].struct_size */
    O3D_ASSERT_FAILS(o3d_register_ransac_based_on_correspondence(&r, s, t, corres, 50, 0.1, mixed, 2, &ok), E);
    corres[2 * 7 + 1] = 50; /* index out of range */
    O3D_ASSERT_FAILS(o3d_register_ransac_based_on_correspondence(&r, s, t, corres, 50, 0.1, NULL, 0, &ok), E);
    corres[2 * 7 + 1] = 7;
    corres[2 * 7] = -1;
    O3D_ASSERT_FAILS(o3d_register_ransac_based_on_correspondence(&r, s, t, corres, 50, 0.1, NULL, 0, &ok), E);
    corres[2 * 7] = 7;

    /* Feature matching. */
    o3d_feature_t* f3 = coordinate_feature(s);
    o3d_feature_t* f4 = NULL;
    o3d_feature_t* f_short = NULL;
    assert_int_equal(o3d_feature_create(&f4, 4, 50), O3D_OK);
    assert_int_equal(o3d_feature_create(&f_short, 3, 49), O3D_OK);
    O3D_ASSERT_FAILS(o3d_register_ransac_based_on_feature_matching(NULL, s, t, f3, f3, 0.1, NULL, 0, &ok), E);
    O3D_ASSERT_FAILS(o3d_register_ransac_based_on_feature_matching(&r, NULL, t, f3, f3, 0.1, NULL, 0, &ok), E);
    O3D_ASSERT_FAILS(o3d_register_ransac_based_on_feature_matching(&r, s, NULL, f3, f3, 0.1, NULL, 0, &ok), E);
    O3D_ASSERT_FAILS(o3d_register_ransac_based_on_feature_matching(&r, s, t, NULL, f3, 0.1, NULL, 0, &ok), E);
    O3D_ASSERT_FAILS(o3d_register_ransac_based_on_feature_matching(&r, s, t, f3, NULL, 0.1, NULL, 0, &ok), E);
    O3D_ASSERT_FAILS(o3d_register_ransac_based_on_feature_matching(&r, s, t, f3, f4, 0.1, NULL, 0, &ok), E);
    O3D_ASSERT_FAILS(o3d_register_ransac_based_on_feature_matching(&r, s, t, f_short, f3, 0.1, NULL, 0, &ok), E);
    O3D_ASSERT_FAILS(o3d_register_ransac_based_on_feature_matching(&r, s, t, f3, f_short, 0.1, NULL, 0, &ok), E);
    O3D_ASSERT_FAILS(o3d_register_ransac_based_on_feature_matching(&r, s, t, f3, f3, NAN, NULL, 0, &ok), E);
    O3D_ASSERT_FAILS(o3d_register_ransac_based_on_feature_matching(&r, empty, t, f3, f3, 0.1, NULL, 0, &ok), E);
    o = ok;
    o.ransac_n = 1;
    O3D_ASSERT_FAILS(o3d_register_ransac_based_on_feature_matching(&r, s, t, f3, f3, 0.1, NULL, 0, &o), E);
    assert_null(r);

    /* Fewer pairs than ransac_n is not an error: Open3D's empty result. */
    assert_int_equal(o3d_register_ransac_based_on_correspondence(&r, s, t, corres, 2, 0.1, NULL, 0, NULL), O3D_OK);
    Result got = take(r);
    assert_true(got.fitness == 0.0);
    assert_int_equal(got.pairs, 0);
    free(got.corres);

    o3d_feature_destroy(f3);
    o3d_feature_destroy(f4);
    o3d_feature_destroy(f_short);
    free(corres);
    o3d_pointcloud_destroy(s);
    o3d_pointcloud_destroy(t);
    o3d_pointcloud_destroy(empty);
    o3d_pointcloud_destroy(bare);
}

static void test_fgr_recovers_exact_transform(void** state) {
    (void)state;
    double m[16];
    rigid(80.0, -0.3, 0.8, 0.5, kT, m);
    o3d_pointcloud_t* s = height_field(1000);
    o3d_pointcloud_t* t = moved(s, m);
    int32_t* exact = malloc(2 * 1000 * sizeof(int32_t));
    assert_non_null(exact);
    for (int i = 0; i < 1000; ++i) exact[2 * i] = exact[2 * i + 1] = i;
    o3d_fgr_options_t o;
    assert_int_equal(o3d_fgr_options_init(&o, sizeof o), O3D_OK);
    o.use_seed = 1;
    o.seed = 5;
    o3d_registration_result_t* r = NULL;
    assert_int_equal(o3d_register_fgr_based_on_correspondence(&r, s, t, exact, 1000, &o), O3D_OK);
    Result got = take(r);
    assert_true(max_abs_diff(got.transformation, m) < 1e-9);
    assert_true(got.fitness == 1.0);
    free(got.corres);

    /* Mutual matches of identifying descriptors, and bitwise reproducibility on 1 and 2 threads. */
    o3d_feature_t* f = coordinate_feature(s);
    Result runs[2];
    for (int k = 0; k < 2; ++k) {
        o.num_threads = k + 1;
        assert_int_equal(o3d_register_fgr_based_on_feature_matching(&r, s, t, f, f, &o), O3D_OK);
        runs[k] = take(r);
    }
    assert_true(max_abs_diff(runs[0].transformation, m) < 1e-9);
    assert_true(bitwise_equal(&runs[0], &runs[1]));
    free(runs[0].corres);
    free(runs[1].corres);
    o3d_feature_destroy(f);
    free(exact);
    o3d_pointcloud_destroy(s);
    o3d_pointcloud_destroy(t);
}

static void test_fgr_invalid_arguments(void** state) {
    (void)state;
    o3d_pointcloud_t* s = height_field(50);
    o3d_pointcloud_t* empty = NULL;
    assert_int_equal(o3d_pointcloud_create(&empty), O3D_OK);
    int32_t* corres = half_outliers(50);
    o3d_fgr_options_t ok;
    assert_int_equal(o3d_fgr_options_init(&ok, sizeof ok), O3D_OK);
    o3d_registration_result_t* r = NULL;
    const int E = O3D_ERROR_INVALID_ARGUMENT;
    O3D_ASSERT_FAILS(o3d_register_fgr_based_on_correspondence(NULL, s, s, corres, 50, &ok), E);
    O3D_ASSERT_FAILS(o3d_register_fgr_based_on_correspondence(&r, NULL, s, corres, 50, &ok), E);
    O3D_ASSERT_FAILS(o3d_register_fgr_based_on_correspondence(&r, s, NULL, corres, 50, &ok), E);
    O3D_ASSERT_FAILS(o3d_register_fgr_based_on_correspondence(&r, s, s, NULL, 50, &ok), E);
    O3D_ASSERT_FAILS(o3d_register_fgr_based_on_correspondence(&r, empty, s, corres, 0, &ok), E);
    O3D_ASSERT_FAILS(o3d_register_fgr_based_on_correspondence(&r, s, empty, corres, 0, &ok), E);
    o3d_fgr_options_t o = ok;
    o.division_factor = 1.0;
    O3D_ASSERT_FAILS(o3d_register_fgr_based_on_correspondence(&r, s, s, corres, 50, &o), E);
    o = ok;
    o.maximum_correspondence_distance = NAN;
    O3D_ASSERT_FAILS(o3d_register_fgr_based_on_correspondence(&r, s, s, corres, 50, &o), E);
    o = ok;
    o.maximum_correspondence_distance = 0.0;
    O3D_ASSERT_FAILS(o3d_register_fgr_based_on_correspondence(&r, s, s, corres, 50, &o), E);
    o = ok;
    o.iteration_number = -1;
    O3D_ASSERT_FAILS(o3d_register_fgr_based_on_correspondence(&r, s, s, corres, 50, &o), E);
    o = ok;
    o.tuple_scale = 0.0;
    O3D_ASSERT_FAILS(o3d_register_fgr_based_on_correspondence(&r, s, s, corres, 50, &o), E);
    o = ok;
    o.tuple_scale = 1.2;
    O3D_ASSERT_FAILS(o3d_register_fgr_based_on_correspondence(&r, s, s, corres, 50, &o), E);
    o = ok;
    o.maximum_tuple_count = -1;
    O3D_ASSERT_FAILS(o3d_register_fgr_based_on_correspondence(&r, s, s, corres, 50, &o), E);
    o = ok;
    o.num_threads = -2;
    O3D_ASSERT_FAILS(o3d_register_fgr_based_on_correspondence(&r, s, s, corres, 50, &o), E);
    o = ok;
    o.struct_size = 1;
    O3D_ASSERT_FAILS(o3d_register_fgr_based_on_correspondence(&r, s, s, corres, 50, &o), E);
    corres[9] = 50;
    O3D_ASSERT_FAILS(o3d_register_fgr_based_on_correspondence(&r, s, s, corres, 50, &ok), E);

    o3d_feature_t* f3 = coordinate_feature(s);
    o3d_feature_t* f4 = NULL;
    o3d_feature_t* f_short = NULL;
    assert_int_equal(o3d_feature_create(&f4, 4, 50), O3D_OK);
    assert_int_equal(o3d_feature_create(&f_short, 3, 49), O3D_OK);
    O3D_ASSERT_FAILS(o3d_register_fgr_based_on_feature_matching(NULL, s, s, f3, f3, &ok), E);
    O3D_ASSERT_FAILS(o3d_register_fgr_based_on_feature_matching(&r, NULL, s, f3, f3, &ok), E);
    O3D_ASSERT_FAILS(o3d_register_fgr_based_on_feature_matching(&r, s, NULL, f3, f3, &ok), E);
    O3D_ASSERT_FAILS(o3d_register_fgr_based_on_feature_matching(&r, s, s, NULL, f3, &ok), E);
    O3D_ASSERT_FAILS(o3d_register_fgr_based_on_feature_matching(&r, s, s, f3, NULL, &ok), E);
    O3D_ASSERT_FAILS(o3d_register_fgr_based_on_feature_matching(&r, s, s, f3, f4, &ok), E);
    O3D_ASSERT_FAILS(o3d_register_fgr_based_on_feature_matching(&r, s, s, f_short, f3, &ok), E);
    O3D_ASSERT_FAILS(o3d_register_fgr_based_on_feature_matching(&r, empty, s, f3, f3, &ok), E);
    o = ok;
    o.tuple_scale = NAN;
    O3D_ASSERT_FAILS(o3d_register_fgr_based_on_feature_matching(&r, s, s, f3, f3, &o), E);
    assert_null(r);
    o3d_feature_destroy(f3);
    o3d_feature_destroy(f4);
    o3d_feature_destroy(f_short);
    free(corres);
    o3d_pointcloud_destroy(s);
    o3d_pointcloud_destroy(empty);
}

/* The test through the C API: cloud_bin_0 moved by 75 degrees about a tilted axis through its
 * centroid, registered onto cloud_bin_1 from the stored (rotation-invariant) FPFH features. The scans
 * are aligned to ~0.4 deg / 17 mm, so the answer is the move's inverse up to that (and RANSAC's own
 * coarseness at a 0.075 m gate, a few degrees; tests/core/ransac_test.cpp has the numbers). */
static double angle_to_inverse_degrees(const double t[16], const double m[16]) {
    /* trace(R_t R_m) = 1 + 2 cos(angle) when R_t = R_m^-1. */
    double trace = 0.0;
    for (int i = 0; i < 3; ++i)
        for (int k = 0; k < 3; ++k) trace += t[4 * i + k] * m[4 * k + i];
    return acos(fmin(1.0, fmax(-1.0, (trace - 1.0) / 2.0))) * 180.0 / M_PI;
}

static void test_shared_data_known_motion(void** state) {
    (void)state;
    O3D_C_TEST_DATA_OR_SKIP(source_path, "open3d/Feature/cloud_bin_0.pcd");
    o3d_pointcloud_t* source = NULL;
    assert_int_equal(o3d_io_read_point_cloud(&source, source_path, "auto", NULL), O3D_OK);
    O3D_C_TEST_DATA_OR_SKIP(target_path, "open3d/Feature/cloud_bin_1.pcd");
    o3d_pointcloud_t* target = NULL;
    assert_int_equal(o3d_io_read_point_cloud(&target, target_path, "auto", NULL), O3D_OK);
    O3D_C_TEST_DATA_OR_SKIP(source_feature_path, "open3d/Feature/cloud_bin_0.fpfh.bin");
    o3d_feature_t* fs = NULL;
    assert_int_equal(o3d_io_read_feature(&fs, source_feature_path), O3D_OK);
    O3D_C_TEST_DATA_OR_SKIP(target_feature_path, "open3d/Feature/cloud_bin_1.fpfh.bin");
    o3d_feature_t* ft = NULL;
    assert_int_equal(o3d_io_read_feature(&ft, target_feature_path), O3D_OK);

    double centre[3], m[16];
    assert_int_equal(o3d_pointcloud_get_center(centre, source), O3D_OK);
    rigid(75.0, 0.3, -1.0, 0.5, kT, m);
    for (int i = 0; i < 3; ++i) /* about the centroid, then (0.4, -0.2, 0.3) */
        m[4 * i + 3] = centre[i] - (m[4 * i] * centre[0] + m[4 * i + 1] * centre[1] + m[4 * i + 2] * centre[2]) +
                       (i == 0 ? 0.4 : i == 1 ? -0.2 : 0.3);
    o3d_pointcloud_t* moved_source = moved(source, m);

    o3d_correspondence_checker_t checkers[2];
    assert_int_equal(o3d_correspondence_checker_init(&checkers[0], sizeof checkers[0], O3D_CHECKER_EDGE_LENGTH),
                     O3D_OK);
    assert_int_equal(o3d_correspondence_checker_init(&checkers[1], sizeof checkers[1], O3D_CHECKER_DISTANCE), O3D_OK);
    o3d_ransac_options_t ro;
    assert_int_equal(o3d_ransac_options_init(&ro, sizeof ro), O3D_OK);
    ro.use_seed = 1;
    ro.seed = 11;
    o3d_registration_result_t* r = NULL;
    assert_int_equal(o3d_register_ransac_based_on_feature_matching(&r, moved_source, target, fs, ft, 0.075, checkers,
                                                                   2, &ro),
                     O3D_OK);
    Result ransac = take(r);
    assert_true(angle_to_inverse_degrees(ransac.transformation, m) < 5.0);
    assert_true(ransac.fitness > 0.74);

    o3d_fgr_options_t fo;
    assert_int_equal(o3d_fgr_options_init(&fo, sizeof fo), O3D_OK);
    fo.use_seed = 1;
    fo.seed = 1;
    assert_int_equal(o3d_register_fgr_based_on_feature_matching(&r, moved_source, target, fs, ft, &fo), O3D_OK);
    Result fgr = take(r);
    assert_true(angle_to_inverse_degrees(fgr.transformation, m) < 2.0);
    assert_true(fgr.fitness > 0.4);

    free(ransac.corres);
    free(fgr.corres);
    o3d_feature_destroy(fs);
    o3d_feature_destroy(ft);
    o3d_pointcloud_destroy(source);
    o3d_pointcloud_destroy(target);
    o3d_pointcloud_destroy(moved_source);
}

int main(void) {
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_checker_init_defaults),
        cmocka_unit_test(test_checker_check),
        cmocka_unit_test(test_options_init),
        cmocka_unit_test(test_ransac_recovers_exact_transform),
        cmocka_unit_test(test_ransac_reproducible),
        cmocka_unit_test(test_cancel),
        cmocka_unit_test(test_ransac_invalid_arguments),
        cmocka_unit_test(test_fgr_recovers_exact_transform),
        cmocka_unit_test(test_fgr_invalid_arguments),
        cmocka_unit_test(test_shared_data_known_motion),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
