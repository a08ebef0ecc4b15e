/* SPDX-License-Identifier: MIT */
/* C API voxel-grid editing and octree building (voxelgrid.h, octree.h): dense grids, adding and removing voxels, cell
 * centres and corners, mesh voxelization within bounds, carving with a synthetic silhouette, and the conversions
 * between octrees and voxel grids, against analytic answers; NULL / bad input. */
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

static size_t voxel_count(const o3d_voxelgrid_t* g) {
    size_t n = 0;
    assert_int_equal(o3d_voxelgrid_num_voxels(&n, g), O3D_OK);
    return n;
}

/* A 1 x 0.5 x 0.25 block of voxels of 0.25: 4 x 2 x 1 voxels; centres at origin + (i + 1/2) * size. */
static void test_dense_grid_cells_and_edits(void** state) {
    (void)state;
    const double origin[3] = {1.0, 2.0, 3.0}, red[3] = {1, 0, 0};
    o3d_voxelgrid_t* g = NULL;
    assert_int_equal(o3d_voxelgrid_create_dense(&g, origin, red, 0.25, 1.0, 0.5, 0.25), O3D_OK);
    assert_int_equal(voxel_count(g), 8);
    const int32_t idx[3] = {3, 1, 0};
    double c[3], corners[24];
    assert_int_equal(o3d_voxelgrid_get_voxel_center_coordinate(c, g, idx), O3D_OK);
    assert_true(fabs(c[0] - 1.875) < 1e-12 && fabs(c[1] - 2.375) < 1e-12 && fabs(c[2] - 3.125) < 1e-12);
    assert_int_equal(o3d_voxelgrid_get_voxel_bounding_points(corners, g, idx), O3D_OK);
    for (int k = 0; k < 8; ++k) /* every corner is the centre +- half a voxel on each axis */
        for (int d = 0; d < 3; ++d) assert_true(fabs(fabs(corners[3 * k + d] - c[d]) - 0.125) < 1e-12);
    /* Add a new voxel and replace an old one's color; remove one; removing a missing one does nothing. */
    const int32_t fresh[3] = {-1, 0, 0}, old[3] = {0, 0, 0}, missing[3] = {9, 9, 9};
    const double blue[3] = {0, 0, 1};
    assert_int_equal(o3d_voxelgrid_add_voxel(g, fresh, blue), O3D_OK);
    assert_int_equal(o3d_voxelgrid_add_voxel(g, old, blue), O3D_OK);
    assert_int_equal(voxel_count(g), 9);
    int32_t found[3];
    const double probe[3] = {1.1, 2.1, 3.1};
    assert_int_equal(o3d_voxelgrid_get_voxel(found, g, probe), O3D_OK);
    assert_true(found[0] == 0 && found[1] == 0 && found[2] == 0);
    double colors[3 * 9];
    int32_t indices[3 * 9];
    size_t rows = 0;
    assert_int_equal(o3d_voxelgrid_get_index_array(indices, 9, &rows, g, O3D_VOXELGRID_GRID_INDEX), O3D_OK);
    assert_int_equal(o3d_voxelgrid_get_array(colors, 9, &rows, g, O3D_VOXELGRID_COLORS), O3D_OK);
    assert_int_equal(indices[0], -1); /* sorted by index: the new voxel first */
    assert_true(colors[2] == 1.0 && colors[3 + 2] == 1.0 && colors[6] == 1.0); /* (-1,0,0) and (0,0,0) blue */
    assert_int_equal(o3d_voxelgrid_remove_voxel(g, fresh), O3D_OK);
    assert_int_equal(o3d_voxelgrid_remove_voxel(g, missing), O3D_OK);
    assert_int_equal(voxel_count(g), 8);
    const double nan3[3] = {NAN, 0, 0};
    O3D_ASSERT_FAILS(o3d_voxelgrid_add_voxel(g, fresh, nan3), INV);
    O3D_ASSERT_FAILS(o3d_voxelgrid_add_voxel(NULL, fresh, blue), INV);
    o3d_voxelgrid_destroy(g);
    g = (o3d_voxelgrid_t*)1;
    O3D_ASSERT_FAILS(o3d_voxelgrid_create_dense(&g, origin, red, 0.0, 1, 1, 1), INV);
    assert_null(g);
    O3D_ASSERT_FAILS(o3d_voxelgrid_create_dense(&g, origin, red, 1e-6, 1e3, 1e3, 1e3), INV); /* 1e27 voxels */
}

/* A triangle in z = 0.1 over [0, 1]^2 within bounds [0, 0.5]^2 x [0, 0.5]: only cells of the half-open box, all
 * in the layer k = 0. */
static void test_mesh_voxels_within_bounds(void** state) {
    (void)state;
    o3d_trianglemesh_t* m = NULL;
    assert_int_equal(o3d_trianglemesh_create(&m), O3D_OK);
    const double v[9] = {0, 0, 0.1, 1, 0, 0.1, 0, 1, 0.1};
    const int32_t t[3] = {0, 1, 2};
    assert_int_equal(o3d_trianglemesh_set_array(m, O3D_MESH_VERTICES, v, 3), O3D_OK);
    assert_int_equal(o3d_trianglemesh_set_index_array(m, O3D_MESH_TRIANGLES, t, 1), O3D_OK);
    const double lo[3] = {0, 0, 0}, hi[3] = {0.5, 0.5, 0.5};
    o3d_voxelgrid_t* g = NULL;
    assert_int_equal(o3d_voxelgrid_create_from_triangle_mesh_within_bounds(&g, m, 0.125, lo, hi), O3D_OK);
    const size_t n = voxel_count(g);
    assert_true(n >= 16 && n <= 25); /* the 4 x 4 cells below the bound, plus at most the boundary layer */
    int32_t* idx = malloc(3 * n * sizeof(int32_t));
    size_t rows = 0;
    assert_int_equal(o3d_voxelgrid_get_index_array(idx, n, &rows, g, O3D_VOXELGRID_GRID_INDEX), O3D_OK);
    for (size_t i = 0; i < n; ++i) {
        assert_true(idx[3 * i] >= 0 && idx[3 * i] <= 4 && idx[3 * i + 1] >= 0 && idx[3 * i + 1] <= 4);
        assert_int_equal(idx[3 * i + 2], 0);
    }
    free(idx);
    o3d_voxelgrid_destroy(g);
    O3D_ASSERT_FAILS(o3d_voxelgrid_create_from_triangle_mesh_within_bounds(&g, m, 0.125, hi, lo), INV);
    o3d_trianglemesh_destroy(m);
}

/* A camera at the origin looking down +z at a dense cube around z = 3; a silhouette mask of the left half of the
 * image keeps exactly the voxels with a corner projecting there (x < 0 side), a full mask keeps everything, an
 * empty one removes everything. */
static void test_carve_silhouette(void** state) {
    (void)state;
    const double origin[3] = {-0.5, -0.5, 2.5}, white[3] = {1, 1, 1};
    const o3d_pinhole_intrinsic_t K = {64, 64, 50.0, 50.0, 31.5, 31.5};
    const double E[16] = {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1};
    o3d_image_t* mask = NULL;
    assert_int_equal(o3d_image_create(&mask, 64, 64, 1, 4), O3D_OK);
    uint8_t* bytes = NULL;
    size_t rows = 0;
    assert_int_equal(o3d_image_array_mutable_view(&bytes, &rows, mask, O3D_IMAGE_DATA), O3D_OK);
    float* px = (float*)bytes;
    for (int v = 0; v < 64; ++v)
        for (int u = 0; u < 64; ++u) px[64 * v + u] = 1.0f;
    o3d_voxelgrid_t* g = NULL;
    assert_int_equal(o3d_voxelgrid_create_dense(&g, origin, white, 0.1, 1.0, 1.0, 1.0), O3D_OK);
    assert_int_equal(voxel_count(g), 1000);
    assert_int_equal(o3d_voxelgrid_carve_silhouette(g, mask, &K, E, 0), O3D_OK);
    assert_int_equal(voxel_count(g), 1000);
    for (int v = 0; v < 64; ++v)
        for (int u = 32; u < 64; ++u) px[64 * v + u] = 0.0f; /* keep the left half (u < 32: x < 0) */
    assert_int_equal(o3d_voxelgrid_carve_silhouette(g, mask, &K, E, 0), O3D_OK);
    const size_t left = voxel_count(g);
    assert_true(left >= 500 && left < 1000);
    double* colors = malloc(3 * left * sizeof(double));
    int32_t* idx = malloc(3 * left * sizeof(int32_t));
    assert_int_equal(o3d_voxelgrid_get_index_array(idx, left, &rows, g, O3D_VOXELGRID_GRID_INDEX), O3D_OK);
    for (size_t i = 0; i < left; ++i) assert_true(idx[3 * i] <= 5); /* no voxel wholly on the x > 0 side */
    free(colors);
    free(idx);
    /* Bad input: a uint8 mask, an intrinsic of another size, a non-rigid extrinsic. */
    o3d_image_t* small = NULL;
    assert_int_equal(o3d_image_create(&small, 64, 64, 1, 1), O3D_OK);
    O3D_ASSERT_FAILS(o3d_voxelgrid_carve_silhouette(g, small, &K, E, 0), INV);
    const o3d_pinhole_intrinsic_t K2 = {32, 32, 50.0, 50.0, 15.5, 15.5};
    O3D_ASSERT_FAILS(o3d_voxelgrid_carve_depth_map(g, mask, &K2, E, 0), INV);
    const double scaled[16] = {2, 0, 0, 0, 0, 2, 0, 0, 0, 0, 2, 0, 0, 0, 0, 1};
    O3D_ASSERT_FAILS(o3d_voxelgrid_carve_depth_map(g, mask, &K, scaled, 0), INV);
    O3D_ASSERT_FAILS(o3d_voxelgrid_carve_depth_map(g, NULL, &K, E, 0), INV);
    memset(px, 0, 64 * 64 * sizeof(float));
    assert_int_equal(o3d_voxelgrid_carve_silhouette(g, mask, &K, E, 0), O3D_OK);
    assert_int_equal(voxel_count(g), 0);
    o3d_image_destroy(small);
    o3d_image_destroy(mask);
    o3d_voxelgrid_destroy(g);
}

/* Points inserted one by one into an octree of depth 3 over [0, 8)^3 land in unit leaves; the octree's voxel grid
 * has one unit voxel per leaf, and rebuilding an octree from that grid gives the same leaves. */
static void test_octree_insert_and_voxel_conversion(void** state) {
    (void)state;
    const double origin[3] = {0, 0, 0};
    o3d_octree_t* tree = NULL;
    assert_int_equal(o3d_octree_create_with_bounds(&tree, 3, origin, 8.0), O3D_OK);
    const double pts[4][3] = {{0.5, 0.5, 0.5}, {0.7, 0.2, 0.9}, {7.5, 3.5, 1.5}, {4.0, 4.0, 4.0}};
    const double colors[4][3] = {{1, 0, 0}, {0, 0, 1}, {0, 1, 0}, {1, 1, 1}};
    for (int i = 0; i < 4; ++i) {
        int32_t inserted = 0;
        assert_int_equal(o3d_octree_insert_point(&inserted, tree, pts[i], i, colors[i]), O3D_OK);
        assert_int_equal(inserted, 1);
    }
    const double outside[3] = {8.0, 1.0, 1.0};
    int32_t inserted = 1;
    assert_int_equal(o3d_octree_insert_point(&inserted, tree, outside, 4, colors[0]), O3D_OK);
    assert_int_equal(inserted, 0);
    size_t leaves = 0;
    assert_int_equal(o3d_octree_num_leaf_nodes(&leaves, tree), O3D_OK);
    assert_int_equal(leaves, 3); /* points 0 and 1 share the unit cell (0, 0, 0) */
    int32_t in = -1;
    assert_int_equal(o3d_octree_is_point_in_bound(&in, outside, origin, 8.0), O3D_OK);
    assert_int_equal(in, 0);
    assert_int_equal(o3d_octree_is_point_in_bound(&in, pts[2], origin, 8.0), O3D_OK);
    assert_int_equal(in, 1);
    o3d_voxelgrid_t* g = NULL;
    assert_int_equal(o3d_voxelgrid_create_from_octree(&g, tree), O3D_OK);
    assert_int_equal(voxel_count(g), 3);
    double size = 0.0;
    assert_int_equal(o3d_voxelgrid_get_voxel_size(&size, g), O3D_OK);
    assert_true(size == 1.0);
    double c[3 * 3];
    size_t rows = 0;
    assert_int_equal(o3d_voxelgrid_get_array(c, 3, &rows, g, O3D_VOXELGRID_COLORS), O3D_OK);
    assert_true(fabs(c[0] - 0.5) < 1e-12 && fabs(c[2] - 0.5) < 1e-12); /* the mean of red and blue */
    o3d_octree_t* back = NULL;
    assert_int_equal(o3d_octree_create(&back, 3), O3D_OK);
    assert_int_equal(o3d_octree_create_from_voxel_grid(back, g), O3D_OK);
    assert_int_equal(o3d_octree_num_leaf_nodes(&leaves, back), O3D_OK);
    assert_int_equal(leaves, 3);
    const double nan3[3] = {NAN, 0, 0};
    O3D_ASSERT_FAILS(o3d_octree_insert_point(&inserted, tree, nan3, 0, colors[0]), INV);
    O3D_ASSERT_FAILS(o3d_octree_insert_point(&inserted, tree, pts[0], -1, colors[0]), INV);
    o3d_octree_t* bad = NULL;
    O3D_ASSERT_FAILS(o3d_octree_create_with_bounds(&bad, 0, origin, 8.0), INV);
    O3D_ASSERT_FAILS(o3d_octree_create_with_bounds(&bad, 3, origin, -1.0), INV);
    O3D_ASSERT_FAILS(o3d_octree_create_from_voxel_grid(back, NULL), INV);
    o3d_octree_destroy(back);
    o3d_voxelgrid_destroy(g);
    o3d_octree_destroy(tree);
}

int main(void) {
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_dense_grid_cells_and_edits),
        cmocka_unit_test(test_mesh_voxels_within_bounds),
        cmocka_unit_test(test_carve_silhouette),
        cmocka_unit_test(test_octree_insert_and_voxel_conversion),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
