/* SPDX-License-Identifier: MIT */
/* Figure 1 through the C API: read a cloud, voxel down-sample (0.05), estimate normals
 * (hybrid radius 0.1, max 30 neighbours), write the result.
 * Usage: figure1 <input> <output> */
#include <stdio.h>
#include <stdlib.h>

#include "o3d/o3d.h"

/* Print the failed call, its status name and the library's message; return 1. */
static int report(const char* what, o3d_status status) {
    fprintf(stderr, "figure1: %s failed: %s: %s\n", what, o3d_status_string(status), o3d_last_error_message());
    return 1;
}

int main(int argc, char** argv) {
    o3d_pointcloud_t *cloud = NULL, *down = NULL;
    o3d_search_param_t param;
    o3d_status s;
    size_t n_in = 0, n_out = 0;
    int32_t has_normals = 0;
    int rc = 1;

    if (argc != 3) {
        fprintf(stderr, "usage: %s <input> <output>\n", argv[0]);
        return 2;
    }
    printf("o3d %s\n", o3d_version());

    if ((s = o3d_io_read_point_cloud(&cloud, argv[1], NULL, NULL)) != O3D_OK) return report("read", s);
    if ((s = o3d_pointcloud_size(&n_in, cloud)) != O3D_OK) {
        report("size", s);
        goto done;
    }
    printf("read %zu points from %s\n", n_in, argv[1]);

    if ((s = o3d_pointcloud_voxel_down_sample(&down, cloud, 0.05)) != O3D_OK) {
        report("voxel_down_sample", s);
        goto done;
    }
    if ((s = o3d_pointcloud_size(&n_out, down)) != O3D_OK) {
        report("size", s);
        goto done;
    }
    printf("voxel_down_sample(0.05): %zu -> %zu points\n", n_in, n_out);

    if ((s = o3d_search_param_init(&param, sizeof param)) != O3D_OK) {
        report("search_param_init", s);
        goto done;
    }
    param.kind = O3D_SEARCH_HYBRID;
    param.radius = 0.1;
    param.knn = 30;
    if ((s = o3d_pointcloud_estimate_normals(down, &param, 0)) != O3D_OK) {
        report("estimate_normals", s);
        goto done;
    }
    if ((s = o3d_pointcloud_has_array(&has_normals, down, O3D_POINTCLOUD_NORMALS)) != O3D_OK) {
        report("has_normals", s);
        goto done;
    }
    printf("estimate_normals(hybrid radius=0.1 max_nn=30): normals %s\n", has_normals ? "yes" : "no");

    if ((s = o3d_io_write_point_cloud(argv[2], down, NULL, NULL)) != O3D_OK) {
        report("write", s);
        goto done;
    }
    printf("wrote %zu points with normals to %s\n", n_out, argv[2]);
    rc = has_normals && n_out > 0 ? 0 : 1;

done:
    o3d_pointcloud_destroy(down);
    o3d_pointcloud_destroy(cloud);
    return rc;
}
