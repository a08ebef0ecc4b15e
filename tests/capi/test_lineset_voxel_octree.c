/* SPDX-License-Identifier: MIT */
/* C API line sets, voxel grids and octrees (lineset.h, voxelgrid.h, octree.h): results through the ABI,
 * copy-out conventions, NULL handles and outputs, bad parameters, out-of-range indices. Reference numbers
 * from Open3D 0.20 are recorded by tools/reference/record_lineset_voxel_octree.py; the algorithms are
 * checked in depth in tests/core/{line_set,voxel_grid,octree}_test.cpp. */
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <setjmp.h>
#include <cmocka.h>

#include <math.h>
#include <string.h>

#include "o3d/o3d.h"
#include "o3d_test_util.h"

#define INV O3D_ERROR_INVALID_ARGUMENT

static double dist3(const double* a, const double* b) {
    return sqrt((a[0] - b[0]) * (a[0] - b[0]) + (a[1] - b[1]) * (a[1] - b[1]) + (a[2] - b[2]) * (a[2] - b[2]));
}

static o3d_pointcloud_t* make_cloud(const double* xyz, size_t n) {
    o3d_pointcloud_t* pc = NULL;
    assert_int_equal(o3d_pointcloud_create(&pc), O3D_OK);
    assert_int_equal(o3d_pointcloud_set_array(pc, O3D_POINTCLOUD_POINTS, xyz, n), O3D_OK);
    return pc;
}

static void test_lineset_container(void** state) {
    (void)state;
    o3d_lineset_t* ls = NULL;
    assert_int_equal(o3d_lineset_create(&ls), O3D_OK);
    const double pts[9] = {0, 0, 0, 3, 4, 0, 0, 0, 2};
    const int32_t lines[4] = {0, 1, 1, 2};
    assert_int_equal(o3d_lineset_set_array(ls, O3D_LINESET_POINTS, pts, 3), O3D_OK);
    assert_int_equal(o3d_lineset_set_index_array(ls, O3D_LINESET_LINES, lines, 2), O3D_OK);
    size_t n = 0;
    assert_int_equal(o3d_lineset_num_points(&n, ls), O3D_OK);
    assert_int_equal(n, 3);
    assert_int_equal(o3d_lineset_num_lines(&n, ls), O3D_OK);
    assert_int_equal(n, 2);
    const double rgb[3] = {0.25, 0.5, 2.0};
    assert_int_equal(o3d_lineset_paint_uniform_color(ls, rgb), O3D_OK);
    double colors[6];
    assert_int_equal(o3d_lineset_get_array(colors, 2, &n, ls, O3D_LINESET_COLORS), O3D_OK);
    assert_int_equal(n, 2);
    assert_true(colors[3] == 0.25 && colors[4] == 0.5 && colors[5] == 1.0);  // clamped
    const double t[16] = {1, 0, 0, 1, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1};
    assert_int_equal(o3d_lineset_transform(ls, t), O3D_OK);
    const double* view = NULL;
    assert_int_equal(o3d_lineset_array_view(&view, &n, ls, O3D_LINESET_POINTS), O3D_OK);
    assert_int_equal(n, 3);
    assert_true(view[0] == 1.0 && view[3] == 4.0);
    const int32_t* lv = NULL;
    assert_int_equal(o3d_lineset_index_array_view(&lv, &n, ls, O3D_LINESET_LINES), O3D_OK);
    assert_int_equal(n, 2);
    assert_int_equal(lv[3], 2);
    int32_t small[2];
    O3D_ASSERT_FAILS(o3d_lineset_get_index_array(small, 1, &n, ls, O3D_LINESET_LINES), O3D_ERROR_BUFFER_TOO_SMALL);
    assert_int_equal(n, 2);
    o3d_lineset_t* copy = NULL;
    assert_int_equal(o3d_lineset_clone(&copy, ls), O3D_OK);
    assert_int_equal(o3d_lineset_num_lines(&n, copy), O3D_OK);
    assert_int_equal(n, 2);

    O3D_ASSERT_FAILS(o3d_lineset_set_array(ls, 7, pts, 3), INV);
    O3D_ASSERT_FAILS(o3d_lineset_set_array(ls, O3D_LINESET_POINTS, NULL, 3), INV);
    O3D_ASSERT_FAILS(o3d_lineset_num_points(&n, NULL), INV);
    O3D_ASSERT_FAILS(o3d_lineset_num_points(NULL, ls), INV);
    O3D_ASSERT_FAILS(o3d_lineset_transform(ls, NULL), INV);
    O3D_ASSERT_FAILS(o3d_lineset_clone(NULL, ls), INV);
    o3d_lineset_destroy(copy);
    o3d_lineset_destroy(ls);
    o3d_lineset_destroy(NULL);
}

static void test_lineset_builders(void** state) {
    (void)state;
    /* Axis-aligned box 1 x 2 x 3: 8 points, 12 lines, four of each length. */
    const double lo[3] = {0, 0, 0}, hi[3] = {1, 2, 3};
    o3d_lineset_t* ls = NULL;
    assert_int_equal(o3d_lineset_create_from_axis_aligned_bounding_box(&ls, lo, hi), O3D_OK);
    double pts[24];
    int32_t lines[24];
    size_t np = 0, nl = 0;
    assert_int_equal(o3d_lineset_get_array(pts, 8, &np, ls, O3D_LINESET_POINTS), O3D_OK);
    assert_int_equal(o3d_lineset_get_index_array(lines, 12, &nl, ls, O3D_LINESET_LINES), O3D_OK);
    assert_int_equal(np, 8);
    assert_int_equal(nl, 12);
    int count[4] = {0, 0, 0, 0};
    for (size_t i = 0; i < nl; ++i) {
        const double len = dist3(pts + 3 * lines[2 * i], pts + 3 * lines[2 * i + 1]);
        const int k = (int)lround(len);
        assert_true(fabs(len - k) < 1e-12 && k >= 1 && k <= 3);
        ++count[k];
    }
    assert_true(count[1] == 4 && count[2] == 4 && count[3] == 4);
    o3d_lineset_destroy(ls);

    /* The same box as an oriented box gives the same points (Open3D's get_box_points order). */
    const o3d_obb_t obb = {{0.5, 1, 1.5}, {1, 0, 0, 0, 1, 0, 0, 0, 1}, {1, 2, 3}};
    assert_int_equal(o3d_lineset_create_from_oriented_bounding_box(&ls, &obb), O3D_OK);
    double pts2[24];
    assert_int_equal(o3d_lineset_get_array(pts2, 8, &np, ls, O3D_LINESET_POINTS), O3D_OK);
    for (int i = 0; i < 24; ++i) assert_true(fabs(pts[i] - pts2[i]) < 1e-12);
    /* Open3D: corner 7 is (+x, +y, -z). */
    assert_true(pts2[21] == 1 && pts2[22] == 2 && pts2[23] == 0);
    o3d_lineset_destroy(ls);

    /* Correspondences: line i joins cloud0[pairs[i][0]] and cloud1[pairs[i][1]]. */
    const double a[6] = {0, 0, 0, 1, 0, 0}, b[9] = {0, 5, 0, 1, 5, 0, 2, 5, 0};
    o3d_pointcloud_t* c0 = make_cloud(a, 2);
    o3d_pointcloud_t* c1 = make_cloud(b, 3);
    const int32_t pairs[4] = {0, 2, 1, 0};
    assert_int_equal(o3d_lineset_create_from_point_cloud_correspondences(&ls, c0, c1, pairs, 2), O3D_OK);
    assert_int_equal(o3d_lineset_get_index_array(lines, 12, &nl, ls, O3D_LINESET_LINES), O3D_OK);
    assert_int_equal(nl, 2);
    assert_true(lines[0] == 0 && lines[1] == 4 && lines[2] == 1 && lines[3] == 2);
    o3d_lineset_destroy(ls);
    const int32_t bad[2] = {0, 3};
    ls = (o3d_lineset_t*)1;
    O3D_ASSERT_FAILS(o3d_lineset_create_from_point_cloud_correspondences(&ls, c0, c1, bad, 1), INV);
    assert_null(ls);
    O3D_ASSERT_FAILS(o3d_lineset_create_from_point_cloud_correspondences(&ls, NULL, c1, pairs, 2), INV);
    O3D_ASSERT_FAILS(o3d_lineset_create_from_point_cloud_correspondences(&ls, c0, c1, NULL, 2), INV);
    O3D_ASSERT_FAILS(o3d_lineset_create_from_axis_aligned_bounding_box(&ls, hi, lo), INV);
    O3D_ASSERT_FAILS(o3d_lineset_create_from_oriented_bounding_box(&ls, NULL), INV);
    o3d_pointcloud_destroy(c0);
    o3d_pointcloud_destroy(c1);

    /* A tetrahedron has 6 unique edges; an out-of-range triangle index is an error. */
    const double v[12] = {0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1};
    int32_t t[12] = {0, 1, 2, 0, 3, 1, 0, 2, 3, 1, 3, 2};
    o3d_trianglemesh_t* m = NULL;
    assert_int_equal(o3d_trianglemesh_create(&m), O3D_OK);
    assert_int_equal(o3d_trianglemesh_set_array(m, O3D_MESH_VERTICES, v, 4), O3D_OK);
    assert_int_equal(o3d_trianglemesh_set_index_array(m, O3D_MESH_TRIANGLES, t, 4), O3D_OK);
    assert_int_equal(o3d_lineset_create_from_triangle_mesh(&ls, m), O3D_OK);
    assert_int_equal(o3d_lineset_num_lines(&nl, ls), O3D_OK);
    assert_int_equal(nl, 6);
    o3d_lineset_destroy(ls);
    t[11] = 9;
    assert_int_equal(o3d_trianglemesh_set_index_array(m, O3D_MESH_TRIANGLES, t, 4), O3D_OK);
    O3D_ASSERT_FAILS(o3d_lineset_create_from_triangle_mesh(&ls, m), INV);
    o3d_trianglemesh_destroy(m);
}

static void test_voxelgrid(void** state) {
    (void)state;
    /* Unit-cube corners with voxel 0.5: origin -0.25, corners at even indices 0 and 2. */
    double xyz[24], rgb[24];
    for (int i = 0; i < 8; ++i) {
        xyz[3 * i] = i & 1, xyz[3 * i + 1] = (i >> 1) & 1, xyz[3 * i + 2] = (i >> 2) & 1;
        rgb[3 * i] = 0.1 * i, rgb[3 * i + 1] = 0.5, rgb[3 * i + 2] = 1.0;
    }
    o3d_pointcloud_t* pc = make_cloud(xyz, 8);
    assert_int_equal(o3d_pointcloud_set_array(pc, O3D_POINTCLOUD_COLORS, rgb, 8), O3D_OK);
    o3d_voxelgrid_t* g = NULL;
    assert_int_equal(o3d_voxelgrid_create_from_point_cloud(&g, pc, 0.5), O3D_OK);
    double origin[3], size = 0;
    assert_int_equal(o3d_voxelgrid_get_origin(origin, g), O3D_OK);
    assert_int_equal(o3d_voxelgrid_get_voxel_size(&size, g), O3D_OK);
    assert_true(origin[0] == -0.25 && origin[1] == -0.25 && origin[2] == -0.25 && size == 0.5);
    size_t n = 0;
    assert_int_equal(o3d_voxelgrid_num_voxels(&n, g), O3D_OK);
    assert_int_equal(n, 8);
    int32_t idx[24];
    double col[24];
    O3D_ASSERT_FAILS(o3d_voxelgrid_get_index_array(idx, 7, &n, g, O3D_VOXELGRID_GRID_INDEX), O3D_ERROR_BUFFER_TOO_SMALL);
    assert_int_equal(n, 8);
    assert_int_equal(o3d_voxelgrid_get_index_array(idx, 8, &n, g, O3D_VOXELGRID_GRID_INDEX), O3D_OK);
    assert_int_equal(o3d_voxelgrid_get_array(col, 8, &n, g, O3D_VOXELGRID_COLORS), O3D_OK);
    O3D_ASSERT_FAILS(o3d_voxelgrid_get_array(col, 8, &n, g, O3D_VOXELGRID_GRID_INDEX), O3D_ERROR_INVALID_ARGUMENT);
    /* Sorted by (x, y, z): voxel r has index 2 * (bits of r, x most significant) and corner (z, y, x)'s color. */
    for (int r = 0; r < 8; ++r) {
        const int x = (r >> 2) & 1, y = (r >> 1) & 1, z = r & 1;
        assert_int_equal(idx[3 * r], 2 * x);
        assert_int_equal(idx[3 * r + 1], 2 * y);
        assert_int_equal(idx[3 * r + 2], 2 * z);
        assert_true(fabs(col[3 * r] - 0.1 * (x + 2 * y + 4 * z)) < 1e-12);
    }
    const double q[9] = {1, 1, 1, 0.5, 0.5, 0.5, 0.1, 0.0, 0.9};
    int32_t inc[3], cell[3];
    assert_int_equal(o3d_voxelgrid_check_if_included(inc, 3, &n, g, q, 3), O3D_OK);
    assert_int_equal(n, 3);
    O3D_ASSERT_FAILS(o3d_voxelgrid_check_if_included(inc, 2, &n, g, q, 3), O3D_ERROR_BUFFER_TOO_SMALL);
    assert_true(inc[0] == 1 && inc[1] == 0 && inc[2] == 1);
    assert_int_equal(o3d_voxelgrid_get_voxel(cell, g, q + 3), O3D_OK);
    assert_true(cell[0] == 1 && cell[1] == 1 && cell[2] == 1);
    o3d_voxelgrid_destroy(g);

    /* Within bounds: only the corners inside [0, 0.5]^3 count. */
    const double lo[3] = {0, 0, 0}, hi[3] = {0.5, 0.5, 0.5};
    assert_int_equal(o3d_voxelgrid_create_from_point_cloud_within_bounds(&g, pc, 0.5, lo, hi), O3D_OK);
    assert_int_equal(o3d_voxelgrid_num_voxels(&n, g), O3D_OK);
    assert_int_equal(n, 1);
    o3d_voxelgrid_destroy(g);

    g = (o3d_voxelgrid_t*)1;
    O3D_ASSERT_FAILS(o3d_voxelgrid_create_from_point_cloud(&g, pc, 0.0), INV);
    assert_null(g);
    O3D_ASSERT_FAILS(o3d_voxelgrid_create_from_point_cloud(&g, pc, NAN), INV);
    O3D_ASSERT_FAILS(o3d_voxelgrid_create_from_point_cloud(&g, NULL, 0.5), INV);
    O3D_ASSERT_FAILS(o3d_voxelgrid_create_from_point_cloud_within_bounds(&g, pc, 0.5, hi, lo), INV);
    O3D_ASSERT_FAILS(o3d_voxelgrid_create_from_point_cloud_within_bounds(&g, pc, 0.5, NULL, hi), INV);
    O3D_ASSERT_FAILS(o3d_voxelgrid_create_from_triangle_mesh(&g, NULL, 0.5), INV);
    O3D_ASSERT_FAILS(o3d_voxelgrid_num_voxels(&n, NULL), INV);
    o3d_pointcloud_t* empty = NULL;
    assert_int_equal(o3d_pointcloud_create(&empty), O3D_OK);
    O3D_ASSERT_FAILS(o3d_voxelgrid_create_from_point_cloud(&g, empty, 0.5), INV);
    o3d_pointcloud_destroy(empty);
    o3d_pointcloud_destroy(pc);
    o3d_voxelgrid_destroy(NULL);

    /* A flat triangle in z = 0.3: every voxel is in the one layer holding the plane. */
    const double v[9] = {0, 0, 0.3, 2, 0, 0.3, 0, 2, 0.3};
    const int32_t t[3] = {0, 1, 2};
    o3d_trianglemesh_t* m = NULL;
    assert_int_equal(o3d_trianglemesh_create(&m), O3D_OK);
    assert_int_equal(o3d_trianglemesh_set_array(m, O3D_MESH_VERTICES, v, 3), O3D_OK);
    assert_int_equal(o3d_trianglemesh_set_index_array(m, O3D_MESH_TRIANGLES, t, 1), O3D_OK);
    assert_int_equal(o3d_voxelgrid_create_from_triangle_mesh(&g, m, 0.25), O3D_OK);
    assert_int_equal(o3d_voxelgrid_get_array(NULL, 0, &n, g, O3D_VOXELGRID_COLORS), O3D_OK);
    assert_int_equal(n, 53); /* cells (i, j) of the 9 x 9 layer with i + j <= 9: 81 - 28 */
    int32_t cells[159];
    assert_int_equal(o3d_voxelgrid_get_index_array(cells, 53, &n, g, O3D_VOXELGRID_GRID_INDEX), O3D_OK);
    for (size_t i = 0; i < n; ++i) assert_int_equal(cells[3 * i + 2], 0);
    o3d_voxelgrid_destroy(g);
    o3d_trianglemesh_destroy(m);
}

static void test_voxelgrid_reference(void** state) {
    (void)state;
    O3D_C_TEST_DATA_OR_SKIP(path, "open3d/Feature/cloud_bin_0.pcd");
    o3d_pointcloud_t* pc = NULL;
    assert_int_equal(o3d_io_read_point_cloud(&pc, path, NULL, NULL), O3D_OK);
    o3d_voxelgrid_t* g = NULL;
    assert_int_equal(o3d_voxelgrid_create_from_point_cloud(&g, pc, 0.05), O3D_OK);
    size_t n = 0;
    assert_int_equal(o3d_voxelgrid_num_voxels(&n, g), O3D_OK);
    assert_int_equal(n, 2655); /* Open3D 0.20 */
    int32_t* idx = (int32_t*)test_malloc(3 * n * sizeof(int32_t));
    assert_int_equal(o3d_voxelgrid_get_index_array(idx, n, &n, g, O3D_VOXELGRID_GRID_INDEX), O3D_OK);
    long long checksum = 0;
    for (size_t r = 0; r < n; ++r)
        checksum += (long long)(r + 1) * (idx[3 * r] + 1009LL * idx[3 * r + 1] + 1009LL * 1009LL * idx[3 * r + 2]);
    assert_true(checksum == 44848341670868LL); /* Open3D 0.20, sorted as o3d exports */
    test_free(idx);
    o3d_voxelgrid_destroy(g);
    o3d_pointcloud_destroy(pc);
}

static void test_octree(void** state) {
    (void)state;
    double xyz[24];
    for (int i = 0; i < 8; ++i) xyz[3 * i] = i & 1, xyz[3 * i + 1] = (i >> 1) & 1, xyz[3 * i + 2] = (i >> 2) & 1;
    o3d_pointcloud_t* pc = make_cloud(xyz, 8);
    o3d_octree_t* tree = NULL;
    assert_int_equal(o3d_octree_create(&tree, 1), O3D_OK);
    size_t n = 99;
    assert_int_equal(o3d_octree_num_leaf_nodes(&n, tree), O3D_OK);
    assert_int_equal(n, 0);
    assert_int_equal(o3d_octree_convert_from_point_cloud(tree, pc, 0.01), O3D_OK);
    double origin[3], size = 0;
    int32_t depth = 0;
    assert_int_equal(o3d_octree_get_root(origin, &size, &depth, tree), O3D_OK);
    assert_true(origin[0] == 0 && origin[1] == 0 && origin[2] == 0 && fabs(size - 1.01) < 1e-15 && depth == 1);
    assert_int_equal(o3d_octree_num_leaf_nodes(&n, tree), O3D_OK);
    assert_int_equal(n, 8);
    for (int i = 0; i < 8; ++i) {
        int32_t found = 0, ind[4];
        o3d_octree_node_info_t info;
        double color[3];
        assert_int_equal(o3d_octree_locate_leaf_node(&found, &info, color, ind, 4, &n, tree, xyz + 3 * i), O3D_OK);
        assert_int_equal(found, 1);
        assert_int_equal(n, 1);
        assert_int_equal(ind[0], i);
        assert_int_equal(info.depth, 1);
        assert_int_equal(info.child_index, i);
        assert_true(fabs(info.size - 0.505) < 1e-15);
        for (int k = 0; k < 3; ++k)
            assert_true(xyz[3 * i + k] >= info.origin[k] && xyz[3 * i + k] < info.origin[k] + info.size);
    }
    const double outside[3] = {5, 5, 5};
    int32_t found = 1;
    assert_int_equal(o3d_octree_locate_leaf_node(&found, NULL, NULL, NULL, 0, &n, tree, outside), O3D_OK);
    assert_int_equal(found, 0);
    int32_t one[1];
    O3D_ASSERT_FAILS(o3d_octree_locate_leaf_node(&found, NULL, NULL, one, 0, &n, tree, xyz), O3D_ERROR_BUFFER_TOO_SMALL);

    o3d_octree_t* bad = (o3d_octree_t*)1;
    O3D_ASSERT_FAILS(o3d_octree_create(&bad, 0), INV);
    assert_null(bad);
    O3D_ASSERT_FAILS(o3d_octree_create(&bad, 64), INV);
    O3D_ASSERT_FAILS(o3d_octree_convert_from_point_cloud(tree, pc, -1.0), INV);
    O3D_ASSERT_FAILS(o3d_octree_convert_from_point_cloud(tree, NULL, 0.01), INV);
    O3D_ASSERT_FAILS(o3d_octree_convert_from_point_cloud(NULL, pc, 0.01), INV);
    O3D_ASSERT_FAILS(o3d_octree_locate_leaf_node(&found, NULL, NULL, NULL, 0, &n, tree, NULL), INV);
    O3D_ASSERT_FAILS(o3d_octree_num_leaf_nodes(&n, NULL), INV);
    /* A failed rebuild leaves the tree as it was. */
    assert_int_equal(o3d_octree_num_leaf_nodes(&n, tree), O3D_OK);
    assert_int_equal(n, 8);
    o3d_octree_destroy(tree);
    o3d_octree_destroy(NULL);
    o3d_pointcloud_destroy(pc);
}

static void test_octree_reference(void** state) {
    (void)state;
    O3D_C_TEST_DATA_OR_SKIP(path, "open3d/Feature/cloud_bin_0.pcd");
    o3d_pointcloud_t* pc = NULL;
    assert_int_equal(o3d_io_read_point_cloud(&pc, path, NULL, NULL), O3D_OK);
    o3d_octree_t* tree = NULL;
    assert_int_equal(o3d_octree_create(&tree, 4), O3D_OK);
    assert_int_equal(o3d_octree_convert_from_point_cloud(tree, pc, 0.01), O3D_OK);
    size_t n = 0;
    assert_int_equal(o3d_octree_num_leaf_nodes(&n, tree), O3D_OK);
    assert_int_equal(n, 472); /* Open3D 0.20 */
    double p[3];
    size_t rows = 0;
    const double* view = NULL;
    assert_int_equal(o3d_pointcloud_array_view(&view, &rows, pc, O3D_POINTCLOUD_POINTS), O3D_OK);
    memcpy(p, view + 3 * 1000, sizeof p);
    int32_t found = 0, ind[16];
    o3d_octree_node_info_t info;
    assert_int_equal(o3d_octree_locate_leaf_node(&found, &info, NULL, ind, 16, &n, tree, p), O3D_OK);
    assert_int_equal(found, 1);
    assert_int_equal(n, 12);
    assert_true(ind[0] == 473 && ind[4] == 1000 && ind[11] == 3453);
    assert_int_equal(info.depth, 4);
    assert_int_equal(info.child_index, 1);
    assert_true(fabs(info.size - 0.1319891678763088) < 1e-12);
    assert_true(fabs(info.origin[0] - 2.760767922949744) < 1e-12);
    o3d_octree_destroy(tree);
    o3d_pointcloud_destroy(pc);
}

int main(void) {
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_lineset_container), cmocka_unit_test(test_lineset_builders),
        cmocka_unit_test(test_voxelgrid),         cmocka_unit_test(test_voxelgrid_reference),
        cmocka_unit_test(test_octree),            cmocka_unit_test(test_octree_reference),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
