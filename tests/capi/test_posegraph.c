/* SPDX-License-Identifier: MIT */
/* C API posegraph.h: building graphs, edge structs and their versioning, JSON files, global optimization
 * (a false loop closure pruned, the poses recovered, cancellation), and every function's NULL /
 * invalid-argument paths (status plus a non-empty message). */
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

#ifndef M_PI
#define M_PI 3.14159265358979323846
#endif

static const double kIdentity[16] = {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1};

/* Row-major 4x4 helpers. */
static void mat_mul(const double a[16], const double b[16], double out[16]) {
    double r[16];
    for (int i = 0; i < 4; ++i)
        for (int j = 0; j < 4; ++j) {
            double s = 0;
            for (int k = 0; k < 4; ++k) s += a[4 * i + k] * b[4 * k + j];
            r[4 * i + j] = s;
        }
    memcpy(out, r, sizeof r);
}

static void rigid_inverse(const double m[16], double out[16]) {
    double r[16] = {0};
    for (int i = 0; i < 3; ++i) {
        for (int j = 0; j < 3; ++j) r[4 * i + j] = m[4 * j + i];
        r[4 * i + 3] = -(m[i] * m[3] + m[4 + i] * m[7] + m[8 + i] * m[11]);
    }
    r[15] = 1;
    memcpy(out, r, sizeof r);
}

/* Rotation by `rad` about z, then translation. */
static void motion_z(double rad, double tx, double ty, double tz, double m[16]) {
    const double c = cos(rad), s = sin(rad);
    const double t[16] = {c, -s, 0, tx, s, c, 0, ty, 0, 0, 1, tz, 0, 0, 0, 1};
    memcpy(m, t, sizeof t);
}

/* Open3D's information matrix of point pairs on a 5 x 5 x 2 block (row-major; entry 35 = 50 pairs). */
static void information(double info[36]) {
    memset(info, 0, 36 * sizeof(double));
    for (int k = 0; k < 50; ++k) {
        const double x = 0.4 * (k % 5) - 0.8, y = 0.4 * ((k / 5) % 5) - 0.8, z = 0.3 * (k / 25) - 0.15;
        const double g[3][6] = {{0, z, -y, 1, 0, 0}, {-z, 0, x, 0, 1, 0}, {y, -x, 0, 0, 0, 1}};
        for (int r = 0; r < 3; ++r)
            for (int i = 0; i < 6; ++i)
                for (int j = 0; j < 6; ++j) info[6 * i + j] += g[r][i] * g[r][j];
    }
}

/* The true pose of node i of a ring of n. */
static void truth(int i, int n, double m[16]) {
    const double a = 2.0 * M_PI * i / n;
    motion_z(a, 2.0 * cos(a) - 2.0, 2.0 * sin(a), 0.1 * sin(2.0 * a), m);
}

/* A ring of 8 nodes started up to ~8 cm off the truth, exact odometry (certain), true closures 7 -> 0,
 * 3 -> 0, 6 -> 3 (uncertain) and one false closure 4 -> 1 (uncertain, off by 0.8 rad and ~0.8 m), last. */
static o3d_pose_graph_t* ring(void) {
    enum { N = 8 };
    o3d_pose_graph_t* g = NULL;
    assert_int_equal(o3d_pose_graph_create(&g), O3D_OK);
    for (int i = 0; i < N; ++i) {
        double pose[16], offset[16];
        truth(i, N, pose);
        motion_z(i ? 0.03 * sin(i) : 0.0, i ? 0.05 * cos(3.0 * i) : 0.0, i ? 0.05 * sin(2.0 * i) : 0.0, 0.0,
                 offset);
        mat_mul(pose, offset, pose);
        assert_int_equal(o3d_pose_graph_add_node(g, pose), O3D_OK);
    }
    const int pairs[][3] = {{0, 1, 0}, {1, 2, 0}, {2, 3, 0}, {3, 4, 0}, {4, 5, 0}, {5, 6, 0},
                            {6, 7, 0}, {7, 0, 1}, {3, 0, 1}, {6, 3, 1}, {4, 1, 1}};
    const size_t count = sizeof pairs / sizeof pairs[0];
    for (size_t k = 0; k < count; ++k) {
        o3d_pose_graph_edge_t e;
        assert_int_equal(o3d_pose_graph_edge_init(&e, sizeof e), O3D_OK);
        e.source_node_id = pairs[k][0];
        e.target_node_id = pairs[k][1];
        e.uncertain = pairs[k][2];
        double ts[16], tt[16], tt_inv[16];
        truth(e.source_node_id, N, ts);
        truth(e.target_node_id, N, tt);
        rigid_inverse(tt, tt_inv);
        mat_mul(tt_inv, ts, e.transformation);
        if (k == count - 1) {
            double wrong[16];
            motion_z(0.8, 0.6, -0.4, 0.3, wrong);
            mat_mul(wrong, e.transformation, e.transformation);
        }
        information(e.information);
        assert_int_equal(o3d_pose_graph_add_edge(g, &e), O3D_OK);
    }
    return g;
}

static void assert_same_graph(const o3d_pose_graph_t* a, const o3d_pose_graph_t* b) {
    size_t na, nb, ea, eb;
    assert_int_equal(o3d_pose_graph_num_nodes(&na, a), O3D_OK);
    assert_int_equal(o3d_pose_graph_num_nodes(&nb, b), O3D_OK);
    assert_int_equal(o3d_pose_graph_num_edges(&ea, a), O3D_OK);
    assert_int_equal(o3d_pose_graph_num_edges(&eb, b), O3D_OK);
    assert_int_equal(na, nb);
    assert_int_equal(ea, eb);
    for (size_t i = 0; i < na; ++i) {
        double pa[16], pb[16];
        assert_int_equal(o3d_pose_graph_get_node(pa, a, i), O3D_OK);
        assert_int_equal(o3d_pose_graph_get_node(pb, b, i), O3D_OK);
        assert_memory_equal(pa, pb, sizeof pa);
    }
    for (size_t k = 0; k < ea; ++k) {
        o3d_pose_graph_edge_t x, y;
        memset(&x, 0, sizeof x);
        memset(&y, 0, sizeof y);
        x.struct_size = y.struct_size = sizeof x;
        assert_int_equal(o3d_pose_graph_get_edge(&x, a, k), O3D_OK);
        assert_int_equal(o3d_pose_graph_get_edge(&y, b, k), O3D_OK);
        assert_memory_equal(&x, &y, sizeof x);
    }
}

static void test_edge_init(void** state) {
    (void)state;
    o3d_pose_graph_edge_t e;
    memset(&e, 0x7f, sizeof e);
    assert_int_equal(o3d_pose_graph_edge_init(&e, sizeof e), O3D_OK);
    assert_int_equal(e.struct_size, sizeof e);
    assert_int_equal(e.source_node_id, 0);
    assert_int_equal(e.target_node_id, 0);
    assert_memory_equal(e.transformation, kIdentity, sizeof kIdentity);
    for (int i = 0; i < 36; ++i) assert_true(e.information[i] == (i % 7 == 0 ? 1.0 : 0.0));
    assert_int_equal(e.uncertain, 0);
    assert_true(e.confidence == 1.0);
    /* An older, shorter struct: only its bytes are written. */
    memset(&e, 0x7f, sizeof e);
    const uint32_t old = (uint32_t)offsetof(o3d_pose_graph_edge_t, uncertain);
    assert_int_equal(o3d_pose_graph_edge_init(&e, old), O3D_OK);
    assert_int_equal(e.struct_size, old);
    assert_int_equal(e.uncertain, 0x7f7f7f7f);
    O3D_ASSERT_FAILS(o3d_pose_graph_edge_init(NULL, sizeof e), O3D_ERROR_INVALID_ARGUMENT);
    O3D_ASSERT_FAILS(o3d_pose_graph_edge_init(&e, 0), O3D_ERROR_INVALID_ARGUMENT);
    O3D_ASSERT_FAILS(o3d_pose_graph_edge_init(&e, 2), O3D_ERROR_INVALID_ARGUMENT);
    O3D_ASSERT_FAILS(o3d_pose_graph_edge_init(&e, sizeof e + 8), O3D_ERROR_INVALID_ARGUMENT);
}

static void test_nodes_and_edges(void** state) {
    (void)state;
    o3d_pose_graph_t* g = NULL;
    assert_int_equal(o3d_pose_graph_create(&g), O3D_OK);
    size_t n = 99;
    assert_int_equal(o3d_pose_graph_num_nodes(&n, g), O3D_OK);
    assert_int_equal(n, 0);
    assert_int_equal(o3d_pose_graph_add_node(g, NULL), O3D_OK); /* identity */
    double pose[16], out[16];
    motion_z(0.3, 1, 2, 3, pose);
    assert_int_equal(o3d_pose_graph_add_node(g, pose), O3D_OK);
    assert_int_equal(o3d_pose_graph_num_nodes(&n, g), O3D_OK);
    assert_int_equal(n, 2);
    assert_int_equal(o3d_pose_graph_get_node(out, g, 0), O3D_OK);
    assert_memory_equal(out, kIdentity, sizeof out);
    assert_int_equal(o3d_pose_graph_get_node(out, g, 1), O3D_OK);
    assert_memory_equal(out, pose, sizeof out); /* row-major in, row-major out */
    assert_int_equal(o3d_pose_graph_set_node(g, 0, pose), O3D_OK);
    assert_int_equal(o3d_pose_graph_get_node(out, g, 0), O3D_OK);
    assert_memory_equal(out, pose, sizeof out);

    o3d_pose_graph_edge_t e, back;
    assert_int_equal(o3d_pose_graph_edge_init(&e, sizeof e), O3D_OK);
    e.source_node_id = 1;
    e.target_node_id = 5; /* not checked until optimization, as Open3D builds edges first */
    memcpy(e.transformation, pose, sizeof pose);
    information(e.information);
    e.uncertain = 1;
    e.confidence = 0.25;
    assert_int_equal(o3d_pose_graph_add_edge(g, &e), O3D_OK);
    assert_int_equal(o3d_pose_graph_num_edges(&n, g), O3D_OK);
    assert_int_equal(n, 1);
    memset(&back, 0, sizeof back);
    back.struct_size = sizeof back;
    assert_int_equal(o3d_pose_graph_get_edge(&back, g, 0), O3D_OK);
    assert_memory_equal(&back, &e, sizeof e);
    e.target_node_id = 0;
    e.uncertain = 0;
    e.confidence = 1.0;
    assert_int_equal(o3d_pose_graph_set_edge(g, 0, &e), O3D_OK);
    assert_int_equal(o3d_pose_graph_get_edge(&back, g, 0), O3D_OK);
    assert_memory_equal(&back, &e, sizeof e);
    /* An older, shorter output struct gets only what fits. */
    memset(&back, 0x7f, sizeof back);
    back.struct_size = (uint32_t)offsetof(o3d_pose_graph_edge_t, information);
    assert_int_equal(o3d_pose_graph_get_edge(&back, g, 0), O3D_OK);
    assert_int_equal(back.target_node_id, 0);
    assert_int_equal(back.uncertain, 0x7f7f7f7f);

    /* Deep copy: changing the original leaves the clone alone. */
    o3d_pose_graph_t* copy = NULL;
    assert_int_equal(o3d_pose_graph_clone(&copy, g), O3D_OK);
    assert_same_graph(copy, g);
    assert_int_equal(o3d_pose_graph_clear(g), O3D_OK);
    assert_int_equal(o3d_pose_graph_num_nodes(&n, g), O3D_OK);
    assert_int_equal(n, 0);
    assert_int_equal(o3d_pose_graph_num_edges(&n, g), O3D_OK);
    assert_int_equal(n, 0);
    assert_int_equal(o3d_pose_graph_num_nodes(&n, copy), O3D_OK);
    assert_int_equal(n, 2);
    o3d_pose_graph_destroy(copy);
    o3d_pose_graph_destroy(g);
    o3d_pose_graph_destroy(NULL);
}

static void test_graph_invalid_arguments(void** state) {
    (void)state;
    o3d_pose_graph_t* g = NULL;
    o3d_pose_graph_t* out = (o3d_pose_graph_t*)&out;
    assert_int_equal(o3d_pose_graph_create(&g), O3D_OK);
    assert_int_equal(o3d_pose_graph_add_node(g, kIdentity), O3D_OK);
    double pose[16];
    size_t n;
    O3D_ASSERT_FAILS(o3d_pose_graph_create(NULL), O3D_ERROR_INVALID_ARGUMENT);
    O3D_ASSERT_FAILS(o3d_pose_graph_clone(NULL, g), O3D_ERROR_INVALID_ARGUMENT);
    O3D_ASSERT_FAILS(o3d_pose_graph_clone(&out, NULL), O3D_ERROR_INVALID_ARGUMENT);
    assert_null(out);
    O3D_ASSERT_FAILS(o3d_pose_graph_num_nodes(&n, NULL), O3D_ERROR_INVALID_ARGUMENT);
    O3D_ASSERT_FAILS(o3d_pose_graph_num_nodes(NULL, g), O3D_ERROR_INVALID_ARGUMENT);
    O3D_ASSERT_FAILS(o3d_pose_graph_num_edges(&n, NULL), O3D_ERROR_INVALID_ARGUMENT);
    O3D_ASSERT_FAILS(o3d_pose_graph_num_edges(NULL, g), O3D_ERROR_INVALID_ARGUMENT);
    O3D_ASSERT_FAILS(o3d_pose_graph_clear(NULL), O3D_ERROR_INVALID_ARGUMENT);

    /* Nodes: NULL, out of range, and poses that are not finite rigid transforms. */
    O3D_ASSERT_FAILS(o3d_pose_graph_add_node(NULL, kIdentity), O3D_ERROR_INVALID_ARGUMENT);
    O3D_ASSERT_FAILS(o3d_pose_graph_get_node(pose, NULL, 0), O3D_ERROR_INVALID_ARGUMENT);
    O3D_ASSERT_FAILS(o3d_pose_graph_get_node(NULL, g, 0), O3D_ERROR_INVALID_ARGUMENT);
    O3D_ASSERT_FAILS(o3d_pose_graph_get_node(pose, g, 1), O3D_ERROR_INVALID_ARGUMENT);
    O3D_ASSERT_FAILS(o3d_pose_graph_get_node(pose, g, (size_t)-1), O3D_ERROR_INVALID_ARGUMENT);
    O3D_ASSERT_FAILS(o3d_pose_graph_set_node(NULL, 0, kIdentity), O3D_ERROR_INVALID_ARGUMENT);
    O3D_ASSERT_FAILS(o3d_pose_graph_set_node(g, 0, NULL), O3D_ERROR_INVALID_ARGUMENT);
    O3D_ASSERT_FAILS(o3d_pose_graph_set_node(g, 1, kIdentity), O3D_ERROR_INVALID_ARGUMENT);
    const double bad_poses[][16] = {
        {NAN, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1},      /* NaN */
        {1, 0, 0, INFINITY, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1}, /* infinite translation */
        {2, 0, 0, 0, 0, 2, 0, 0, 0, 0, 2, 0, 0, 0, 0, 1},        /* a scale */
        {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, -1, 0, 0, 0, 0, 1},       /* a reflection */
        {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 1, 1},        /* last row */
    };
    for (size_t k = 0; k < sizeof bad_poses / sizeof bad_poses[0]; ++k) {
        O3D_ASSERT_FAILS(o3d_pose_graph_add_node(g, bad_poses[k]), O3D_ERROR_INVALID_ARGUMENT);
        O3D_ASSERT_FAILS(o3d_pose_graph_set_node(g, 0, bad_poses[k]), O3D_ERROR_INVALID_ARGUMENT);
    }
    assert_int_equal(o3d_pose_graph_num_nodes(&n, g), O3D_OK);
    assert_int_equal(n, 1);
    assert_int_equal(o3d_pose_graph_get_node(pose, g, 0), O3D_OK);
    assert_memory_equal(pose, kIdentity, sizeof pose);

    /* Edges: NULL, sizes, out of range, non-finite matrices, confidence outside [0, 1]. */
    o3d_pose_graph_edge_t e;
    assert_int_equal(o3d_pose_graph_edge_init(&e, sizeof e), O3D_OK);
    O3D_ASSERT_FAILS(o3d_pose_graph_add_edge(NULL, &e), O3D_ERROR_INVALID_ARGUMENT);
    O3D_ASSERT_FAILS(o3d_pose_graph_add_edge(g, NULL), O3D_ERROR_INVALID_ARGUMENT);
    O3D_ASSERT_FAILS(o3d_pose_graph_get_edge(&e, g, 0), O3D_ERROR_INVALID_ARGUMENT); /* no edges yet */
    assert_int_equal(o3d_pose_graph_add_edge(g, &e), O3D_OK);
    O3D_ASSERT_FAILS(o3d_pose_graph_get_edge(&e, NULL, 0), O3D_ERROR_INVALID_ARGUMENT);
    O3D_ASSERT_FAILS(o3d_pose_graph_get_edge(NULL, g, 0), O3D_ERROR_INVALID_ARGUMENT);
    O3D_ASSERT_FAILS(o3d_pose_graph_get_edge(&e, g, 1), O3D_ERROR_INVALID_ARGUMENT);
    O3D_ASSERT_FAILS(o3d_pose_graph_set_edge(NULL, 0, &e), O3D_ERROR_INVALID_ARGUMENT);
    O3D_ASSERT_FAILS(o3d_pose_graph_set_edge(g, 0, NULL), O3D_ERROR_INVALID_ARGUMENT);
    O3D_ASSERT_FAILS(o3d_pose_graph_set_edge(g, 1, &e), O3D_ERROR_INVALID_ARGUMENT);
    for (int which = 0; which < 7; ++which) {
        o3d_pose_graph_edge_t bad = e;
        if (which == 0) bad.struct_size = 0;
        if (which == 1) bad.struct_size = sizeof bad + 4;
        if (which == 2) bad.transformation[5] = NAN;
        if (which == 3) bad.information[35] = INFINITY;
        if (which == 4) bad.confidence = 1.5;
        if (which == 5) bad.confidence = -0.1;
        if (which == 6) bad.confidence = NAN;
        O3D_ASSERT_FAILS(o3d_pose_graph_add_edge(g, &bad), O3D_ERROR_INVALID_ARGUMENT);
        O3D_ASSERT_FAILS(o3d_pose_graph_set_edge(g, 0, &bad), O3D_ERROR_INVALID_ARGUMENT);
        o3d_pose_graph_edge_t out_edge = e;
        if (which < 2) {
            out_edge.struct_size = bad.struct_size;
            O3D_ASSERT_FAILS(o3d_pose_graph_get_edge(&out_edge, g, 0), O3D_ERROR_INVALID_ARGUMENT);
        }
    }
    assert_int_equal(o3d_pose_graph_num_edges(&n, g), O3D_OK);
    assert_int_equal(n, 1);
    o3d_pose_graph_destroy(g);
}

static void test_io(void** state) {
    (void)state;
    char path[256], bad_path[256];
    snprintf(path, sizeof path, "/tmp/o3d_test_posegraph_%d.json", (int)getpid());
    snprintf(bad_path, sizeof bad_path, "/tmp/o3d_test_posegraph_%d_bad.json", (int)getpid());
    o3d_pose_graph_t* g = ring();
    assert_int_equal(o3d_io_write_pose_graph(path, g), O3D_OK);
    o3d_pose_graph_t* back = NULL;
    assert_int_equal(o3d_io_read_pose_graph(&back, path), O3D_OK);
    assert_same_graph(back, g); /* exact */
    o3d_pose_graph_destroy(back);

    o3d_pose_graph_t* out = (o3d_pose_graph_t*)&out;
    O3D_ASSERT_FAILS(o3d_io_read_pose_graph(NULL, path), O3D_ERROR_INVALID_ARGUMENT);
    O3D_ASSERT_FAILS(o3d_io_read_pose_graph(&out, NULL), O3D_ERROR_INVALID_ARGUMENT);
    assert_null(out);
    O3D_ASSERT_FAILS(o3d_io_read_pose_graph(&out, "/nonexistent/graph.json"), O3D_ERROR_IO);
    assert_null(out);
    const char* malformed[] = {"{", "{\"class_name\": \"PointCloud\", \"nodes\": [], \"edges\": []}",
                               "{\"class_name\": \"PoseGraph\", \"nodes\": [{\"class_name\": \"PoseGraphNode\", "
                               "\"pose\": [1, 2, 3]}], \"edges\": []}"};
    for (size_t k = 0; k < sizeof malformed / sizeof malformed[0]; ++k) {
        FILE* f = fopen(bad_path, "wb");
        assert_non_null(f);
        fputs(malformed[k], f);
        fclose(f);
        O3D_ASSERT_FAILS(o3d_io_read_pose_graph(&out, bad_path), O3D_ERROR_PARSE);
        assert_null(out);
    }
    O3D_ASSERT_FAILS(o3d_io_write_pose_graph(NULL, g), O3D_ERROR_INVALID_ARGUMENT);
    O3D_ASSERT_FAILS(o3d_io_write_pose_graph(path, NULL), O3D_ERROR_INVALID_ARGUMENT);
    O3D_ASSERT_FAILS(o3d_io_write_pose_graph("/nonexistent/dir/graph.json", g), O3D_ERROR_IO);
    remove(path);
    remove(bad_path);
    o3d_pose_graph_destroy(g);
}

static void test_read_shared_file(void** state) {
    (void)state;
    O3D_C_TEST_DATA_OR_SKIP(path, "open3d/test_pose_graph.json");
    o3d_pose_graph_t* g = NULL;
    assert_int_equal(o3d_io_read_pose_graph(&g, path), O3D_OK);
    size_t n;
    assert_int_equal(o3d_pose_graph_num_nodes(&n, g), O3D_OK);
    assert_int_equal(n, 2);
    o3d_pose_graph_edge_t e;
    e.struct_size = sizeof e;
    assert_int_equal(o3d_pose_graph_get_edge(&e, g, 1), O3D_OK);
    assert_int_equal(e.source_node_id, 2);
    /* Its second edge names node 2 of 2: Open3D refuses the graph, so do we, and it stays as it was. */
    o3d_pose_graph_t* before = NULL;
    assert_int_equal(o3d_pose_graph_clone(&before, g), O3D_OK);
    O3D_ASSERT_FAILS(o3d_global_optimization(NULL, g, NULL), O3D_ERROR_INVALID_ARGUMENT);
    assert_same_graph(g, before);
    o3d_pose_graph_destroy(before);
    o3d_pose_graph_destroy(g);
}

static void test_options_init(void** state) {
    (void)state;
    o3d_global_optimization_options_t o;
    memset(&o, 0x55, sizeof o);
    assert_int_equal(o3d_global_optimization_options_init(&o, sizeof o), O3D_OK);
    assert_int_equal(o.struct_size, sizeof o);
    assert_int_equal(o.method, O3D_GLOBAL_OPTIMIZATION_LEVENBERG_MARQUARDT);
    assert_int_equal(o.max_iteration, 100);
    assert_true(o.min_relative_increment == 1e-6 && o.min_relative_residual_increment == 1e-6);
    assert_true(o.min_right_term == 1e-6 && o.min_residual == 1e-6);
    assert_int_equal(o.max_iteration_lm, 20);
    assert_true(o.upper_scale_factor == 2.0 / 3.0 && o.lower_scale_factor == 1.0 / 3.0);
    assert_true(o.max_correspondence_distance == 0.075 && o.edge_prune_threshold == 0.25);
    assert_true(o.preference_loop_closure == 1.0);
    assert_int_equal(o.reference_node, -1);
    assert_int_equal(o.num_threads, 0);
    assert_null(o.progress);
    assert_null(o.user_data);
    O3D_ASSERT_FAILS(o3d_global_optimization_options_init(NULL, sizeof o), O3D_ERROR_INVALID_ARGUMENT);
    O3D_ASSERT_FAILS(o3d_global_optimization_options_init(&o, 0), O3D_ERROR_INVALID_ARGUMENT);
    O3D_ASSERT_FAILS(o3d_global_optimization_options_init(&o, sizeof o + 8), O3D_ERROR_INVALID_ARGUMENT);
}

/* The largest entry-wise distance of the graph's poses from the truth. */
static double pose_error(const o3d_pose_graph_t* g) {
    double worst = 0;
    for (int i = 0; i < 8; ++i) {
        double p[16], t[16];
        assert_int_equal(o3d_pose_graph_get_node(p, g, (size_t)i), O3D_OK);
        truth(i, 8, t);
        for (int k = 0; k < 16; ++k) worst = fmax(worst, fabs(p[k] - t[k]));
    }
    return worst;
}

static void optimization_prunes_false_closure(int32_t method) {
    o3d_pose_graph_t* g = ring();
    assert_true(pose_error(g) > 0.04);
    o3d_global_optimization_options_t o;
    assert_int_equal(o3d_global_optimization_options_init(&o, sizeof o), O3D_OK);
    o.method = method;
    o3d_global_optimization_summary_t s;
    memset(&s, 0, sizeof s);
    s.struct_size = sizeof s;
    assert_int_equal(o3d_global_optimization(&s, g, &o), O3D_OK);
    assert_int_equal(s.struct_size, sizeof s);
    assert_int_equal(s.pruned_edges, 1);
    assert_true(s.iterations > 0);
    assert_true(s.final_residual < 1e-9 * s.initial_residual);
    size_t n;
    assert_int_equal(o3d_pose_graph_num_edges(&n, g), O3D_OK);
    assert_int_equal(n, 10);
    for (size_t k = 0; k < n; ++k) { /* the false closure 4 -> 1 was the last edge; the rest agree */
        o3d_pose_graph_edge_t e;
        e.struct_size = sizeof e;
        assert_int_equal(o3d_pose_graph_get_edge(&e, g, k), O3D_OK);
        assert_false(e.source_node_id == 4 && e.target_node_id == 1);
        assert_true(e.confidence > 1.0 - 1e-6);
    }
    /* From 5 cm off to within the default stopping tolerances; node 0 started at the truth and is the reference. */
    assert_true(pose_error(g) < 1e-5);
    o3d_pose_graph_destroy(g);
}

static void test_gauss_newton(void** state) {
    (void)state;
    optimization_prunes_false_closure(O3D_GLOBAL_OPTIMIZATION_GAUSS_NEWTON);
}

static void test_levenberg_marquardt(void** state) {
    (void)state;
    optimization_prunes_false_closure(O3D_GLOBAL_OPTIMIZATION_LEVENBERG_MARQUARDT);
}

static void test_reference_node_and_threads(void** state) {
    (void)state;
    o3d_pose_graph_t* one = ring();
    o3d_pose_graph_t* two = NULL;
    assert_int_equal(o3d_pose_graph_clone(&two, one), O3D_OK);
    double before[16], after[16];
    assert_int_equal(o3d_pose_graph_get_node(before, one, 5), O3D_OK);
    o3d_global_optimization_options_t o;
    assert_int_equal(o3d_global_optimization_options_init(&o, sizeof o), O3D_OK);
    o.reference_node = 5;
    o.num_threads = 1;
    assert_int_equal(o3d_global_optimization(NULL, one, &o), O3D_OK);
    o.num_threads = 3;
    assert_int_equal(o3d_global_optimization(NULL, two, &o), O3D_OK);
    assert_same_graph(one, two); /* bit for bit */
    assert_int_equal(o3d_pose_graph_get_node(after, one, 5), O3D_OK);
    assert_memory_equal(before, after, sizeof before);
    o3d_pose_graph_destroy(two);
    o3d_pose_graph_destroy(one);
}

static int32_t stop_at_second(double fraction, void* user_data) {
    int* calls = (int*)user_data;
    assert_true(fraction > 0.0 && fraction <= 1.0);
    return ++*calls >= 2;
}

static int32_t keep_going(double fraction, void* user_data) {
    double* last = (double*)user_data;
    assert_true(fraction >= *last);
    *last = fraction;
    return 0;
}

static void test_progress_and_cancel(void** state) {
    (void)state;
    o3d_pose_graph_t* g = ring();
    o3d_pose_graph_t* before = NULL;
    assert_int_equal(o3d_pose_graph_clone(&before, g), O3D_OK);
    o3d_global_optimization_options_t o;
    assert_int_equal(o3d_global_optimization_options_init(&o, sizeof o), O3D_OK);
    int calls = 0;
    o.progress = stop_at_second;
    o.user_data = &calls;
    o3d_global_optimization_summary_t s;
    s.struct_size = sizeof s;
    O3D_ASSERT_FAILS(o3d_global_optimization(&s, g, &o), O3D_ERROR_CANCELLED);
    assert_int_equal(calls, 2);
    assert_same_graph(g, before);
    double last = 0.0;
    o.progress = keep_going;
    o.user_data = &last;
    assert_int_equal(o3d_global_optimization(NULL, g, &o), O3D_OK);
    assert_true(last == 1.0);
    o3d_pose_graph_destroy(before);
    o3d_pose_graph_destroy(g);
}

static void test_optimization_invalid_arguments(void** state) {
    (void)state;
    o3d_pose_graph_t* g = ring();
    o3d_pose_graph_t* before = NULL;
    assert_int_equal(o3d_pose_graph_clone(&before, g), O3D_OK);
    o3d_global_optimization_options_t o;
    o3d_global_optimization_summary_t s;
    s.struct_size = sizeof s;
    O3D_ASSERT_FAILS(o3d_global_optimization(NULL, NULL, NULL), O3D_ERROR_INVALID_ARGUMENT);
    for (int which = 0; which < 12; ++which) {
        assert_int_equal(o3d_global_optimization_options_init(&o, sizeof o), O3D_OK);
        if (which == 0) o.struct_size = 0;
        if (which == 1) o.struct_size = sizeof o + 4;
        if (which == 2) o.method = 7;
        if (which == 3) o.method = -1;
        if (which == 4) o.max_iteration = -1;
        if (which == 5) o.max_iteration_lm = 0;
        if (which == 6) o.min_right_term = NAN;
        if (which == 7) o.lower_scale_factor = 0.0;
        if (which == 8) o.max_correspondence_distance = -0.1;
        if (which == 9) o.edge_prune_threshold = 2.0;
        if (which == 10) o.reference_node = 8; /* the ring has 8 nodes */
        if (which == 11) o.num_threads = -1;
        O3D_ASSERT_FAILS(o3d_global_optimization(&s, g, &o), O3D_ERROR_INVALID_ARGUMENT);
        assert_same_graph(g, before);
    }
    /* A bad summary size fails before anything is done. */
    s.struct_size = 2;
    O3D_ASSERT_FAILS(o3d_global_optimization(&s, g, NULL), O3D_ERROR_INVALID_ARGUMENT);
    s.struct_size = sizeof s + 8;
    O3D_ASSERT_FAILS(o3d_global_optimization(&s, g, NULL), O3D_ERROR_INVALID_ARGUMENT);
    assert_same_graph(g, before);
    /* An edge naming a missing node, on either side. */
    o3d_pose_graph_edge_t e;
    assert_int_equal(o3d_pose_graph_edge_init(&e, sizeof e), O3D_OK);
    e.source_node_id = 0;
    e.target_node_id = 8;
    assert_int_equal(o3d_pose_graph_add_edge(g, &e), O3D_OK);
    o3d_pose_graph_destroy(before);
    assert_int_equal(o3d_pose_graph_clone(&before, g), O3D_OK);
    O3D_ASSERT_FAILS(o3d_global_optimization(NULL, g, NULL), O3D_ERROR_INVALID_ARGUMENT);
    assert_same_graph(g, before);
    e.source_node_id = -1;
    e.target_node_id = 0;
    assert_int_equal(o3d_pose_graph_set_edge(g, 11, &e), O3D_OK);
    O3D_ASSERT_FAILS(o3d_global_optimization(NULL, g, NULL), O3D_ERROR_INVALID_ARGUMENT);
    o3d_pose_graph_destroy(before);
    o3d_pose_graph_destroy(g);
}

int main(void) {
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_edge_init),
        cmocka_unit_test(test_nodes_and_edges),
        cmocka_unit_test(test_graph_invalid_arguments),
        cmocka_unit_test(test_io),
        cmocka_unit_test(test_read_shared_file),
        cmocka_unit_test(test_options_init),
        cmocka_unit_test(test_gauss_newton),
        cmocka_unit_test(test_levenberg_marquardt),
        cmocka_unit_test(test_reference_node_and_threads),
        cmocka_unit_test(test_progress_and_cancel),
        cmocka_unit_test(test_optimization_invalid_arguments),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
