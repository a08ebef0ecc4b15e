/* SPDX-License-Identifier: MIT */
/* C API selection.h and VisualizerWithEditing's crop. Checked: Open3D's own crop of its test fragment
 * (reference numbers recorded from the open3d 0.20 wheel: read_selection_polygon_volume("Crop/cropped.json")
 * .crop_point_cloud(read_point_cloud("fragment.pcd")) keeps 29873 of 113662 points, coordinate sums
 * 72136.99282503, 53441.75809902, 39966.93971372), analytic crops of grids and a two-triangle quad, the
 * viewer's rectangle and polygon selections against the points' projections through the view's pinhole
 * camera, the crop written to the crop directory, and the error paths. */
#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include <cmocka.h>

#include "o3d/o3d.h"
#include "o3d_test_util.h"

static size_t cloud_size(const o3d_pointcloud_t* pc) {
    size_t n = 0;
    assert_int_equal(o3d_pointcloud_size(&n, pc), O3D_OK);
    return n;
}

/* A square [0, 1] x [0, 1] across z, from z = 0 to 1 (corners' z ignored). */
static o3d_selection_polygon_volume_t* unit_square_volume(void) {
    o3d_selection_polygon_volume_t* v = NULL;
    assert_int_equal(o3d_selection_polygon_volume_create(&v), O3D_OK);
    const double corners[12] = {0, 0, 7, 1, 0, 7, 1, 1, 7, 0, 1, 7};
    assert_int_equal(o3d_selection_polygon_volume_set_bounding_polygon(v, corners, 4), O3D_OK);
    assert_int_equal(o3d_selection_polygon_volume_set_orthogonal_axis(v, O3D_AXIS_Z), O3D_OK);
    assert_int_equal(o3d_selection_polygon_volume_set_axis_min(v, 0.0), O3D_OK);
    assert_int_equal(o3d_selection_polygon_volume_set_axis_max(v, 1.0), O3D_OK);
    return v;
}

/* Points on a grid of step 0.1 + 0.05 offset over [-1, 2)^2 at height z: none on the square's edges. */
static o3d_pointcloud_t* grid_cloud(double z) {
    double xyz[30 * 30 * 3];
    size_t n = 0;
    for (int i = 0; i < 30; ++i)
        for (int j = 0; j < 30; ++j) {
            xyz[3 * n] = -1.0 + 0.05 + 0.1 * i;
            xyz[3 * n + 1] = -1.0 + 0.05 + 0.1 * j;
            xyz[3 * n + 2] = z;
            ++n;
        }
    o3d_pointcloud_t* pc = NULL;
    assert_int_equal(o3d_pointcloud_create(&pc), O3D_OK);
    assert_int_equal(o3d_pointcloud_set_array(pc, O3D_POINTCLOUD_POINTS, xyz, n), O3D_OK);
    return pc;
}

static void test_crop_grid_analytic(void** state) {
    (void)state;
    o3d_selection_polygon_volume_t* v = unit_square_volume();
    o3d_pointcloud_t* inside = grid_cloud(0.5);
    o3d_pointcloud_t* above = grid_cloud(1.5);
    o3d_pointcloud_t* out = NULL;
    assert_int_equal(o3d_selection_polygon_volume_crop_point_cloud(&out, v, inside), O3D_OK);
    assert_int_equal(cloud_size(out), 100); /* 10 x 10 grid points inside the unit square */
    double first[3 * 100];
    size_t rows = 0;
    assert_int_equal(o3d_pointcloud_get_array(first, 100, &rows, out, O3D_POINTCLOUD_POINTS), O3D_OK);
    for (size_t i = 0; i < rows; ++i) {
        assert_true(first[3 * i] > 0 && first[3 * i] < 1);
        assert_true(first[3 * i + 1] > 0 && first[3 * i + 1] < 1);
    }
    o3d_pointcloud_destroy(out);
    assert_int_equal(o3d_selection_polygon_volume_crop_point_cloud(&out, v, above), O3D_OK);
    assert_int_equal(cloud_size(out), 0); /* outside the axis range */
    o3d_pointcloud_destroy(out);

    int32_t idx[100];
    size_t n = 0;
    assert_int_equal(o3d_selection_polygon_volume_crop_in_polygon(NULL, 0, &n, v, inside), O3D_OK);
    assert_int_equal(n, 100);
    O3D_ASSERT_FAILS(o3d_selection_polygon_volume_crop_in_polygon(idx, 10, &n, v, inside), O3D_ERROR_BUFFER_TOO_SMALL);
    assert_int_equal(o3d_selection_polygon_volume_crop_in_polygon(idx, 100, &n, v, inside), O3D_OK);
    assert_int_equal(idx[0], 10 * 30 + 10); /* grid (10, 10) is (0.05, 0.05) */
    for (size_t i = 1; i < n; ++i) assert_true(idx[i] > idx[i - 1]);

    /* The even-odd rule on a non-convex shape: the square with a triangular notch cut down to (0.5, 0.48). */
    const double notch[15] = {0, 0, 0, 1, 0, 0, 1, 1, 0, 0.5, 0.48, 0, 0, 1, 0};
    assert_int_equal(o3d_selection_polygon_volume_set_bounding_polygon(v, notch, 5), O3D_OK);
    assert_int_equal(o3d_selection_polygon_volume_crop_in_polygon(NULL, 0, &n, v, inside), O3D_OK);
    /* The notch holds the points with y > 0.48 + 1.04 |x - 0.5|: 2 * (5 + 4 + 3 + 2 + 1) of them. */
    assert_int_equal(n, 100 - 30);
    o3d_pointcloud_destroy(inside);
    o3d_pointcloud_destroy(above);
    o3d_selection_polygon_volume_destroy(v);
}

static void test_crop_mesh_keeps_whole_triangles(void** state) {
    (void)state;
    o3d_selection_polygon_volume_t* v = unit_square_volume();
    /* Two triangles sharing an edge; vertex 3 lies outside, so only triangle 0 stays, with its 3 vertices. */
    const double vertices[12] = {0.1, 0.1, 0.5, 0.9, 0.1, 0.5, 0.1, 0.9, 0.5, 1.5, 0.9, 0.5};
    const int32_t triangles[6] = {0, 1, 2, 1, 3, 2};
    o3d_trianglemesh_t* mesh = NULL;
    assert_int_equal(o3d_trianglemesh_create(&mesh), O3D_OK);
    assert_int_equal(o3d_trianglemesh_set_array(mesh, O3D_MESH_VERTICES, vertices, 4), O3D_OK);
    assert_int_equal(o3d_trianglemesh_set_index_array(mesh, O3D_MESH_TRIANGLES, triangles, 2), O3D_OK);
    o3d_trianglemesh_t* out = NULL;
    assert_int_equal(o3d_selection_polygon_volume_crop_triangle_mesh(&out, v, mesh), O3D_OK);
    size_t nv = 0, nt = 0;
    assert_int_equal(o3d_trianglemesh_num_vertices(&nv, out), O3D_OK);
    assert_int_equal(o3d_trianglemesh_num_triangles(&nt, out), O3D_OK);
    assert_int_equal(nv, 3);
    assert_int_equal(nt, 1);
    o3d_trianglemesh_destroy(out);
    o3d_trianglemesh_destroy(mesh);
    o3d_selection_polygon_volume_destroy(v);
}

static void test_open3d_fragment_reference(void** state) {
    (void)state;
    O3D_C_TEST_DATA_OR_SKIP(json, "open3d/Crop/cropped.json");
    o3d_selection_polygon_volume_t* v = NULL;
    assert_int_equal(o3d_selection_polygon_volume_read_json(&v, json), O3D_OK);
    O3D_C_TEST_DATA_OR_SKIP(pcd, "open3d/fragment.pcd"); /* after: the path lives in a static buffer */
    o3d_axis axis = -1;
    double lo = 0, hi = 0;
    size_t corners = 0;
    assert_int_equal(o3d_selection_polygon_volume_get_orthogonal_axis(&axis, v), O3D_OK);
    assert_int_equal(o3d_selection_polygon_volume_get_axis_min(&lo, v), O3D_OK);
    assert_int_equal(o3d_selection_polygon_volume_get_axis_max(&hi, v), O3D_OK);
    assert_int_equal(o3d_selection_polygon_volume_get_bounding_polygon(NULL, 0, &corners, v), O3D_OK);
    assert_int_equal(axis, O3D_AXIS_Y);
    assert_float_equal(lo, -0.76341366767883301, 1e-15);
    assert_float_equal(hi, 4.022921085357666, 1e-15);
    assert_int_equal(corners, 20);
    o3d_pointcloud_t* pc = NULL;
    assert_int_equal(o3d_io_read_point_cloud(&pc, pcd, NULL, NULL), O3D_OK);
    assert_int_equal(cloud_size(pc), 113662);
    o3d_pointcloud_t* out = NULL;
    assert_int_equal(o3d_selection_polygon_volume_crop_point_cloud(&out, v, pc), O3D_OK);
    const size_t n = cloud_size(out);
    assert_int_equal(n, 29873);
    double* xyz = malloc(n * 3 * sizeof(double));
    size_t rows = 0;
    assert_int_equal(o3d_pointcloud_get_array(xyz, n, &rows, out, O3D_POINTCLOUD_POINTS), O3D_OK);
    double sum[3] = {0, 0, 0};
    for (size_t i = 0; i < rows; ++i)
        for (int k = 0; k < 3; ++k) sum[k] += xyz[3 * i + k];
    assert_float_equal(sum[0], 72136.99282503, 1e-6);
    assert_float_equal(sum[1], 53441.75809902, 1e-6);
    assert_float_equal(sum[2], 39966.93971372, 1e-6);
    free(xyz);
    o3d_pointcloud_destroy(out);
    o3d_pointcloud_destroy(pc);
    o3d_selection_polygon_volume_destroy(v);
}

static void test_volume_errors(void** state) {
    (void)state;
    o3d_selection_polygon_volume_t* v = NULL;
    O3D_ASSERT_FAILS(o3d_selection_polygon_volume_create(NULL), O3D_ERROR_INVALID_ARGUMENT);
    assert_int_equal(o3d_selection_polygon_volume_create(&v), O3D_OK);
    o3d_pointcloud_t* pc = grid_cloud(0.0);
    o3d_pointcloud_t* out = NULL;
    O3D_ASSERT_FAILS(o3d_selection_polygon_volume_crop_point_cloud(&out, v, pc), O3D_ERROR_INVALID_ARGUMENT); /* no polygon */
    assert_null(out);
    O3D_ASSERT_FAILS(o3d_selection_polygon_volume_set_orthogonal_axis(v, 3), O3D_ERROR_INVALID_ARGUMENT);
    O3D_ASSERT_FAILS(o3d_selection_polygon_volume_set_axis_min(v, NAN), O3D_ERROR_INVALID_ARGUMENT);
    const double bad[9] = {0, 0, 0, 1, INFINITY, 0, 1, 1, 0};
    O3D_ASSERT_FAILS(o3d_selection_polygon_volume_set_bounding_polygon(v, bad, 3), O3D_ERROR_INVALID_ARGUMENT);
    O3D_ASSERT_FAILS(o3d_selection_polygon_volume_set_bounding_polygon(v, NULL, 3), O3D_ERROR_INVALID_ARGUMENT);
    const double tri[9] = {0, 0, 0, 1, 0, 0, 0, 1, 0};
    assert_int_equal(o3d_selection_polygon_volume_set_bounding_polygon(v, tri, 3), O3D_OK);
    assert_int_equal(o3d_selection_polygon_volume_set_axis_min(v, 2.0), O3D_OK);
    assert_int_equal(o3d_selection_polygon_volume_set_axis_max(v, 1.0), O3D_OK);
    O3D_ASSERT_FAILS(o3d_selection_polygon_volume_crop_point_cloud(&out, v, pc), O3D_ERROR_INVALID_ARGUMENT); /* min > max */
    O3D_ASSERT_FAILS(o3d_selection_polygon_volume_crop_point_cloud(&out, NULL, pc), O3D_ERROR_INVALID_ARGUMENT);
    O3D_ASSERT_FAILS(o3d_selection_polygon_volume_crop_triangle_mesh(NULL, v, NULL), O3D_ERROR_INVALID_ARGUMENT);

    char path[] = "/tmp/o3d_selection_XXXXXX";
    const int fd = mkstemp(path);
    assert_true(fd >= 0);
    const char* broken = "{\"class_name\": \"SelectionPolygonVolume\", \"orthogonal_axis\": \"W\"}";
    assert_int_equal(write(fd, broken, strlen(broken)), (ssize_t)strlen(broken));
    close(fd);
    o3d_selection_polygon_volume_t* read = NULL;
    O3D_ASSERT_FAILS(o3d_selection_polygon_volume_read_json(&read, path), O3D_ERROR_PARSE);
    assert_null(read);
    unlink(path);
    O3D_ASSERT_FAILS(o3d_selection_polygon_volume_read_json(&read, "/nonexistent/volume.json"), O3D_ERROR_IO);
    o3d_pointcloud_destroy(pc);
    o3d_selection_polygon_volume_destroy(v);
    o3d_selection_polygon_volume_destroy(NULL);
}

/* Expected survivors of a screen selection: project each point through the view's pinhole camera. */
static size_t count_projected_inside(o3d_visualizer_t* vis, const o3d_pointcloud_t* pc, double u0, double v0,
                                     double u1, double v1) {
    o3d_pinhole_intrinsic_t k;
    double e[16];
    assert_int_equal(o3d_visualizer_view_to_pinhole(&k, e, vis), O3D_OK);
    double xyz[30 * 30 * 3];
    size_t rows = 0, n = 0;
    assert_int_equal(o3d_pointcloud_get_array(xyz, 900, &rows, pc, O3D_POINTCLOUD_POINTS), O3D_OK);
    for (size_t i = 0; i < rows; ++i) {
        const double* p = xyz + 3 * i;
        const double x = e[0] * p[0] + e[1] * p[1] + e[2] * p[2] + e[3];
        const double y = e[4] * p[0] + e[5] * p[1] + e[6] * p[2] + e[7];
        const double z = e[8] * p[0] + e[9] * p[1] + e[10] * p[2] + e[11];
        const double u = k.fx * x / z + k.cx, v = k.fy * y / z + k.cy;
        n += z > 0 && u > u0 && u < u1 && v > v0 && v < v1;
    }
    return n;
}

static void test_visualizer_crops_the_selection(void** state) {
    (void)state;
    o3d_visualizer_t* vis = NULL;
    assert_int_equal(o3d_visualizer_create(&vis, 1), O3D_OK);
    assert_int_equal(o3d_visualizer_create_window(vis, "crop", 160, 120, -1, -1, 0), O3D_OK);
    char dir[] = "/tmp/o3d_crop_XXXXXX";
    assert_non_null(mkdtemp(dir));
    assert_int_equal(o3d_visualizer_set_crop_directory(vis, dir), O3D_OK);
    o3d_pointcloud_t* pc = grid_cloud(0.0);
    assert_int_equal(o3d_visualizer_add_pointcloud(vis, "grid", pc, 1), O3D_OK);
    o3d_pointcloud_t* cropped = NULL;
    assert_int_equal(o3d_visualizer_get_cropped_pointcloud(&cropped, vis), O3D_OK);
    assert_null(cropped); /* nothing cropped yet */
    O3D_ASSERT_FAILS(o3d_visualizer_crop_to_selection(vis), O3D_ERROR_INVALID_ARGUMENT); /* no selection */

    o3d_bool selecting = 0;
    assert_int_equal(o3d_visualizer_send_key(vis, 'K', O3D_KEY_ACTION_PRESS, 0), O3D_OK);
    assert_int_equal(o3d_visualizer_is_selecting(&selecting, vis), O3D_OK);
    assert_true(selecting);
    /* Drag a rectangle from (50, 40) to (110, 80): the view must not turn while selecting. */
    double before[16], after[16];
    o3d_pinhole_intrinsic_t k;
    assert_int_equal(o3d_visualizer_view_to_pinhole(&k, before, vis), O3D_OK);
    assert_int_equal(o3d_visualizer_send_mouse_move(vis, 50, 40), O3D_OK);
    assert_int_equal(o3d_visualizer_send_mouse_button(vis, O3D_MOUSE_BUTTON_LEFT, O3D_KEY_ACTION_PRESS, 0), O3D_OK);
    assert_int_equal(o3d_visualizer_send_mouse_move(vis, 80, 60), O3D_OK);
    assert_int_equal(o3d_visualizer_send_mouse_move(vis, 110, 80), O3D_OK);
    assert_int_equal(o3d_visualizer_send_mouse_button(vis, O3D_MOUSE_BUTTON_LEFT, O3D_KEY_ACTION_RELEASE, 0), O3D_OK);
    assert_int_equal(o3d_visualizer_view_to_pinhole(&k, after, vis), O3D_OK);
    assert_true(o3d_test_max_abs_diff16(before, after) == 0.0);
    const size_t expected = count_projected_inside(vis, pc, 50, 40, 110, 80);
    assert_true(expected > 20 && expected < 900);
    assert_int_equal(o3d_visualizer_send_key(vis, 'C', O3D_KEY_ACTION_PRESS, 0), O3D_OK);
    assert_int_equal(o3d_visualizer_is_selecting(&selecting, vis), O3D_OK);
    assert_false(selecting);
    assert_int_equal(o3d_visualizer_get_cropped_pointcloud(&cropped, vis), O3D_OK);
    assert_non_null(cropped);
    assert_int_equal(cloud_size(cropped), expected);
    o3d_pointcloud_destroy(cropped);

    /* Written to the crop directory. */
    char path[128];
    snprintf(path, sizeof path, "%s/cropped_1.ply", dir);
    o3d_pointcloud_t* written = NULL;
    assert_int_equal(o3d_io_read_point_cloud(&written, path, NULL, NULL), O3D_OK);
    assert_int_equal(cloud_size(written), expected);
    o3d_pointcloud_destroy(written);
    unlink(path);
    rmdir(dir);

    /* A polygon of Ctrl + clicks on the crop: a triangle keeps fewer; K again leaves without cropping. */
    assert_int_equal(o3d_visualizer_send_key(vis, 'K', O3D_KEY_ACTION_PRESS, 0), O3D_OK);
    assert_int_equal(o3d_visualizer_send_key(vis, 'K', O3D_KEY_ACTION_PRESS, 0), O3D_OK);
    assert_int_equal(o3d_visualizer_is_selecting(&selecting, vis), O3D_OK);
    assert_false(selecting);
    O3D_ASSERT_FAILS(o3d_visualizer_crop_to_selection(vis), O3D_ERROR_INVALID_ARGUMENT);
    assert_int_equal(o3d_visualizer_set_crop_directory(vis, NULL), O3D_OK);
    assert_int_equal(o3d_visualizer_send_key(vis, 'K', O3D_KEY_ACTION_PRESS, 0), O3D_OK);
    const double corners[3][2] = {{50, 40}, {110, 40}, {50, 80}};
    for (int i = 0; i < 3; ++i) {
        assert_int_equal(o3d_visualizer_send_mouse_move(vis, corners[i][0], corners[i][1]), O3D_OK);
        assert_int_equal(o3d_visualizer_send_mouse_button(vis, O3D_MOUSE_BUTTON_LEFT, O3D_KEY_ACTION_PRESS,
                                                          O3D_KEY_MOD_CONTROL), O3D_OK);
        assert_int_equal(o3d_visualizer_send_mouse_button(vis, O3D_MOUSE_BUTTON_LEFT, O3D_KEY_ACTION_RELEASE,
                                                          O3D_KEY_MOD_CONTROL), O3D_OK);
    }
    assert_int_equal(o3d_visualizer_crop_to_selection(vis), O3D_OK);
    assert_int_equal(o3d_visualizer_get_cropped_pointcloud(&cropped, vis), O3D_OK);
    const size_t triangle = cloud_size(cropped);
    assert_true(triangle > 0 && triangle < expected);
    o3d_pointcloud_destroy(cropped);
    o3d_trianglemesh_t* mesh = NULL;
    assert_int_equal(o3d_visualizer_get_cropped_trianglemesh(&mesh, vis), O3D_OK);
    assert_null(mesh); /* the crop was of a cloud */
    o3d_pointcloud_destroy(pc);
    o3d_visualizer_destroy(vis);
}

int main(void) {
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_crop_grid_analytic),
        cmocka_unit_test(test_crop_mesh_keeps_whole_triangles),
        cmocka_unit_test(test_open3d_fragment_reference),
        cmocka_unit_test(test_volume_errors),
        cmocka_unit_test(test_visualizer_crops_the_selection),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
