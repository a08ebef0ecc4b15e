/* SPDX-License-Identifier: MIT */
/* Paths are UTF-8 everywhere: write and read a cloud under a non-ASCII directory and file name. */
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <setjmp.h>
#include <cmocka.h>

#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#include "o3d/o3d.h"
#include "o3d_test_util.h"

static void test_round_trip_through_utf8_path(void** state) {
    (void)state;
    char dir[] = "/tmp/o3d-utf8-XXXXXX";
    assert_non_null(mkdtemp(dir));
    char sub[512], ply[600], pcd[600];
    snprintf(sub, sizeof sub, "%s/点云 données", dir);           /* CJK, accent and a space */
    assert_int_equal(mkdir(sub, 0700), 0);
    snprintf(ply, sizeof ply, "%s/scan-été.ply", sub);
    snprintf(pcd, sizeof pcd, "%s/скан.pcd", sub);

    const double xyz[] = {0, 0, 0, 1, 2, 3, -4.5, 0.25, 8};
    o3d_pointcloud_t* pc = NULL;
    assert_int_equal(o3d_pointcloud_create(&pc), O3D_OK);
    assert_int_equal(o3d_pointcloud_set_array(pc, O3D_POINTCLOUD_POINTS, xyz, 3), O3D_OK);
    assert_int_equal(o3d_io_write_point_cloud(ply, pc, NULL, NULL), O3D_OK);
    assert_int_equal(o3d_io_write_point_cloud(pcd, pc, NULL, NULL), O3D_OK);

    const char* paths[] = {ply, pcd};
    for (int i = 0; i < 2; ++i) {
        o3d_pointcloud_t* back = NULL;
        assert_int_equal(o3d_io_read_point_cloud(&back, paths[i], NULL, NULL), O3D_OK);
        double out[9];
        size_t n = 0;
        assert_int_equal(o3d_pointcloud_get_array(out, 3, &n, back, O3D_POINTCLOUD_POINTS), O3D_OK);
        assert_int_equal(n, 3);
        for (int k = 0; k < 9; ++k) assert_float_equal(out[k], xyz[k], 1e-6);
        o3d_pointcloud_destroy(back);
    }

    /* A missing file's error message names the UTF-8 path as given. */
    char missing[700];
    snprintf(missing, sizeof missing, "%s/нет.ply", sub);
    o3d_pointcloud_t* none = NULL;
    O3D_ASSERT_FAILS(o3d_io_read_point_cloud(&none, missing, NULL, NULL), O3D_ERROR_IO);
    assert_null(none);
    assert_non_null(strstr(o3d_last_error_message(), "нет.ply"));

    o3d_pointcloud_destroy(pc);
    unlink(ply);
    unlink(pcd);
    rmdir(sub);
    rmdir(dir);
}

int main(void) {
    const struct CMUnitTest tests[] = {cmocka_unit_test(test_round_trip_through_utf8_path)};
    return cmocka_run_group_tests_name("o3d_utf8_paths", tests, NULL, NULL);
}
