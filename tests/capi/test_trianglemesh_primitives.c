/* SPDX-License-Identifier: MIT */
/* C API trianglemesh.h, primitives: Open3D 0.20's counts (tools/reference/record_primitives.py), analytic
 * areas and volumes computed here from the copied-out arrays, outward winding, and the error codes of bad
 * arguments (radius <= 0, NaN, resolution < 1, NULL out). */
#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdlib.h>

#include <cmocka.h>

#include "o3d/o3d.h"
#include "o3d_test_util.h"

#ifndef M_PI
#define M_PI 3.14159265358979323846
#endif

typedef struct {
    size_t nv, nt;
    double* v;
    int32_t* t;
} arrays;

static arrays copy_out(const o3d_trianglemesh_t* m) {
    arrays a;
    assert_int_equal(o3d_trianglemesh_num_vertices(&a.nv, m), O3D_OK);
    assert_int_equal(o3d_trianglemesh_num_triangles(&a.nt, m), O3D_OK);
    a.v = malloc(3 * a.nv * sizeof(double));
    a.t = malloc(3 * a.nt * sizeof(int32_t));
    size_t rows = 0;
    assert_int_equal(o3d_trianglemesh_get_array(a.v, a.nv, &rows, m, O3D_MESH_VERTICES), O3D_OK);
    assert_int_equal(rows, a.nv);
    assert_int_equal(o3d_trianglemesh_get_index_array(a.t, a.nt, &rows, m, O3D_MESH_TRIANGLES), O3D_OK);
    assert_int_equal(rows, a.nt);
    return a;
}

/* Surface area, and the signed volume (positive when every triangle winds outward). */
static void measure(const arrays* a, double* area, double* volume) {
    *area = *volume = 0;
    for (size_t t = 0; t < a->nt; ++t) {
        const double* p = a->v + 3 * a->t[3 * t];
        const double* q = a->v + 3 * a->t[3 * t + 1];
        const double* r = a->v + 3 * a->t[3 * t + 2];
        const double u[3] = {q[0] - p[0], q[1] - p[1], q[2] - p[2]}, w[3] = {r[0] - p[0], r[1] - p[1], r[2] - p[2]};
        const double c[3] = {u[1] * w[2] - u[2] * w[1], u[2] * w[0] - u[0] * w[2], u[0] * w[1] - u[1] * w[0]};
        *area += 0.5 * sqrt(c[0] * c[0] + c[1] * c[1] + c[2] * c[2]);
        *volume += (p[0] * (q[1] * r[2] - q[2] * r[1]) - p[1] * (q[0] * r[2] - q[2] * r[0]) +
                    p[2] * (q[0] * r[1] - q[1] * r[0])) / 6.0;
    }
}

static void check(o3d_trianglemesh_t* m, size_t nv, size_t nt, double area, double volume, double tol) {
    assert_non_null(m);
    arrays a = copy_out(m);
    assert_int_equal(a.nv, nv);
    assert_int_equal(a.nt, nt);
    double got_area, got_volume;
    measure(&a, &got_area, &got_volume);
    assert_float_equal(got_area, area, tol);
    if (volume > 0) assert_float_equal(got_volume, volume, tol);
    assert_true(got_volume > 0);
    free(a.v);
    free(a.t);
    o3d_trianglemesh_destroy(m);
}

static void test_counts_areas_volumes(void** state) {
    (void)state;
    o3d_trianglemesh_t* m = NULL;
    /* Counts and areas from Open3D 0.20 (tools/reference/record_primitives.py); volumes analytic. */
    assert_int_equal(o3d_trianglemesh_create_box(&m, 1, 2, 3), O3D_OK);
    check(m, 8, 12, 22.0, 6.0, 1e-12);
    assert_int_equal(o3d_trianglemesh_create_sphere(&m, 1, 20), O3D_OK);
    check(m, 762, 1520, 12.501878921475342, -1, 1e-9);
    assert_int_equal(o3d_trianglemesh_create_cylinder(&m, 1, 2, 20, 4), O3D_OK);
    check(m, 102, 200, 18.69509709071738, 20 * 0.5 * sin(2 * M_PI / 20) * 2, 1e-9);
    assert_int_equal(o3d_trianglemesh_create_cone(&m, 1, 2, 20, 1), O3D_OK);
    check(m, 22, 40, 10.068990563677295, 20 * 0.5 * sin(2 * M_PI / 20) * 2 / 3, 1e-9);
    assert_int_equal(o3d_trianglemesh_create_torus(&m, 1, 0.5, 30, 20), O3D_OK);
    check(m, 600, 1200, 19.56851568284109, -1, 1e-9);
    assert_int_equal(o3d_trianglemesh_create_arrow(&m, 1, 1.5, 5, 4, 20, 4, 1), O3D_OK);
    check(m, 124, 240, 64.43849822000266, -1, 1e-9);
    assert_int_equal(o3d_trianglemesh_create_tetrahedron(&m, 1), O3D_OK);
    check(m, 4, 4, 4.618802153517006, 8 / (9 * sqrt(3.0)), 1e-12);
    assert_int_equal(o3d_trianglemesh_create_octahedron(&m, 1), O3D_OK);
    check(m, 6, 8, 6.928203230275508, 4.0 / 3.0, 1e-12);
    /* Vertices at distance `radius` (the header's promise); Open3D 0.20 leaves them at 1.902 * radius. */
    assert_int_equal(o3d_trianglemesh_create_icosahedron(&m, 1), O3D_OK);
    check(m, 12, 20, 34.64101615137755 / (1 + pow((1 + sqrt(5.0)) / 2, 2)), -1, 1e-12);

    const double origin[3] = {1, 2, 3};
    assert_int_equal(o3d_trianglemesh_create_coordinate_frame(&m, 2, origin), O3D_OK);
    int32_t has = 0;
    assert_int_equal(o3d_trianglemesh_has_array(&has, m, O3D_MESH_VERTEX_COLORS), O3D_OK);
    assert_int_equal(has, 1);
    assert_int_equal(o3d_trianglemesh_has_array(&has, m, O3D_MESH_VERTEX_NORMALS), O3D_OK);
    assert_int_equal(has, 1);
    check(m, 1134, 2240, 2.9767455943032073, -1, 1e-9);
    assert_int_equal(o3d_trianglemesh_create_coordinate_frame(&m, 1, NULL), O3D_OK); /* NULL origin: 0, 0, 0 */
    check(m, 1134, 2240, 0.7441863985758009, -1, 1e-9);
}

static void test_sphere_area_converges(void** state) {
    (void)state;
    double last = 1;
    for (int32_t res = 10; res <= 160; res *= 4) {
        o3d_trianglemesh_t* m = NULL;
        assert_int_equal(o3d_trianglemesh_create_sphere(&m, 2, res), O3D_OK);
        arrays a = copy_out(m);
        double area, volume;
        measure(&a, &area, &volume);
        const double err = fabs(area / (16 * M_PI) - 1);
        assert_true(err < last);
        last = err;
        free(a.v);
        free(a.t);
        o3d_trianglemesh_destroy(m);
    }
    assert_true(last < 1e-3);
}

static void test_bad_arguments(void** state) {
    (void)state;
    o3d_trianglemesh_t* m = (o3d_trianglemesh_t*)&m;
    const double bad[3] = {0.0, -1.0, NAN};
    for (int i = 0; i < 3; ++i) {
        O3D_ASSERT_FAILS(o3d_trianglemesh_create_box(&m, 1, bad[i], 1), O3D_ERROR_INVALID_ARGUMENT);
        assert_null(m);
        O3D_ASSERT_FAILS(o3d_trianglemesh_create_sphere(&m, bad[i], 20), O3D_ERROR_INVALID_ARGUMENT);
        O3D_ASSERT_FAILS(o3d_trianglemesh_create_cylinder(&m, bad[i], 2, 20, 4), O3D_ERROR_INVALID_ARGUMENT);
        O3D_ASSERT_FAILS(o3d_trianglemesh_create_cone(&m, 1, bad[i], 20, 1), O3D_ERROR_INVALID_ARGUMENT);
        O3D_ASSERT_FAILS(o3d_trianglemesh_create_torus(&m, bad[i], 0.5, 30, 20), O3D_ERROR_INVALID_ARGUMENT);
        O3D_ASSERT_FAILS(o3d_trianglemesh_create_arrow(&m, 1, bad[i], 5, 4, 20, 4, 1), O3D_ERROR_INVALID_ARGUMENT);
        O3D_ASSERT_FAILS(o3d_trianglemesh_create_coordinate_frame(&m, bad[i], NULL), O3D_ERROR_INVALID_ARGUMENT);
        O3D_ASSERT_FAILS(o3d_trianglemesh_create_tetrahedron(&m, bad[i]), O3D_ERROR_INVALID_ARGUMENT);
        O3D_ASSERT_FAILS(o3d_trianglemesh_create_octahedron(&m, bad[i]), O3D_ERROR_INVALID_ARGUMENT);
        O3D_ASSERT_FAILS(o3d_trianglemesh_create_icosahedron(&m, bad[i]), O3D_ERROR_INVALID_ARGUMENT);
        assert_null(m);
    }
    O3D_ASSERT_FAILS(o3d_trianglemesh_create_sphere(&m, 1, 0), O3D_ERROR_INVALID_ARGUMENT);
    O3D_ASSERT_FAILS(o3d_trianglemesh_create_sphere(&m, 1, 1), O3D_ERROR_INVALID_ARGUMENT);
    O3D_ASSERT_FAILS(o3d_trianglemesh_create_cylinder(&m, 1, 2, 0, 4), O3D_ERROR_INVALID_ARGUMENT);
    O3D_ASSERT_FAILS(o3d_trianglemesh_create_cylinder(&m, 1, 2, 20, 0), O3D_ERROR_INVALID_ARGUMENT);
    O3D_ASSERT_FAILS(o3d_trianglemesh_create_torus(&m, 1, 0.5, 30, -1), O3D_ERROR_INVALID_ARGUMENT);
    O3D_ASSERT_FAILS(o3d_trianglemesh_create_arrow(&m, 1, 1.5, 5, 4, 20, 4, 0), O3D_ERROR_INVALID_ARGUMENT);
    const double nan_origin[3] = {0, NAN, 0};
    O3D_ASSERT_FAILS(o3d_trianglemesh_create_coordinate_frame(&m, 1, nan_origin), O3D_ERROR_INVALID_ARGUMENT);
    O3D_ASSERT_FAILS(o3d_trianglemesh_create_box(NULL, 1, 1, 1), O3D_ERROR_INVALID_ARGUMENT);
    O3D_ASSERT_FAILS(o3d_trianglemesh_create_sphere(NULL, 1, 20), O3D_ERROR_INVALID_ARGUMENT);
}

/* The Moebius strip: counts, topology (Euler characteristic 0 for any band; one-sided for odd twists)
 * and geometry (every vertex within width/2 of the centre circle, the first column across the x axis). */
static void test_mobius(void** state) {
    (void)state;
    o3d_mobius_options_t opts;
    assert_int_equal(o3d_mobius_options_init(&opts, sizeof opts), O3D_OK);
    assert_true(opts.length_split == 70 && opts.width_split == 15 && opts.twists == 1 && opts.radius == 1.0);
    for (int32_t twists = 1; twists <= 2; ++twists) {
        opts.twists = twists;
        o3d_trianglemesh_t* m = NULL;
        assert_int_equal(o3d_trianglemesh_create_mobius(&m, &opts), O3D_OK);
        size_t nv = 0, nt = 0;
        assert_int_equal(o3d_trianglemesh_num_vertices(&nv, m), O3D_OK);
        assert_int_equal(o3d_trianglemesh_num_triangles(&nt, m), O3D_OK);
        assert_int_equal(nv, 70 * 15);
        assert_int_equal(nt, 2 * 70 * 14);
        int64_t euler = -1;
        int32_t orientable = -1, manifold = -1, watertight = -1;
        assert_int_equal(o3d_trianglemesh_euler_poincare_characteristic(&euler, m), O3D_OK);
        assert_int_equal(o3d_trianglemesh_is_orientable(&orientable, m), O3D_OK);
        assert_int_equal(o3d_trianglemesh_is_edge_manifold(&manifold, m, 1), O3D_OK);
        assert_int_equal(o3d_trianglemesh_is_watertight(&watertight, m), O3D_OK);
        assert_int_equal(euler, 0);
        assert_int_equal(orientable, twists % 2 == 0);
        assert_int_equal(manifold, 1);
        assert_int_equal(watertight, 0);
        const double* v = NULL;
        size_t rows = 0;
        assert_int_equal(o3d_trianglemesh_array_view(&v, &rows, m, O3D_MESH_VERTICES), O3D_OK);
        assert_true(fabs(v[0] - 0.5) < 1e-15 && fabs(v[3 * 14] - 1.5) < 1e-15 && v[1] == 0.0 && v[2] == 0.0);
        for (size_t i = 0; i < rows; ++i) {
            const double ring = sqrt(v[3 * i] * v[3 * i] + v[3 * i + 1] * v[3 * i + 1]) - 1.0;
            assert_true(sqrt(ring * ring + v[3 * i + 2] * v[3 * i + 2]) <= 0.5 + 1e-12);
        }
        o3d_trianglemesh_destroy(m);
    }
    o3d_trianglemesh_t* m = NULL;
    assert_int_equal(o3d_trianglemesh_create_mobius(&m, NULL), O3D_OK); /* NULL: the defaults */
    o3d_trianglemesh_destroy(m);
    m = NULL;
    opts.twists = -1;
    O3D_ASSERT_FAILS(o3d_trianglemesh_create_mobius(&m, &opts), O3D_ERROR_INVALID_ARGUMENT);
    assert_null(m);
    opts.twists = 1;
    opts.width_split = 1;
    O3D_ASSERT_FAILS(o3d_trianglemesh_create_mobius(&m, &opts), O3D_ERROR_INVALID_ARGUMENT);
    opts.width_split = 15;
    opts.struct_size = 3;
    O3D_ASSERT_FAILS(o3d_trianglemesh_create_mobius(&m, &opts), O3D_ERROR_INVALID_ARGUMENT);
    O3D_ASSERT_FAILS(o3d_mobius_options_init(NULL, sizeof opts), O3D_ERROR_INVALID_ARGUMENT);
}

int main(void) {
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_counts_areas_volumes),
        cmocka_unit_test(test_sphere_area_converges),
        cmocka_unit_test(test_bad_arguments),
        cmocka_unit_test(test_mobius),
    };
    return cmocka_run_group_tests_name("o3d_trianglemesh_primitives", tests, NULL, NULL);
}
