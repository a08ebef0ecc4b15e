/* SPDX-License-Identifier: MIT */
/* C API boundingbox.h, hull.h and the per-point covariances of pointcloud.h: analytic results through the ABI,
 * Open3D 0.20 reference numbers (tools/reference/record_hull_obb.py), copy-out buffers, NULL / bad input. */
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

/* The unit cube's 8 corners at indices 3..10, among interior points. */
static o3d_pointcloud_t* cube_cloud(void) {
    double xyz[3 * 14] = {0.5, 0.5, 0.5, 0.2, 0.3, 0.4, 0.9, 0.1, 0.5};
    for (int i = 0; i < 8; ++i) {
        xyz[3 * (3 + i) + 0] = i & 1;
        xyz[3 * (3 + i) + 1] = (i >> 1) & 1;
        xyz[3 * (3 + i) + 2] = (i >> 2) & 1;
    }
    const double tail[9] = {0.7, 0.7, 0.2, 0.1, 0.8, 0.9, 0.4, 0.6, 0.1};
    memcpy(xyz + 33, tail, sizeof tail);
    o3d_pointcloud_t* pc = NULL;
    assert_int_equal(o3d_pointcloud_create(&pc), O3D_OK);
    assert_int_equal(o3d_pointcloud_set_array(pc, O3D_POINTCLOUD_POINTS, xyz, 14), O3D_OK);
    return pc;
}

static void test_convex_hull_of_cube(void** state) {
    (void)state;
    o3d_pointcloud_t* pc = cube_cloud();
    o3d_trianglemesh_t* hull = NULL;
    int32_t idx[14];
    size_t n = 0, nv = 0, nt = 0;
    assert_int_equal(o3d_pointcloud_compute_convex_hull(&hull, idx, 14, &n, pc, 0), O3D_OK);
    assert_int_equal(n, 8);
    assert_int_equal(o3d_trianglemesh_num_vertices(&nv, hull), O3D_OK);
    assert_int_equal(nv, 8);
    assert_int_equal(o3d_trianglemesh_num_triangles(&nt, hull), O3D_OK);
    assert_int_equal(nt, 12);
    int seen = 0;
    for (size_t i = 0; i < n; ++i) {
        assert_true(idx[i] >= 3 && idx[i] <= 10);
        seen |= 1 << (idx[i] - 3);
    }
    assert_int_equal(seen, 0xff);
    double volume = 0.0, area = 0.0;
    assert_int_equal(o3d_trianglemesh_get_volume(&volume, hull), O3D_OK);
    assert_true(fabs(volume - 1.0) < 1e-12);
    assert_int_equal(o3d_trianglemesh_get_surface_area(&area, hull), O3D_OK);
    assert_true(fabs(area - 6.0) < 1e-12);
    o3d_trianglemesh_destroy(hull);

    /* Indices optional; a small buffer fails and leaves no mesh. */
    hull = NULL;
    assert_int_equal(o3d_pointcloud_compute_convex_hull(&hull, NULL, 0, NULL, pc, 1), O3D_OK);
    assert_non_null(hull);
    o3d_trianglemesh_destroy(hull);
    hull = (o3d_trianglemesh_t*)1;
    O3D_ASSERT_FAILS(o3d_pointcloud_compute_convex_hull(&hull, idx, 2, &n, pc, 0), O3D_ERROR_BUFFER_TOO_SMALL);
    assert_null(hull);
    assert_int_equal(n, 8);

    /* The same through a mesh's vertices. */
    o3d_trianglemesh_t* m = NULL;
    o3d_pointcloud_compute_convex_hull(&m, NULL, 0, NULL, pc, 0);
    assert_int_equal(o3d_trianglemesh_compute_convex_hull(&hull, idx, 14, &n, m, 0), O3D_OK);
    assert_int_equal(n, 8);
    o3d_trianglemesh_destroy(hull);
    o3d_trianglemesh_destroy(m);
    o3d_pointcloud_destroy(pc);
}

static void test_hull_errors(void** state) {
    (void)state;
    o3d_pointcloud_t* pc = NULL;
    o3d_trianglemesh_t* hull = NULL;
    size_t n = 0;
    assert_int_equal(o3d_pointcloud_create(&pc), O3D_OK);
    const double tri[9] = {0, 0, 0, 1, 0, 0, 0, 1, 0};
    assert_int_equal(o3d_pointcloud_set_array(pc, O3D_POINTCLOUD_POINTS, tri, 3), O3D_OK);
    O3D_ASSERT_FAILS(o3d_pointcloud_compute_convex_hull(&hull, NULL, 0, &n, pc, 0), INV); /* < 4 points */
    const double square[15] = {0, 0, 0, 1, 0, 0, 0, 1, 0, 1, 1, 0, 0.5, 0.5, 0};
    assert_int_equal(o3d_pointcloud_set_array(pc, O3D_POINTCLOUD_POINTS, square, 5), O3D_OK);
    O3D_ASSERT_FAILS(o3d_pointcloud_compute_convex_hull(&hull, NULL, 0, &n, pc, 0), INV); /* coplanar */
    assert_int_equal(o3d_pointcloud_compute_convex_hull(&hull, NULL, 0, &n, pc, 1), O3D_OK);
    o3d_trianglemesh_destroy(hull);
    const double with_nan[12] = {0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, NAN};
    assert_int_equal(o3d_pointcloud_set_array(pc, O3D_POINTCLOUD_POINTS, with_nan, 4), O3D_OK);
    O3D_ASSERT_FAILS(o3d_pointcloud_compute_convex_hull(&hull, NULL, 0, &n, pc, 1), INV);
    O3D_ASSERT_FAILS(o3d_pointcloud_compute_convex_hull(NULL, NULL, 0, &n, pc, 0), INV);
    O3D_ASSERT_FAILS(o3d_pointcloud_compute_convex_hull(&hull, NULL, 0, &n, NULL, 0), INV);
    O3D_ASSERT_FAILS(o3d_trianglemesh_compute_convex_hull(&hull, NULL, 0, &n, NULL, 0), INV);
    const double cam[3] = {0, 0, 5};
    O3D_ASSERT_FAILS(o3d_pointcloud_hidden_point_removal(&hull, NULL, 0, &n, pc, NULL, 1.0), INV);
    O3D_ASSERT_FAILS(o3d_pointcloud_hidden_point_removal(&hull, NULL, 0, &n, NULL, cam, 1.0), INV);
    o3d_pointcloud_destroy(pc);
    pc = cube_cloud();
    O3D_ASSERT_FAILS(o3d_pointcloud_hidden_point_removal(&hull, NULL, 0, &n, pc, cam, 0.0), INV);
    O3D_ASSERT_FAILS(o3d_pointcloud_hidden_point_removal(&hull, NULL, 0, &n, pc, cam, -2.0), INV);
    O3D_ASSERT_FAILS(o3d_pointcloud_hidden_point_removal(&hull, NULL, 0, &n, pc, cam, NAN), INV);
    o3d_pointcloud_destroy(pc);
}

static void test_hidden_point_removal_of_sphere(void** state) {
    (void)state;
    enum { N = 2000 };
    double* xyz = malloc(sizeof(double) * 3 * N);
    /* Fibonacci sphere: evenly spread unit points. */
    for (int i = 0; i < N; ++i) {
        const double z = 1.0 - (2.0 * i + 1.0) / N, r = sqrt(1.0 - z * z), phi = i * 2.399963229728653;
        xyz[3 * i] = r * cos(phi);
        xyz[3 * i + 1] = r * sin(phi);
        xyz[3 * i + 2] = z;
    }
    o3d_pointcloud_t* pc = NULL;
    assert_int_equal(o3d_pointcloud_create(&pc), O3D_OK);
    assert_int_equal(o3d_pointcloud_set_array(pc, O3D_POINTCLOUD_POINTS, xyz, N), O3D_OK);
    const double cam[3] = {0, 0, 100};
    o3d_trianglemesh_t* visible = NULL;
    int32_t* idx = malloc(sizeof(int32_t) * N);
    size_t n = 0;
    assert_int_equal(o3d_pointcloud_hidden_point_removal(&visible, idx, N, &n, pc, cam, 1e5), O3D_OK);
    assert_true(n > 0.45 * N && n < 0.56 * N);
    for (size_t i = 0; i < n; ++i) assert_true(xyz[3 * idx[i] + 2] > -0.1); /* none from the far side */
    o3d_trianglemesh_destroy(visible);
    free(idx);
    free(xyz);
    o3d_pointcloud_destroy(pc);
}

static void test_obb_of_rotated_box(void** state) {
    (void)state;
    /* A 4 x 2 x 1 box rotated 30 degrees about z, centred at (1, 2, 3): corners plus the centre. */
    const double c = cos(M_PI / 6), s = sin(M_PI / 6);
    double xyz[27];
    for (int i = 0; i < 8; ++i) {
        const double x = ((i & 1) - 0.5) * 4, y = (((i >> 1) & 1) - 0.5) * 2, z = (((i >> 2) & 1) - 0.5);
        xyz[3 * i] = c * x - s * y + 1;
        xyz[3 * i + 1] = s * x + c * y + 2;
        xyz[3 * i + 2] = z + 3;
    }
    xyz[24] = 1, xyz[25] = 2, xyz[26] = 3;
    o3d_obb_t box;
    assert_int_equal(o3d_obb_create_from_points(&box, xyz, 9, 0), O3D_OK);
    assert_true(fabs(box.extent[0] - 4) < 1e-9 && fabs(box.extent[1] - 2) < 1e-9 && fabs(box.extent[2] - 1) < 1e-9);
    assert_true(fabs(box.center[0] - 1) < 1e-9 && fabs(box.center[1] - 2) < 1e-9 && fabs(box.center[2] - 3) < 1e-9);
    assert_true(fabs(fabs(box.R[0]) - c) < 1e-9 && fabs(fabs(box.R[3]) - s) < 1e-9); /* column 0 = rotated x */
    double corners[24];
    assert_int_equal(o3d_obb_get_box_points(corners, &box), O3D_OK);
    for (int i = 0; i < 8; ++i) { /* each corner is one of the input corners */
        int found = 0;
        for (int j = 0; j < 8; ++j)
            found |= fabs(corners[3 * i] - xyz[3 * j]) < 1e-9 && fabs(corners[3 * i + 1] - xyz[3 * j + 1]) < 1e-9 &&
                     fabs(corners[3 * i + 2] - xyz[3 * j + 2]) < 1e-9;
        assert_true(found);
    }
    int32_t inside[9];
    size_t n = 0;
    assert_int_equal(o3d_obb_get_point_indices_within(inside, 9, &n, &box, xyz, 9), O3D_OK);
    assert_int_equal(n, 9);
    const double outside[3] = {1, 2, 4};
    assert_int_equal(o3d_obb_get_point_indices_within(inside, 9, &n, &box, outside, 1), O3D_OK);
    assert_int_equal(n, 0);

    /* Crop: the centre point and its neighbours, or the rest when inverted. */
    o3d_pointcloud_t* pc = NULL;
    assert_int_equal(o3d_pointcloud_create(&pc), O3D_OK);
    const double pts[9] = {1, 2, 3, 1, 2, 3.4, 1, 2, 3.6};
    assert_int_equal(o3d_pointcloud_set_array(pc, O3D_POINTCLOUD_POINTS, pts, 3), O3D_OK);
    o3d_pointcloud_t* cropped = NULL;
    assert_int_equal(o3d_pointcloud_crop_obb(&cropped, pc, &box, 0), O3D_OK);
    assert_int_equal(o3d_pointcloud_size(&n, cropped), O3D_OK);
    assert_int_equal(n, 2);
    o3d_pointcloud_destroy(cropped);
    assert_int_equal(o3d_pointcloud_crop_obb(&cropped, pc, &box, 1), O3D_OK);
    assert_int_equal(o3d_pointcloud_size(&n, cropped), O3D_OK);
    assert_int_equal(n, 1);
    o3d_pointcloud_destroy(cropped);

    /* Box of a cloud and of a mesh's vertices agree with the box of the raw points. */
    assert_int_equal(o3d_pointcloud_set_array(pc, O3D_POINTCLOUD_POINTS, xyz, 9), O3D_OK);
    o3d_obb_t again;
    assert_int_equal(o3d_pointcloud_get_oriented_bounding_box(&again, pc, 0), O3D_OK);
    assert_memory_equal(&again, &box, sizeof box);
    o3d_trianglemesh_t* hull = NULL;
    assert_int_equal(o3d_pointcloud_compute_convex_hull(&hull, NULL, 0, NULL, pc, 0), O3D_OK);
    assert_int_equal(o3d_trianglemesh_get_oriented_bounding_box(&again, hull, 0), O3D_OK);
    assert_true(fabs(again.extent[0] * again.extent[1] * again.extent[2] - 8.0) < 1e-9);
    o3d_trianglemesh_t* mesh_cropped = NULL;
    assert_int_equal(o3d_trianglemesh_crop_obb(&mesh_cropped, hull, &box), O3D_OK);
    size_t nt = 0;
    assert_int_equal(o3d_trianglemesh_num_triangles(&nt, mesh_cropped), O3D_OK);
    assert_int_equal(nt, 12); /* the whole hull is inside its own box */
    o3d_trianglemesh_destroy(mesh_cropped);
    o3d_trianglemesh_destroy(hull);
    o3d_pointcloud_destroy(pc);
}

static void test_obb_from_aabb_and_errors(void** state) {
    (void)state;
    o3d_obb_t box;
    const double lo[3] = {-1, -2, -3}, hi[3] = {1, 2, 3};
    assert_int_equal(o3d_obb_create_from_axis_aligned_bounding_box(&box, lo, hi), O3D_OK);
    double corners[24];
    assert_int_equal(o3d_obb_get_box_points(corners, &box), O3D_OK);
    /* Open3D's order: ---, +--, -+-, --+, +++, -++, +-+, ++- */
    const double expected[24] = {-1, -2, -3, 1, -2, -3, -1, 2, -3, -1, -2, 3,
                                 1,  2,  3,  -1, 2, 3,  1,  -2, 3, 1,  2,  -3};
    for (int i = 0; i < 24; ++i) assert_true(corners[i] == expected[i]);
    O3D_ASSERT_FAILS(o3d_obb_create_from_axis_aligned_bounding_box(&box, hi, lo), INV);
    O3D_ASSERT_FAILS(o3d_obb_create_from_axis_aligned_bounding_box(NULL, lo, hi), INV);
    O3D_ASSERT_FAILS(o3d_obb_get_box_points(corners, NULL), INV);
    O3D_ASSERT_FAILS(o3d_obb_create_from_points(&box, NULL, 5, 0), INV);
    const double few[9] = {0, 0, 0, 1, 0, 0, 0, 1, 0};
    O3D_ASSERT_FAILS(o3d_obb_create_from_points(&box, few, 3, 1), INV);
    const double flat[15] = {0, 0, 0, 2, 0, 0, 0, 1, 0, 2, 1, 0, 1, 0.5, 0};
    O3D_ASSERT_FAILS(o3d_obb_create_from_points(&box, flat, 5, 0), INV);
    assert_int_equal(o3d_obb_create_from_points(&box, flat, 5, 1), O3D_OK);
    assert_true(fabs(box.extent[0] - 2) < 1e-6 && fabs(box.extent[2]) < 1e-6);

    /* A flat box cannot crop (Open3D: zero size); a bad rotation is rejected. */
    o3d_pointcloud_t* pc = NULL;
    o3d_pointcloud_t* out = (o3d_pointcloud_t*)1;
    assert_int_equal(o3d_pointcloud_create(&pc), O3D_OK);
    assert_int_equal(o3d_pointcloud_set_array(pc, O3D_POINTCLOUD_POINTS, few, 3), O3D_OK);
    O3D_ASSERT_FAILS(o3d_pointcloud_crop_obb(&out, pc, &box, 0), INV);
    assert_null(out);
    assert_int_equal(o3d_obb_create_from_axis_aligned_bounding_box(&box, lo, hi), O3D_OK);
    box.R[0] = 3.0;
    size_t n = 0;
    O3D_ASSERT_FAILS(o3d_obb_get_point_indices_within(NULL, 0, &n, &box, few, 3), INV);
    box.R[0] = NAN;
    O3D_ASSERT_FAILS(o3d_pointcloud_crop_obb(&out, pc, &box, 0), INV);
    O3D_ASSERT_FAILS(o3d_pointcloud_crop_obb(&out, pc, NULL, 0), INV);
    O3D_ASSERT_FAILS(o3d_pointcloud_get_oriented_bounding_box(&box, NULL, 0), INV);
    O3D_ASSERT_FAILS(o3d_trianglemesh_crop_obb(NULL, NULL, &box), INV);
    o3d_pointcloud_destroy(pc);
}

/* Numbers from tools/reference/record_hull_obb.py (Open3D 0.20). */
static void test_cloud_bin_0_reference(void** state) {
    (void)state;
    O3D_C_TEST_DATA_OR_SKIP(path, "open3d/Feature/cloud_bin_0.pcd");
    o3d_pointcloud_t* pc = NULL;
    assert_int_equal(o3d_io_read_point_cloud(&pc, path, NULL, NULL), O3D_OK);
    o3d_trianglemesh_t* hull = NULL;
    size_t n = 0, nt = 0;
    assert_int_equal(o3d_pointcloud_compute_convex_hull(&hull, NULL, 0, &n, pc, 0), O3D_OK);
    assert_int_equal(n, 85);
    assert_int_equal(o3d_trianglemesh_num_triangles(&nt, hull), O3D_OK);
    assert_int_equal(nt, 166);
    double volume = 0.0;
    assert_int_equal(o3d_trianglemesh_get_volume(&volume, hull), O3D_OK);
    assert_true(fabs(volume - 2.30335298548) < 1e-8);
    o3d_trianglemesh_destroy(hull);

    o3d_obb_t box;
    assert_int_equal(o3d_pointcloud_get_oriented_bounding_box(&box, pc, 0), O3D_OK);
    assert_true(fabs(box.extent[0] * box.extent[1] * box.extent[2] - 6.74249408362) < 1e-8);
    assert_true(fabs(box.center[0] - 2.15397555865) < 1e-9 && fabs(box.center[1] - 0.979776182279) < 1e-9 &&
                fabs(box.center[2] + 1.73828953775) < 1e-9);

    const double cam[3] = {0, 0, 5};
    assert_int_equal(o3d_pointcloud_hidden_point_removal(&hull, NULL, 0, &n, pc, cam, 500.0), O3D_OK);
    assert_int_equal(n, 1318);
    o3d_trianglemesh_destroy(hull);

    assert_int_equal(o3d_pointcloud_estimate_covariances(pc, NULL), O3D_OK); /* KNN 30 */
    const double* view = NULL;
    assert_int_equal(o3d_pointcloud_array_view(&view, &n, pc, O3D_POINTCLOUD_COVARIANCES), O3D_OK);
    assert_int_equal(n, 3903);
    const double cov0[9] = {0.00107995231629,  0.000934985542567, -0.000514799600145,
                            0.000934985542567, 0.00424541377841,  -0.00091369316711,
                            -0.000514799600145, -0.00091369316711, 0.00301379055436};
    for (int k = 0; k < 9; ++k) assert_true(fabs(view[k] - cov0[k]) < 1e-12);
    o3d_pointcloud_destroy(pc);
}

static void test_covariances(void** state) {
    (void)state;
    o3d_pointcloud_t* pc = NULL;
    assert_int_equal(o3d_pointcloud_create(&pc), O3D_OK);
    /* A 5 x 5 grid in the plane z = 0. */
    double xyz[75];
    for (int i = 0; i < 25; ++i) xyz[3 * i] = i % 5, xyz[3 * i + 1] = i / 5, xyz[3 * i + 2] = 0;
    assert_int_equal(o3d_pointcloud_set_array(pc, O3D_POINTCLOUD_POINTS, xyz, 25), O3D_OK);
    int32_t has = -1;
    assert_int_equal(o3d_pointcloud_has_array(&has, pc, O3D_POINTCLOUD_COVARIANCES), O3D_OK);
    assert_int_equal(has, 0);
    o3d_search_param_t param;
    assert_int_equal(o3d_search_param_init(&param, sizeof param), O3D_OK);
    param.kind = O3D_SEARCH_HYBRID;
    param.radius = 1.5;
    param.knn = 9;
    assert_int_equal(o3d_pointcloud_estimate_covariances(pc, &param), O3D_OK);
    assert_int_equal(o3d_pointcloud_has_array(&has, pc, O3D_POINTCLOUD_COVARIANCES), O3D_OK);
    assert_int_equal(has, 1);
    double cov[25 * 9];
    size_t n = 0;
    assert_int_equal(o3d_pointcloud_get_array(cov, 25, &n, pc, O3D_POINTCLOUD_COVARIANCES), O3D_OK);
    assert_int_equal(n, 25);
    for (int i = 0; i < 25; ++i) /* zero variance along the plane's normal (z) */
        for (int k = 0; k < 3; ++k) assert_true(cov[9 * i + 6 + k] == 0.0 && cov[9 * i + 3 * k + 2] == 0.0);
    /* The centre's 3x3 neighbourhood: variance 2/3 along x and y, no correlation. */
    assert_true(fabs(cov[9 * 12] - 2.0 / 3.0) < 1e-12 && fabs(cov[9 * 12 + 4] - 2.0 / 3.0) < 1e-12);
    assert_true(fabs(cov[9 * 12 + 1]) < 1e-12);
    O3D_ASSERT_FAILS(o3d_pointcloud_get_array(cov, 3, &n, pc, O3D_POINTCLOUD_COVARIANCES), O3D_ERROR_BUFFER_TOO_SMALL);

    /* Covariances are symmetric: an asymmetric matrix is refused and the cloud keeps what it had. */
    const double asym[9] = {1, 2, 3, 4, 5, 6, 7, 8, 9};
    O3D_ASSERT_FAILS(o3d_pointcloud_set_array(pc, O3D_POINTCLOUD_COVARIANCES, asym, 1), O3D_ERROR_INVALID_ARGUMENT);
    assert_int_equal(o3d_pointcloud_get_array(NULL, 0, &n, pc, O3D_POINTCLOUD_COVARIANCES), O3D_OK);
    assert_int_equal(n, 25);
    /* Set / get round trip (row-major), carried by select_by_index. */
    double mats[18] = {1, 2, 3, 2, 5, 6, 3, 6, 9, 1, 0, 0, 0, 2, 0, 0, 0, 3};
    assert_int_equal(o3d_pointcloud_set_array(pc, O3D_POINTCLOUD_COVARIANCES, mats, 2), O3D_OK);
    assert_int_equal(o3d_pointcloud_has_array(&has, pc, O3D_POINTCLOUD_COVARIANCES), O3D_OK);
    assert_int_equal(has, 0); /* 2 matrices for 25 points do not count */
    assert_int_equal(o3d_pointcloud_set_array(pc, O3D_POINTCLOUD_POINTS, xyz, 2), O3D_OK);
    assert_int_equal(o3d_pointcloud_has_array(&has, pc, O3D_POINTCLOUD_COVARIANCES), O3D_OK);
    assert_int_equal(has, 1);
    assert_int_equal(o3d_pointcloud_get_array(cov, 2, &n, pc, O3D_POINTCLOUD_COVARIANCES), O3D_OK);
    assert_memory_equal(cov, mats, sizeof mats);
    const double* view = NULL;
    assert_int_equal(o3d_pointcloud_array_view(&view, &n, pc, O3D_POINTCLOUD_COVARIANCES), O3D_OK);
    assert_int_equal(n, 2);
    assert_memory_equal(view, mats, sizeof mats); /* symmetric: the zero-copy view is the row-major layout */
    const int32_t one = 1;
    o3d_pointcloud_t* picked = NULL;
    assert_int_equal(o3d_pointcloud_select_by_index(&picked, pc, &one, 1, 0), O3D_OK);
    assert_int_equal(o3d_pointcloud_array_view(&view, &n, picked, O3D_POINTCLOUD_COVARIANCES), O3D_OK);
    assert_int_equal(n, 1);
    assert_memory_equal(view, mats + 9, 9 * sizeof(double));
    /* Rotating by 90 degrees about z swaps the x and y variances. */
    const double rz[9] = {0, -1, 0, 1, 0, 0, 0, 0, 1};
    assert_int_equal(o3d_pointcloud_rotate(picked, rz, NULL), O3D_OK);
    assert_int_equal(o3d_pointcloud_array_view(&view, &n, picked, O3D_POINTCLOUD_COVARIANCES), O3D_OK);
    assert_true(fabs(view[0] - 2) < 1e-12 && fabs(view[4] - 1) < 1e-12 && fabs(view[8] - 3) < 1e-12);
    o3d_pointcloud_destroy(picked);

    O3D_ASSERT_FAILS(o3d_pointcloud_set_array(pc, O3D_POINTCLOUD_COVARIANCES, NULL, 2), INV);
    O3D_ASSERT_FAILS(o3d_pointcloud_set_array(NULL, O3D_POINTCLOUD_COVARIANCES, mats, 2), INV);
    O3D_ASSERT_FAILS(o3d_pointcloud_has_array(NULL, pc, O3D_POINTCLOUD_COVARIANCES), INV);
    O3D_ASSERT_FAILS(o3d_pointcloud_get_array(cov, 2, NULL, pc, O3D_POINTCLOUD_COVARIANCES), INV);
    O3D_ASSERT_FAILS(o3d_pointcloud_estimate_covariances(NULL, NULL), INV);
    param.kind = O3D_SEARCH_RADIUS;
    param.radius = 0.0;
    O3D_ASSERT_FAILS(o3d_pointcloud_estimate_covariances(pc, &param), INV);
    param.radius = -1.0;
    O3D_ASSERT_FAILS(o3d_pointcloud_estimate_covariances(pc, &param), INV);
    param.radius = NAN;
    O3D_ASSERT_FAILS(o3d_pointcloud_estimate_covariances(pc, &param), INV);
    xyz[0] = NAN;
    assert_int_equal(o3d_pointcloud_set_array(pc, O3D_POINTCLOUD_POINTS, xyz, 25), O3D_OK);
    O3D_ASSERT_FAILS(o3d_pointcloud_estimate_covariances(pc, NULL), INV);
    o3d_pointcloud_destroy(pc);
}

int main(void) {
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_convex_hull_of_cube),     cmocka_unit_test(test_hull_errors),
        cmocka_unit_test(test_hidden_point_removal_of_sphere), cmocka_unit_test(test_obb_of_rotated_box),
        cmocka_unit_test(test_obb_from_aabb_and_errors), cmocka_unit_test(test_cloud_bin_0_reference),
        cmocka_unit_test(test_covariances),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
