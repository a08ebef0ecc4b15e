/* SPDX-License-Identifier: MIT */
/* C API io.h, triangle meshes: options, memory and file round trips of every format, the shared meshes
 * (counts recorded from Open3D 0.20 by tools/reference/record_mesh_io.py), and the error codes of bad input. */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include <cmocka.h>

#include "o3d/o3d.h"
#include "o3d_test_util.h"

/* A tetrahedron with vertex normals and colours. */
static o3d_trianglemesh_t* make_tetra(void) {
    static const double v[12] = {0, 0, 0, 1.25, 0, 0, 0, 1.5, 0, 0, 0, 1.75};
    static const double n[12] = {-0.5, -0.5, -0.5, 1, 0, 0, 0, 1, 0, 0, 0, 1};
    static const double c[12] = {0, 0, 0, 1, 0, 0, 0, 1, 0, 0.2, 0.4, 0.6};
    static const int32_t t[12] = {0, 2, 1, 0, 1, 3, 0, 3, 2, 1, 2, 3};
    o3d_trianglemesh_t* m = NULL;
    assert_int_equal(o3d_trianglemesh_create(&m), O3D_OK);
    assert_int_equal(o3d_trianglemesh_set_array(m, O3D_MESH_VERTICES, v, 4), O3D_OK);
    assert_int_equal(o3d_trianglemesh_set_array(m, O3D_MESH_VERTEX_NORMALS, n, 4), O3D_OK);
    assert_int_equal(o3d_trianglemesh_set_array(m, O3D_MESH_VERTEX_COLORS, c, 4), O3D_OK);
    assert_int_equal(o3d_trianglemesh_set_index_array(m, O3D_MESH_TRIANGLES, t, 4), O3D_OK);
    return m;
}

static size_t num_vertices(const o3d_trianglemesh_t* m) {
    size_t n = 0;
    assert_int_equal(o3d_trianglemesh_num_vertices(&n, m), O3D_OK);
    return n;
}

static size_t num_triangles(const o3d_trianglemesh_t* m) {
    size_t n = 0;
    assert_int_equal(o3d_trianglemesh_num_triangles(&n, m), O3D_OK);
    return n;
}

static int32_t has(const o3d_trianglemesh_t* m, int32_t which) {
    int32_t v = -1;
    assert_int_equal(o3d_trianglemesh_has_array(&v, m, which), O3D_OK);
    return v;
}

static void test_options_init(void** state) {
    (void)state;
    o3d_mesh_read_options_t r;
    memset(&r, 0x55, sizeof r);
    assert_int_equal(o3d_mesh_read_options_init(&r, sizeof r), O3D_OK);
    assert_int_equal(r.struct_size, sizeof r);
    assert_int_equal(r.enable_post_processing, 0);
    o3d_mesh_write_options_t w;
    memset(&w, 0x55, sizeof w);
    assert_int_equal(o3d_mesh_write_options_init(&w, sizeof w), O3D_OK);
    assert_int_equal(w.write_ascii, 0);
    assert_int_equal(w.compressed, 0);
    assert_int_equal(w.write_vertex_normals, 1);
    assert_int_equal(w.write_vertex_colors, 1);
    assert_int_equal(w.write_triangle_uvs, 1);
    /* An older, shorter struct: only its fields are written. */
    memset(&w, 0x55, sizeof w);
    assert_int_equal(o3d_mesh_write_options_init(&w, offsetof(o3d_mesh_write_options_t, write_vertex_colors)), O3D_OK);
    assert_int_equal(w.write_vertex_normals, 1);
    assert_int_equal(w.write_vertex_colors, 0x55555555);
    O3D_ASSERT_FAILS(o3d_mesh_read_options_init(NULL, sizeof r), O3D_ERROR_INVALID_ARGUMENT);
    O3D_ASSERT_FAILS(o3d_mesh_write_options_init(&w, 2), O3D_ERROR_INVALID_ARGUMENT);
    O3D_ASSERT_FAILS(o3d_mesh_write_options_init(&w, sizeof w + 4), O3D_ERROR_INVALID_ARGUMENT);
}

static void test_memory_round_trip_every_format(void** state) {
    (void)state;
    static const char* const formats[] = {"ply", "obj", "stl", "off", "glb", "gltf"};
    o3d_trianglemesh_t* m = make_tetra();
    for (size_t f = 0; f < sizeof formats / sizeof *formats; ++f) {
        for (int ascii = 0; ascii < 2; ++ascii) {
            o3d_mesh_write_options_t w;
            assert_int_equal(o3d_mesh_write_options_init(&w, sizeof w), O3D_OK);
            w.write_ascii = ascii;
            o3d_buffer_t* buf = NULL;
            assert_int_equal(o3d_io_write_triangle_mesh_to_memory(&buf, m, formats[f], &w), O3D_OK);
            const uint8_t* data = NULL;
            size_t size = 0;
            assert_int_equal(o3d_buffer_view(&data, &size, buf), O3D_OK);
            o3d_trianglemesh_t* r = NULL;
            assert_int_equal(o3d_io_read_triangle_mesh_from_memory(&r, data, size, formats[f], NULL), O3D_OK);
            const int stl = strcmp(formats[f], "stl") == 0;
            assert_int_equal(num_triangles(r), 4);
            assert_int_equal(num_vertices(r), stl ? 12 : 4);
            assert_int_equal(has(r, O3D_MESH_VERTEX_NORMALS), stl ? 0 : 1);
            assert_int_equal(has(r, O3D_MESH_VERTEX_COLORS), stl ? 0 : 1);
            assert_int_equal(has(r, O3D_MESH_TRIANGLE_NORMALS), stl);
            double v[12];
            size_t rows = 0;
            assert_int_equal(o3d_trianglemesh_get_array(v, 4, &rows, r, O3D_MESH_VERTICES), stl ? O3D_ERROR_BUFFER_TOO_SMALL : O3D_OK);
            if (!stl) assert_float_equal(v[11], 1.75, 1e-6);
            /* STL with post-processing merges the 12 corners back into 4 vertices. */
            o3d_mesh_read_options_t ro;
            assert_int_equal(o3d_mesh_read_options_init(&ro, sizeof ro), O3D_OK);
            ro.enable_post_processing = 1;
            o3d_trianglemesh_t* pp = NULL;
            assert_int_equal(o3d_io_read_triangle_mesh_from_memory(&pp, data, size, formats[f], &ro), O3D_OK);
            assert_int_equal(num_vertices(pp), 4);
            o3d_trianglemesh_destroy(pp);
            o3d_trianglemesh_destroy(r);
            o3d_buffer_destroy(buf);
        }
    }
    o3d_trianglemesh_destroy(m);
}

static void test_file_round_trip_and_auto_format(void** state) {
    (void)state;
    char dir[] = "/tmp/o3d_mesh_io_XXXXXX";
    assert_non_null(mkdtemp(dir));
    static const char* const exts[] = {"ply", "obj", "stl", "off", "gltf", "glb"};
    o3d_trianglemesh_t* m = make_tetra();
    for (size_t i = 0; i < sizeof exts / sizeof *exts; ++i) {
        char path[128];
        snprintf(path, sizeof path, "%s/tetra.%s", dir, exts[i]);
        assert_int_equal(o3d_io_write_triangle_mesh(path, m, NULL, NULL), O3D_OK);
        o3d_trianglemesh_t* r = NULL;
        assert_int_equal(o3d_io_read_triangle_mesh(&r, path, "auto", NULL), O3D_OK);
        assert_int_equal(num_triangles(r), 4);
        o3d_trianglemesh_destroy(r);
        unlink(path);
    }
    char mtl[128];
    snprintf(mtl, sizeof mtl, "%s/tetra.mtl", dir);
    assert_int_equal(access(mtl, F_OK), 0); /* OBJ writes its material library beside it */
    unlink(mtl);
    rmdir(dir);
    o3d_trianglemesh_destroy(m);
}

static void test_errors(void** state) {
    (void)state;
    o3d_trianglemesh_t* out = (o3d_trianglemesh_t*)&out;
    O3D_ASSERT_FAILS(o3d_io_read_triangle_mesh(&out, "/nonexistent/o3d/mesh.ply", NULL, NULL), O3D_ERROR_IO);
    assert_null(out);
    O3D_ASSERT_FAILS(o3d_io_read_triangle_mesh(&out, "/nonexistent/o3d/mesh.fbx", NULL, NULL), O3D_ERROR_UNSUPPORTED);
    O3D_ASSERT_FAILS(o3d_io_read_triangle_mesh(&out, "mesh.ply", "vrml", NULL), O3D_ERROR_UNSUPPORTED);
    O3D_ASSERT_FAILS(o3d_io_read_triangle_mesh(NULL, "mesh.ply", NULL, NULL), O3D_ERROR_INVALID_ARGUMENT);
    O3D_ASSERT_FAILS(o3d_io_read_triangle_mesh(&out, NULL, NULL, NULL), O3D_ERROR_INVALID_ARGUMENT);
    O3D_ASSERT_FAILS(o3d_io_read_triangle_mesh_from_memory(&out, NULL, 5, "ply", NULL), O3D_ERROR_INVALID_ARGUMENT);
    O3D_ASSERT_FAILS(o3d_io_read_triangle_mesh_from_memory(&out, (const uint8_t*)"x", 1, NULL, NULL),
                     O3D_ERROR_INVALID_ARGUMENT);

    static const char* const bad[][2] = {
        {"ply", "ply\nformat ascii 1.0\nelement vertex 1\nproperty float x\nproperty float y\nproperty float z\n"
                "element face 1\nproperty list uchar int vertex_indices\nend_header\n0 0 0\n3 0 0 1\n"},
        {"off", "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 3\n"},
        {"obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 4\n"},
        {"stl", "solid t\nfacet normal 0 0 1\nouter loop\nvertex 0 0 0\n"},
        {"gltf", "{\"asset\":"},
        {"glb", "glTF"},
    };
    for (size_t i = 0; i < sizeof bad / sizeof *bad; ++i) {
        out = (o3d_trianglemesh_t*)&out;
        O3D_ASSERT_FAILS(o3d_io_read_triangle_mesh_from_memory(&out, (const uint8_t*)bad[i][1], strlen(bad[i][1]),
                                                               bad[i][0], NULL),
                         O3D_ERROR_PARSE);
        assert_null(out);
        assert_non_null(strstr(o3d_last_error_message(), "<memory>"));
    }

    o3d_trianglemesh_t* m = make_tetra();
    const int32_t wrong[3] = {0, 1, 4};
    assert_int_equal(o3d_trianglemesh_set_index_array(m, O3D_MESH_TRIANGLES, wrong, 1), O3D_OK);
    o3d_buffer_t* buf = NULL;
    O3D_ASSERT_FAILS(o3d_io_write_triangle_mesh_to_memory(&buf, m, "ply", NULL), O3D_ERROR_INVALID_ARGUMENT);
    assert_null(buf);
    O3D_ASSERT_FAILS(o3d_io_write_triangle_mesh_to_memory(&buf, NULL, "ply", NULL), O3D_ERROR_INVALID_ARGUMENT);
    O3D_ASSERT_FAILS(o3d_io_write_triangle_mesh(NULL, m, NULL, NULL), O3D_ERROR_INVALID_ARGUMENT);
    o3d_trianglemesh_destroy(m);
    m = make_tetra();
    O3D_ASSERT_FAILS(o3d_io_write_triangle_mesh("/nonexistent/o3d/out.stl", m, NULL, NULL), O3D_ERROR_IO);
    O3D_ASSERT_FAILS(o3d_io_write_triangle_mesh("out.unknown", m, NULL, NULL), O3D_ERROR_UNSUPPORTED);
    o3d_trianglemesh_destroy(m);
}

static void test_shared_meshes(void** state) {
    (void)state;
    /* Open3D 0.20 read_triangle_mesh (tools/reference/record_mesh_io.py). */
    O3D_C_TEST_DATA_OR_SKIP(knot, "open3d/knot.ply");
    o3d_trianglemesh_t* m = NULL;
    assert_int_equal(o3d_io_read_triangle_mesh(&m, knot, NULL, NULL), O3D_OK);
    assert_int_equal(num_vertices(m), 1440);
    assert_int_equal(num_triangles(m), 2880);
    o3d_trianglemesh_destroy(m);
    O3D_C_TEST_DATA_OR_SKIP(crate, "open3d/crate/crate.obj");
    assert_int_equal(o3d_io_read_triangle_mesh(&m, crate, NULL, NULL), O3D_OK);
    assert_int_equal(num_vertices(m), 8);
    assert_int_equal(num_triangles(m), 12);
    assert_int_equal(has(m, O3D_MESH_TRIANGLE_UVS), 1);
    assert_int_equal(has(m, O3D_MESH_TRIANGLE_MATERIAL_IDS), 1);
    o3d_trianglemesh_destroy(m);
}

int main(void) {
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_options_init),
        cmocka_unit_test(test_memory_round_trip_every_format),
        cmocka_unit_test(test_file_round_trip_and_auto_format),
        cmocka_unit_test(test_errors),
        cmocka_unit_test(test_shared_meshes),
    };
    return cmocka_run_group_tests_name("o3d_mesh_io", tests, NULL, NULL);
}
