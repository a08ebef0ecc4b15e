/* SPDX-License-Identifier: MIT */
/* C API pointcloud.h: values through the ABI, NULL / invalid arguments, buffers, views. */
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <setjmp.h>
#include <cmocka.h>

#include <math.h>
#include <string.h>

#include "o3d/pointcloud.h"
#include "o3d_test_util.h"

#define INV O3D_ERROR_INVALID_ARGUMENT

static o3d_pointcloud_t* make_cloud(const double* xyz, size_t n) {
    o3d_pointcloud_t* pc = NULL;
    assert_int_equal(o3d_pointcloud_create(&pc), O3D_OK);
    assert_int_equal(o3d_pointcloud_set_array(pc, O3D_POINTCLOUD_POINTS, xyz, n), O3D_OK);
    return pc;
}

static const double kSquare[] = {0, 0, 0, 2, 0, 0, 2, 2, 0, 0, 2, 0};

static void test_lifecycle_and_accessors(void** state) {
    (void)state;
    o3d_pointcloud_t* pc = make_cloud(kSquare, 4);
    size_t n = 0;
    int32_t flag = -1;
    assert_int_equal(o3d_pointcloud_size(&n, pc), O3D_OK);
    assert_int_equal(n, 4);
    assert_int_equal(o3d_pointcloud_has_array(&flag, pc, O3D_POINTCLOUD_POINTS), O3D_OK);
    assert_int_equal(flag, 1);
    assert_int_equal(o3d_pointcloud_has_array(&flag, pc, O3D_POINTCLOUD_NORMALS), O3D_OK);
    assert_int_equal(flag, 0);
    size_t rows = 0, cols = 0;
    assert_int_equal(o3d_pointcloud_array_shape(&rows, &cols, pc, O3D_POINTCLOUD_POINTS), O3D_OK);
    assert_true(rows == 4 && cols == 3);
    assert_int_equal(o3d_pointcloud_array_shape(&rows, &cols, pc, O3D_POINTCLOUD_COVARIANCES), O3D_OK);
    assert_true(rows == 0 && cols == 9);
    O3D_ASSERT_FAILS(o3d_pointcloud_array_shape(&rows, &cols, pc, 7), O3D_ERROR_INVALID_ARGUMENT);
    O3D_ASSERT_FAILS(o3d_pointcloud_array_shape(&rows, NULL, pc, 0), O3D_ERROR_INVALID_ARGUMENT);
    O3D_ASSERT_FAILS(o3d_pointcloud_has_array(&flag, pc, O3D_INDEX_ARRAY_FIRST), O3D_ERROR_INVALID_ARGUMENT);

    const float normals[] = {0, 0, 1, 0, 0, 1, 0, 0, 1, 0, 0.5f, 1};
    assert_int_equal(o3d_pointcloud_set_array_f32(pc, O3D_POINTCLOUD_NORMALS, normals, 4), O3D_OK);
    assert_int_equal(o3d_pointcloud_has_array(&flag, pc, O3D_POINTCLOUD_NORMALS), O3D_OK);
    assert_int_equal(flag, 1);
    double out[12];
    assert_int_equal(o3d_pointcloud_get_array(out, 4, &n, pc, O3D_POINTCLOUD_NORMALS), O3D_OK);
    assert_true(out[10] == 0.5 && out[11] == 1.0);  // converted in the copy

    /* Copy-out: NULL queries the count; a short buffer is reported with the needed count. */
    n = 0;
    assert_int_equal(o3d_pointcloud_get_array(NULL, 0, &n, pc, O3D_POINTCLOUD_POINTS), O3D_OK);
    assert_int_equal(n, 4);
    O3D_ASSERT_FAILS(o3d_pointcloud_get_array(out, 3, &n, pc, O3D_POINTCLOUD_POINTS), O3D_ERROR_BUFFER_TOO_SMALL);
    assert_int_equal(n, 4);
    assert_int_equal(o3d_pointcloud_get_array(out, 4, &n, pc, O3D_POINTCLOUD_POINTS), O3D_OK);
    assert_memory_equal(out, kSquare, sizeof kSquare);

    /* Views point at the live data; writing through the mutable view changes the cloud. */
    const double* view = NULL;
    assert_int_equal(o3d_pointcloud_array_view(&view, &n, pc, O3D_POINTCLOUD_POINTS), O3D_OK);
    assert_int_equal(n, 4);
    assert_true(view[3] == 2.0);
    double* mview = NULL;
    assert_int_equal(o3d_pointcloud_array_mutable_view(&mview, &n, pc, O3D_POINTCLOUD_POINTS), O3D_OK);
    mview[3] = 7.0;
    assert_true(view == mview);
    double maxb[3];
    assert_int_equal(o3d_pointcloud_get_max_bound(maxb, pc), O3D_OK);
    assert_true(maxb[0] == 7.0);
    assert_int_equal(o3d_pointcloud_array_view(&view, &n, pc, O3D_POINTCLOUD_COLORS), O3D_OK);
    assert_null(view);
    assert_int_equal(n, 0);

    o3d_pointcloud_t* copy = NULL;
    assert_int_equal(o3d_pointcloud_clone(&copy, pc), O3D_OK);
    assert_int_equal(o3d_pointcloud_clear(pc), O3D_OK);
    assert_int_equal(o3d_pointcloud_size(&n, pc), O3D_OK);
    assert_int_equal(n, 0);
    assert_int_equal(o3d_pointcloud_size(&n, copy), O3D_OK);
    assert_int_equal(n, 4);  // the clone is independent
    o3d_pointcloud_destroy(copy);
    o3d_pointcloud_destroy(pc);
    o3d_pointcloud_destroy(NULL);
}

static void test_geometry_ops(void** state) {
    (void)state;
    o3d_pointcloud_t* pc = make_cloud(kSquare, 4);
    double c[3], lo[3], hi[3];
    assert_int_equal(o3d_pointcloud_get_center(c, pc), O3D_OK);
    assert_true(c[0] == 1.0 && c[1] == 1.0 && c[2] == 0.0);
    const double t[3] = {1, 2, 3};
    assert_int_equal(o3d_pointcloud_translate(pc, t, 0), O3D_OK);  /* center -> (1,2,3) */
    assert_int_equal(o3d_pointcloud_get_axis_aligned_bounding_box(lo, hi, pc), O3D_OK);
    assert_true(lo[0] == 0 && lo[1] == 1 && lo[2] == 3 && hi[0] == 2 && hi[1] == 3);
    assert_int_equal(o3d_pointcloud_scale(pc, 2.0, NULL), O3D_OK); /* about the center */
    assert_int_equal(o3d_pointcloud_get_min_bound(lo, pc), O3D_OK);
    assert_true(lo[0] == -1 && lo[1] == 0 && lo[2] == 3);
    /* Row-major 90 degrees about Z, then a translation (row-major 4x4). */
    const double m[16] = {0, -1, 0, 10, 1, 0, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1};
    assert_int_equal(o3d_pointcloud_set_array(pc, O3D_POINTCLOUD_POINTS, kSquare, 4), O3D_OK);
    assert_int_equal(o3d_pointcloud_transform(pc, m), O3D_OK);
    double p[12];
    size_t n;
    assert_int_equal(o3d_pointcloud_get_array(p, 4, &n, pc, O3D_POINTCLOUD_POINTS), O3D_OK);
    assert_true(fabs(p[3] - 10) < 1e-12 && fabs(p[4] - 2) < 1e-12);  /* (2,0,0) -> (10,2,0) */
    const double r[9] = {0, -1, 0, 1, 0, 0, 0, 0, 1};
    const double origin[3] = {0, 0, 0};
    assert_int_equal(o3d_pointcloud_set_array(pc, O3D_POINTCLOUD_POINTS, kSquare, 4), O3D_OK);
    assert_int_equal(o3d_pointcloud_rotate(pc, r, origin), O3D_OK);
    assert_int_equal(o3d_pointcloud_get_array(p, 4, &n, pc, O3D_POINTCLOUD_POINTS), O3D_OK);
    assert_true(fabs(p[3]) < 1e-12 && fabs(p[4] - 2) < 1e-12);
    const double bad[16] = {NAN};
    O3D_ASSERT_FAILS(o3d_pointcloud_transform(pc, bad), INV);
    O3D_ASSERT_FAILS(o3d_pointcloud_scale(pc, INFINITY, NULL), INV);
    o3d_pointcloud_destroy(pc);
}

static void test_selection_and_filters(void** state) {
    (void)state;
    const double xyz[] = {0, 0, 0, 1, 0, 0, NAN, 0, 0, 3, 0, INFINITY, 4, 0, 0};
    o3d_pointcloud_t* pc = make_cloud(xyz, 5);
    o3d_pointcloud_t* sel = NULL;
    const int32_t idx[] = {4, 1, 4};
    assert_int_equal(o3d_pointcloud_select_by_index(&sel, pc, idx, 3, 0), O3D_OK);
    double p[15];
    size_t n;
    assert_int_equal(o3d_pointcloud_get_array(p, 5, &n, sel, O3D_POINTCLOUD_POINTS), O3D_OK);
    assert_int_equal(n, 2);
    assert_true(p[0] == 1 && p[3] == 4);
    o3d_pointcloud_destroy(sel);
    assert_int_equal(o3d_pointcloud_select_by_index(&sel, pc, idx, 3, 1), O3D_OK);
    assert_int_equal(o3d_pointcloud_size(&n, sel), O3D_OK);
    assert_int_equal(n, 3);
    o3d_pointcloud_destroy(sel);
    const int32_t out_of_range[] = {5};
    const int32_t negative[] = {-1};
    sel = (o3d_pointcloud_t*)1;
    O3D_ASSERT_FAILS(o3d_pointcloud_select_by_index(&sel, pc, out_of_range, 1, 0), INV);
    assert_null(sel);  // never a half-made handle
    O3D_ASSERT_FAILS(o3d_pointcloud_select_by_index(&sel, pc, negative, 1, 0), INV);
    O3D_ASSERT_FAILS(o3d_pointcloud_select_by_index(&sel, pc, NULL, 1, 0), INV);

    assert_int_equal(o3d_pointcloud_remove_non_finite_points(pc, 0, 1), O3D_OK);
    assert_int_equal(o3d_pointcloud_size(&n, pc), O3D_OK);
    assert_int_equal(n, 4);
    assert_int_equal(o3d_pointcloud_remove_non_finite_points(pc, 1, 0), O3D_OK);
    assert_int_equal(o3d_pointcloud_size(&n, pc), O3D_OK);
    assert_int_equal(n, 3);
    o3d_pointcloud_destroy(pc);
}

static void test_down_sampling(void** state) {
    (void)state;
    const double xyz[] = {0, 0, 0, 0.4, 0.2, 0, 3, 0, 0, 0.2, 0.4, 0.3};
    o3d_pointcloud_t* pc = make_cloud(xyz, 4);
    o3d_pointcloud_t* d = NULL;
    double p[12];
    size_t n;
    assert_int_equal(o3d_pointcloud_voxel_down_sample(&d, pc, 1.0), O3D_OK);
    assert_int_equal(o3d_pointcloud_get_array(p, 4, &n, d, O3D_POINTCLOUD_POINTS), O3D_OK);
    assert_int_equal(n, 2);
    assert_true(fabs(p[0] - 0.2) < 1e-15 && fabs(p[2] - 0.1) < 1e-15 && p[3] == 3.0);
    o3d_pointcloud_destroy(d);
    assert_int_equal(o3d_pointcloud_uniform_down_sample(&d, pc, 2), O3D_OK);
    assert_int_equal(o3d_pointcloud_get_array(p, 4, &n, d, O3D_POINTCLOUD_POINTS), O3D_OK);
    assert_true(n == 2 && p[3] == 3.0);
    o3d_pointcloud_destroy(d);
    assert_int_equal(o3d_pointcloud_random_down_sample(&d, pc, 0.5, 9), O3D_OK);
    assert_int_equal(o3d_pointcloud_size(&n, d), O3D_OK);
    assert_int_equal(n, 2);
    o3d_pointcloud_destroy(d);
    assert_int_equal(o3d_pointcloud_farthest_point_down_sample(&d, pc, 2, 0), O3D_OK);
    assert_int_equal(o3d_pointcloud_get_array(p, 4, &n, d, O3D_POINTCLOUD_POINTS), O3D_OK);
    assert_true(n == 2 && p[0] == 0 && p[3] == 3.0);  /* start, then the far point */
    o3d_pointcloud_destroy(d);

    O3D_ASSERT_FAILS(o3d_pointcloud_voxel_down_sample(&d, pc, 0.0), INV);
    O3D_ASSERT_FAILS(o3d_pointcloud_voxel_down_sample(&d, pc, NAN), INV);
    O3D_ASSERT_FAILS(o3d_pointcloud_uniform_down_sample(&d, pc, 0), INV);
    O3D_ASSERT_FAILS(o3d_pointcloud_random_down_sample(&d, pc, 1.5, 0), INV);
    O3D_ASSERT_FAILS(o3d_pointcloud_random_down_sample(&d, pc, NAN, 0), INV);
    O3D_ASSERT_FAILS(o3d_pointcloud_farthest_point_down_sample(&d, pc, 5, 0), INV);
    O3D_ASSERT_FAILS(o3d_pointcloud_farthest_point_down_sample(&d, pc, 2, 4), INV);
    o3d_pointcloud_destroy(pc);
}

static void test_normals_and_distances(void** state) {
    (void)state;
    /* A 10x10 grid on z = 1: normals are +-Z; orientation then fixes the sign. */
    double grid[300];
    for (int i = 0; i < 100; ++i) {
        grid[3 * i] = i % 10;
        grid[3 * i + 1] = i / 10;
        grid[3 * i + 2] = 1.0;
    }
    o3d_pointcloud_t* pc = make_cloud(grid, 100);
    o3d_search_param_t param;
    assert_int_equal(o3d_search_param_init(&param, sizeof param), O3D_OK);
    assert_int_equal(param.kind, O3D_SEARCH_KNN);
    assert_int_equal(param.knn, 30);
    param.kind = O3D_SEARCH_HYBRID;
    param.radius = 1.5;
    param.knn = 9;
    assert_int_equal(o3d_pointcloud_estimate_normals(pc, &param, 2), O3D_OK);
    const double down[3] = {0, 0, -1};
    assert_int_equal(o3d_pointcloud_orient_normals_to_align_with_direction(pc, down), O3D_OK);
    const double* nv;
    size_t n;
    assert_int_equal(o3d_pointcloud_array_view(&nv, &n, pc, O3D_POINTCLOUD_NORMALS), O3D_OK);
    assert_int_equal(n, 100);
    for (int i = 0; i < 100; ++i) assert_true(fabs(nv[3 * i + 2] + 1.0) < 1e-12);
    assert_int_equal(o3d_pointcloud_orient_normals_towards_camera_location(pc, NULL), O3D_OK); /* origin is below */
    for (int i = 0; i < 100; ++i) assert_true(nv[3 * i + 2] < 0);
    const double above[3] = {0, 0, 5};
    assert_int_equal(o3d_pointcloud_orient_normals_towards_camera_location(pc, above), O3D_OK);
    for (int i = 0; i < 100; ++i) assert_true(nv[3 * i + 2] > 0);
    assert_int_equal(o3d_pointcloud_normalize_normals(pc), O3D_OK);

    double d[100];
    assert_int_equal(o3d_pointcloud_compute_nearest_neighbor_distance(d, 100, &n, pc, 0), O3D_OK);
    for (int i = 0; i < 100; ++i) assert_true(fabs(d[i] - 1.0) < 1e-15);
    O3D_ASSERT_FAILS(o3d_pointcloud_compute_nearest_neighbor_distance(d, 99, &n, pc, 0), O3D_ERROR_BUFFER_TOO_SMALL);
    assert_int_equal(n, 100);
    const double one[3] = {0, 0, 3};
    o3d_pointcloud_t* other = make_cloud(one, 1);
    assert_int_equal(o3d_pointcloud_compute_point_cloud_distance(d, 100, &n, other, pc, 1), O3D_OK);
    assert_int_equal(n, 1);
    assert_true(fabs(d[0] - 2.0) < 1e-15);
    o3d_pointcloud_t* empty = NULL;
    assert_int_equal(o3d_pointcloud_create(&empty), O3D_OK);
    O3D_ASSERT_FAILS(o3d_pointcloud_compute_point_cloud_distance(d, 100, &n, other, empty, 1), INV);
    O3D_ASSERT_FAILS(o3d_pointcloud_orient_normals_to_align_with_direction(empty, NULL), INV); /* no normals */

    param.radius = NAN;
    O3D_ASSERT_FAILS(o3d_pointcloud_estimate_normals(pc, &param, 0), INV);
    param.radius = 1.0;
    param.kind = 7;
    O3D_ASSERT_FAILS(o3d_pointcloud_estimate_normals(pc, &param, 0), INV);
    param.kind = O3D_SEARCH_KNN;
    param.knn = 0;
    O3D_ASSERT_FAILS(o3d_pointcloud_estimate_normals(pc, &param, 0), INV);
    param.knn = 5;
    param.struct_size = 1000;
    O3D_ASSERT_FAILS(o3d_pointcloud_estimate_normals(pc, &param, 0), INV);
    O3D_ASSERT_FAILS(o3d_pointcloud_estimate_normals(pc, NULL, -1), INV);
    assert_int_equal(o3d_pointcloud_estimate_normals(pc, NULL, 0), O3D_OK); /* NULL: KNN 30 */
    const double nan3[3] = {NAN, 0, 0};
    O3D_ASSERT_FAILS(o3d_pointcloud_orient_normals_to_align_with_direction(pc, nan3), INV);
    O3D_ASSERT_FAILS(o3d_search_param_init(&param, 2), INV);
    o3d_pointcloud_destroy(empty);
    o3d_pointcloud_destroy(other);
    o3d_pointcloud_destroy(pc);
}

static void test_append(void** state) {
    (void)state;
    o3d_pointcloud_t* a = make_cloud(kSquare, 4);
    o3d_pointcloud_t* b = make_cloud(kSquare, 2);
    const double rgb[3] = {0.5, 2.0, 0.1};
    assert_int_equal(o3d_pointcloud_paint_uniform_color(a, rgb), O3D_OK);
    assert_int_equal(o3d_pointcloud_append(a, b), O3D_OK); /* b has no colors: they are dropped */
    size_t n;
    int32_t flag;
    assert_int_equal(o3d_pointcloud_size(&n, a), O3D_OK);
    assert_int_equal(n, 6);
    assert_int_equal(o3d_pointcloud_has_array(&flag, a, O3D_POINTCLOUD_COLORS), O3D_OK);
    assert_int_equal(flag, 0);
    assert_int_equal(o3d_pointcloud_append(a, a), O3D_OK); /* self-append doubles */
    assert_int_equal(o3d_pointcloud_size(&n, a), O3D_OK);
    assert_int_equal(n, 12);
    o3d_pointcloud_destroy(a);
    o3d_pointcloud_destroy(b);
}

/* Every function with a NULL for each pointer argument that must not be NULL. */
static void test_null_arguments(void** state) {
    (void)state;
    o3d_pointcloud_t* pc = make_cloud(kSquare, 4);
    o3d_pointcloud_t* out = NULL;
    size_t n;
    int32_t flag;
    double buf[12], v3[3];
    const double* cview;
    double* mview;
    const double m16[16] = {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1};
    const double m9[9] = {1, 0, 0, 0, 1, 0, 0, 0, 1};
    const int32_t idx[1] = {0};
    O3D_ASSERT_FAILS(o3d_pointcloud_create(NULL), INV);
    O3D_ASSERT_FAILS(o3d_pointcloud_clone(NULL, pc), INV);
    O3D_ASSERT_FAILS(o3d_pointcloud_clone(&out, NULL), INV);
    O3D_ASSERT_FAILS(o3d_pointcloud_size(&n, NULL), INV);
    O3D_ASSERT_FAILS(o3d_pointcloud_size(NULL, pc), INV);
    O3D_ASSERT_FAILS(o3d_pointcloud_has_array(&flag, NULL, O3D_POINTCLOUD_POINTS), INV);
    O3D_ASSERT_FAILS(o3d_pointcloud_has_array(NULL, pc, O3D_POINTCLOUD_POINTS), INV);
    O3D_ASSERT_FAILS(o3d_pointcloud_has_array(&flag, NULL, O3D_POINTCLOUD_NORMALS), INV);
    O3D_ASSERT_FAILS(o3d_pointcloud_has_array(NULL, pc, O3D_POINTCLOUD_NORMALS), INV);
    O3D_ASSERT_FAILS(o3d_pointcloud_has_array(&flag, NULL, O3D_POINTCLOUD_COLORS), INV);
    O3D_ASSERT_FAILS(o3d_pointcloud_has_array(NULL, pc, O3D_POINTCLOUD_COLORS), INV);
    O3D_ASSERT_FAILS(o3d_pointcloud_clear(NULL), INV);
    O3D_ASSERT_FAILS(o3d_pointcloud_set_array(NULL, O3D_POINTCLOUD_POINTS, kSquare, 4), INV);
    O3D_ASSERT_FAILS(o3d_pointcloud_set_array(pc, O3D_POINTCLOUD_POINTS, NULL, 4), INV);
    O3D_ASSERT_FAILS(o3d_pointcloud_set_array_f32(pc, O3D_POINTCLOUD_POINTS, NULL, 4), INV);
    O3D_ASSERT_FAILS(o3d_pointcloud_set_array(pc, O3D_POINTCLOUD_NORMALS, NULL, 4), INV);
    O3D_ASSERT_FAILS(o3d_pointcloud_set_array_f32(NULL, O3D_POINTCLOUD_NORMALS, NULL, 0), INV);
    O3D_ASSERT_FAILS(o3d_pointcloud_set_array(pc, O3D_POINTCLOUD_COLORS, NULL, 1), INV);
    O3D_ASSERT_FAILS(o3d_pointcloud_set_array_f32(pc, O3D_POINTCLOUD_COLORS, NULL, 1), INV);
    O3D_ASSERT_FAILS(o3d_pointcloud_get_array(buf, 4, &n, NULL, O3D_POINTCLOUD_POINTS), INV);
    O3D_ASSERT_FAILS(o3d_pointcloud_get_array(buf, 4, NULL, pc, O3D_POINTCLOUD_POINTS), INV);
    O3D_ASSERT_FAILS(o3d_pointcloud_get_array(buf, 4, &n, NULL, O3D_POINTCLOUD_NORMALS), INV);
    O3D_ASSERT_FAILS(o3d_pointcloud_get_array(buf, 4, NULL, pc, O3D_POINTCLOUD_COLORS), INV);
    O3D_ASSERT_FAILS(o3d_pointcloud_array_view(&cview, &n, NULL, O3D_POINTCLOUD_POINTS), INV);
    O3D_ASSERT_FAILS(o3d_pointcloud_array_view(NULL, &n, pc, O3D_POINTCLOUD_POINTS), INV);
    O3D_ASSERT_FAILS(o3d_pointcloud_array_view(&cview, NULL, pc, O3D_POINTCLOUD_NORMALS), INV);
    O3D_ASSERT_FAILS(o3d_pointcloud_array_view(&cview, &n, NULL, O3D_POINTCLOUD_COLORS), INV);
    O3D_ASSERT_FAILS(o3d_pointcloud_array_mutable_view(NULL, &n, pc, O3D_POINTCLOUD_POINTS), INV);
    O3D_ASSERT_FAILS(o3d_pointcloud_array_mutable_view(&mview, &n, NULL, O3D_POINTCLOUD_NORMALS), INV);
    O3D_ASSERT_FAILS(o3d_pointcloud_array_mutable_view(&mview, NULL, pc, O3D_POINTCLOUD_COLORS), INV);
    O3D_ASSERT_FAILS(o3d_pointcloud_append(NULL, pc), INV);
    O3D_ASSERT_FAILS(o3d_pointcloud_append(pc, NULL), INV);
    O3D_ASSERT_FAILS(o3d_pointcloud_transform(NULL, m16), INV);
    O3D_ASSERT_FAILS(o3d_pointcloud_transform(pc, NULL), INV);
    O3D_ASSERT_FAILS(o3d_pointcloud_translate(NULL, v3, 1), INV);
    O3D_ASSERT_FAILS(o3d_pointcloud_translate(pc, NULL, 1), INV);
    O3D_ASSERT_FAILS(o3d_pointcloud_rotate(NULL, m9, NULL), INV);
    O3D_ASSERT_FAILS(o3d_pointcloud_rotate(pc, NULL, NULL), INV);
    O3D_ASSERT_FAILS(o3d_pointcloud_scale(NULL, 1.0, NULL), INV);
    O3D_ASSERT_FAILS(o3d_pointcloud_get_min_bound(v3, NULL), INV);
    O3D_ASSERT_FAILS(o3d_pointcloud_get_min_bound(NULL, pc), INV);
    O3D_ASSERT_FAILS(o3d_pointcloud_get_max_bound(NULL, pc), INV);
    O3D_ASSERT_FAILS(o3d_pointcloud_get_center(v3, NULL), INV);
    O3D_ASSERT_FAILS(o3d_pointcloud_get_axis_aligned_bounding_box(NULL, v3, pc), INV);
    O3D_ASSERT_FAILS(o3d_pointcloud_get_axis_aligned_bounding_box(v3, NULL, pc), INV);
    O3D_ASSERT_FAILS(o3d_pointcloud_paint_uniform_color(pc, NULL), INV);
    O3D_ASSERT_FAILS(o3d_pointcloud_select_by_index(NULL, pc, idx, 1, 0), INV);
    O3D_ASSERT_FAILS(o3d_pointcloud_select_by_index(&out, NULL, idx, 1, 0), INV);
    O3D_ASSERT_FAILS(o3d_pointcloud_remove_non_finite_points(NULL, 1, 1), INV);
    O3D_ASSERT_FAILS(o3d_pointcloud_normalize_normals(NULL), INV);
    O3D_ASSERT_FAILS(o3d_pointcloud_voxel_down_sample(NULL, pc, 1.0), INV);
    O3D_ASSERT_FAILS(o3d_pointcloud_voxel_down_sample(&out, NULL, 1.0), INV);
    O3D_ASSERT_FAILS(o3d_pointcloud_uniform_down_sample(&out, NULL, 1), INV);
    O3D_ASSERT_FAILS(o3d_pointcloud_random_down_sample(NULL, pc, 0.5, 1), INV);
    O3D_ASSERT_FAILS(o3d_pointcloud_farthest_point_down_sample(&out, NULL, 1, 0), INV);
    O3D_ASSERT_FAILS(o3d_search_param_init(NULL, sizeof(o3d_search_param_t)), INV);
    O3D_ASSERT_FAILS(o3d_pointcloud_estimate_normals(NULL, NULL, 0), INV);
    O3D_ASSERT_FAILS(o3d_pointcloud_orient_normals_to_align_with_direction(NULL, NULL), INV);
    O3D_ASSERT_FAILS(o3d_pointcloud_orient_normals_towards_camera_location(NULL, NULL), INV);
    O3D_ASSERT_FAILS(o3d_pointcloud_compute_nearest_neighbor_distance(buf, 12, &n, NULL, 0), INV);
    O3D_ASSERT_FAILS(o3d_pointcloud_compute_nearest_neighbor_distance(buf, 12, NULL, pc, 0), INV);
    O3D_ASSERT_FAILS(o3d_pointcloud_compute_point_cloud_distance(buf, 12, &n, NULL, pc, 0), INV);
    O3D_ASSERT_FAILS(o3d_pointcloud_compute_point_cloud_distance(buf, 12, &n, pc, NULL, 0), INV);
    O3D_ASSERT_FAILS(o3d_pointcloud_compute_point_cloud_distance(buf, 12, NULL, pc, pc, 0), INV);
    assert_null(out);
    o3d_pointcloud_destroy(pc);
}

int main(void) {
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_lifecycle_and_accessors), cmocka_unit_test(test_geometry_ops),
        cmocka_unit_test(test_selection_and_filters),   cmocka_unit_test(test_down_sampling),
        cmocka_unit_test(test_normals_and_distances),   cmocka_unit_test(test_append),
        cmocka_unit_test(test_null_arguments),
    };
    return cmocka_run_group_tests_name("o3d_pointcloud", tests, NULL, NULL);
}
