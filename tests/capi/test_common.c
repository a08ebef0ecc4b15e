/* SPDX-License-Identifier: MIT */
/* C API tests for common.h: version, thread-local errors, status names, logging, threads, buffers,
 * options struct_size checks, and parallel code in a child forked after parallel code. */
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <setjmp.h>
#include <cmocka.h>

#include <math.h>
#include <pthread.h>
#include <signal.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/wait.h>
#include <unistd.h>

#include "o3d/o3d.h"
#include "o3d_test_util.h"

/* ---- version ---- */

static void test_version_functions_equal_macros(void** state) {
    (void)state;
    char expected[64];
    assert_int_equal(o3d_version_major(), O3D_VERSION_MAJOR);
    assert_int_equal(o3d_version_minor(), O3D_VERSION_MINOR);
    assert_int_equal(o3d_version_patch(), O3D_VERSION_PATCH);
    snprintf(expected, sizeof expected, "%d.%d.%d", O3D_VERSION_MAJOR, O3D_VERSION_MINOR, O3D_VERSION_PATCH);
    assert_non_null(o3d_version());
    assert_string_equal(o3d_version(), expected);
}

/* ---- error state ---- */

static void test_clear_error_resets_code_and_message(void** state) {
    (void)state;
    O3D_ASSERT_FAILS(o3d_set_num_threads(-1), O3D_ERROR_INVALID_ARGUMENT);
    o3d_clear_error();
    assert_int_equal(o3d_last_error_code(), O3D_OK);
    assert_non_null(o3d_last_error_message());
    assert_string_equal(o3d_last_error_message(), "");
}

static void test_failure_message_names_function_and_reason(void** state) {
    (void)state;
    O3D_ASSERT_FAILS(o3d_set_num_threads(-3), O3D_ERROR_INVALID_ARGUMENT);
    assert_non_null(strstr(o3d_last_error_message(), "o3d_set_num_threads"));
    assert_non_null(strstr(o3d_last_error_message(), "num_threads"));
    O3D_ASSERT_FAILS(o3d_set_verbosity_level(17), O3D_ERROR_INVALID_ARGUMENT);
    assert_non_null(strstr(o3d_last_error_message(), "o3d_set_verbosity_level"));
}

typedef struct {
    o3d_status code_at_start;
    o3d_status code_after;
    char message_after[256];
} thread_report;

static void* fail_on_other_thread(void* arg) {
    thread_report* r = (thread_report*)arg;
    r->code_at_start = o3d_last_error_code();
    o3d_buffer_view(NULL, NULL, NULL); /* a different failure than the main thread's */
    r->code_after = o3d_last_error_code();
    snprintf(r->message_after, sizeof r->message_after, "%s", o3d_last_error_message());
    o3d_clear_error();
    return NULL;
}

static void test_error_state_is_thread_local(void** state) {
    (void)state;
    pthread_t t;
    thread_report r;
    char mine[256];
    memset(&r, 0, sizeof r);
    O3D_ASSERT_FAILS(o3d_set_num_threads(-1), O3D_ERROR_INVALID_ARGUMENT);
    snprintf(mine, sizeof mine, "%s", o3d_last_error_message());

    assert_int_equal(pthread_create(&t, NULL, fail_on_other_thread, &r), 0);
    assert_int_equal(pthread_join(t, NULL), 0);

    /* The other thread started clean and saw its own failure... */
    assert_int_equal(r.code_at_start, O3D_OK);
    assert_int_equal(r.code_after, O3D_ERROR_INVALID_ARGUMENT);
    assert_non_null(strstr(r.message_after, "o3d_buffer_view"));
    /* ...and neither its failure nor its clear_error touched this thread's state. */
    assert_int_equal(o3d_last_error_code(), O3D_ERROR_INVALID_ARGUMENT);
    assert_string_equal(o3d_last_error_message(), mine);
}

/* ---- status names ---- */

static void test_status_string_names_every_code(void** state) {
    (void)state;
    static const struct {
        o3d_status code;
        const char* name;
    } table[] = {
        {O3D_OK, "O3D_OK"},
        {O3D_ERROR_INVALID_ARGUMENT, "O3D_ERROR_INVALID_ARGUMENT"},
        {O3D_ERROR_OUT_OF_MEMORY, "O3D_ERROR_OUT_OF_MEMORY"},
        {O3D_ERROR_IO, "O3D_ERROR_IO"},
        {O3D_ERROR_PARSE, "O3D_ERROR_PARSE"},
        {O3D_ERROR_UNSUPPORTED, "O3D_ERROR_UNSUPPORTED"},
        {O3D_ERROR_BUFFER_TOO_SMALL, "O3D_ERROR_BUFFER_TOO_SMALL"},
        {O3D_ERROR_NOT_CONVERGED, "O3D_ERROR_NOT_CONVERGED"},
        {O3D_ERROR_CANCELLED, "O3D_ERROR_CANCELLED"},
        {O3D_ERROR_INTERNAL, "O3D_ERROR_INTERNAL"},
    };
    size_t i, j;
    for (i = 0; i < sizeof table / sizeof table[0]; ++i) assert_string_equal(o3d_status_string(table[i].code), table[i].name);
    /* Unknown codes still give a non-NULL name, distinct from every real one. */
    {
        const o3d_status unknown[] = {1, 42, -10, -1000, INT32_MIN, INT32_MAX};
        for (i = 0; i < sizeof unknown / sizeof unknown[0]; ++i) {
            const char* s = o3d_status_string(unknown[i]);
            assert_non_null(s);
            assert_true(s[0] != '\0');
            for (j = 0; j < sizeof table / sizeof table[0]; ++j) assert_string_not_equal(s, table[j].name);
        }
    }
}

/* ---- verbosity and log callback ---- */

static void test_verbosity_set_get_and_invalid_levels(void** state) {
    (void)state;
    const int32_t old = o3d_get_verbosity_level();
    int32_t level;
    assert_int_equal(old, O3D_LOG_WARNING); /* documented default */
    for (level = O3D_LOG_ERROR; level <= O3D_LOG_DEBUG; ++level) {
        assert_int_equal(o3d_set_verbosity_level(level), O3D_OK);
        assert_int_equal(o3d_get_verbosity_level(), level);
    }
    assert_int_equal(o3d_set_verbosity_level(O3D_LOG_INFO), O3D_OK);
    O3D_ASSERT_FAILS(o3d_set_verbosity_level(-1), O3D_ERROR_INVALID_ARGUMENT);
    O3D_ASSERT_FAILS(o3d_set_verbosity_level(4), O3D_ERROR_INVALID_ARGUMENT);
    O3D_ASSERT_FAILS(o3d_set_verbosity_level(INT32_MAX), O3D_ERROR_INVALID_ARGUMENT);
    assert_int_equal(o3d_get_verbosity_level(), O3D_LOG_INFO); /* unchanged by the failures */
    assert_int_equal(o3d_set_verbosity_level(old), O3D_OK);
}

typedef struct {
    int calls;
    int32_t last_level;
    char last_message[512];
} log_capture;

static void capture_log(int32_t level, const char* message, void* user_data) {
    log_capture* c = (log_capture*)user_data;
    c->calls++;
    c->last_level = level;
    snprintf(c->last_message, sizeof c->last_message, "%s", message);
}

static void test_log_callback_receives_debug_messages(void** state) {
    (void)state;
    log_capture cap;
    memset(&cap, 0, sizeof cap);
    assert_int_equal(o3d_set_log_callback(capture_log, &cap), O3D_OK);

    /* At the default Warning level, Debug lines are filtered out. */
    assert_int_equal(o3d_set_verbosity_level(O3D_LOG_WARNING), O3D_OK);
    assert_int_equal(o3d_set_num_threads(-2), O3D_ERROR_INVALID_ARGUMENT);
    assert_int_equal(cap.calls, 0);

    /* At Debug, the guard logs each failure with its message. */
    assert_int_equal(o3d_set_verbosity_level(O3D_LOG_DEBUG), O3D_OK);
    assert_int_equal(o3d_set_num_threads(-2), O3D_ERROR_INVALID_ARGUMENT);
    assert_int_equal(cap.calls, 1);
    assert_int_equal(cap.last_level, O3D_LOG_DEBUG);
    assert_non_null(strstr(cap.last_message, "o3d_set_num_threads"));

    /* NULL restores the default sink: no more calls to ours. */
    assert_int_equal(o3d_set_log_callback(NULL, NULL), O3D_OK);
    fprintf(stderr, "(one o3d debug line on stderr is expected next)\n");
    assert_int_equal(o3d_set_num_threads(-2), O3D_ERROR_INVALID_ARGUMENT);
    assert_int_equal(cap.calls, 1);
    assert_int_equal(o3d_set_verbosity_level(O3D_LOG_WARNING), O3D_OK);
}

/* ---- threads ---- */

static void test_num_threads_set_get(void** state) {
    (void)state;
    assert_int_equal(o3d_set_num_threads(2), O3D_OK);
    assert_int_equal(o3d_get_num_threads(), 2);
    assert_int_equal(o3d_set_num_threads(5), O3D_OK);
    assert_int_equal(o3d_get_num_threads(), 5);
    O3D_ASSERT_FAILS(o3d_set_num_threads(-1), O3D_ERROR_INVALID_ARGUMENT);
    assert_int_equal(o3d_get_num_threads(), 5); /* unchanged */
    assert_int_equal(o3d_set_num_threads(0), O3D_OK);
    assert_true(o3d_get_num_threads() >= 1);
}

/* ---- buffers ---- */

static void test_buffer_null_arguments(void** state) {
    (void)state;
    const uint8_t* data = (const uint8_t*)"x";
    size_t size = 77;
    uint8_t out[4];
    o3d_buffer_destroy(NULL); /* no-op */
    O3D_ASSERT_FAILS(o3d_buffer_view(&data, &size, NULL), O3D_ERROR_INVALID_ARGUMENT);
    O3D_ASSERT_FAILS(o3d_buffer_get_data(out, sizeof out, &size, NULL), O3D_ERROR_INVALID_ARGUMENT);
    O3D_ASSERT_FAILS(o3d_buffer_get_data(NULL, 0, &size, NULL), O3D_ERROR_INVALID_ARGUMENT);
}

static void test_buffer_view_and_copy(void** state) {
    (void)state;
    const double xyz[6] = {1, 2, 3, 4, 5, 6};
    o3d_pointcloud_t* pc = NULL;
    o3d_buffer_t* buf = NULL;
    const uint8_t* data = NULL;
    size_t size = 0, copied = 0;
    uint8_t* copy;
    assert_int_equal(o3d_pointcloud_create(&pc), O3D_OK);
    assert_int_equal(o3d_pointcloud_set_array(pc, O3D_POINTCLOUD_POINTS, xyz, 2), O3D_OK);
    assert_int_equal(o3d_io_write_point_cloud_to_memory(&buf, pc, "xyz", NULL), O3D_OK);
    o3d_pointcloud_destroy(pc);

    O3D_ASSERT_FAILS(o3d_buffer_view(NULL, &size, buf), O3D_ERROR_INVALID_ARGUMENT);
    O3D_ASSERT_FAILS(o3d_buffer_view(&data, NULL, buf), O3D_ERROR_INVALID_ARGUMENT);
    assert_int_equal(o3d_buffer_view(&data, &size, buf), O3D_OK);
    assert_true(size > 10);
    assert_non_null(data);

    /* Size query, too-small copy, exact copy. */
    assert_int_equal(o3d_buffer_get_data(NULL, 0, &copied, buf), O3D_OK);
    assert_int_equal(copied, size);
    copy = (uint8_t*)malloc(size);
    assert_non_null(copy);
    O3D_ASSERT_FAILS(o3d_buffer_get_data(copy, size - 1, &copied, buf), O3D_ERROR_BUFFER_TOO_SMALL);
    assert_int_equal(copied, size);
    assert_int_equal(o3d_buffer_get_data(copy, size, &copied, buf), O3D_OK);
    assert_memory_equal(copy, data, size);
    assert_non_null(memchr(copy, '4', size));
    free(copy);
    o3d_buffer_destroy(buf);
}

/* ---- options struct_size ---- */

#define CHECK_INIT_SIZES(type, init_fn)                                                           \
    do {                                                                                          \
        type opts;                                                                                \
        unsigned char raw[sizeof(type) + 16];                                                     \
        O3D_ASSERT_FAILS(init_fn(NULL, (uint32_t)sizeof(type)), O3D_ERROR_INVALID_ARGUMENT);      \
        O3D_ASSERT_FAILS(init_fn(&opts, 0), O3D_ERROR_INVALID_ARGUMENT);                          \
        O3D_ASSERT_FAILS(init_fn(&opts, 2), O3D_ERROR_INVALID_ARGUMENT);                          \
        O3D_ASSERT_FAILS(init_fn((type*)(void*)raw, (uint32_t)sizeof(type) + 1), O3D_ERROR_INVALID_ARGUMENT); \
        O3D_ASSERT_FAILS(init_fn((type*)(void*)raw, (uint32_t)sizeof(type) + 16), O3D_ERROR_INVALID_ARGUMENT); \
        O3D_ASSERT_FAILS(init_fn(&opts, UINT32_MAX), O3D_ERROR_INVALID_ARGUMENT);                 \
        assert_int_equal(init_fn(&opts, (uint32_t)sizeof(type)), O3D_OK);                        \
        assert_int_equal(opts.struct_size, sizeof(type));                                        \
    } while (0)

static void test_options_init_rejects_bad_struct_size(void** state) {
    (void)state;
    CHECK_INIT_SIZES(o3d_search_param_t, o3d_search_param_init);
    CHECK_INIT_SIZES(o3d_read_options_t, o3d_read_options_init);
    CHECK_INIT_SIZES(o3d_write_options_t, o3d_write_options_init);
    CHECK_INIT_SIZES(o3d_icp_options_t, o3d_icp_options_init);
}

static void test_options_init_fills_defaults(void** state) {
    (void)state;
    o3d_search_param_t sp;
    o3d_read_options_t ro;
    o3d_write_options_t wo;
    o3d_icp_options_t io;
    assert_int_equal(o3d_search_param_init(&sp, sizeof sp), O3D_OK);
    assert_int_equal(sp.kind, O3D_SEARCH_KNN);
    assert_int_equal(sp.knn, 30);
    assert_true(sp.radius == 0.0);
    assert_int_equal(o3d_read_options_init(&ro, sizeof ro), O3D_OK);
    assert_int_equal(ro.remove_nan_points, 0);
    assert_int_equal(ro.remove_infinite_points, 0);
    assert_int_equal(o3d_write_options_init(&wo, sizeof wo), O3D_OK);
    assert_int_equal(wo.write_ascii, 0);
    assert_int_equal(wo.compressed, 0);
    assert_int_equal(o3d_icp_options_init(&io, sizeof io), O3D_OK);
    assert_int_equal(io.estimation, O3D_ESTIMATION_POINT_TO_POINT);
    assert_int_equal(io.with_scaling, 0);
    assert_true(io.relative_fitness == 1e-6);
    assert_true(io.relative_rmse == 1e-6);
    assert_int_equal(io.max_iteration, 30);
    assert_int_equal(io.num_threads, 0);
    assert_null(io.progress);
    assert_null(io.user_data);
}

static void test_options_init_older_smaller_size_writes_only_prefix(void** state) {
    (void)state;
    o3d_search_param_t sp;
    const uint32_t old_size = (uint32_t)offsetof(o3d_search_param_t, radius);
    memset(&sp, 0xAB, sizeof sp);
    assert_int_equal(o3d_search_param_init(&sp, old_size), O3D_OK);
    assert_int_equal(sp.struct_size, old_size);
    assert_int_equal(sp.knn, 30);
    {
        unsigned char expected[sizeof sp.radius];
        memset(expected, 0xAB, sizeof expected);
        assert_memory_equal(&sp.radius, expected, sizeof expected); /* beyond the old size: untouched */
    }
}

/* ---- fork after parallel code ---- */

#define FORK_POINTS 4000

static void make_wavy_surface(double* xyz, size_t n) {
    size_t i;
    for (i = 0; i < n; ++i) {
        const double x = (double)(i % 64) * 0.02, y = (double)(i / 64) * 0.02;
        xyz[3 * i + 0] = x;
        xyz[3 * i + 1] = y;
        xyz[3 * i + 2] = 0.1 * sin(3.0 * x) * cos(2.0 * y);
    }
}

static int estimate(double* normals_out, size_t n) {
    static double xyz[3 * FORK_POINTS];
    o3d_pointcloud_t* pc = NULL;
    o3d_search_param_t sp;
    size_t got = 0;
    int ok;
    make_wavy_surface(xyz, n);
    if (o3d_pointcloud_create(&pc) != O3D_OK) return 0;
    ok = o3d_pointcloud_set_array(pc, O3D_POINTCLOUD_POINTS, xyz, n) == O3D_OK && o3d_search_param_init(&sp, sizeof sp) == O3D_OK;
    if (ok) {
        sp.kind = O3D_SEARCH_HYBRID;
        sp.radius = 0.1;
        sp.knn = 20;
        ok = o3d_pointcloud_estimate_normals(pc, &sp, 4) == O3D_OK &&
             o3d_pointcloud_get_array(normals_out, n, &got, pc, O3D_POINTCLOUD_NORMALS) == O3D_OK && got == n;
    }
    o3d_pointcloud_destroy(pc);
    return ok;
}

static void test_parallel_call_in_forked_child_completes(void** state) {
    (void)state;
    static double parent_normals[3 * FORK_POINTS];
    pid_t pid;
    int status = 0;
    /* Parallel code in the parent first: libgomp's thread pool now exists and will not survive fork. */
    assert_true(estimate(parent_normals, FORK_POINTS));
    fflush(NULL);
    pid = fork();
    assert_true(pid >= 0);
    if (pid == 0) {
        static double child_normals[3 * FORK_POINTS];
        alarm(30); /* a hang becomes SIGALRM, i.e. a failure, instead of blocking CI */
        if (!estimate(child_normals, FORK_POINTS)) _exit(2);
        /* Deterministic: same normals as in the parent, whatever thread count the child used. */
        if (memcmp(child_normals, parent_normals, sizeof child_normals) != 0) _exit(3);
        _exit(0);
    }
    assert_int_equal(waitpid(pid, &status, 0), pid);
    if (WIFSIGNALED(status)) fail_msg("child killed by signal %d (SIGALRM=%d means it hung)", WTERMSIG(status), SIGALRM);
    assert_true(WIFEXITED(status));
    assert_int_equal(WEXITSTATUS(status), 0);
}

int main(void) {
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_version_functions_equal_macros),
        cmocka_unit_test(test_clear_error_resets_code_and_message),
        cmocka_unit_test(test_failure_message_names_function_and_reason),
        cmocka_unit_test(test_error_state_is_thread_local),
        cmocka_unit_test(test_status_string_names_every_code),
        cmocka_unit_test(test_verbosity_set_get_and_invalid_levels),
        cmocka_unit_test(test_log_callback_receives_debug_messages),
        cmocka_unit_test(test_num_threads_set_get),
        cmocka_unit_test(test_buffer_null_arguments),
        cmocka_unit_test(test_buffer_view_and_copy),
        cmocka_unit_test(test_options_init_rejects_bad_struct_size),
        cmocka_unit_test(test_options_init_fills_defaults),
        cmocka_unit_test(test_options_init_older_smaller_size_writes_only_prefix),
        cmocka_unit_test(test_parallel_call_in_forked_child_completes),
    };
    return cmocka_run_group_tests_name("o3d_common", tests, NULL, NULL);
}
