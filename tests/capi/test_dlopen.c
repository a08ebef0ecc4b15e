/* SPDX-License-Identifier: MIT */
/* libo3d.so through dlopen/dlsym only (this test does not link libo3d; the headers give typedefs):
 * every public function resolves, the list below matches the headers, a small pipeline runs through
 * function pointers, the version matches, and internal C++ symbols are not resolvable. */
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <setjmp.h>
#include <cmocka.h>

#include <dirent.h>
#include <dlfcn.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "o3d/o3d.h"

#ifndef O3D_LIB_PATH
#error "O3D_LIB_PATH must name the built libo3d.so"
#endif

static void* g_lib = NULL;

/* Every function declared in capi/include/o3d/\*.h, derived from the headers at build time
 * (tools/capi_model.py --c-names); test_list_matches_headers parses the headers itself as a cross-check. */
static const char* const k_api[] = {
#include "o3d_api_functions.inc"
};
#define API_COUNT (sizeof k_api / sizeof k_api[0])

static int group_setup(void** state) {
    (void)state;
    /* Only dlclose-safe because libo3d is linked with -z nodelete (libgomp workers); we never close it. */
    g_lib = dlopen(O3D_LIB_PATH, RTLD_NOW | RTLD_LOCAL);
    if (!g_lib) fprintf(stderr, "dlopen(%s): %s\n", O3D_LIB_PATH, dlerror());
    return g_lib ? 0 : -1;
}

static void* sym(const char* name) {
    void* p;
    dlerror();
    p = dlsym(g_lib, name);
    if (!p) fail_msg("dlsym(%s): %s", name, dlerror());
    return p;
}

/* Convert a dlsym'd object pointer to a function pointer (POSIX guarantees this works). */
#define LOAD(var, name) memcpy(&(var), &(void*){sym(name)}, sizeof(var))

static void test_every_public_function_resolves(void** state) {
    size_t i;
    (void)state;
    for (i = 0; i < API_COUNT; ++i) assert_non_null(sym(k_api[i]));
}

/* ---- the static list equals the O3D_API declarations in the headers ---- */

static int in_list(const char* name) {
    size_t i;
    for (i = 0; i < API_COUNT; ++i)
        if (strcmp(k_api[i], name) == 0) return 1;
    return 0;
}

/* Append the name of every `O3D_API ... name(` declaration in `text` to names[]. */
static size_t scan_declarations(const char* text, char names[][96], size_t count, size_t max) {
    const char* p = text;
    while ((p = strstr(p, "O3D_API")) != NULL) {
        const char* line = p;
        const char *paren, *end, *begin;
        while (line > text && line[-1] != '\n') --line;
        p += 7;
        if (strstr(line, "#define") && strstr(line, "#define") < p) continue; /* the macro itself */
        if (*line == '#') continue;
        paren = strchr(p, '(');
        if (!paren) break;
        end = paren;
        while (end > p && (end[-1] == ' ' || end[-1] == '\n')) --end;
        begin = end;
        while (begin > p && (begin[-1] == '_' || (begin[-1] >= 'a' && begin[-1] <= 'z') ||
                             (begin[-1] >= 'A' && begin[-1] <= 'Z') || (begin[-1] >= '0' && begin[-1] <= '9')))
            --begin;
        if (count < max && end > begin && (size_t)(end - begin) < 96) {
            memcpy(names[count], begin, (size_t)(end - begin));
            names[count][end - begin] = '\0';
            ++count;
        }
        p = paren;
    }
    return count;
}

static void test_list_matches_headers(void** state) {
    /* Every function declared in the public headers (O3D_PUBLIC_HEADER_DIR) is in k_api. */
    static char names[512][96];
    char dir[4096], path[4200];
    DIR* d;
    struct dirent* e;
    size_t count = 0, i, j, headers = 0;
    (void)state;
    /* An absolute path from CMake: __FILE__ may be relative (ccache base_dir, out-of-tree builds). */
    snprintf(dir, sizeof dir, "%s", O3D_PUBLIC_HEADER_DIR);
    d = opendir(dir);
    if (!d) fail_msg("cannot open the public header folder %s", dir);
    while ((e = readdir(d)) != NULL) {
        FILE* f;
        long size;
        char* text;
        const size_t len = strlen(e->d_name);
        if (len < 3 || strcmp(e->d_name + len - 2, ".h") != 0) continue;
        snprintf(path, sizeof path, "%s/%s", dir, e->d_name);
        f = fopen(path, "rb");
        assert_non_null(f);
        fseek(f, 0, SEEK_END);
        size = ftell(f);
        fseek(f, 0, SEEK_SET);
        text = (char*)calloc((size_t)size + 1, 1);
        assert_non_null(text);
        assert_int_equal(fread(text, 1, (size_t)size, f), (size_t)size);
        fclose(f);
        count = scan_declarations(text, names, count, 512);
        free(text);
        ++headers;
    }
    closedir(d);
    assert_true(headers >= 5);
    for (i = 0; i < count; ++i)
        if (!in_list(names[i])) fail_msg("%s is declared in the headers but missing from test_dlopen.c", names[i]);
    for (i = 0; i < API_COUNT; ++i) {
        int found = 0;
        for (j = 0; j < count && !found; ++j) found = strcmp(names[j], k_api[i]) == 0;
        if (!found) fail_msg("%s is in test_dlopen.c but not declared in any header", k_api[i]);
    }
    assert_int_equal(count, API_COUNT);
}

/* ---- version and errors through pointers ---- */

static void test_version_matches_header(void** state) {
    const char* (*version)(void);
    int32_t (*major)(void);
    int32_t (*minor)(void);
    char expected[64];
    (void)state;
    LOAD(version, "o3d_version");
    LOAD(major, "o3d_version_major");
    LOAD(minor, "o3d_version_minor");
    snprintf(expected, sizeof expected, "%d.%d.%d", O3D_VERSION_MAJOR, O3D_VERSION_MINOR, O3D_VERSION_PATCH);
    assert_string_equal(version(), expected);
    assert_int_equal(major(), O3D_VERSION_MAJOR);
    assert_int_equal(minor(), O3D_VERSION_MINOR);
}

static void test_error_through_pointers(void** state) {
    o3d_status (*set_num_threads)(int32_t);
    const char* (*message)(void);
    o3d_status (*code)(void);
    (void)state;
    LOAD(set_num_threads, "o3d_set_num_threads");
    LOAD(message, "o3d_last_error_message");
    LOAD(code, "o3d_last_error_code");
    assert_int_equal(set_num_threads(-1), O3D_ERROR_INVALID_ARGUMENT);
    assert_int_equal(code(), O3D_ERROR_INVALID_ARGUMENT);
    assert_true(message()[0] != '\0');
}

/* ---- a small pipeline through function pointers ---- */

static void test_pipeline_through_pointers(void** state) {
    o3d_status (*create)(o3d_pointcloud_t**);
    void (*destroy)(o3d_pointcloud_t*);
    o3d_status (*set_array)(o3d_pointcloud_t*, int32_t, const double*, size_t);
    o3d_status (*voxel)(o3d_pointcloud_t**, const o3d_pointcloud_t*, double);
    o3d_status (*size)(size_t*, const o3d_pointcloud_t*);
    o3d_status (*get_array)(double*, size_t, size_t*, const o3d_pointcloud_t*, int32_t);
    o3d_pointcloud_t *pc = NULL, *down = NULL;
    /* 8 tight clusters (5x5x5 points, spacing 0.01) at the corners of a cube of side 10: voxel size 1
     * keeps one point per cluster, their means, wherever the voxel grid starts. */
    static double xyz[3 * 1000];
    double out[3 * 8];
    size_t n = 0, i;
    (void)state;
    LOAD(create, "o3d_pointcloud_create");
    LOAD(destroy, "o3d_pointcloud_destroy");
    LOAD(set_array, "o3d_pointcloud_set_array");
    LOAD(voxel, "o3d_pointcloud_voxel_down_sample");
    LOAD(size, "o3d_pointcloud_size");
    LOAD(get_array, "o3d_pointcloud_get_array");
    for (i = 0; i < 1000; ++i) {
        const size_t c = i / 125, l = i % 125;
        xyz[3 * i + 0] = 10.0 * (double)(c & 1) + 0.01 * (double)(l % 5);
        xyz[3 * i + 1] = 10.0 * (double)((c >> 1) & 1) + 0.01 * (double)((l / 5) % 5);
        xyz[3 * i + 2] = 10.0 * (double)((c >> 2) & 1) + 0.01 * (double)(l / 25);
    }
    assert_int_equal(create(&pc), O3D_OK);
    assert_int_equal(set_array(pc, O3D_POINTCLOUD_POINTS, xyz, 1000), O3D_OK);
    assert_int_equal(size(&n, pc), O3D_OK);
    assert_int_equal(n, 1000);
    assert_int_equal(voxel(&down, pc, 1.0), O3D_OK);
    assert_non_null(down);
    assert_int_equal(size(&n, down), O3D_OK);
    assert_int_equal(n, 8);
    assert_int_equal(get_array(out, 8, &n, down, O3D_POINTCLOUD_POINTS), O3D_OK);
    for (i = 0; i < 24; ++i) {
        const double d0 = out[i] - 0.02, d1 = out[i] - 10.02;
        if (!((d0 > -1e-9 && d0 < 1e-9) || (d1 > -1e-9 && d1 < 1e-9))) fail_msg("coordinate %zu = %.17g", i, out[i]);
    }
    destroy(down);
    destroy(pc);
    destroy(NULL);
}

/* ---- nothing but o3d_* is exported ---- */

static void test_internal_symbols_are_hidden(void** state) {
    /* Mangled names of functions inside libo3d.so (see `nm build/core/libo3d_core.a`). */
    static const char* const internal[] = {
        "_ZN3o3d7utility19resolve_num_threadsEi",           /* o3d::utility::resolve_num_threads(int) */
        "_ZN3o3d7utility19set_verbosity_levelENS0_8LogLevelE", /* o3d::utility::set_verbosity_level */
        "_ZN3o3d7utility19get_verbosity_levelEv",
        "_ZN3o3d4capi11reset_errorEv", /* o3d::capi::reset_error() */
    };
    size_t i;
    (void)state;
    for (i = 0; i < sizeof internal / sizeof internal[0]; ++i) {
        dlerror();
        if (dlsym(g_lib, internal[i]) != NULL) fail_msg("internal symbol %s is exported", internal[i]);
    }
    /* Sanity: the same lookup does find a public one. */
    assert_non_null(dlsym(g_lib, "o3d_version"));
}

int main(void) {
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_every_public_function_resolves),
        cmocka_unit_test(test_list_matches_headers),
        cmocka_unit_test(test_version_matches_header),
        cmocka_unit_test(test_error_through_pointers),
        cmocka_unit_test(test_pipeline_through_pointers),
        cmocka_unit_test(test_internal_symbols_are_hidden),
    };
    return cmocka_run_group_tests_name("o3d_dlopen", tests, group_setup, NULL);
}
