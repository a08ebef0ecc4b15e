/* SPDX-License-Identifier: MIT */
/* C API kdtree.h: batch search vs brute force, thread independence, lifetimes, bad arguments. */
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <setjmp.h>
#include <cmocka.h>

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "o3d/kdtree.h"
#include "o3d/pointcloud.h"
#include "o3d_test_util.h"

#define INV O3D_ERROR_INVALID_ARGUMENT
#define N 3000
#define Q 200

static double g_points[3 * N];
static double g_queries[3 * Q];

/* Deterministic pseudo-random coordinates in [0,1) (LCG; no libc rand state). */
static double next_unit(uint64_t* s) {
    *s = *s * 6364136223846793005ULL + 1442695040888963407ULL;
    return (double)(*s >> 11) / 9007199254740992.0;
}

static int setup(void** state) {
    (void)state;
    uint64_t s = 12345;
    for (int i = 0; i < 3 * N; ++i) g_points[i] = next_unit(&s);
    for (int i = 0; i < 3 * Q; ++i) g_queries[i] = next_unit(&s);
    return 0;
}

static double dist2(const double* a, const double* b) {
    const double dx = a[0] - b[0], dy = a[1] - b[1], dz = a[2] - b[2];
    return dx * dx + dy * dy + dz * dz;
}

/* Count of points strictly within r of q, and the k-th smallest squared distance (k >= 1). */
static size_t brute_count(const double* q, double r) {
    size_t c = 0;
    for (int i = 0; i < N; ++i) c += dist2(q, g_points + 3 * i) < r * r;
    return c;
}

static void check_result(o3d_search_result_t* res, const o3d_search_param_t* p) {
    size_t nq, total;
    assert_int_equal(o3d_search_result_counts(&nq, &total, res), O3D_OK);
    assert_int_equal(nq, Q);
    const int64_t* off;
    const int32_t* idx;
    const double* d2;
    assert_int_equal(o3d_search_result_view(&off, &idx, &d2, res), O3D_OK);
    assert_int_equal(off[0], 0);
    assert_int_equal(off[Q], (int64_t)total);
    for (int q = 0; q < Q; ++q) {
        const double* query = g_queries + 3 * q;
        const size_t count = (size_t)(off[q + 1] - off[q]);
        size_t expect = p->kind == O3D_SEARCH_KNN ? (size_t)p->knn : brute_count(query, p->radius);
        if (p->kind == O3D_SEARCH_HYBRID && expect > (size_t)p->knn) expect = (size_t)p->knn;
        assert_int_equal(count, expect);
        for (int64_t j = off[q]; j < off[q + 1]; ++j) {
            assert_true(fabs(d2[j] - dist2(query, g_points + 3 * idx[j])) < 1e-15);
            if (j > off[q]) assert_true(d2[j - 1] <= d2[j]);
        }
        if (count > 0 && p->kind != O3D_SEARCH_RADIUS) {
            /* Nothing outside the result is closer than its farthest member. */
            size_t closer = 0;
            for (int i = 0; i < N; ++i) closer += dist2(query, g_points + 3 * i) < d2[off[q + 1] - 1];
            assert_true(closer < count);
        }
    }
}

static void test_search_matches_brute_force(void** state) {
    (void)state;
    o3d_kdtree_t* tree = NULL;
    assert_int_equal(o3d_kdtree_create_from_points(&tree, g_points, N), O3D_OK);
    size_t n;
    assert_int_equal(o3d_kdtree_size(&n, tree), O3D_OK);
    assert_int_equal(n, N);
    o3d_search_param_t p;
    assert_int_equal(o3d_search_param_init(&p, sizeof p), O3D_OK);
    const int32_t kinds[3] = {O3D_SEARCH_KNN, O3D_SEARCH_RADIUS, O3D_SEARCH_HYBRID};
    for (int k = 0; k < 3; ++k) {
        p.kind = kinds[k];
        p.knn = 12;
        p.radius = 0.1;
        o3d_search_result_t* res = NULL;
        assert_int_equal(o3d_kdtree_search(&res, tree, g_queries, Q, &p, 2), O3D_OK);
        check_result(res, &p);
        o3d_search_result_destroy(res);
    }
    o3d_kdtree_destroy(tree);
}

static void test_threads_f32_and_copies(void** state) {
    (void)state;
    o3d_pointcloud_t* pc = NULL;
    assert_int_equal(o3d_pointcloud_create(&pc), O3D_OK);
    assert_int_equal(o3d_pointcloud_set_array(pc, O3D_POINTCLOUD_POINTS, g_points, N), O3D_OK);
    o3d_kdtree_t* tree = NULL;
    assert_int_equal(o3d_kdtree_create_from_pointcloud(&tree, pc), O3D_OK);
    o3d_pointcloud_destroy(pc); /* the tree owns its copy */
    o3d_search_param_t p;
    assert_int_equal(o3d_search_param_init(&p, sizeof p), O3D_OK);
    p.kind = O3D_SEARCH_HYBRID;
    p.radius = 0.15;
    p.knn = 20;
    o3d_search_result_t *a = NULL, *b = NULL, *f = NULL;
    assert_int_equal(o3d_kdtree_search(&a, tree, g_queries, Q, &p, 1), O3D_OK);
    assert_int_equal(o3d_kdtree_search(&b, tree, g_queries, Q, &p, 2), O3D_OK);
    size_t qa, ta, qb, tb;
    assert_int_equal(o3d_search_result_counts(&qa, &ta, a), O3D_OK);
    assert_int_equal(o3d_search_result_counts(&qb, &tb, b), O3D_OK);
    assert_int_equal(ta, tb);
    int64_t* offa = malloc((Q + 1) * sizeof *offa);
    int64_t* offb = malloc((Q + 1) * sizeof *offb);
    int32_t* ia = malloc(ta * sizeof *ia);
    int32_t* ib = malloc(tb * sizeof *ib);
    double* da = malloc(ta * sizeof *da);
    double* db = malloc(tb * sizeof *db);
    size_t got = 0;
    assert_int_equal(o3d_search_result_get_offsets(offa, Q + 1, &got, a), O3D_OK);
    assert_int_equal(got, Q + 1);
    assert_int_equal(o3d_search_result_get_offsets(offb, Q + 1, &got, b), O3D_OK);
    assert_int_equal(o3d_search_result_get_indices(ia, ta, &got, a), O3D_OK);
    assert_int_equal(got, ta);
    assert_int_equal(o3d_search_result_get_indices(ib, tb, &got, b), O3D_OK);
    assert_int_equal(o3d_search_result_get_distances2(da, ta, &got, a), O3D_OK);
    assert_int_equal(o3d_search_result_get_distances2(db, tb, &got, b), O3D_OK);
    assert_int_equal(got, tb);
    /* NULL out only reports the count */
    got = 0;
    assert_int_equal(o3d_search_result_get_indices(NULL, 0, &got, a), O3D_OK);
    assert_int_equal(got, ta);
    assert_memory_equal(offa, offb, (Q + 1) * sizeof *offa);
    assert_memory_equal(ia, ib, ta * sizeof *ia);
    assert_memory_equal(da, db, ta * sizeof *da); /* bitwise */
    O3D_ASSERT_FAILS(o3d_search_result_get_offsets(offa, Q, &got, a), O3D_ERROR_BUFFER_TOO_SMALL);
    assert_int_equal(got, Q + 1); /* the needed count is reported even when it does not fit */
    O3D_ASSERT_FAILS(o3d_search_result_get_indices(ia, ta - 1, &got, a), O3D_ERROR_BUFFER_TOO_SMALL);
    O3D_ASSERT_FAILS(o3d_search_result_get_distances2(da, ta - 1, &got, a), O3D_ERROR_BUFFER_TOO_SMALL);

    /* float32 queries: the same as double queries holding the same (float-rounded) values. */
    float fq[3 * Q];
    double dq[3 * Q];
    for (int i = 0; i < 3 * Q; ++i) {
        fq[i] = (float)g_queries[i];
        dq[i] = (double)fq[i];
    }
    o3d_search_result_t* d = NULL;
    assert_int_equal(o3d_kdtree_search_f32(&f, tree, fq, Q, &p, 0), O3D_OK);
    assert_int_equal(o3d_kdtree_search(&d, tree, dq, Q, &p, 0), O3D_OK);
    const int64_t *of, *od;
    const int32_t *xf, *xd;
    const double *df, *dd;
    assert_int_equal(o3d_search_result_view(&of, &xf, &df, f), O3D_OK);
    assert_int_equal(o3d_search_result_view(&od, &xd, &dd, d), O3D_OK);
    assert_memory_equal(of, od, (Q + 1) * sizeof *of);
    assert_memory_equal(xf, xd, (size_t)of[Q] * sizeof *xf);
    free(offa), free(offb), free(ia), free(ib), free(da), free(db);
    o3d_search_result_destroy(a);
    o3d_search_result_destroy(b);
    o3d_search_result_destroy(f);
    o3d_search_result_destroy(d);
    o3d_kdtree_destroy(tree);
}

static void test_knn_larger_than_tree_and_empty(void** state) {
    (void)state;
    o3d_kdtree_t* tree = NULL;
    assert_int_equal(o3d_kdtree_create_from_points(&tree, g_points, 5), O3D_OK);
    o3d_search_param_t p;
    assert_int_equal(o3d_search_param_init(&p, sizeof p), O3D_OK); /* KNN 30 > 5 points */
    o3d_search_result_t* r = NULL;
    assert_int_equal(o3d_kdtree_search(&r, tree, g_queries, 2, &p, 0), O3D_OK);
    size_t nq, total;
    assert_int_equal(o3d_search_result_counts(&nq, &total, r), O3D_OK);
    assert_int_equal(total, 10);
    o3d_search_result_destroy(r);
    o3d_kdtree_destroy(tree);

    assert_int_equal(o3d_kdtree_create_from_points(&tree, NULL, 0), O3D_OK);
    assert_int_equal(o3d_kdtree_search(&r, tree, g_queries, 2, NULL, 0), O3D_OK);
    assert_int_equal(o3d_search_result_counts(&nq, &total, r), O3D_OK);
    assert_int_equal(nq, 2);
    assert_int_equal(total, 0);
    o3d_search_result_destroy(r);
    o3d_kdtree_destroy(tree);
}

static void test_bad_arguments(void** state) {
    (void)state;
    o3d_kdtree_t* tree = NULL;
    o3d_search_result_t* r = NULL;
    const double bad[6] = {0, 0, 0, NAN, 0, 0};
    O3D_ASSERT_FAILS(o3d_kdtree_create_from_points(&tree, bad, 2), INV);
    assert_null(tree);
    O3D_ASSERT_FAILS(o3d_kdtree_create_from_points(&tree, NULL, 2), INV);
    O3D_ASSERT_FAILS(o3d_kdtree_create_from_points(NULL, g_points, 2), INV);
    O3D_ASSERT_FAILS(o3d_kdtree_create_from_pointcloud(&tree, NULL), INV);
    O3D_ASSERT_FAILS(o3d_kdtree_create_from_pointcloud(NULL, NULL), INV);
    O3D_ASSERT_FAILS(o3d_kdtree_size(NULL, NULL), INV);
    assert_int_equal(o3d_kdtree_create_from_points(&tree, g_points, 10), O3D_OK);
    size_t n;
    O3D_ASSERT_FAILS(o3d_kdtree_size(NULL, tree), INV);
    O3D_ASSERT_FAILS(o3d_kdtree_size(&n, NULL), INV);
    o3d_search_param_t p;
    assert_int_equal(o3d_search_param_init(&p, sizeof p), O3D_OK);
    O3D_ASSERT_FAILS(o3d_kdtree_search(&r, NULL, g_queries, 1, &p, 0), INV);
    O3D_ASSERT_FAILS(o3d_kdtree_search(&r, tree, NULL, 1, &p, 0), INV);
    O3D_ASSERT_FAILS(o3d_kdtree_search(NULL, tree, g_queries, 1, &p, 0), INV);
    O3D_ASSERT_FAILS(o3d_kdtree_search(&r, tree, g_queries, 1, &p, -2), INV);
    O3D_ASSERT_FAILS(o3d_kdtree_search(&r, tree, bad, 2, &p, 0), INV); /* NaN query */
    O3D_ASSERT_FAILS(o3d_kdtree_search_f32(&r, tree, NULL, 1, &p, 0), INV);
    O3D_ASSERT_FAILS(o3d_kdtree_search_f32(&r, NULL, NULL, 0, &p, 0), INV);
    p.kind = O3D_SEARCH_RADIUS;
    p.radius = -1;
    O3D_ASSERT_FAILS(o3d_kdtree_search(&r, tree, g_queries, 1, &p, 0), INV);
    p.radius = INFINITY;
    O3D_ASSERT_FAILS(o3d_kdtree_search(&r, tree, g_queries, 1, &p, 0), INV);
    p.kind = O3D_SEARCH_HYBRID;
    p.radius = 0.1;
    p.knn = -3;
    O3D_ASSERT_FAILS(o3d_kdtree_search(&r, tree, g_queries, 1, &p, 0), INV);
    p.kind = 42;
    O3D_ASSERT_FAILS(o3d_kdtree_search(&r, tree, g_queries, 1, &p, 0), INV);
    assert_null(r);

    int64_t off[2];
    int32_t idx[1];
    double d2[1];
    const int64_t* vo;
    const int32_t* vi;
    const double* vd;
    size_t nq, total;
    O3D_ASSERT_FAILS(o3d_search_result_counts(&nq, &total, NULL), INV);
    O3D_ASSERT_FAILS(o3d_search_result_view(&vo, &vi, &vd, NULL), INV);
    size_t got = 0;
    O3D_ASSERT_FAILS(o3d_search_result_get_offsets(off, 2, &got, NULL), INV);
    O3D_ASSERT_FAILS(o3d_search_result_get_indices(idx, 1, &got, NULL), INV);
    O3D_ASSERT_FAILS(o3d_search_result_get_distances2(d2, 1, &got, NULL), INV);
    assert_int_equal(o3d_search_param_init(&p, sizeof p), O3D_OK);
    p.knn = 1;
    assert_int_equal(o3d_kdtree_search(&r, tree, g_queries, 1, &p, 0), O3D_OK);
    O3D_ASSERT_FAILS(o3d_search_result_counts(NULL, &total, r), INV);
    O3D_ASSERT_FAILS(o3d_search_result_counts(&nq, NULL, r), INV);
    O3D_ASSERT_FAILS(o3d_search_result_view(NULL, &vi, &vd, r), INV);
    O3D_ASSERT_FAILS(o3d_search_result_view(&vo, NULL, &vd, r), INV);
    O3D_ASSERT_FAILS(o3d_search_result_view(&vo, &vi, NULL, r), INV);
    O3D_ASSERT_FAILS(o3d_search_result_get_offsets(off, 2, NULL, r), INV);
    O3D_ASSERT_FAILS(o3d_search_result_get_indices(idx, 1, NULL, r), INV);
    O3D_ASSERT_FAILS(o3d_search_result_get_distances2(d2, 1, NULL, r), INV);
    o3d_search_result_destroy(r);
    o3d_search_result_destroy(NULL);
    o3d_kdtree_destroy(tree);
    o3d_kdtree_destroy(NULL);
}

int main(void) {
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_search_matches_brute_force),
        cmocka_unit_test(test_threads_f32_and_copies),
        cmocka_unit_test(test_knn_larger_than_tree_and_empty),
        cmocka_unit_test(test_bad_arguments),
    };
    return cmocka_run_group_tests_name("o3d_kdtree", tests, setup, NULL);
}
