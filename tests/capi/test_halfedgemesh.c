/* SPDX-License-Identifier: MIT */
/* C API half-edge meshes (halfedgemesh.h): the half-edge structure of a closed and an open mesh checked against its
 * definition (next cycles of 3, twins reversed, boundary loops), fans, copy-out buffers, non-manifold input and
 * NULL / bad arguments. */
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <setjmp.h>
#include <cmocka.h>

#include <stdlib.h>
#include <string.h>

#include "o3d/o3d.h"
#include "o3d_test_util.h"

#define INV O3D_ERROR_INVALID_ARGUMENT

static int32_t* half_edges_of(const o3d_halfedgemesh_t* h, size_t* n) {
    assert_int_equal(o3d_halfedgemesh_get_half_edges(NULL, 0, n, h), O3D_OK);
    int32_t* rows = malloc((5 * *n + 1) * sizeof(int32_t));
    size_t got = 0;
    assert_int_equal(o3d_halfedgemesh_get_half_edges(rows, *n, &got, h), O3D_OK);
    assert_int_equal(got, *n);
    return rows;
}

/* An icosahedron: 60 half-edges, each next-cycle of length 3 inside its triangle, every twin present and reversed. */
static void test_closed_mesh_half_edges(void** state) {
    (void)state;
    o3d_trianglemesh_t* ico = NULL;
    assert_int_equal(o3d_trianglemesh_create_icosahedron(&ico, 1.0), O3D_OK);
    o3d_halfedgemesh_t* h = NULL;
    assert_int_equal(o3d_halfedgemesh_create_from_triangle_mesh(&h, ico), O3D_OK);
    size_t n = 0;
    int32_t* he = half_edges_of(h, &n);
    assert_int_equal(n, 60);
    for (size_t i = 0; i < n; ++i) {
        const int32_t* e = he + 5 * i;
        const int32_t next = e[0], twin = e[1];
        assert_int_equal(e[4], (int32_t)(i / 3));                 /* its triangle */
        assert_int_equal(he[5 * next + 4], e[4]);                  /* next stays in the triangle */
        assert_int_equal(he[5 * he[5 * next]], (int32_t)i);        /* and comes back after 3 steps */
        assert_int_equal(he[5 * next + 2], e[3]);                 /* next starts where this ends */
        assert_true(twin >= 0);
        assert_int_equal(he[5 * twin + 2], e[3]);                 /* twin reversed */
        assert_int_equal(he[5 * twin + 3], e[2]);
        assert_int_equal(he[5 * twin + 1], (int32_t)i);
    }
    free(he);
    o3d_index_lists_t* loops = NULL;
    size_t nl = 0, total = 0;
    assert_int_equal(o3d_halfedgemesh_get_boundaries(&loops, h), O3D_OK);
    assert_int_equal(o3d_index_lists_num_lists(&nl, loops), O3D_OK);
    assert_int_equal(o3d_index_lists_num_values(&total, loops), O3D_OK);
    assert_int_equal(nl, 0);
    o3d_index_lists_destroy(loops);
    o3d_index_lists_t* fans = NULL;
    assert_int_equal(o3d_halfedgemesh_get_ordered_half_edge_from_vertex(&fans, h), O3D_OK);
    assert_int_equal(o3d_index_lists_num_lists(&nl, fans), O3D_OK);
    assert_int_equal(o3d_index_lists_num_values(&total, fans), O3D_OK);
    assert_int_equal(nl, 12);
    assert_int_equal(total, 60); /* five outgoing half-edges per vertex */
    o3d_index_lists_destroy(fans);
    /* Arrays: 12 unit-length vertex normals and 20 triangles. */
    double normals[3 * 12];
    size_t rows = 0;
    assert_int_equal(o3d_halfedgemesh_get_array(normals, 12, &rows, h, O3D_HALFEDGEMESH_VERTEX_NORMALS), O3D_OK);
    assert_int_equal(rows, 12);
    for (int i = 0; i < 12; ++i) {
        const double len2 = normals[3 * i] * normals[3 * i] + normals[3 * i + 1] * normals[3 * i + 1] +
                            normals[3 * i + 2] * normals[3 * i + 2];
        assert_true(len2 > 1.0 - 1e-12 && len2 < 1.0 + 1e-12);
    }
    assert_int_equal(o3d_halfedgemesh_get_triangles(NULL, 0, &rows, h), O3D_OK);
    assert_int_equal(rows, 20);
    assert_int_equal(o3d_halfedgemesh_get_array(NULL, 0, &rows, h, O3D_HALFEDGEMESH_VERTEX_COLORS), O3D_OK);
    assert_int_equal(rows, 0);
    O3D_ASSERT_FAILS(o3d_halfedgemesh_get_array(normals, 12, &rows, h, 9), INV);
    O3D_ASSERT_FAILS(o3d_halfedgemesh_get_array(normals, 5, &rows, h, O3D_HALFEDGEMESH_VERTICES),
                     O3D_ERROR_BUFFER_TOO_SMALL);
    assert_int_equal(rows, 12);
    o3d_halfedgemesh_destroy(h);
    o3d_trianglemesh_destroy(ico);
}

/* A 3 x 2 grid of squares (12 vertices, 12 triangles): one boundary loop through the 10 outer vertices; interior
 * vertices are on none. */
static void test_open_grid_boundary(void** state) {
    (void)state;
    double v[3 * 12];
    for (int j = 0; j < 3; ++j)
        for (int i = 0; i < 4; ++i) {
            v[3 * (4 * j + i)] = i;
            v[3 * (4 * j + i) + 1] = j;
            v[3 * (4 * j + i) + 2] = 0.0;
        }
    int32_t t[3 * 12];
    int k = 0;
    for (int j = 0; j < 2; ++j)
        for (int i = 0; i < 3; ++i) {
            const int a = 4 * j + i, b = a + 1, c = a + 4, d = a + 5;
            t[k++] = a; t[k++] = b; t[k++] = d;
            t[k++] = a; t[k++] = d; t[k++] = c;
        }
    o3d_trianglemesh_t* m = NULL;
    assert_int_equal(o3d_trianglemesh_create(&m), O3D_OK);
    assert_int_equal(o3d_trianglemesh_set_array(m, O3D_MESH_VERTICES, v, 12), O3D_OK);
    assert_int_equal(o3d_trianglemesh_set_index_array(m, O3D_MESH_TRIANGLES, t, 12), O3D_OK);
    o3d_halfedgemesh_t* h = NULL;
    assert_int_equal(o3d_halfedgemesh_create_from_triangle_mesh(&h, m), O3D_OK);
    o3d_index_lists_t* loops = NULL;
    assert_int_equal(o3d_halfedgemesh_get_boundaries(&loops, h), O3D_OK);
    size_t nl = 0, total = 0;
    assert_int_equal(o3d_index_lists_num_lists(&nl, loops), O3D_OK);
    assert_int_equal(o3d_index_lists_num_values(&total, loops), O3D_OK);
    assert_int_equal(nl, 1);
    assert_int_equal(total, 10);
    int32_t loop[10];
    size_t got = 0;
    assert_int_equal(o3d_index_lists_get_values(loop, 10, &got, loops), O3D_OK);
    /* Counter-clockwise (the triangles' winding) from vertex 0: 0 1 2 3 7 11 10 9 8 4. */
    const int32_t want[10] = {0, 1, 2, 3, 7, 11, 10, 9, 8, 4};
    assert_memory_equal(loop, want, sizeof want);
    o3d_index_lists_destroy(loops);
    int32_t from5[16];
    assert_int_equal(o3d_halfedgemesh_boundary_vertices_from_vertex(from5, 16, &got, h, 5), O3D_OK);
    assert_int_equal(got, 0); /* interior */
    assert_int_equal(o3d_halfedgemesh_boundary_vertices_from_vertex(from5, 16, &got, h, 7), O3D_OK);
    assert_int_equal(got, 10);
    assert_int_equal(from5[0], 7);
    assert_int_equal(from5[1], 11);
    int32_t edges[16];
    assert_int_equal(o3d_halfedgemesh_boundary_half_edges_from_vertex(edges, 16, &got, h, 7), O3D_OK);
    assert_int_equal(got, 10);
    size_t n = 0;
    int32_t* he = half_edges_of(h, &n);
    for (size_t i = 0; i < got; ++i) {
        assert_int_equal(he[5 * edges[i] + 1], -1);          /* a boundary half-edge */
        assert_int_equal(he[5 * edges[i] + 2], from5[i]);    /* starting at the listed vertex */
    }
    free(he);
    O3D_ASSERT_FAILS(o3d_halfedgemesh_boundary_vertices_from_vertex(from5, 16, &got, h, 12), INV);
    O3D_ASSERT_FAILS(o3d_halfedgemesh_boundary_vertices_from_vertex(from5, 16, &got, h, -1), INV);
    o3d_halfedgemesh_destroy(h);
    o3d_trianglemesh_destroy(m);
}

/* An edge of three triangles is refused with a message; NULLs are refused; an empty mesh gives an empty one. */
static void test_non_manifold_and_bad_input(void** state) {
    (void)state;
    const double v[15] = {0, 0, 0, 1, 0, 0, 0, 1, 0, 0, -1, 0, 0, 0, 1};
    const int32_t t[9] = {0, 1, 2, 1, 0, 3, 0, 1, 4};
    o3d_trianglemesh_t* m = NULL;
    assert_int_equal(o3d_trianglemesh_create(&m), O3D_OK);
    assert_int_equal(o3d_trianglemesh_set_array(m, O3D_MESH_VERTICES, v, 5), O3D_OK);
    assert_int_equal(o3d_trianglemesh_set_index_array(m, O3D_MESH_TRIANGLES, t, 3), O3D_OK);
    o3d_halfedgemesh_t* h = (o3d_halfedgemesh_t*)1;
    O3D_ASSERT_FAILS(o3d_halfedgemesh_create_from_triangle_mesh(&h, m), INV);
    assert_null(h);
    o3d_trianglemesh_destroy(m);
    O3D_ASSERT_FAILS(o3d_halfedgemesh_create_from_triangle_mesh(&h, NULL), INV);
    O3D_ASSERT_FAILS(o3d_halfedgemesh_create_from_triangle_mesh(NULL, NULL), INV);
    size_t n = 0;
    O3D_ASSERT_FAILS(o3d_halfedgemesh_get_half_edges(NULL, 0, &n, NULL), INV);
    assert_int_equal(o3d_trianglemesh_create(&m), O3D_OK);
    assert_int_equal(o3d_halfedgemesh_create_from_triangle_mesh(&h, m), O3D_OK);
    assert_int_equal(o3d_halfedgemesh_get_half_edges(NULL, 0, &n, h), O3D_OK);
    assert_int_equal(n, 0);
    o3d_halfedgemesh_destroy(h);
    o3d_halfedgemesh_destroy(NULL);
    o3d_trianglemesh_destroy(m);
}

int main(void) {
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_closed_mesh_half_edges),
        cmocka_unit_test(test_open_grid_boundary),
        cmocka_unit_test(test_non_manifold_and_bad_input),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
