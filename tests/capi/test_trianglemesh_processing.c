/* SPDX-License-Identifier: MIT */
/* C API mesh processing (trianglemesh.h, "Processing"): results through the ABI, NULL handles and outputs,
 * bad parameters, out-of-range triangle indices. The algorithms themselves are checked in
 * tests/core/mesh_processing_*_test.cpp. */
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <setjmp.h>
#include <cmocka.h>

#include <math.h>
#include <string.h>

#include "o3d/trianglemesh.h"
#include "o3d_test_util.h"

#define INV O3D_ERROR_INVALID_ARGUMENT

/* Unit square in z = 0 as two triangles, vertex colors (x, y, 0.5). */
static o3d_trianglemesh_t* make_square(void) {
    const double v[12] = {0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0};
    const double c[12] = {0, 0, 0.5, 1, 0, 0.5, 1, 1, 0.5, 0, 1, 0.5};
    const int32_t t[6] = {0, 1, 2, 0, 2, 3};
    o3d_trianglemesh_t* m = NULL;
    assert_int_equal(o3d_trianglemesh_create(&m), O3D_OK);
    assert_int_equal(o3d_trianglemesh_set_array(m, O3D_MESH_VERTICES, v, 4), O3D_OK);
    assert_int_equal(o3d_trianglemesh_set_array(m, O3D_MESH_VERTEX_COLORS, c, 4), O3D_OK);
    assert_int_equal(o3d_trianglemesh_set_index_array(m, O3D_MESH_TRIANGLES, t, 2), O3D_OK);
    return m;
}

/* Regular tetrahedron, outward triangles. */
static o3d_trianglemesh_t* make_tetrahedron(void) {
    const double v[12] = {1, 1, 1, 1, -1, -1, -1, 1, -1, -1, -1, 1};
    const int32_t t[12] = {0, 1, 2, 0, 3, 1, 0, 2, 3, 1, 3, 2};
    o3d_trianglemesh_t* m = NULL;
    assert_int_equal(o3d_trianglemesh_create(&m), O3D_OK);
    assert_int_equal(o3d_trianglemesh_set_array(m, O3D_MESH_VERTICES, v, 4), O3D_OK);
    assert_int_equal(o3d_trianglemesh_set_index_array(m, O3D_MESH_TRIANGLES, t, 4), O3D_OK);
    return m;
}

static size_t triangles_of(const o3d_trianglemesh_t* m) {
    size_t n = 0;
    assert_int_equal(o3d_trianglemesh_num_triangles(&n, m), O3D_OK);
    return n;
}

static size_t vertices_of(const o3d_trianglemesh_t* m) {
    size_t n = 0;
    assert_int_equal(o3d_trianglemesh_num_vertices(&n, m), O3D_OK);
    return n;
}

static double area_of(const o3d_trianglemesh_t* m) {
    const double* v = NULL;
    const int32_t* t = NULL;
    size_t nv = 0, nt = 0;
    assert_int_equal(o3d_trianglemesh_array_view(&v, &nv, m, O3D_MESH_VERTICES), O3D_OK);
    assert_int_equal(o3d_trianglemesh_index_array_view(&t, &nt, m, O3D_MESH_TRIANGLES), O3D_OK);
    double area = 0;
    for (size_t i = 0; i < nt; ++i) {
        const double* a = v + 3 * t[3 * i];
        const double* b = v + 3 * t[3 * i + 1];
        const double* c = v + 3 * t[3 * i + 2];
        const double u[3] = {b[0] - a[0], b[1] - a[1], b[2] - a[2]}, w[3] = {c[0] - a[0], c[1] - a[1], c[2] - a[2]};
        const double x = u[1] * w[2] - u[2] * w[1], y = u[2] * w[0] - u[0] * w[2], z = u[0] * w[1] - u[1] * w[0];
        area += 0.5 * sqrt(x * x + y * y + z * z);
    }
    return area;
}

static void test_sampling(void** state) {
    (void)state;
    o3d_trianglemesh_t* m = make_square();
    o3d_pointcloud_t* pc = NULL;
    assert_int_equal(o3d_trianglemesh_sample_points_uniformly(&pc, m, 1000, 1, 5), O3D_OK);
    size_t n = 0;
    const double* p = NULL;
    const double* c = NULL;
    assert_int_equal(o3d_pointcloud_array_view(&p, &n, pc, O3D_POINTCLOUD_POINTS), O3D_OK);
    assert_int_equal(n, 1000);
    size_t nc = 0;
    assert_int_equal(o3d_pointcloud_array_view(&c, &nc, pc, O3D_POINTCLOUD_COLORS), O3D_OK);
    assert_int_equal(nc, 1000);
    for (size_t i = 0; i < n; ++i) {
        assert_true(p[3 * i] >= 0 && p[3 * i] <= 1 && p[3 * i + 1] >= 0 && p[3 * i + 1] <= 1);
        assert_true(p[3 * i + 2] == 0.0);
        assert_true(fabs(c[3 * i] - p[3 * i]) < 1e-12 && fabs(c[3 * i + 1] - p[3 * i + 1]) < 1e-12);
    }
    /* Same seed, same cloud. */
    o3d_pointcloud_t* again = NULL;
    assert_int_equal(o3d_trianglemesh_sample_points_uniformly(&again, m, 1000, 1, 5), O3D_OK);
    const double* q = NULL;
    assert_int_equal(o3d_pointcloud_array_view(&q, &n, again, O3D_POINTCLOUD_POINTS), O3D_OK);
    assert_memory_equal(p, q, 3000 * sizeof(double));
    o3d_pointcloud_destroy(again);
    o3d_pointcloud_destroy(pc);

    pc = NULL;
    assert_int_equal(o3d_trianglemesh_sample_points_poisson_disk(&pc, m, 50, 5.0, 0, 1), O3D_OK);
    assert_int_equal(o3d_pointcloud_size(&n, pc), O3D_OK);
    assert_int_equal(n, 50);
    o3d_pointcloud_destroy(pc);

    /* Errors leave *out NULL. */
    pc = (o3d_pointcloud_t*)&n;
    O3D_ASSERT_FAILS(o3d_trianglemesh_sample_points_uniformly(&pc, m, 0, 0, 1), INV);
    assert_null(pc);
    O3D_ASSERT_FAILS(o3d_trianglemesh_sample_points_uniformly(NULL, m, 10, 0, 1), INV);
    O3D_ASSERT_FAILS(o3d_trianglemesh_sample_points_uniformly(&pc, NULL, 10, 0, 1), INV);
    O3D_ASSERT_FAILS(o3d_trianglemesh_sample_points_poisson_disk(&pc, m, 10, 0.5, 0, 1), INV);
    O3D_ASSERT_FAILS(o3d_trianglemesh_sample_points_poisson_disk(&pc, m, 10, NAN, 0, 1), INV);
    O3D_ASSERT_FAILS(o3d_trianglemesh_sample_points_poisson_disk(NULL, m, 10, 5, 0, 1), INV);
    o3d_trianglemesh_t* empty = NULL;
    assert_int_equal(o3d_trianglemesh_create(&empty), O3D_OK);
    O3D_ASSERT_FAILS(o3d_trianglemesh_sample_points_uniformly(&pc, empty, 10, 0, 1), INV);
    O3D_ASSERT_FAILS(o3d_trianglemesh_sample_points_poisson_disk(&pc, empty, 10, 5, 0, 1), INV);
    o3d_trianglemesh_destroy(empty);
    o3d_trianglemesh_destroy(m);
}

static void test_simplification(void** state) {
    (void)state;
    o3d_trianglemesh_t* m = make_tetrahedron();
    o3d_trianglemesh_t* out = NULL;
    /* Everything in one voxel: a single vertex at the centre, no triangles. */
    assert_int_equal(o3d_trianglemesh_simplify_vertex_clustering(&out, m, 10.0, O3D_SIMPLIFICATION_AVERAGE), O3D_OK);
    assert_int_equal(vertices_of(out), 1);
    assert_int_equal(triangles_of(out), 0);
    double centre[3];
    size_t rows = 0;
    assert_int_equal(o3d_trianglemesh_get_array(centre, 1, &rows, out, O3D_MESH_VERTICES), O3D_OK);
    assert_true(fabs(centre[0]) < 1e-12 && fabs(centre[1]) < 1e-12 && fabs(centre[2]) < 1e-12);
    o3d_trianglemesh_destroy(out);

    /* A subdivided tetrahedron decimates back to a closed surface of the target size. */
    o3d_trianglemesh_t* fine = NULL;
    assert_int_equal(o3d_trianglemesh_subdivide_midpoint(&fine, m, 3), O3D_OK);
    assert_int_equal(triangles_of(fine), 256);
    assert_int_equal(o3d_trianglemesh_simplify_quadric_decimation(&out, fine, 40, INFINITY, 1.0), O3D_OK);
    assert_int_equal(triangles_of(out), 40);
    assert_int_equal(vertices_of(out), 22); /* closed genus 0: V = F / 2 + 2 */
    /* Planar faces: a flat collapse costs nothing and the area is kept. */
    assert_true(fabs(area_of(out) - area_of(m)) < 1e-9);
    o3d_trianglemesh_destroy(out);
    o3d_trianglemesh_destroy(fine);

    out = (o3d_trianglemesh_t*)m;
    O3D_ASSERT_FAILS(o3d_trianglemesh_simplify_vertex_clustering(&out, m, 0.0, O3D_SIMPLIFICATION_AVERAGE), INV);
    assert_null(out);
    O3D_ASSERT_FAILS(o3d_trianglemesh_simplify_vertex_clustering(&out, m, -1.0, O3D_SIMPLIFICATION_QUADRIC), INV);
    O3D_ASSERT_FAILS(o3d_trianglemesh_simplify_vertex_clustering(&out, m, NAN, O3D_SIMPLIFICATION_AVERAGE), INV);
    O3D_ASSERT_FAILS(o3d_trianglemesh_simplify_vertex_clustering(&out, m, 1.0, 2), INV);
    O3D_ASSERT_FAILS(o3d_trianglemesh_simplify_vertex_clustering(&out, NULL, 1.0, 0), INV);
    O3D_ASSERT_FAILS(o3d_trianglemesh_simplify_vertex_clustering(NULL, m, 1.0, 0), INV);
    O3D_ASSERT_FAILS(o3d_trianglemesh_simplify_quadric_decimation(&out, m, 2, NAN, 1.0), INV);
    O3D_ASSERT_FAILS(o3d_trianglemesh_simplify_quadric_decimation(&out, m, 2, INFINITY, -1.0), INV);
    O3D_ASSERT_FAILS(o3d_trianglemesh_simplify_quadric_decimation(&out, NULL, 2, INFINITY, 1.0), INV);
    O3D_ASSERT_FAILS(o3d_trianglemesh_simplify_quadric_decimation(NULL, m, 2, INFINITY, 1.0), INV);
    o3d_trianglemesh_destroy(m);
}

static void test_smoothing(void** state) {
    (void)state;
    o3d_trianglemesh_t* m = make_square();
    o3d_trianglemesh_t* out = NULL;
    /* A flat mesh stays flat. */
    assert_int_equal(o3d_trianglemesh_filter_smooth_laplacian(&out, m, 5, 0.5, O3D_FILTER_SCOPE_ALL), O3D_OK);
    const double* v = NULL;
    size_t n = 0;
    assert_int_equal(o3d_trianglemesh_array_view(&v, &n, out, O3D_MESH_VERTICES), O3D_OK);
    assert_int_equal(n, 4);
    for (size_t i = 0; i < n; ++i) assert_true(v[3 * i + 2] == 0.0);
    o3d_trianglemesh_destroy(out);
    assert_int_equal(o3d_trianglemesh_filter_smooth_taubin(&out, m, 3, 0.5, -0.53, O3D_FILTER_SCOPE_VERTEX), O3D_OK);
    o3d_trianglemesh_destroy(out);
    /* Colors only: positions untouched. */
    assert_int_equal(o3d_trianglemesh_filter_smooth_simple(&out, m, 1, O3D_FILTER_SCOPE_COLOR), O3D_OK);
    const double* orig = NULL;
    assert_int_equal(o3d_trianglemesh_array_view(&v, &n, out, O3D_MESH_VERTICES), O3D_OK);
    assert_int_equal(o3d_trianglemesh_array_view(&orig, &n, m, O3D_MESH_VERTICES), O3D_OK);
    assert_memory_equal(v, orig, 12 * sizeof(double));
    o3d_trianglemesh_destroy(out);

    out = (o3d_trianglemesh_t*)m;
    O3D_ASSERT_FAILS(o3d_trianglemesh_filter_smooth_simple(&out, m, -1, O3D_FILTER_SCOPE_ALL), INV);
    assert_null(out);
    O3D_ASSERT_FAILS(o3d_trianglemesh_filter_smooth_simple(&out, m, 1, 4), INV);
    O3D_ASSERT_FAILS(o3d_trianglemesh_filter_smooth_simple(&out, m, 1, -1), INV);
    O3D_ASSERT_FAILS(o3d_trianglemesh_filter_smooth_laplacian(&out, m, 1, NAN, O3D_FILTER_SCOPE_ALL), INV);
    O3D_ASSERT_FAILS(o3d_trianglemesh_filter_smooth_laplacian(&out, m, -3, 0.5, O3D_FILTER_SCOPE_ALL), INV);
    O3D_ASSERT_FAILS(o3d_trianglemesh_filter_smooth_taubin(&out, m, 1, 0.5, INFINITY, O3D_FILTER_SCOPE_ALL), INV);
    O3D_ASSERT_FAILS(o3d_trianglemesh_filter_smooth_taubin(&out, NULL, 1, 0.5, -0.53, O3D_FILTER_SCOPE_ALL), INV);
    O3D_ASSERT_FAILS(o3d_trianglemesh_filter_smooth_taubin(NULL, m, 1, 0.5, -0.53, O3D_FILTER_SCOPE_ALL), INV);
    o3d_trianglemesh_destroy(m);
}

static void test_subdivision(void** state) {
    (void)state;
    o3d_trianglemesh_t* m = make_tetrahedron();
    o3d_trianglemesh_t* out = NULL;
    assert_int_equal(o3d_trianglemesh_subdivide_midpoint(&out, m, 2), O3D_OK);
    assert_int_equal(triangles_of(out), 64);
    assert_int_equal(vertices_of(out), 34);
    assert_true(fabs(area_of(out) - area_of(m)) < 1e-12);
    o3d_trianglemesh_destroy(out);
    assert_int_equal(o3d_trianglemesh_subdivide_loop(&out, m, 1), O3D_OK);
    assert_int_equal(triangles_of(out), 16);
    assert_int_equal(vertices_of(out), 10);
    o3d_trianglemesh_destroy(out);

    out = (o3d_trianglemesh_t*)m;
    O3D_ASSERT_FAILS(o3d_trianglemesh_subdivide_midpoint(&out, m, -1), INV);
    assert_null(out);
    O3D_ASSERT_FAILS(o3d_trianglemesh_subdivide_loop(&out, m, 30), INV); /* 4^31 triangles */
    O3D_ASSERT_FAILS(o3d_trianglemesh_subdivide_loop(&out, NULL, 1), INV);
    O3D_ASSERT_FAILS(o3d_trianglemesh_subdivide_midpoint(NULL, m, 1), INV);
    o3d_trianglemesh_destroy(m);
}

static void test_crop(void** state) {
    (void)state;
    o3d_trianglemesh_t* m = make_square();
    o3d_trianglemesh_t* out = NULL;
    /* The lower half in y: both triangles have a corner at y = 1, so nothing is kept. */
    const double lo[3] = {0, 0, -1}, hi[3] = {1, 0.5, 1}, all_hi[3] = {1, 1, 1};
    assert_int_equal(o3d_trianglemesh_crop_aabb(&out, m, lo, hi), O3D_OK);
    assert_int_equal(triangles_of(out), 0);
    assert_int_equal(vertices_of(out), 0);
    o3d_trianglemesh_destroy(out);
    assert_int_equal(o3d_trianglemesh_crop_aabb(&out, m, lo, all_hi), O3D_OK);
    assert_int_equal(triangles_of(out), 2);
    assert_int_equal(vertices_of(out), 4);
    o3d_trianglemesh_destroy(out);

    const double nan_lo[3] = {0, NAN, 0}, inverted_hi[3] = {-1, 1, 1};
    out = (o3d_trianglemesh_t*)m;
    O3D_ASSERT_FAILS(o3d_trianglemesh_crop_aabb(&out, m, nan_lo, all_hi), INV);
    assert_null(out);
    O3D_ASSERT_FAILS(o3d_trianglemesh_crop_aabb(&out, m, lo, inverted_hi), INV);
    O3D_ASSERT_FAILS(o3d_trianglemesh_crop_aabb(&out, m, NULL, all_hi), INV);
    O3D_ASSERT_FAILS(o3d_trianglemesh_crop_aabb(&out, m, lo, NULL), INV);
    O3D_ASSERT_FAILS(o3d_trianglemesh_crop_aabb(&out, NULL, lo, all_hi), INV);
    O3D_ASSERT_FAILS(o3d_trianglemesh_crop_aabb(NULL, m, lo, all_hi), INV);
    o3d_trianglemesh_destroy(m);
}

/* Every processing function refuses a triangle that points past the vertices (or below 0). */
static void test_out_of_range_triangles(void** state) {
    (void)state;
    for (int bad = 0; bad < 2; ++bad) {
        o3d_trianglemesh_t* m = make_square();
        const int32_t t[6] = {0, 1, 2, 0, 2, bad ? -1 : 4};
        assert_int_equal(o3d_trianglemesh_set_index_array(m, O3D_MESH_TRIANGLES, t, 2), O3D_OK);
        o3d_pointcloud_t* pc = NULL;
        o3d_trianglemesh_t* out = NULL;
        const double lo[3] = {-1, -1, -1}, hi[3] = {2, 2, 2};
        O3D_ASSERT_FAILS(o3d_trianglemesh_sample_points_uniformly(&pc, m, 10, 0, 1), INV);
        O3D_ASSERT_FAILS(o3d_trianglemesh_sample_points_poisson_disk(&pc, m, 10, 5, 0, 1), INV);
        O3D_ASSERT_FAILS(o3d_trianglemesh_simplify_vertex_clustering(&out, m, 0.1, 0), INV);
        O3D_ASSERT_FAILS(o3d_trianglemesh_simplify_quadric_decimation(&out, m, 1, INFINITY, 1), INV);
        O3D_ASSERT_FAILS(o3d_trianglemesh_filter_smooth_simple(&out, m, 1, 0), INV);
        O3D_ASSERT_FAILS(o3d_trianglemesh_filter_smooth_laplacian(&out, m, 1, 0.5, 0), INV);
        O3D_ASSERT_FAILS(o3d_trianglemesh_filter_smooth_taubin(&out, m, 1, 0.5, -0.53, 0), INV);
        O3D_ASSERT_FAILS(o3d_trianglemesh_subdivide_midpoint(&out, m, 1), INV);
        O3D_ASSERT_FAILS(o3d_trianglemesh_subdivide_loop(&out, m, 1), INV);
        O3D_ASSERT_FAILS(o3d_trianglemesh_crop_aabb(&out, m, lo, hi), INV);
        assert_null(pc);
        assert_null(out);
        o3d_trianglemesh_destroy(m);
    }
}

int main(void) {
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_sampling),  cmocka_unit_test(test_simplification),
        cmocka_unit_test(test_smoothing), cmocka_unit_test(test_subdivision),
        cmocka_unit_test(test_crop),      cmocka_unit_test(test_out_of_range_triangles),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
