/* SPDX-License-Identifier: MIT */
#include "o3d_test_util.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

const char* o3d_test_data_path(const char* relative) {
    static char buf[4096];
    const char* root = getenv("O3D_TEST_DATA");
    if (!root || !*root) root = O3D_TEST_DATA_DEFAULT;
    snprintf(buf, sizeof buf, "%s/%s", root, relative);
    return access(buf, R_OK) == 0 ? buf : NULL;
}

int o3d_test_data_required(void) {
    const char* env = getenv("O3D_REQUIRE_TEST_DATA");
    return env && strcmp(env, "1") == 0;
}
