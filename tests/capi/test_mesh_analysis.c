/* SPDX-License-Identifier: MIT */
/* C API mesh connectivity queries (trianglemesh.h) and the index lists they return (indexlists.h): analytic
 * answers on small meshes built by hand or by the primitives, copy-out buffers, NULL / bad input. */
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

/* A mesh of `nv` vertices (x = index, y = index^2, z = 0) and the given triangles. */
static o3d_trianglemesh_t* mesh_of(size_t nv, const int32_t* tris, size_t nt) {
    o3d_trianglemesh_t* m = NULL;
    assert_int_equal(o3d_trianglemesh_create(&m), O3D_OK);
    double* v = calloc(3 * nv, sizeof(double));
    for (size_t i = 0; i < nv; ++i) {
        v[3 * i] = (double)i;
        v[3 * i + 1] = (double)(i * i);
    }
    assert_int_equal(o3d_trianglemesh_set_array(m, O3D_MESH_VERTICES, v, nv), O3D_OK);
    assert_int_equal(o3d_trianglemesh_set_index_array(m, O3D_MESH_TRIANGLES, tris, nt), O3D_OK);
    free(v);
    return m;
}

/* The lists as flat offsets and values (malloc'ed; the caller frees). */
static void read_lists(const o3d_index_lists_t* lists, int64_t** offsets, size_t* n_lists, int32_t** values,
                       size_t* n_values) {
    size_t n = 0, total = 0;
    assert_int_equal(o3d_index_lists_counts(&n, &total, lists), O3D_OK);
    *offsets = malloc((n + 1) * sizeof(int64_t));
    *values = malloc((total + 1) * sizeof(int32_t));
    size_t got = 0;
    assert_int_equal(o3d_index_lists_get_offsets(*offsets, n + 1, &got, lists), O3D_OK);
    assert_int_equal(got, n + 1);
    assert_int_equal(o3d_index_lists_get_values(*values, total, &got, lists), O3D_OK);
    assert_int_equal(got, total);
    *n_lists = n;
    *n_values = total;
}

/* A strip of two triangles (0,1,2), (2,1,3) and an unused vertex 4: 0-{1,2}, 1-{0,2,3}, 2-{0,1,3}, 3-{1,2}, 4-{}. */
static void test_adjacency_list_of_a_strip(void** state) {
    (void)state;
    const int32_t tris[] = {0, 1, 2, 2, 1, 3};
    o3d_trianglemesh_t* m = mesh_of(5, tris, 2);
    o3d_index_lists_t* adj = NULL;
    assert_int_equal(o3d_trianglemesh_compute_adjacency_list(&adj, m), O3D_OK);
    int64_t* off = NULL;
    int32_t* val = NULL;
    size_t n = 0, total = 0;
    read_lists(adj, &off, &n, &val, &total);
    assert_int_equal(n, 5);
    assert_int_equal(total, 10); /* 5 edges, each listed at both ends */
    const int64_t expect_off[] = {0, 2, 5, 8, 10, 10};
    const int32_t expect_val[] = {1, 2, 0, 2, 3, 0, 1, 3, 1, 2};
    for (size_t i = 0; i < 6; ++i) assert_int_equal(off[i], expect_off[i]);
    for (size_t i = 0; i < 10; ++i) assert_int_equal(val[i], expect_val[i]);
    /* Copy-out: a short buffer is refused with the count reported; NULL only counts. */
    int32_t small[3];
    size_t got = 0;
    O3D_ASSERT_FAILS(o3d_index_lists_get_values(small, 3, &got, adj), O3D_ERROR_BUFFER_TOO_SMALL);
    assert_int_equal(got, 10);
    assert_int_equal(o3d_index_lists_get_offsets(NULL, 0, &got, adj), O3D_OK);
    assert_int_equal(got, 6);
    free(off);
    free(val);
    o3d_index_lists_destroy(adj);
    o3d_trianglemesh_destroy(m);
}

/* Every vertex of a tetrahedron is joined to the three others; of an icosahedron, to five. */
static void test_adjacency_list_of_platonic_solids(void** state) {
    (void)state;
    o3d_trianglemesh_t* m = NULL;
    assert_int_equal(o3d_trianglemesh_create_icosahedron(&m, 1.0), O3D_OK);
    o3d_index_lists_t* adj = NULL;
    assert_int_equal(o3d_trianglemesh_compute_adjacency_list(&adj, m), O3D_OK);
    int64_t* off = NULL;
    int32_t* val = NULL;
    size_t n = 0, total = 0;
    read_lists(adj, &off, &n, &val, &total);
    assert_int_equal(n, 12);
    assert_int_equal(total, 60); /* 30 edges */
    for (size_t v = 0; v < n; ++v) {
        assert_int_equal(off[v + 1] - off[v], 5);
        for (int64_t k = off[v]; k < off[v + 1]; ++k) {
            assert_true(val[k] != (int32_t)v);
            if (k > off[v]) assert_true(val[k] > val[k - 1]); /* ascending, distinct */
        }
    }
    free(off);
    free(val);
    o3d_index_lists_destroy(adj);
    o3d_trianglemesh_destroy(m);
}

static void test_adjacency_list_bad_input(void** state) {
    (void)state;
    const int32_t tris[] = {0, 1, 7};
    o3d_trianglemesh_t* m = mesh_of(3, tris, 1);
    o3d_index_lists_t* adj = (o3d_index_lists_t*)1;
    O3D_ASSERT_FAILS(o3d_trianglemesh_compute_adjacency_list(&adj, m), INV);
    assert_null(adj);
    O3D_ASSERT_FAILS(o3d_trianglemesh_compute_adjacency_list(NULL, m), INV);
    O3D_ASSERT_FAILS(o3d_trianglemesh_compute_adjacency_list(&adj, NULL), INV);
    size_t n = 0;
    O3D_ASSERT_FAILS(o3d_index_lists_counts(&n, NULL, NULL), INV);
    O3D_ASSERT_FAILS(o3d_index_lists_get_values(NULL, 0, NULL, NULL), INV);
    o3d_index_lists_destroy(NULL);
    o3d_trianglemesh_destroy(m);
}

int main(void) {
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_adjacency_list_of_a_strip),
        cmocka_unit_test(test_adjacency_list_of_platonic_solids),
        cmocka_unit_test(test_adjacency_list_bad_input),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
