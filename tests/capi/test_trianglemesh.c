/* SPDX-License-Identifier: MIT */
/* C API trianglemesh.h (container, normals/transforms/bounds, clean-up, queries): values through the ABI,
 * NULL / invalid arguments, copy-out buffers, views, clone independence, append re-indexing. */
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

static const double kCubeVertices[] = {0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0, 0, 0, 1, 1, 0, 1, 1, 1, 1, 0, 1, 1};
static const int32_t kCubeTriangles[] = {0, 2, 1, 0, 3, 2, 4, 5, 6, 4, 6, 7, 0, 1, 5, 0, 5, 4,
                                         1, 2, 6, 1, 6, 5, 2, 3, 7, 2, 7, 6, 3, 0, 4, 3, 4, 7};

static o3d_trianglemesh_t* make_cube(void) {
    o3d_trianglemesh_t* m = NULL;
    assert_int_equal(o3d_trianglemesh_create(&m), O3D_OK);
    assert_int_equal(o3d_trianglemesh_set_array(m, O3D_MESH_VERTICES, kCubeVertices, 8), O3D_OK);
    assert_int_equal(o3d_trianglemesh_set_index_array(m, O3D_MESH_TRIANGLES, kCubeTriangles, 12), O3D_OK);
    return m;
}

static void test_arrays_views_and_copy_out(void** state) {
    (void)state;
    o3d_trianglemesh_t* m = make_cube();
    size_t n = 0;
    int32_t flag = -1;
    assert_int_equal(o3d_trianglemesh_num_vertices(&n, m), O3D_OK);
    assert_int_equal(n, 8);
    assert_int_equal(o3d_trianglemesh_num_triangles(&n, m), O3D_OK);
    assert_int_equal(n, 12);
    assert_int_equal(o3d_trianglemesh_has_array(&flag, m, O3D_MESH_TRIANGLES), O3D_OK);
    assert_int_equal(flag, 1);
    assert_int_equal(o3d_trianglemesh_has_array(&flag, m, O3D_MESH_VERTEX_COLORS), O3D_OK);
    assert_int_equal(flag, 0);

    /* An attribute counts only with the right row count. */
    const double colors[24] = {0.5};
    assert_int_equal(o3d_trianglemesh_set_array(m, O3D_MESH_VERTEX_COLORS, colors, 7), O3D_OK);
    assert_int_equal(o3d_trianglemesh_has_array(&flag, m, O3D_MESH_VERTEX_COLORS), O3D_OK);
    assert_int_equal(flag, 0);
    assert_int_equal(o3d_trianglemesh_set_array(m, O3D_MESH_VERTEX_COLORS, colors, 8), O3D_OK);
    assert_int_equal(o3d_trianglemesh_has_array(&flag, m, O3D_MESH_VERTEX_COLORS), O3D_OK);
    assert_int_equal(flag, 1);
    double uvs[72];
    for (int i = 0; i < 72; ++i) uvs[i] = i / 72.0;
    assert_int_equal(o3d_trianglemesh_set_array(m, O3D_MESH_TRIANGLE_UVS, uvs, 36), O3D_OK);
    assert_int_equal(o3d_trianglemesh_has_array(&flag, m, O3D_MESH_TRIANGLE_UVS), O3D_OK);
    assert_int_equal(flag, 1);
    double uv_out[72];
    assert_int_equal(o3d_trianglemesh_get_array(uv_out, 36, &n, m, O3D_MESH_TRIANGLE_UVS), O3D_OK);
    assert_int_equal(n, 36);
    assert_memory_equal(uv_out, uvs, sizeof uvs);

    /* Copy-out: NULL queries, a short buffer fails with the count reported. */
    double out[24];
    assert_int_equal(o3d_trianglemesh_get_array(NULL, 0, &n, m, O3D_MESH_VERTICES), O3D_OK);
    assert_int_equal(n, 8);
    O3D_ASSERT_FAILS(o3d_trianglemesh_get_array(out, 7, &n, m, O3D_MESH_VERTICES), O3D_ERROR_BUFFER_TOO_SMALL);
    assert_int_equal(n, 8);
    assert_int_equal(o3d_trianglemesh_get_array(out, 8, &n, m, O3D_MESH_VERTICES), O3D_OK);
    assert_memory_equal(out, kCubeVertices, sizeof kCubeVertices);
    int32_t tris[36];
    O3D_ASSERT_FAILS(o3d_trianglemesh_get_index_array(tris, 11, &n, m, O3D_MESH_TRIANGLES),
                     O3D_ERROR_BUFFER_TOO_SMALL);
    assert_int_equal(o3d_trianglemesh_get_index_array(tris, 12, &n, m, O3D_MESH_TRIANGLES), O3D_OK);
    assert_memory_equal(tris, kCubeTriangles, sizeof kCubeTriangles);

    /* Views see the live data; writing through the mutable ones changes the mesh. */
    const double* view = NULL;
    assert_int_equal(o3d_trianglemesh_array_view(&view, &n, m, O3D_MESH_VERTICES), O3D_OK);
    assert_int_equal(n, 8);
    assert_true(view[3] == 1.0);
    double* mview = NULL;
    assert_int_equal(o3d_trianglemesh_array_mutable_view(&mview, &n, m, O3D_MESH_VERTICES), O3D_OK);
    mview[0] = -1.0;
    double lo[3], hi[3];
    assert_int_equal(o3d_trianglemesh_get_axis_aligned_bounding_box(lo, hi, m), O3D_OK);
    assert_true(lo[0] == -1.0 && hi[2] == 1.0);
    mview[0] = 0.0;
    const int32_t* iview = NULL;
    assert_int_equal(o3d_trianglemesh_index_array_view(&iview, &n, m, O3D_MESH_TRIANGLES), O3D_OK);
    assert_int_equal(n, 12);
    assert_int_equal(iview[1], 2);
    int32_t* miview = NULL;
    assert_int_equal(o3d_trianglemesh_index_array_mutable_view(&miview, &n, m, O3D_MESH_TRIANGLES), O3D_OK);
    miview[0] = 99; /* now out of range: operations refuse, nothing is read out of bounds */
    double area = 0;
    O3D_ASSERT_FAILS(o3d_trianglemesh_get_surface_area(&area, m), INV);
    miview[0] = 0;
    assert_int_equal(o3d_trianglemesh_get_surface_area(&area, m), O3D_OK);
    assert_true(area == 6.0);
    assert_int_equal(o3d_trianglemesh_array_view(&view, &n, m, O3D_MESH_VERTEX_NORMALS), O3D_OK);
    assert_null(view);
    assert_int_equal(n, 0);

    /* Material ids. */
    const int32_t ids[12] = {0, 0, 1, 1, 2, 2, 3, 3, 4, 4, 5, 5};
    assert_int_equal(o3d_trianglemesh_set_index_array(m, O3D_MESH_TRIANGLE_MATERIAL_IDS, ids, 12), O3D_OK);
    assert_int_equal(o3d_trianglemesh_has_array(&flag, m, O3D_MESH_TRIANGLE_MATERIAL_IDS), O3D_OK);
    assert_int_equal(flag, 1);
    int32_t ids_out[12];
    assert_int_equal(o3d_trianglemesh_get_index_array(ids_out, 12, &n, m, O3D_MESH_TRIANGLE_MATERIAL_IDS), O3D_OK);
    assert_memory_equal(ids_out, ids, sizeof ids);

    assert_int_equal(o3d_trianglemesh_clear(m), O3D_OK);
    assert_int_equal(o3d_trianglemesh_num_vertices(&n, m), O3D_OK);
    assert_int_equal(n, 0);
    o3d_trianglemesh_destroy(m);
}

static void test_bad_arguments(void** state) {
    (void)state;
    o3d_trianglemesh_t* m = make_cube();
    size_t n = 0;
    int32_t flag = 0;
    double d = 0, v3[3];
    int64_t euler = 0;
    /* NULL handles and outputs. */
    O3D_ASSERT_FAILS(o3d_trianglemesh_create(NULL), INV);
    O3D_ASSERT_FAILS(o3d_trianglemesh_num_vertices(&n, NULL), INV);
    O3D_ASSERT_FAILS(o3d_trianglemesh_num_vertices(NULL, m), INV);
    O3D_ASSERT_FAILS(o3d_trianglemesh_has_array(NULL, m, O3D_MESH_VERTICES), INV);
    O3D_ASSERT_FAILS(o3d_trianglemesh_get_array(NULL, 0, NULL, m, O3D_MESH_VERTICES), INV);
    O3D_ASSERT_FAILS(o3d_trianglemesh_array_view(NULL, &n, m, O3D_MESH_VERTICES), INV);
    O3D_ASSERT_FAILS(o3d_trianglemesh_get_surface_area(&d, NULL), INV);
    O3D_ASSERT_FAILS(o3d_trianglemesh_get_volume(NULL, m), INV);
    O3D_ASSERT_FAILS(o3d_trianglemesh_is_watertight(&flag, NULL), INV);
    O3D_ASSERT_FAILS(o3d_trianglemesh_euler_poincare_characteristic(NULL, m), INV);
    O3D_ASSERT_FAILS(o3d_trianglemesh_get_center(NULL, m), INV);
    O3D_ASSERT_FAILS(o3d_trianglemesh_get_axis_aligned_bounding_box(v3, NULL, m), INV);
    O3D_ASSERT_FAILS(o3d_trianglemesh_paint_uniform_color(m, NULL), INV);
    O3D_ASSERT_FAILS(o3d_trianglemesh_transform(m, NULL), INV);
    O3D_ASSERT_FAILS(o3d_trianglemesh_translate(m, NULL, 1), INV);
    O3D_ASSERT_FAILS(o3d_trianglemesh_rotate(m, NULL, NULL), INV);
    O3D_ASSERT_FAILS(o3d_trianglemesh_append(m, NULL), INV);
    O3D_ASSERT_FAILS(o3d_trianglemesh_remove_duplicated_vertices(NULL), INV);
    O3D_ASSERT_FAILS(o3d_trianglemesh_compute_vertex_normals(NULL, 1), INV);
    O3D_ASSERT_FAILS(o3d_trianglemesh_cluster_connected_triangles(NULL, NULL, NULL, 0, NULL, &n, m), INV);
    o3d_trianglemesh_destroy(NULL);
    o3d_trianglemesh_t* out = (o3d_trianglemesh_t*)&n;
    O3D_ASSERT_FAILS(o3d_trianglemesh_clone(&out, NULL), INV);
    assert_null(out);

    /* Bad `which`, NULL data with rows, too many rows. */
    O3D_ASSERT_FAILS(o3d_trianglemesh_has_array(&flag, m, 7), INV);
    O3D_ASSERT_FAILS(o3d_trianglemesh_set_array(m, O3D_MESH_TRIANGLES, kCubeVertices, 1), INV);
    O3D_ASSERT_FAILS(o3d_trianglemesh_set_index_array(m, O3D_MESH_VERTICES, kCubeTriangles, 1), INV);
    O3D_ASSERT_FAILS(o3d_trianglemesh_get_array(NULL, 0, &n, m, -1), INV);
    O3D_ASSERT_FAILS(o3d_trianglemesh_index_array_view(NULL, &n, m, O3D_MESH_TRIANGLE_NORMALS), INV);
    O3D_ASSERT_FAILS(o3d_trianglemesh_set_array(m, O3D_MESH_VERTICES, NULL, 3), INV);
    O3D_ASSERT_FAILS(o3d_trianglemesh_set_array(m, O3D_MESH_VERTICES, kCubeVertices, SIZE_MAX / 8), INV);
    assert_int_equal(o3d_trianglemesh_num_vertices(&n, m), O3D_OK);
    assert_int_equal(n, 8); /* failed calls changed nothing */

    /* NaN parameters. */
    const double nan3[3] = {NAN, 0, 0};
    double T[16] = {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1};
    T[3] = NAN;
    O3D_ASSERT_FAILS(o3d_trianglemesh_paint_uniform_color(m, nan3), INV);
    O3D_ASSERT_FAILS(o3d_trianglemesh_translate(m, nan3, 1), INV);
    O3D_ASSERT_FAILS(o3d_trianglemesh_transform(m, T), INV);
    O3D_ASSERT_FAILS(o3d_trianglemesh_scale(m, NAN, NULL), INV);
    O3D_ASSERT_FAILS(o3d_trianglemesh_merge_close_vertices(m, NAN), INV);
    O3D_ASSERT_FAILS(o3d_trianglemesh_merge_close_vertices(m, -0.5), INV);

    /* NaN vertices are data, not errors: queries answer without crashing. */
    double* verts = NULL;
    assert_int_equal(o3d_trianglemesh_array_mutable_view(&verts, &n, m, O3D_MESH_VERTICES), O3D_OK);
    verts[0] = NAN;
    assert_int_equal(o3d_trianglemesh_is_self_intersecting(&flag, m), O3D_OK);
    assert_int_equal(o3d_trianglemesh_merge_close_vertices(m, 0.1), O3D_OK);
    assert_int_equal(o3d_trianglemesh_get_surface_area(&d, m), O3D_OK);
    assert_true(isnan(d));
    verts = NULL;
    assert_int_equal(o3d_trianglemesh_array_mutable_view(&verts, &n, m, O3D_MESH_VERTICES), O3D_OK);
    verts[0] = 0.0;

    /* Out-of-range triangle indices: every following operation refuses. */
    int32_t* tris = NULL;
    assert_int_equal(o3d_trianglemesh_index_array_mutable_view(&tris, &n, m, O3D_MESH_TRIANGLES), O3D_OK);
    tris[35] = -4;
    O3D_ASSERT_FAILS(o3d_trianglemesh_compute_vertex_normals(m, 1), INV);
    O3D_ASSERT_FAILS(o3d_trianglemesh_compute_triangle_normals(m, 1), INV);
    O3D_ASSERT_FAILS(o3d_trianglemesh_remove_duplicated_vertices(m), INV);
    O3D_ASSERT_FAILS(o3d_trianglemesh_remove_unreferenced_vertices(m), INV);
    O3D_ASSERT_FAILS(o3d_trianglemesh_remove_non_manifold_edges(m), INV);
    O3D_ASSERT_FAILS(o3d_trianglemesh_merge_close_vertices(m, 0.1), INV);
    O3D_ASSERT_FAILS(o3d_trianglemesh_is_watertight(&flag, m), INV);
    O3D_ASSERT_FAILS(o3d_trianglemesh_is_orientable(&flag, m), INV);
    O3D_ASSERT_FAILS(o3d_trianglemesh_is_vertex_manifold(&flag, m), INV);
    O3D_ASSERT_FAILS(o3d_trianglemesh_euler_poincare_characteristic(&euler, m), INV);
    O3D_ASSERT_FAILS(o3d_trianglemesh_cluster_connected_triangles(NULL, NULL, NULL, 0, &n, &n, m), INV);
    o3d_trianglemesh_t* other = make_cube();
    O3D_ASSERT_FAILS(o3d_trianglemesh_append(other, m), INV);

    /* Textures: copies in and out, index checked. */
    o3d_image_t* image = NULL;
    o3d_image_t* got = (o3d_image_t*)&n;
    O3D_ASSERT_FAILS(o3d_trianglemesh_get_texture(&got, other, 0), INV);
    assert_null(got);
    assert_int_equal(o3d_image_create(&image, 4, 2, 3, 1), O3D_OK);
    assert_int_equal(o3d_trianglemesh_add_texture(other, image), O3D_OK);
    o3d_image_destroy(image);
    assert_int_equal(o3d_trianglemesh_texture_count(&n, other), O3D_OK);
    assert_int_equal(n, 1);
    assert_int_equal(o3d_trianglemesh_get_texture(&got, other, 0), O3D_OK);
    int32_t width = 0;
    assert_int_equal(o3d_image_width(&width, got), O3D_OK);
    assert_int_equal(width, 4);
    o3d_image_destroy(got);
    O3D_ASSERT_FAILS(o3d_trianglemesh_add_texture(other, NULL), INV);
    assert_int_equal(o3d_trianglemesh_clear_textures(other), O3D_OK);
    assert_int_equal(o3d_trianglemesh_texture_count(&n, other), O3D_OK);
    assert_int_equal(n, 0);
    o3d_trianglemesh_destroy(other);
    o3d_trianglemesh_destroy(m);
}

static void test_clone_and_append(void** state) {
    (void)state;
    o3d_trianglemesh_t* a = make_cube();
    o3d_trianglemesh_t* b = NULL;
    assert_int_equal(o3d_trianglemesh_clone(&b, a), O3D_OK);
    const double shift[3] = {5, 0, 0};
    assert_int_equal(o3d_trianglemesh_translate(b, shift, 1), O3D_OK);
    double c[3];
    assert_int_equal(o3d_trianglemesh_get_center(c, a), O3D_OK); /* the clone is independent */
    assert_true(c[0] == 0.5);

    assert_int_equal(o3d_trianglemesh_append(a, b), O3D_OK);
    size_t n = 0;
    int32_t tris[72];
    assert_int_equal(o3d_trianglemesh_get_index_array(tris, 24, &n, a, O3D_MESH_TRIANGLES), O3D_OK);
    assert_int_equal(n, 24);
    for (int i = 0; i < 36; ++i) assert_int_equal(tris[36 + i], kCubeTriangles[i] + 8);
    assert_int_equal(o3d_trianglemesh_append(a, a), O3D_OK); /* self-append reads a copy */
    assert_int_equal(o3d_trianglemesh_num_triangles(&n, a), O3D_OK);
    assert_int_equal(n, 48);

    int32_t clusters[48], sizes[48];
    double areas[48];
    size_t nt = 0, nc = 0;
    O3D_ASSERT_FAILS(o3d_trianglemesh_cluster_connected_triangles(clusters, NULL, NULL, 47, &nt, &nc, a),
                     O3D_ERROR_BUFFER_TOO_SMALL);
    assert_int_equal(nt, 48);
    assert_int_equal(nc, 4);
    assert_int_equal(o3d_trianglemesh_cluster_connected_triangles(NULL, sizes, areas, 4, &nt, &nc, a), O3D_OK);
    assert_int_equal(o3d_trianglemesh_cluster_connected_triangles(clusters, sizes, areas, 48, &nt, &nc, a), O3D_OK);
    for (int i = 0; i < 48; ++i) assert_int_equal(clusters[i], i / 12);
    for (int k = 0; k < 4; ++k) {
        assert_int_equal(sizes[k], 12);
        assert_true(fabs(areas[k] - 6.0) < 1e-12);
    }
    o3d_trianglemesh_destroy(a);
    o3d_trianglemesh_destroy(b);
}

static void test_normals_transforms_and_queries(void** state) {
    (void)state;
    o3d_trianglemesh_t* m = make_cube();
    double d = 0;
    int32_t flag = 0;
    int64_t euler = 0;
    assert_int_equal(o3d_trianglemesh_get_volume(&d, m), O3D_OK);
    assert_true(fabs(d - 1.0) < 1e-15);
    assert_int_equal(o3d_trianglemesh_euler_poincare_characteristic(&euler, m), O3D_OK);
    assert_int_equal(euler, 2);
    assert_int_equal(o3d_trianglemesh_is_watertight(&flag, m), O3D_OK);
    assert_int_equal(flag, 1);
    assert_int_equal(o3d_trianglemesh_is_orientable(&flag, m), O3D_OK);
    assert_int_equal(flag, 1);
    assert_int_equal(o3d_trianglemesh_is_edge_manifold(&flag, m, 0), O3D_OK);
    assert_int_equal(flag, 1);
    assert_int_equal(o3d_trianglemesh_is_vertex_manifold(&flag, m), O3D_OK);
    assert_int_equal(flag, 1);
    assert_int_equal(o3d_trianglemesh_is_self_intersecting(&flag, m), O3D_OK);
    assert_int_equal(flag, 0);

    assert_int_equal(o3d_trianglemesh_compute_vertex_normals(m, 1), O3D_OK);
    double n0[3];
    size_t n = 0;
    const double* normals = NULL;
    assert_int_equal(o3d_trianglemesh_array_view(&normals, &n, m, O3D_MESH_VERTEX_NORMALS), O3D_OK);
    assert_int_equal(n, 8);
    memcpy(n0, normals, sizeof n0);
    assert_true(fabs(n0[0] + 1.0 / 3) < 1e-15 && fabs(n0[1] + 2.0 / 3) < 1e-15 && fabs(n0[2] + 2.0 / 3) < 1e-15);
    const double* tn = NULL;
    assert_int_equal(o3d_trianglemesh_array_view(&tn, &n, m, O3D_MESH_TRIANGLE_NORMALS), O3D_OK);
    assert_int_equal(n, 12);
    assert_true(tn[0] == 0 && tn[1] == 0 && tn[2] == -1); /* bottom face looks down */

    /* Rotate 90 degrees about z around the center: the bottom normal stays, the y = 0 face turns to +x. */
    const double R[9] = {0, -1, 0, 1, 0, 0, 0, 0, 1};
    assert_int_equal(o3d_trianglemesh_rotate(m, R, NULL), O3D_OK);
    assert_int_equal(o3d_trianglemesh_array_view(&tn, &n, m, O3D_MESH_TRIANGLE_NORMALS), O3D_OK);
    assert_true(fabs(tn[12] - 1) < 1e-15 && fabs(tn[13]) < 1e-15);
    double c[3], lo[3], hi[3];
    assert_int_equal(o3d_trianglemesh_get_center(c, m), O3D_OK);
    assert_true(fabs(c[0] - 0.5) < 1e-15 && fabs(c[1] - 0.5) < 1e-15);
    assert_int_equal(o3d_trianglemesh_scale(m, 2.0, NULL), O3D_OK);
    assert_int_equal(o3d_trianglemesh_get_min_bound(lo, m), O3D_OK);
    assert_int_equal(o3d_trianglemesh_get_max_bound(hi, m), O3D_OK);
    assert_true(fabs(lo[0] + 0.5) < 1e-15 && fabs(hi[2] - 1.5) < 1e-15);
    assert_int_equal(o3d_trianglemesh_get_volume(&d, m), O3D_OK);
    assert_true(fabs(d - 8.0) < 1e-12);
    const double T[16] = {1, 0, 0, 10, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1};
    assert_int_equal(o3d_trianglemesh_transform(m, T), O3D_OK);
    assert_int_equal(o3d_trianglemesh_get_center(c, m), O3D_OK);
    assert_true(fabs(c[0] - 10.5) < 1e-12);
    const double origin[3] = {0, 0, 0};
    assert_int_equal(o3d_trianglemesh_translate(m, origin, 0), O3D_OK);
    assert_int_equal(o3d_trianglemesh_get_center(c, m), O3D_OK);
    assert_true(fabs(c[0]) < 1e-12);
    const double rgb[3] = {0.25, 2.0, -1};
    assert_int_equal(o3d_trianglemesh_paint_uniform_color(m, rgb), O3D_OK);
    double colors[24];
    assert_int_equal(o3d_trianglemesh_get_array(colors, 8, &n, m, O3D_MESH_VERTEX_COLORS), O3D_OK);
    assert_true(colors[21] == 0.25 && colors[22] == 1.0 && colors[23] == 0.0);
    assert_int_equal(o3d_trianglemesh_compute_triangle_normals(m, 0), O3D_OK);
    assert_int_equal(o3d_trianglemesh_array_view(&tn, &n, m, O3D_MESH_TRIANGLE_NORMALS), O3D_OK);
    assert_true(fabs(tn[2] + 4.0) < 1e-12); /* (b - a) x (c - a) of a 2 x 2 face's half */
    assert_int_equal(o3d_trianglemesh_normalize_normals(m), O3D_OK);
    assert_int_equal(o3d_trianglemesh_array_view(&tn, &n, m, O3D_MESH_TRIANGLE_NORMALS), O3D_OK);
    assert_true(fabs(tn[2] + 1.0) < 1e-15);

    /* An open box has no volume. */
    assert_int_equal(o3d_trianglemesh_set_index_array(m, O3D_MESH_TRIANGLES, kCubeTriangles, 11), O3D_OK);
    O3D_ASSERT_FAILS(o3d_trianglemesh_get_volume(&d, m), INV);
    assert_int_equal(o3d_trianglemesh_is_edge_manifold(&flag, m, 1), O3D_OK);
    assert_int_equal(flag, 1);
    assert_int_equal(o3d_trianglemesh_is_edge_manifold(&flag, m, 0), O3D_OK);
    assert_int_equal(flag, 0);
    o3d_trianglemesh_destroy(m);
}

static void test_cleanup(void** state) {
    (void)state;
    /* The cube with a duplicated corner, a degenerate triangle, a repeated triangle and a stray vertex. */
    double verts[33];
    memcpy(verts, kCubeVertices, sizeof kCubeVertices);
    verts[24] = 1, verts[25] = 1, verts[26] = 1; /* vertex 8 = vertex 6 */
    verts[27] = 7, verts[28] = 7, verts[29] = 7; /* vertex 9: unused */
    verts[30] = 0.5, verts[31] = 0.5, verts[32] = 1.0 + 1e-9; /* vertex 10: next to nothing */
    int32_t tris[42];
    memcpy(tris, kCubeTriangles, sizeof kCubeTriangles);
    tris[8] = 8;                                /* triangle 2 uses the duplicate */
    tris[36] = 4, tris[37] = 5, tris[38] = 4;   /* degenerate */
    tris[39] = 6, tris[40] = 4, tris[41] = 5;   /* triangle 2 again, rotated (after merging) */
    o3d_trianglemesh_t* m = NULL;
    assert_int_equal(o3d_trianglemesh_create(&m), O3D_OK);
    assert_int_equal(o3d_trianglemesh_set_array(m, O3D_MESH_VERTICES, verts, 11), O3D_OK);
    assert_int_equal(o3d_trianglemesh_set_index_array(m, O3D_MESH_TRIANGLES, tris, 14), O3D_OK);
    int32_t flag = 1;
    assert_int_equal(o3d_trianglemesh_is_watertight(&flag, m), O3D_OK);
    assert_int_equal(flag, 0);
    size_t n = 0;
    assert_int_equal(o3d_trianglemesh_remove_duplicated_vertices(m), O3D_OK);
    assert_int_equal(o3d_trianglemesh_num_vertices(&n, m), O3D_OK);
    assert_int_equal(n, 10);
    assert_int_equal(o3d_trianglemesh_remove_degenerate_triangles(m), O3D_OK);
    assert_int_equal(o3d_trianglemesh_remove_duplicated_triangles(m), O3D_OK);
    assert_int_equal(o3d_trianglemesh_num_triangles(&n, m), O3D_OK);
    assert_int_equal(n, 12);
    assert_int_equal(o3d_trianglemesh_remove_unreferenced_vertices(m), O3D_OK);
    assert_int_equal(o3d_trianglemesh_num_vertices(&n, m), O3D_OK);
    assert_int_equal(n, 8);
    assert_int_equal(o3d_trianglemesh_remove_non_manifold_edges(m), O3D_OK);
    assert_int_equal(o3d_trianglemesh_num_triangles(&n, m), O3D_OK);
    assert_int_equal(n, 12);
    assert_int_equal(o3d_trianglemesh_is_watertight(&flag, m), O3D_OK);
    assert_int_equal(flag, 1);
    int32_t out[36];
    assert_int_equal(o3d_trianglemesh_get_index_array(out, 12, &n, m, O3D_MESH_TRIANGLES), O3D_OK);
    assert_memory_equal(out, kCubeTriangles, sizeof kCubeTriangles);

    /* Merging with eps larger than the cube's edge collapses corners greedily in vertex order. */
    assert_int_equal(o3d_trianglemesh_merge_close_vertices(m, 1.01), O3D_OK);
    assert_int_equal(o3d_trianglemesh_num_vertices(&n, m), O3D_OK);
    /* Vertex 0 takes 1, 3 and 4 (distance 1); vertex 2 takes 6; 5 and 7 are sqrt(2) from everything left. */
    assert_int_equal(n, 4);
    double merged[12];
    assert_int_equal(o3d_trianglemesh_get_array(merged, 4, &n, m, O3D_MESH_VERTICES), O3D_OK);
    assert_true(merged[0] == 0.25 && merged[1] == 0.25 && merged[2] == 0.25);
    assert_true(merged[3] == 1.0 && merged[4] == 1.0 && merged[5] == 0.5);
    o3d_trianglemesh_destroy(m);
}

int main(void) {
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_arrays_views_and_copy_out), cmocka_unit_test(test_bad_arguments),
        cmocka_unit_test(test_clone_and_append), cmocka_unit_test(test_normals_transforms_and_queries),
        cmocka_unit_test(test_cleanup),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
