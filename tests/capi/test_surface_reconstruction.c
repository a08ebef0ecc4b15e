/* SPDX-License-Identifier: MIT */
/* C API surface reconstruction (trianglemesh.h: Poisson, ball pivoting, alpha shapes), tetramesh.h, and the
 * point-cloud tools that go with them (consistent normal orientation, duplicates, ISS keypoints): analytic
 * results on sampled spheres and cubes through the ABI, options structs, progress + cancel, copy-out buffers,
 * NULL / bad input. */
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

/* `n` points on the sphere of `radius` about the origin (a Fibonacci lattice: even spacing, deterministic), with
 * outward unit normals; `flip` reverses every third normal. */
static o3d_pointcloud_t* sphere_cloud(size_t n, double radius, int flip) {
    double* xyz = malloc(3 * n * sizeof(double));
    double* nrm = malloc(3 * n * sizeof(double));
    const double golden = M_PI * (3.0 - sqrt(5.0));
    for (size_t i = 0; i < n; ++i) {
        const double z = 1.0 - 2.0 * ((double)i + 0.5) / (double)n;
        const double r = sqrt(1.0 - z * z);
        const double phi = golden * (double)i;
        const double u[3] = {r * cos(phi), r * sin(phi), z};
        const double s = (flip && i % 3 == 0) ? -1.0 : 1.0;
        for (int k = 0; k < 3; ++k) {
            xyz[3 * i + k] = radius * u[k];
            nrm[3 * i + k] = s * u[k];
        }
    }
    o3d_pointcloud_t* pc = NULL;
    assert_int_equal(o3d_pointcloud_create(&pc), O3D_OK);
    assert_int_equal(o3d_pointcloud_set_array(pc, O3D_POINTCLOUD_POINTS, xyz, n), O3D_OK);
    assert_int_equal(o3d_pointcloud_set_array(pc, O3D_POINTCLOUD_NORMALS, nrm, n), O3D_OK);
    free(xyz);
    free(nrm);
    return pc;
}

/* Largest | |v| - radius | over the mesh's vertices. */
static double max_radial_error(const o3d_trianglemesh_t* mesh, double radius) {
    const double* v = NULL;
    size_t n = 0;
    assert_int_equal(o3d_trianglemesh_array_view(&v, &n, mesh, O3D_MESH_VERTICES), O3D_OK);
    assert_true(n > 0);
    double worst = 0.0;
    for (size_t i = 0; i < n; ++i) {
        const double e = fabs(sqrt(v[3 * i] * v[3 * i] + v[3 * i + 1] * v[3 * i + 1] + v[3 * i + 2] * v[3 * i + 2]) - radius);
        if (e > worst) worst = e;
    }
    return worst;
}

static int32_t count_calls(double fraction, void* user_data) {
    (void)fraction;
    ++*(int*)user_data;
    return 0;
}

static int32_t cancel_at_once(double fraction, void* user_data) {
    (void)fraction;
    (void)user_data;
    return 1;
}

static void test_poisson_sphere(void** state) {
    (void)state;
    o3d_pointcloud_t* pc = sphere_cloud(6000, 1.0, 0);
    o3d_poisson_options_t opts;
    assert_int_equal(o3d_poisson_options_init(&opts, sizeof opts), O3D_OK);
    assert_int_equal(opts.depth, 8); /* Open3D's defaults */
    assert_true(opts.scale == 1.1);
    assert_true(opts.width == 0.0);
    assert_int_equal(opts.linear_fit, 0);
    opts.depth = 6;
    int calls = 0;
    opts.progress = count_calls;
    opts.user_data = &calls;
    o3d_trianglemesh_t* mesh = NULL;
    o3d_feature_t* densities = NULL;
    assert_int_equal(o3d_trianglemesh_create_from_point_cloud_poisson(&mesh, &densities, pc, &opts), O3D_OK);
    assert_true(calls > 0);
    /* Depth 6 over a cube of side 2.2: cells of 0.034; the surface lies well within one cell of the sphere. */
    assert_true(max_radial_error(mesh, 1.0) < 0.035);
    int32_t watertight = 0;
    assert_int_equal(o3d_trianglemesh_is_watertight(&watertight, mesh), O3D_OK);
    assert_int_equal(watertight, 1);
    double volume = 0.0;
    assert_int_equal(o3d_trianglemesh_get_volume(&volume, mesh), O3D_OK);
    assert_true(fabs(volume - 4.0 / 3.0 * M_PI) < 0.05 * 4.0 / 3.0 * M_PI);
    /* One density per vertex, finite. */
    size_t nv = 0, dim = 0, num = 0;
    assert_int_equal(o3d_trianglemesh_num_vertices(&nv, mesh), O3D_OK);
    assert_int_equal(o3d_feature_dimension(&dim, densities), O3D_OK);
    assert_int_equal(o3d_feature_num(&num, densities), O3D_OK);
    assert_int_equal(dim, 1);
    assert_int_equal(num, nv);
    const double* d = NULL;
    size_t rows = 0;
    assert_int_equal(o3d_feature_array_view(&d, &rows, densities, O3D_FEATURE_DATA), O3D_OK);
    for (size_t i = 0; i < rows; ++i) assert_true(isfinite(d[i]));
    /* The usual trim: drop the vertices with the lowest densities; their triangles go with them. */
    double lowest = d[0], highest = d[0];
    for (size_t i = 0; i < rows; ++i) {
        lowest = fmin(lowest, d[i]);
        highest = fmax(highest, d[i]);
    }
    uint8_t* mask = calloc(nv, 1);
    size_t dropped = 0;
    for (size_t i = 0; i < nv; ++i) dropped += mask[i] = d[i] < lowest + 0.5 * (highest - lowest);
    size_t nt = 0, nt_after = 0, nv_after = 0;
    assert_int_equal(o3d_trianglemesh_num_triangles(&nt, mesh), O3D_OK);
    O3D_ASSERT_FAILS(o3d_trianglemesh_remove_vertices_by_mask(mesh, mask, nv - 1), INV);
    assert_int_equal(o3d_trianglemesh_remove_vertices_by_mask(mesh, mask, nv), O3D_OK);
    assert_int_equal(o3d_trianglemesh_num_vertices(&nv_after, mesh), O3D_OK);
    assert_int_equal(nv_after, nv - dropped);
    assert_int_equal(o3d_trianglemesh_num_triangles(&nt_after, mesh), O3D_OK);
    assert_true(nt_after <= nt);
    free(mask);
    o3d_feature_destroy(densities);
    o3d_trianglemesh_destroy(mesh);

    /* Cancelled: no handles handed out. */
    opts.progress = cancel_at_once;
    mesh = (o3d_trianglemesh_t*)1;
    densities = (o3d_feature_t*)1;
    O3D_ASSERT_FAILS(o3d_trianglemesh_create_from_point_cloud_poisson(&mesh, &densities, pc, &opts),
                     O3D_ERROR_CANCELLED);
    assert_null(mesh);
    assert_null(densities);
    o3d_pointcloud_destroy(pc);
}

static void test_poisson_bad_input(void** state) {
    (void)state;
    o3d_trianglemesh_t* mesh = NULL;
    o3d_feature_t* densities = NULL;
    o3d_pointcloud_t* pc = sphere_cloud(500, 1.0, 0);
    o3d_poisson_options_t opts;
    assert_int_equal(o3d_poisson_options_init(&opts, sizeof opts), O3D_OK);
    opts.depth = 0;
    O3D_ASSERT_FAILS(o3d_trianglemesh_create_from_point_cloud_poisson(&mesh, &densities, pc, &opts), INV);
    opts.depth = 20;
    O3D_ASSERT_FAILS(o3d_trianglemesh_create_from_point_cloud_poisson(&mesh, &densities, pc, &opts), INV);
    opts.depth = 5;
    opts.scale = NAN;
    O3D_ASSERT_FAILS(o3d_trianglemesh_create_from_point_cloud_poisson(&mesh, &densities, pc, &opts), INV);
    O3D_ASSERT_FAILS(o3d_trianglemesh_create_from_point_cloud_poisson(NULL, &densities, pc, NULL), INV);
    O3D_ASSERT_FAILS(o3d_trianglemesh_create_from_point_cloud_poisson(&mesh, NULL, pc, NULL), INV);
    O3D_ASSERT_FAILS(o3d_trianglemesh_create_from_point_cloud_poisson(&mesh, &densities, NULL, NULL), INV);
    opts.struct_size = 3;
    opts.scale = 1.1;
    O3D_ASSERT_FAILS(o3d_trianglemesh_create_from_point_cloud_poisson(&mesh, &densities, pc, &opts), INV);
    /* Without normals; empty; a NaN point. */
    o3d_pointcloud_t* bare = NULL;
    assert_int_equal(o3d_pointcloud_create(&bare), O3D_OK);
    O3D_ASSERT_FAILS(o3d_trianglemesh_create_from_point_cloud_poisson(&mesh, &densities, bare, NULL), INV);
    const double xyz[6] = {0, 0, 0, 1, 0, 0};
    assert_int_equal(o3d_pointcloud_set_array(bare, O3D_POINTCLOUD_POINTS, xyz, 2), O3D_OK);
    O3D_ASSERT_FAILS(o3d_trianglemesh_create_from_point_cloud_poisson(&mesh, &densities, bare, NULL), INV);
    double* p = NULL;
    size_t n = 0;
    assert_int_equal(o3d_pointcloud_array_mutable_view(&p, &n, pc, O3D_POINTCLOUD_POINTS), O3D_OK);
    p[4] = NAN;
    O3D_ASSERT_FAILS(o3d_trianglemesh_create_from_point_cloud_poisson(&mesh, &densities, pc, NULL), INV);
    assert_null(mesh);
    assert_null(densities);
    o3d_pointcloud_destroy(bare);
    o3d_pointcloud_destroy(pc);
}

static void test_ball_pivoting_sphere(void** state) {
    (void)state;
    /* 4000 evenly spread points on the unit sphere: spacing about sqrt(4 pi / 4000) = 0.056. */
    o3d_pointcloud_t* pc = sphere_cloud(4000, 1.0, 0);
    const double radii[2] = {0.06, 0.09};
    o3d_progress_options_t opts;
    assert_int_equal(o3d_progress_options_init(&opts, sizeof opts), O3D_OK);
    int calls = 0;
    opts.progress = count_calls;
    opts.user_data = &calls;
    o3d_trianglemesh_t* mesh = NULL;
    assert_int_equal(o3d_trianglemesh_create_from_point_cloud_ball_pivoting(&mesh, pc, radii, 2, &opts), O3D_OK);
    assert_true(calls > 0);
    size_t nv = 0, nt = 0;
    assert_int_equal(o3d_trianglemesh_num_vertices(&nv, mesh), O3D_OK);
    assert_int_equal(nv, 4000); /* the vertices are the points */
    assert_int_equal(o3d_trianglemesh_num_triangles(&nt, mesh), O3D_OK);
    assert_true(nt > 7600); /* a closed triangulation of 4000 points has 7996 triangles */
    double area = 0.0;
    assert_int_equal(o3d_trianglemesh_get_surface_area(&area, mesh), O3D_OK);
    assert_true(fabs(area - 4.0 * M_PI) < 0.03 * 4.0 * M_PI);
    o3d_trianglemesh_destroy(mesh);

    opts.progress = cancel_at_once;
    O3D_ASSERT_FAILS(o3d_trianglemesh_create_from_point_cloud_ball_pivoting(&mesh, pc, radii, 2, &opts),
                     O3D_ERROR_CANCELLED);
    assert_null(mesh);
    const double negative[1] = {-0.1};
    O3D_ASSERT_FAILS(o3d_trianglemesh_create_from_point_cloud_ball_pivoting(&mesh, pc, negative, 1, NULL), INV);
    O3D_ASSERT_FAILS(o3d_trianglemesh_create_from_point_cloud_ball_pivoting(&mesh, pc, radii, 0, NULL), INV);
    O3D_ASSERT_FAILS(o3d_trianglemesh_create_from_point_cloud_ball_pivoting(&mesh, pc, NULL, 2, NULL), INV);
    O3D_ASSERT_FAILS(o3d_trianglemesh_create_from_point_cloud_ball_pivoting(&mesh, NULL, radii, 2, NULL), INV);
    o3d_pointcloud_destroy(pc);
}

/* The unit cube's corners, and interior points: its alpha shape at a large alpha is the hull (12 triangles). */
static o3d_pointcloud_t* cube_cloud(void) {
    double xyz[3 * 12];
    for (int i = 0; i < 8; ++i) {
        xyz[3 * i + 0] = i & 1;
        xyz[3 * i + 1] = (i >> 1) & 1;
        xyz[3 * i + 2] = (i >> 2) & 1;
    }
    const double inner[12] = {0.5, 0.5, 0.5, 0.3, 0.6, 0.4, 0.7, 0.2, 0.6, 0.4, 0.3, 0.7};
    memcpy(xyz + 24, inner, sizeof inner);
    o3d_pointcloud_t* pc = NULL;
    assert_int_equal(o3d_pointcloud_create(&pc), O3D_OK);
    assert_int_equal(o3d_pointcloud_set_array(pc, O3D_POINTCLOUD_POINTS, xyz, 12), O3D_OK);
    return pc;
}

static void test_tetramesh_and_alpha_shape(void** state) {
    (void)state;
    o3d_pointcloud_t* pc = cube_cloud();
    o3d_tetramesh_t* tm = NULL;
    int32_t map[12];
    size_t n_map = 0, nv = 0, nt = 0;
    assert_int_equal(o3d_tetramesh_create_from_point_cloud(&tm, map, 12, &n_map, pc), O3D_OK);
    assert_int_equal(o3d_tetramesh_num_vertices(&nv, tm), O3D_OK);
    assert_int_equal(nv, n_map);
    assert_int_equal(n_map, 12);
    assert_int_equal(o3d_tetramesh_num_tetras(&nt, tm), O3D_OK);
    assert_true(nt >= 5);
    /* The tetrahedra tile the cube: their volumes sum to 1. */
    const double* v = NULL;
    const int32_t* t = NULL;
    size_t rows = 0;
    assert_int_equal(o3d_tetramesh_array_view(&v, &rows, tm, O3D_TETRAMESH_VERTICES), O3D_OK);
    assert_int_equal(rows, nv);
    assert_int_equal(o3d_tetramesh_index_array_view(&t, &rows, tm, O3D_TETRAMESH_TETRAS), O3D_OK);
    assert_int_equal(rows, nt);
    double total = 0.0;
    for (size_t i = 0; i < nt; ++i) {
        const double* a = v + 3 * t[4 * i];
        double e[3][3];
        for (int k = 1; k < 4; ++k)
            for (int c = 0; c < 3; ++c) e[k - 1][c] = v[3 * t[4 * i + k] + c] - a[c];
        const double det = e[0][0] * (e[1][1] * e[2][2] - e[1][2] * e[2][1]) -
                           e[0][1] * (e[1][0] * e[2][2] - e[1][2] * e[2][0]) +
                           e[0][2] * (e[1][0] * e[2][1] - e[1][1] * e[2][0]);
        total += fabs(det) / 6.0;
    }
    assert_true(fabs(total - 1.0) < 1e-9);

    /* A linear field x - 0.25 cuts the cube in the plane x = 0.25. */
    double* values = malloc(nv * sizeof(double));
    for (size_t i = 0; i < nv; ++i) values[i] = v[3 * i] - 0.25;
    o3d_trianglemesh_t* cut = NULL;
    assert_int_equal(o3d_tetramesh_extract_triangle_mesh(&cut, tm, values, nv, 0.0), O3D_OK);
    const double* cv = NULL;
    size_t ncv = 0;
    assert_int_equal(o3d_trianglemesh_array_view(&cv, &ncv, cut, O3D_MESH_VERTICES), O3D_OK);
    assert_true(ncv >= 3);
    for (size_t i = 0; i < ncv; ++i) assert_true(fabs(cv[3 * i] - 0.25) < 1e-12);
    double area = 0.0;
    assert_int_equal(o3d_trianglemesh_get_surface_area(&area, cut), O3D_OK);
    assert_true(fabs(area - 1.0) < 1e-9);
    o3d_trianglemesh_destroy(cut);
    O3D_ASSERT_FAILS(o3d_tetramesh_extract_triangle_mesh(&cut, tm, values, nv - 1, 0.0), INV);
    free(values);

    /* Alpha shape at a large alpha: the hull, from scratch or from the tetra mesh. */
    o3d_trianglemesh_t* shape = NULL;
    assert_int_equal(o3d_trianglemesh_create_from_point_cloud_alpha_shape(&shape, pc, 100.0, NULL, NULL, 0, NULL), O3D_OK);
    assert_int_equal(o3d_trianglemesh_num_triangles(&nt, shape), O3D_OK);
    assert_int_equal(nt, 12);
    double volume = 0.0;
    assert_int_equal(o3d_trianglemesh_get_volume(&volume, shape), O3D_OK);
    assert_true(fabs(volume - 1.0) < 1e-9);
    o3d_trianglemesh_destroy(shape);
    assert_int_equal(o3d_trianglemesh_create_from_point_cloud_alpha_shape(&shape, pc, 100.0, tm, map, n_map, NULL), O3D_OK);
    assert_int_equal(o3d_trianglemesh_num_triangles(&nt, shape), O3D_OK);
    assert_int_equal(nt, 12);
    /* Removing triangles opens the hull and keeps every vertex. */
    const int32_t two[2] = {0, 5};
    const uint8_t first_only[10] = {1, 0, 0, 0, 0, 0, 0, 0, 0, 0};
    size_t nv_shape = 0;
    assert_int_equal(o3d_trianglemesh_num_vertices(&nv_shape, shape), O3D_OK);
    assert_int_equal(o3d_trianglemesh_remove_triangles_by_index(shape, two, 2), O3D_OK);
    assert_int_equal(o3d_trianglemesh_remove_triangles_by_mask(shape, first_only, 10), O3D_OK);
    assert_int_equal(o3d_trianglemesh_num_triangles(&nt, shape), O3D_OK);
    assert_int_equal(nt, 9);
    assert_int_equal(o3d_trianglemesh_num_vertices(&nv, shape), O3D_OK);
    assert_int_equal(nv, nv_shape);
    const int32_t far_index[1] = {9};
    O3D_ASSERT_FAILS(o3d_trianglemesh_remove_triangles_by_index(shape, far_index, 1), INV);
    const int32_t corner[1] = {0};
    assert_int_equal(o3d_trianglemesh_remove_vertices_by_index(shape, corner, 1), O3D_OK);
    assert_int_equal(o3d_trianglemesh_num_vertices(&nv, shape), O3D_OK);
    assert_int_equal(nv, nv_shape - 1);
    o3d_trianglemesh_destroy(shape);
    /* A tiny alpha keeps no tetrahedron. */
    assert_int_equal(o3d_trianglemesh_create_from_point_cloud_alpha_shape(&shape, pc, 0.01, NULL, NULL, 0, NULL), O3D_OK);
    assert_int_equal(o3d_trianglemesh_num_triangles(&nt, shape), O3D_OK);
    assert_int_equal(nt, 0);
    o3d_trianglemesh_destroy(shape);

    /* Bad input: alpha, a point map that does not fit, cancel. */
    O3D_ASSERT_FAILS(o3d_trianglemesh_create_from_point_cloud_alpha_shape(&shape, pc, -1.0, NULL, NULL, 0, NULL), INV);
    O3D_ASSERT_FAILS(o3d_trianglemesh_create_from_point_cloud_alpha_shape(&shape, pc, NAN, NULL, NULL, 0, NULL), INV);
    O3D_ASSERT_FAILS(o3d_trianglemesh_create_from_point_cloud_alpha_shape(&shape, pc, 1.0, tm, map, n_map - 1, NULL), INV);
    map[0] = 99;
    O3D_ASSERT_FAILS(o3d_trianglemesh_create_from_point_cloud_alpha_shape(&shape, pc, 1.0, tm, map, n_map, NULL), INV);
    o3d_progress_options_t opts;
    assert_int_equal(o3d_progress_options_init(&opts, sizeof opts), O3D_OK);
    opts.progress = cancel_at_once;
    O3D_ASSERT_FAILS(o3d_trianglemesh_create_from_point_cloud_alpha_shape(&shape, pc, 1.0, NULL, NULL, 0, &opts),
                     O3D_ERROR_CANCELLED);
    assert_null(shape);

    /* A short point-map buffer: BUFFER_TOO_SMALL with the count, and no handle. */
    o3d_tetramesh_t* tm2 = (o3d_tetramesh_t*)1;
    O3D_ASSERT_FAILS(o3d_tetramesh_create_from_point_cloud(&tm2, map, 4, &n_map, pc), O3D_ERROR_BUFFER_TOO_SMALL);
    assert_null(tm2);
    assert_int_equal(n_map, 12);
    o3d_tetramesh_destroy(tm);
    o3d_pointcloud_destroy(pc);
}

static void test_tetramesh_bad_input(void** state) {
    (void)state;
    o3d_tetramesh_t* tm = NULL;
    size_t n = 0;
    /* Coplanar points: a clear error, never an abort inside Qhull. */
    const double flat[15] = {0, 0, 0, 1, 0, 0, 0, 1, 0, 1, 1, 0, 0.5, 0.5, 0};
    o3d_pointcloud_t* pc = NULL;
    assert_int_equal(o3d_pointcloud_create(&pc), O3D_OK);
    assert_int_equal(o3d_pointcloud_set_array(pc, O3D_POINTCLOUD_POINTS, flat, 5), O3D_OK);
    O3D_ASSERT_FAILS(o3d_tetramesh_create_from_point_cloud(&tm, NULL, 0, &n, pc), INV);
    o3d_trianglemesh_t* shape = NULL;
    O3D_ASSERT_FAILS(o3d_trianglemesh_create_from_point_cloud_alpha_shape(&shape, pc, 1.0, NULL, NULL, 0, NULL), INV);
    /* Three points. */
    assert_int_equal(o3d_pointcloud_set_array(pc, O3D_POINTCLOUD_POINTS, flat, 3), O3D_OK);
    O3D_ASSERT_FAILS(o3d_tetramesh_create_from_point_cloud(&tm, NULL, 0, &n, pc), INV);
    assert_null(tm);
    O3D_ASSERT_FAILS(o3d_tetramesh_create_from_point_cloud(&tm, NULL, 0, &n, NULL), INV);
    O3D_ASSERT_FAILS(o3d_tetramesh_create_from_point_cloud(NULL, NULL, 0, &n, pc), INV);
    o3d_pointcloud_destroy(pc);

    /* A tetra index out of range is caught before it is followed. */
    assert_int_equal(o3d_tetramesh_create(&tm), O3D_OK);
    const double v[12] = {0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1};
    const int32_t t[4] = {0, 1, 2, 7};
    assert_int_equal(o3d_tetramesh_set_array(tm, O3D_TETRAMESH_VERTICES, v, 4), O3D_OK);
    assert_int_equal(o3d_tetramesh_set_index_array(tm, O3D_TETRAMESH_TETRAS, t, 1), O3D_OK);
    const double values[4] = {0, 1, 1, 1};
    o3d_trianglemesh_t* cut = NULL;
    O3D_ASSERT_FAILS(o3d_tetramesh_extract_triangle_mesh(&cut, tm, values, 4, 0.5), INV);
    o3d_tetramesh_t* copy = NULL;
    assert_int_equal(o3d_tetramesh_clone(&copy, tm), O3D_OK);
    assert_int_equal(o3d_tetramesh_num_vertices(&n, copy), O3D_OK);
    assert_int_equal(n, 4);
    o3d_tetramesh_destroy(copy);
    o3d_tetramesh_destroy(tm);
    o3d_tetramesh_destroy(NULL);
}

static void test_orient_normals_consistent(void** state) {
    (void)state;
    o3d_pointcloud_t* pc = sphere_cloud(2000, 1.0, 1);
    assert_int_equal(o3d_pointcloud_orient_normals_consistent_tangent_plane(pc, 10, 0.0, 1.0), O3D_OK);
    const double* p = NULL;
    const double* nrm = NULL;
    size_t n = 0;
    assert_int_equal(o3d_pointcloud_array_view(&p, &n, pc, O3D_POINTCLOUD_POINTS), O3D_OK);
    assert_int_equal(o3d_pointcloud_array_view(&nrm, &n, pc, O3D_POINTCLOUD_NORMALS), O3D_OK);
    /* Every normal agrees with the first one's side: all outward or all inward. */
    int outward = 0;
    for (size_t i = 0; i < n; ++i)
        outward += p[3 * i] * nrm[3 * i] + p[3 * i + 1] * nrm[3 * i + 1] + p[3 * i + 2] * nrm[3 * i + 2] > 0.0;
    assert_true(outward == 0 || outward == (int)n);
    O3D_ASSERT_FAILS(o3d_pointcloud_orient_normals_consistent_tangent_plane(pc, 0, 0.0, 1.0), INV);
    O3D_ASSERT_FAILS(o3d_pointcloud_orient_normals_consistent_tangent_plane(pc, 10, NAN, 1.0), INV);
    O3D_ASSERT_FAILS(o3d_pointcloud_orient_normals_consistent_tangent_plane(NULL, 10, 0.0, 1.0), INV);
    o3d_pointcloud_t* bare = NULL;
    assert_int_equal(o3d_pointcloud_create(&bare), O3D_OK);
    assert_int_equal(o3d_pointcloud_set_array(bare, O3D_POINTCLOUD_POINTS, p, 10), O3D_OK);
    O3D_ASSERT_FAILS(o3d_pointcloud_orient_normals_consistent_tangent_plane(bare, 5, 0.0, 1.0), INV);
    o3d_pointcloud_destroy(bare);
    o3d_pointcloud_destroy(pc);
}

static void test_remove_duplicated_points(void** state) {
    (void)state;
    const double xyz[15] = {0, 0, 0, 1, 2, 3, 0, 0, 0, 4, 5, 6, 1, 2, 3};
    const double rgb[15] = {0.1, 0.1, 0.1, 0.2, 0.2, 0.2, 0.3, 0.3, 0.3, 0.4, 0.4, 0.4, 0.5, 0.5, 0.5};
    o3d_pointcloud_t* pc = NULL;
    assert_int_equal(o3d_pointcloud_create(&pc), O3D_OK);
    assert_int_equal(o3d_pointcloud_set_array(pc, O3D_POINTCLOUD_POINTS, xyz, 5), O3D_OK);
    assert_int_equal(o3d_pointcloud_set_array(pc, O3D_POINTCLOUD_COLORS, rgb, 5), O3D_OK);
    assert_int_equal(o3d_pointcloud_remove_duplicated_points(pc), O3D_OK);
    double out[9], col[9];
    size_t n = 0;
    assert_int_equal(o3d_pointcloud_get_array(out, 3, &n, pc, O3D_POINTCLOUD_POINTS), O3D_OK);
    assert_int_equal(n, 3);
    const double want[9] = {0, 0, 0, 1, 2, 3, 4, 5, 6};
    for (int i = 0; i < 9; ++i) assert_true(out[i] == want[i]);
    assert_int_equal(o3d_pointcloud_get_array(col, 3, &n, pc, O3D_POINTCLOUD_COLORS), O3D_OK);
    assert_true(col[0] == 0.1 && col[3] == 0.2 && col[6] == 0.4); /* the first of each kept */
    O3D_ASSERT_FAILS(o3d_pointcloud_remove_duplicated_points(NULL), INV);
    o3d_pointcloud_destroy(pc);
}

/* A box sampled on its faces (a degenerate, highly symmetric input: Open3D 0.20 finds 45 keypoints on it, some
 * mid-face). Checked here: the keypoints are points of the cloud at ascending indices, the eigenvalue-ratio
 * tests do filter (ratios below 1e-6 keep none), and the copy-out conventions. */
static void test_iss_keypoints_of_box(void** state) {
    (void)state;
    const int m = 21; /* samples per edge on each face */
    const size_t max_points = 6 * (size_t)m * m;
    double* xyz = malloc(3 * max_points * sizeof(double));
    size_t n = 0;
    for (int axis = 0; axis < 3; ++axis)
        for (int side = 0; side < 2; ++side)
            for (int i = 0; i < m; ++i)
                for (int j = 0; j < m; ++j) {
                    double q[3];
                    q[axis] = side;
                    q[(axis + 1) % 3] = (double)i / (m - 1);
                    q[(axis + 2) % 3] = (double)j / (m - 1);
                    memcpy(xyz + 3 * n++, q, sizeof q);
                }
    o3d_pointcloud_t* pc = NULL;
    assert_int_equal(o3d_pointcloud_create(&pc), O3D_OK);
    assert_int_equal(o3d_pointcloud_set_array(pc, O3D_POINTCLOUD_POINTS, xyz, n), O3D_OK);
    assert_int_equal(o3d_pointcloud_remove_duplicated_points(pc), O3D_OK); /* the edges were sampled twice */
    size_t size = 0;
    assert_int_equal(o3d_pointcloud_size(&size, pc), O3D_OK);
    assert_int_equal(size, 6 * 21 * 21 - 12 * 21 + 8); /* 2402, as Open3D's remove_duplicated_points leaves it */
    o3d_iss_options_t opts;
    assert_int_equal(o3d_iss_options_init(&opts, sizeof opts), O3D_OK);
    assert_true(opts.gamma_21 == 0.975 && opts.gamma_32 == 0.975 && opts.min_neighbors == 5);
    opts.salient_radius = 0.15;
    opts.non_max_radius = 0.15;
    o3d_pointcloud_t* keys = NULL;
    int32_t* idx = malloc(size * sizeof(int32_t));
    size_t nk = 0;
    assert_int_equal(o3d_pointcloud_compute_iss_keypoints(&keys, idx, size, &nk, pc, &opts), O3D_OK);
    assert_true(nk > 0 && nk < size / 10);
    const double* kp = NULL;
    const double* all = NULL;
    size_t rows = 0;
    assert_int_equal(o3d_pointcloud_array_view(&kp, &rows, keys, O3D_POINTCLOUD_POINTS), O3D_OK);
    assert_int_equal(rows, nk);
    assert_int_equal(o3d_pointcloud_array_view(&all, &rows, pc, O3D_POINTCLOUD_POINTS), O3D_OK);
    for (size_t i = 0; i < nk; ++i) {
        assert_true(idx[i] >= 0 && (size_t)idx[i] < size);
        if (i > 0) assert_true(idx[i] > idx[i - 1]);
        assert_memory_equal(kp + 3 * i, all + 3 * (size_t)idx[i], 3 * sizeof(double));
    }
    o3d_pointcloud_destroy(keys);
    /* Short buffer: the count, no cloud. */
    keys = (o3d_pointcloud_t*)1;
    O3D_ASSERT_FAILS(o3d_pointcloud_compute_iss_keypoints(&keys, idx, nk - 1, &nk, pc, &opts),
                     O3D_ERROR_BUFFER_TOO_SMALL);
    assert_null(keys);
    /* No point has eigenvalue ratios below 1e-6. */
    opts.gamma_21 = opts.gamma_32 = 1e-6;
    assert_int_equal(o3d_pointcloud_compute_iss_keypoints(&keys, NULL, 0, &nk, pc, &opts), O3D_OK);
    assert_int_equal(nk, 0);
    o3d_pointcloud_destroy(keys);
    opts.gamma_21 = opts.gamma_32 = 0.975;
    opts.salient_radius = -1.0;
    O3D_ASSERT_FAILS(o3d_pointcloud_compute_iss_keypoints(&keys, NULL, 0, &nk, pc, &opts), INV);
    O3D_ASSERT_FAILS(o3d_pointcloud_compute_iss_keypoints(&keys, NULL, 0, &nk, NULL, NULL), INV);
    free(idx);
    free(xyz);
    o3d_pointcloud_destroy(pc);
}

int main(void) {
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_poisson_sphere),          cmocka_unit_test(test_poisson_bad_input),
        cmocka_unit_test(test_ball_pivoting_sphere),    cmocka_unit_test(test_tetramesh_and_alpha_shape),
        cmocka_unit_test(test_tetramesh_bad_input),     cmocka_unit_test(test_orient_normals_consistent),
        cmocka_unit_test(test_remove_duplicated_points), cmocka_unit_test(test_iss_keypoints_of_box),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
