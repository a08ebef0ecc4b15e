/* SPDX-License-Identifier: MIT */
/* C API mesh analysis (trianglemesh.h: adjacency, non-manifold elements, intersections, orientation, sharpening,
 * ARAP, ellipsoids and meshes of bounding volumes) and the index lists it returns (indexlists.h): analytic answers
 * on small meshes built by hand or by the primitives, copy-out buffers, NULL / bad input. */
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
#ifndef M_PI
#define M_PI 3.14159265358979323846
#endif

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
    assert_int_equal(o3d_index_lists_num_lists(&n, lists), O3D_OK);
    assert_int_equal(o3d_index_lists_num_values(&total, lists), O3D_OK);
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
    O3D_ASSERT_FAILS(o3d_index_lists_num_lists(&n, NULL), INV);
    O3D_ASSERT_FAILS(o3d_index_lists_num_values(NULL, NULL), INV);
    O3D_ASSERT_FAILS(o3d_index_lists_get_values(NULL, 0, NULL, NULL), INV);
    o3d_index_lists_destroy(NULL);
    o3d_trianglemesh_destroy(m);
}


/* Three triangles on edge (0,1) make it non-manifold; with boundary edges disallowed every one-triangle edge is
 * listed too. */
static void test_non_manifold_edges_of_a_fin(void** state) {
    (void)state;
    const int32_t tris[] = {0, 1, 2, 1, 0, 3, 0, 1, 4};
    o3d_trianglemesh_t* m = mesh_of(5, tris, 3);
    int32_t edges[2 * 16];
    size_t n = 0;
    assert_int_equal(o3d_trianglemesh_get_non_manifold_edges(edges, 16, &n, m, 1), O3D_OK);
    assert_int_equal(n, 1);
    assert_int_equal(edges[0], 0);
    assert_int_equal(edges[1], 1);
    assert_int_equal(o3d_trianglemesh_get_non_manifold_edges(NULL, 0, &n, m, 0), O3D_OK);
    assert_int_equal(n, 7); /* (0,1) plus the six one-triangle edges */
    O3D_ASSERT_FAILS(o3d_trianglemesh_get_non_manifold_edges(edges, 3, &n, m, 0), O3D_ERROR_BUFFER_TOO_SMALL);
    assert_int_equal(n, 7);
    /* A closed icosahedron has none either way. */
    o3d_trianglemesh_t* ico = NULL;
    assert_int_equal(o3d_trianglemesh_create_icosahedron(&ico, 1.0), O3D_OK);
    assert_int_equal(o3d_trianglemesh_get_non_manifold_edges(edges, 16, &n, ico, 0), O3D_OK);
    assert_int_equal(n, 0);
    o3d_trianglemesh_destroy(ico);
    o3d_trianglemesh_destroy(m);
}

/* Two triangles sharing only vertex 0 (a bow tie): vertex 0 is the one non-manifold vertex. */
static void test_non_manifold_vertex_of_a_bow_tie(void** state) {
    (void)state;
    const int32_t tris[] = {0, 1, 2, 0, 3, 4};
    o3d_trianglemesh_t* m = mesh_of(5, tris, 2);
    int32_t v[8];
    size_t n = 0;
    assert_int_equal(o3d_trianglemesh_get_non_manifold_vertices(v, 8, &n, m), O3D_OK);
    assert_int_equal(n, 1);
    assert_int_equal(v[0], 0);
    o3d_trianglemesh_destroy(m);
}

static o3d_trianglemesh_t* translated_sphere(double radius, double x) {
    o3d_trianglemesh_t* m = NULL;
    assert_int_equal(o3d_trianglemesh_create_sphere(&m, radius, 10), O3D_OK);
    const double t[3] = {x, 0.0, 0.0};
    assert_int_equal(o3d_trianglemesh_translate(m, t, 1), O3D_OK);
    return m;
}

/* Two unit spheres 1.5 apart intersect; 2.5 apart they do not; their union self-intersects only across the two. */
static void test_intersections_of_two_spheres(void** state) {
    (void)state;
    o3d_trianglemesh_t* a = translated_sphere(1.0, 0.0);
    o3d_trianglemesh_t* b = translated_sphere(1.0, 1.5);
    o3d_trianglemesh_t* c = translated_sphere(1.0, 2.5);
    int32_t hit = -1;
    assert_int_equal(o3d_trianglemesh_is_intersecting(&hit, a, b), O3D_OK);
    assert_int_equal(hit, 1);
    assert_int_equal(o3d_trianglemesh_is_intersecting(&hit, a, c), O3D_OK);
    assert_int_equal(hit, 0);
    size_t nt = 0, n = 0;
    assert_int_equal(o3d_trianglemesh_num_triangles(&nt, a), O3D_OK);
    assert_int_equal(o3d_trianglemesh_get_self_intersecting_triangles(NULL, 0, &n, a), O3D_OK);
    assert_int_equal(n, 0);
    assert_int_equal(o3d_trianglemesh_append(a, b), O3D_OK);
    assert_int_equal(o3d_trianglemesh_get_self_intersecting_triangles(NULL, 0, &n, a), O3D_OK);
    assert_true(n > 0);
    int32_t* pairs = malloc(2 * n * sizeof(int32_t));
    size_t got = 0;
    assert_int_equal(o3d_trianglemesh_get_self_intersecting_triangles(pairs, n, &got, a), O3D_OK);
    assert_int_equal(got, n);
    for (size_t i = 0; i < n; ++i) {
        assert_true(pairs[2 * i] < (int32_t)nt);   /* one triangle from the first sphere */
        assert_true(pairs[2 * i + 1] >= (int32_t)nt); /* the other from the second */
    }
    free(pairs);
    O3D_ASSERT_FAILS(o3d_trianglemesh_is_intersecting(&hit, a, NULL), INV);
    o3d_trianglemesh_destroy(a);
    o3d_trianglemesh_destroy(b);
    o3d_trianglemesh_destroy(c);
}

/* A box with some triangles turned over is orientable again, and its volume is back to w * h * d. */
static void test_orient_triangles_repairs_a_box(void** state) {
    (void)state;
    o3d_trianglemesh_t* box = NULL;
    assert_int_equal(o3d_trianglemesh_create_box(&box, 1.0, 2.0, 3.0), O3D_OK);
    int32_t* tris = NULL;
    size_t rows = 0;
    assert_int_equal(o3d_trianglemesh_index_array_mutable_view(&tris, &rows, box, O3D_MESH_TRIANGLES), O3D_OK);
    assert_int_equal(rows, 12);
    for (size_t t = 0; t < rows; t += 3) { /* turn over triangles 0, 3, 6, 9 */
        const int32_t tmp = tris[3 * t + 1];
        tris[3 * t + 1] = tris[3 * t + 2];
        tris[3 * t + 2] = tmp;
    }
    int32_t ok = -1;
    assert_int_equal(o3d_trianglemesh_orient_triangles(&ok, box), O3D_OK);
    assert_int_equal(ok, 1);
    double volume = 0.0;
    assert_int_equal(o3d_trianglemesh_get_volume(&volume, box), O3D_OK);
    assert_true(fabs(volume - 6.0) < 1e-12);
    assert_int_equal(o3d_trianglemesh_is_orientable(&ok, box), O3D_OK);
    assert_int_equal(ok, 1);
    /* An edge of three triangles cannot be oriented: 0 and the mesh unchanged. */
    const int32_t fin[] = {0, 1, 2, 1, 0, 3, 0, 1, 4};
    o3d_trianglemesh_t* m = mesh_of(5, fin, 3);
    assert_int_equal(o3d_trianglemesh_orient_triangles(&ok, m), O3D_OK);
    assert_int_equal(ok, 0);
    int32_t after[9];
    assert_int_equal(o3d_trianglemesh_get_index_array(after, 3, &rows, m, O3D_MESH_TRIANGLES), O3D_OK);
    assert_memory_equal(after, fin, sizeof fin);
    O3D_ASSERT_FAILS(o3d_trianglemesh_orient_triangles(NULL, m), INV);
    o3d_trianglemesh_destroy(m);
    o3d_trianglemesh_destroy(box);
}

/* Sharpening by hand on a strip: v' = v + strength * sum(v - n) over the neighbours. */
static void test_filter_sharpen_by_hand(void** state) {
    (void)state;
    const int32_t tris[] = {0, 1, 2, 2, 1, 3};
    o3d_trianglemesh_t* m = mesh_of(4, tris, 2); /* vertices (i, i^2, 0) */
    o3d_trianglemesh_t* out = NULL;
    assert_int_equal(o3d_trianglemesh_filter_sharpen(&out, m, 1, 0.5, O3D_FILTER_SCOPE_ALL), O3D_OK);
    const double* v = NULL;
    size_t n = 0;
    assert_int_equal(o3d_trianglemesh_array_view(&v, &n, out, O3D_MESH_VERTICES), O3D_OK);
    assert_int_equal(n, 4);
    const double p[4][2] = {{0, 0}, {1, 1}, {2, 4}, {3, 9}};
    const int nb[4][3] = {{1, 2, -1}, {0, 2, 3}, {0, 1, 3}, {1, 2, -1}};
    for (int i = 0; i < 4; ++i) {
        for (int k = 0; k < 2; ++k) {
            double want = p[i][k];
            for (int j = 0; j < 3 && nb[i][j] >= 0; ++j) want += 0.5 * (p[i][k] - p[nb[i][j]][k]);
            assert_true(fabs(v[3 * i + k] - want) < 1e-12);
        }
    }
    o3d_trianglemesh_destroy(out);
    O3D_ASSERT_FAILS(o3d_trianglemesh_filter_sharpen(&out, m, 1, 0.5, 9), INV);
    assert_null(out);
    O3D_ASSERT_FAILS(o3d_trianglemesh_filter_sharpen(&out, m, -1, 0.5, O3D_FILTER_SCOPE_ALL), INV);
    O3D_ASSERT_FAILS(o3d_trianglemesh_filter_sharpen(&out, m, 1, NAN, O3D_FILTER_SCOPE_ALL), INV);
    o3d_trianglemesh_destroy(m);
}

/* Every vertex of create_ellipsoid lies on x^2/a^2 + y^2/b^2 + z^2/c^2 = 1; 2 + (r - 1) * 2r vertices. */
static void test_create_ellipsoid_on_the_surface(void** state) {
    (void)state;
    o3d_trianglemesh_t* e = NULL;
    assert_int_equal(o3d_trianglemesh_create_ellipsoid(&e, 1.0, 2.0, 0.5, 10, 0), O3D_OK);
    const double* v = NULL;
    size_t n = 0, nt = 0;
    assert_int_equal(o3d_trianglemesh_array_view(&v, &n, e, O3D_MESH_VERTICES), O3D_OK);
    assert_int_equal(n, 2 + 9 * 20);
    for (size_t i = 0; i < n; ++i) {
        const double q = v[3 * i] * v[3 * i] + v[3 * i + 1] * v[3 * i + 1] / 4.0 + v[3 * i + 2] * v[3 * i + 2] * 4.0;
        assert_true(fabs(q - 1.0) < 1e-12);
    }
    assert_int_equal(o3d_trianglemesh_num_triangles(&nt, e), O3D_OK);
    assert_int_equal(nt, 2 * 20 * 9);
    int32_t watertight = 0;
    assert_int_equal(o3d_trianglemesh_is_watertight(&watertight, e), O3D_OK);
    assert_int_equal(watertight, 1);
    o3d_trianglemesh_destroy(e);
    O3D_ASSERT_FAILS(o3d_trianglemesh_create_ellipsoid(&e, -1.0, 1.0, 1.0, 10, 0), INV);
    assert_null(e);
    O3D_ASSERT_FAILS(o3d_trianglemesh_create_ellipsoid(&e, 1.0, 1.0, 1.0, 1, 0), INV);
}

/* Constraints that are a rigid motion of the whole sphere give the moved sphere. */
static void test_arap_reproduces_a_rigid_motion(void** state) {
    (void)state;
    o3d_trianglemesh_t* s = NULL;
    assert_int_equal(o3d_trianglemesh_create_sphere(&s, 1.0, 8), O3D_OK);
    const double* v = NULL;
    size_t n = 0;
    assert_int_equal(o3d_trianglemesh_array_view(&v, &n, s, O3D_MESH_VERTICES), O3D_OK);
    /* Rotation by 30 degrees about z, then translation (0.5, -0.25, 2). */
    const double c = cos(M_PI / 6.0), sn = sin(M_PI / 6.0), t[3] = {0.5, -0.25, 2.0};
    int32_t ids[40];
    double pos[3 * 40];
    size_t k = 0;
    for (size_t i = 0; i < n && k < 40; i += 3, ++k) {
        ids[k] = (int32_t)i;
        pos[3 * k] = c * v[3 * i] - sn * v[3 * i + 1] + t[0];
        pos[3 * k + 1] = sn * v[3 * i] + c * v[3 * i + 1] + t[1];
        pos[3 * k + 2] = v[3 * i + 2] + t[2];
    }
    o3d_trianglemesh_t* out = NULL;
    assert_int_equal(o3d_trianglemesh_deform_as_rigid_as_possible(&out, s, ids, k, pos, k, 50, O3D_ARAP_ENERGY_SPOKES,
                                                                   0.01), O3D_OK);
    const double* w = NULL;
    size_t m = 0;
    assert_int_equal(o3d_trianglemesh_array_view(&w, &m, out, O3D_MESH_VERTICES), O3D_OK);
    assert_int_equal(m, n);
    double worst = 0.0;
    for (size_t i = 0; i < n; ++i) {
        const double want[3] = {c * v[3 * i] - sn * v[3 * i + 1] + t[0], sn * v[3 * i] + c * v[3 * i + 1] + t[1],
                                v[3 * i + 2] + t[2]};
        for (int d = 0; d < 3; ++d) worst = fmax(worst, fabs(w[3 * i + d] - want[d]));
    }
    assert_true(worst < 1e-5);
    o3d_trianglemesh_destroy(out);
    /* Bad input: an index out of range, a repeated index, an unknown energy, no constraints. */
    int32_t bad_ids[2] = {0, (int32_t)n};
    O3D_ASSERT_FAILS(o3d_trianglemesh_deform_as_rigid_as_possible(&out, s, bad_ids, 2, pos, 2, 5,
                                                                  O3D_ARAP_ENERGY_SPOKES, 0.01), INV);
    assert_null(out);
    bad_ids[1] = 0;
    O3D_ASSERT_FAILS(o3d_trianglemesh_deform_as_rigid_as_possible(&out, s, bad_ids, 2, pos, 2, 5,
                                                                  O3D_ARAP_ENERGY_SPOKES, 0.01), INV);
    O3D_ASSERT_FAILS(o3d_trianglemesh_deform_as_rigid_as_possible(&out, s, ids, k, pos, k, 5, 7, 0.01), INV);
    O3D_ASSERT_FAILS(o3d_trianglemesh_deform_as_rigid_as_possible(&out, s, ids, k, pos, k - 1, 5,
                                                                  O3D_ARAP_ENERGY_SPOKES, 0.01), INV);
    O3D_ASSERT_FAILS(o3d_trianglemesh_deform_as_rigid_as_possible(&out, s, NULL, 0, NULL, 0, 5,
                                                                  O3D_ARAP_ENERGY_SMOOTHED, 0.01), INV);
    o3d_trianglemesh_destroy(s);
}

/* The box mesh of an oriented box has the box's 8 corners; the ellipsoid mesh of an ellipsoid lies on it. */
static void test_meshes_of_bounding_volumes(void** state) {
    (void)state;
    const double c = cos(0.3), s = sin(0.3);
    const o3d_obb_t box = {{1.0, 2.0, 3.0}, {c, -s, 0, s, c, 0, 0, 0, 1}, {2.0, 4.0, 6.0}};
    o3d_trianglemesh_t* m = NULL;
    assert_int_equal(o3d_trianglemesh_create_from_oriented_bounding_box(&m, &box, NULL, 0), O3D_OK);
    double corners[24];
    assert_int_equal(o3d_obb_get_box_points(corners, &box), O3D_OK);
    const double* v = NULL;
    size_t n = 0;
    assert_int_equal(o3d_trianglemesh_array_view(&v, &n, m, O3D_MESH_VERTICES), O3D_OK);
    assert_int_equal(n, 8);
    for (size_t i = 0; i < 8; ++i) { /* each vertex is one of the corners */
        double best = 1e9;
        for (size_t j = 0; j < 8; ++j) {
            double d = 0.0;
            for (int k = 0; k < 3; ++k) d += fabs(v[3 * i + k] - corners[3 * j + k]);
            best = fmin(best, d);
        }
        assert_true(best < 1e-12);
    }
    double volume = 0.0;
    assert_int_equal(o3d_trianglemesh_get_volume(&volume, m), O3D_OK);
    assert_true(fabs(volume - 48.0) < 1e-9);
    o3d_trianglemesh_destroy(m);
    const double scale[3] = {0.5, 0.5, 0.5};
    assert_int_equal(o3d_trianglemesh_create_from_oriented_bounding_box(&m, &box, scale, 0), O3D_OK);
    assert_int_equal(o3d_trianglemesh_get_volume(&volume, m), O3D_OK);
    assert_true(fabs(volume - 6.0) < 1e-9);
    o3d_trianglemesh_destroy(m);

    const o3d_obe_t e = {{1.0, 2.0, 3.0}, {c, -s, 0, s, c, 0, 0, 0, 1}, {1.0, 2.0, 3.0}};
    assert_int_equal(o3d_trianglemesh_create_from_oriented_bounding_ellipsoid(&m, &e, NULL, 12, 0), O3D_OK);
    assert_int_equal(o3d_trianglemesh_array_view(&v, &n, m, O3D_MESH_VERTICES), O3D_OK);
    for (size_t i = 0; i < n; ++i) { /* R^T (v - c), scaled by the radii, has unit length */
        const double d[3] = {v[3 * i] - 1.0, v[3 * i + 1] - 2.0, v[3 * i + 2] - 3.0};
        const double u[3] = {(c * d[0] + s * d[1]) / 1.0, (-s * d[0] + c * d[1]) / 2.0, d[2] / 3.0};
        assert_true(fabs(u[0] * u[0] + u[1] * u[1] + u[2] * u[2] - 1.0) < 1e-9);
    }
    o3d_trianglemesh_destroy(m);
    /* The minimal box and the ellipsoid of the box mesh's own vertices. */
    assert_int_equal(o3d_trianglemesh_create_from_oriented_bounding_box(&m, &box, NULL, 0), O3D_OK);
    o3d_obb_t minimal;
    assert_int_equal(o3d_trianglemesh_get_minimal_oriented_bounding_box(&minimal, m, 0), O3D_OK);
    assert_true(fabs(minimal.extent[0] * minimal.extent[1] * minimal.extent[2] - 48.0) < 1e-6);
    o3d_obe_t fit;
    assert_int_equal(o3d_trianglemesh_get_oriented_bounding_ellipsoid(&fit, m, 0), O3D_OK);
    /* The smallest ellipsoid around a box's corners is the box's scaled by sqrt(3): radii = sqrt(3) * extent / 2. */
    const double want[3] = {1.0, 2.0, 3.0};
    double got[3] = {fit.radii[0], fit.radii[1], fit.radii[2]};
    for (int i = 0; i < 3; ++i) /* sort ascending */
        for (int j = i + 1; j < 3; ++j)
            if (got[j] < got[i]) {
                const double t = got[i];
                got[i] = got[j];
                got[j] = t;
            }
    for (int i = 0; i < 3; ++i) assert_true(fabs(got[i] - sqrt(3.0) * want[i]) < 1e-3 * want[i]);
    for (int k = 0; k < 3; ++k) assert_true(fabs(fit.center[k] - box.center[k]) < 1e-4);
    o3d_trianglemesh_destroy(m);
    const o3d_obb_t bad = {{0, 0, 0}, {2, 0, 0, 0, 1, 0, 0, 0, 1}, {1, 1, 1}};
    O3D_ASSERT_FAILS(o3d_trianglemesh_create_from_oriented_bounding_box(&m, &bad, NULL, 0), INV);
    O3D_ASSERT_FAILS(o3d_trianglemesh_create_from_oriented_bounding_ellipsoid(&m, NULL, NULL, 12, 0), INV);
}

int main(void) {
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_adjacency_list_of_a_strip),
        cmocka_unit_test(test_adjacency_list_of_platonic_solids),
        cmocka_unit_test(test_adjacency_list_bad_input),
        cmocka_unit_test(test_non_manifold_edges_of_a_fin),
        cmocka_unit_test(test_non_manifold_vertex_of_a_bow_tie),
        cmocka_unit_test(test_intersections_of_two_spheres),
        cmocka_unit_test(test_orient_triangles_repairs_a_box),
        cmocka_unit_test(test_filter_sharpen_by_hand),
        cmocka_unit_test(test_create_ellipsoid_on_the_surface),
        cmocka_unit_test(test_arap_reproduces_a_rigid_motion),
        cmocka_unit_test(test_meshes_of_bounding_volumes),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
