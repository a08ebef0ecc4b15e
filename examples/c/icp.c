/* SPDX-License-Identifier: MIT */
/* Pairwise point-to-point ICP through the C API.
 * Usage: icp <source> <target> <max_correspondence_distance> */
#include <errno.h>
#include <stdio.h>
#include <stdlib.h>

#include "o3d/o3d.h"

static int report(const char* what, o3d_status status) {
    fprintf(stderr, "icp: %s failed: %s: %s\n", what, o3d_status_string(status), o3d_last_error_message());
    return 1;
}

/* Print fitness, RMSE, correspondence count and the 4x4 of `r`; return a status. */
static o3d_status print_result(const char* title, const o3d_registration_result_t* r) {
    double fitness = 0, rmse = 0, t[16];
    size_t pairs = 0;
    o3d_status s;
    int i;
    if ((s = o3d_registration_result_get_fitness(&fitness, r)) != O3D_OK) return s;
    if ((s = o3d_registration_result_get_inlier_rmse(&rmse, r)) != O3D_OK) return s;
    if ((s = o3d_registration_result_get_correspondence_set(NULL, 0, &pairs, r)) != O3D_OK) return s;
    if ((s = o3d_registration_result_get_transformation(t, r)) != O3D_OK) return s;
    printf("%s: fitness=%.6f inlier_rmse=%.6f correspondences=%zu\n", title, fitness, rmse, pairs);
    for (i = 0; i < 4; ++i) printf("  [% .6f % .6f % .6f % .6f]\n", t[4 * i], t[4 * i + 1], t[4 * i + 2], t[4 * i + 3]);
    return O3D_OK;
}

int main(int argc, char** argv) {
    o3d_pointcloud_t *source = NULL, *target = NULL;
    o3d_registration_result_t *before = NULL, *after = NULL;
    o3d_icp_options_t opts;
    o3d_status s;
    double threshold;
    char* end = NULL;
    int rc = 1;

    if (argc != 4) {
        fprintf(stderr, "usage: %s <source> <target> <max_correspondence_distance>\n", argv[0]);
        return 2;
    }
    errno = 0;
    threshold = strtod(argv[3], &end);
    if (errno || end == argv[3] || *end != '\0' || !(threshold > 0)) {
        fprintf(stderr, "icp: bad threshold '%s' (want a positive number)\n", argv[3]);
        return 2;
    }

    if ((s = o3d_io_read_point_cloud(&source, argv[1], NULL, NULL)) != O3D_OK) return report("read source", s);
    if ((s = o3d_io_read_point_cloud(&target, argv[2], NULL, NULL)) != O3D_OK) {
        report("read target", s);
        goto done;
    }
    if ((s = o3d_evaluate_registration(&before, source, target, threshold, NULL)) != O3D_OK) {
        report("evaluate_registration", s);
        goto done;
    }
    if ((s = print_result("initial alignment", before)) != O3D_OK) {
        report("reading the evaluation", s);
        goto done;
    }
    if ((s = o3d_icp_options_init(&opts, sizeof opts)) != O3D_OK) {
        report("icp_options_init", s);
        goto done;
    }
    opts.estimation = O3D_ESTIMATION_POINT_TO_POINT;
    if ((s = o3d_register_icp(&after, source, target, threshold, NULL, &opts)) != O3D_OK) {
        report("register_icp", s);
        goto done;
    }
    if ((s = print_result("point-to-point ICP", after)) != O3D_OK) {
        report("reading the ICP result", s);
        goto done;
    }
    rc = 0;

done:
    o3d_registration_result_destroy(after);
    o3d_registration_result_destroy(before);
    o3d_pointcloud_destroy(target);
    o3d_pointcloud_destroy(source);
    return rc;
}
