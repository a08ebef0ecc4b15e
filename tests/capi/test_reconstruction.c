/* SPDX-License-Identifier: MIT */
/* C API reconstruction.h on data whose answer is known: eight frames ray-cast inside the textured box room of
 * o3d_test_room.h along a known camera path, written as PNG files (8-bit colour, 16-bit millimetre depth) with an
 * intrinsic JSON, reconstructed in two fragments by all four stages. The trajectory comes back within millimetres
 * and a fraction of a degree, the mesh lies on the walls, progress rises to 1; a resumed stage rewrites nothing;
 * a cancelled one keeps what was finished; a corrupt frame and a missing stage output name the stage and the frame;
 * the command-line program's exit codes; and the argument errors. (The run on the shared living-room frames,
 * against Open3D's numbers, is bindings/python/tests/test_reconstruction.py: too slow for the sanitizer build.) */
#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <sys/wait.h>

#include <cmocka.h>

#include "o3d/o3d.h"
#include "o3d_test_room.h"
#include "o3d_test_util.h"

#define W 160
#define H 120
#define FRAMES 8

static const o3d_pinhole_intrinsic_t kCamera = {W, H, 140.0, 140.0, 79.5, 59.5};

typedef struct {
    char root[256];                /* the temporary folder */
    char config[300];              /* its config.json */
    double truth[FRAMES][16];      /* camera to world */
} dataset_t;

static void path_join(char* out, size_t size, const char* a, const char* b) { snprintf(out, size, "%s/%s", a, b); }

static void write_text(const char* path, const char* text) {
    FILE* f = fopen(path, "wb");
    assert_non_null(f);
    fputs(text, f);
    fclose(f);
}

/* Frame k: the camera drifts sideways and turns slowly while looking into the room's far corner. */
static void camera_pose(int k, double pose[16]) {
    const double centre[3] = {-0.35 + 0.05 * k, 0.1 - 0.01 * k, -0.5 + 0.02 * k};
    const double target[3] = {0.6 - 0.04 * k, 0.2, 1.6};
    o3d_test_look_at(centre, target, pose);
}

static void write_frame(const dataset_t* d, int k) {
    uint8_t* rgb = malloc(3 * W * H);
    float* depth = malloc(sizeof(float) * W * H);
    uint16_t* mm = malloc(sizeof(uint16_t) * W * H);
    o3d_test_room_render(d->truth[k], &kCamera, rgb, depth);
    for (int i = 0; i < W * H; ++i) mm[i] = (uint16_t)lround(depth[i] * 1000.0);
    o3d_image_t *color = NULL, *dimg = NULL;
    assert_int_equal(o3d_image_create_from_data(&color, W, H, 3, 1, rgb, 3 * W * H), O3D_OK);
    assert_int_equal(o3d_image_create_from_data(&dimg, W, H, 1, 2, (const uint8_t*)mm, sizeof(uint16_t) * W * H), O3D_OK);
    char path[400];
    snprintf(path, sizeof path, "%s/data/color/%05d.png", d->root, k);
    assert_int_equal(o3d_io_write_image(path, color, NULL, -1), O3D_OK);
    snprintf(path, sizeof path, "%s/data/depth/%05d.png", d->root, k);
    assert_int_equal(o3d_io_write_image(path, dimg, NULL, -1), O3D_OK);
    o3d_image_destroy(color);
    o3d_image_destroy(dimg);
    free(rgb);
    free(depth);
    free(mm);
}

static int make_dataset(void** state) {
    dataset_t* d = calloc(1, sizeof *d);
    snprintf(d->root, sizeof d->root, "/tmp/o3d_reconstruction_XXXXXX");
    assert_non_null(mkdtemp(d->root));
    char path[400];
    const char* folders[] = {"data", "data/color", "data/depth"};
    for (int i = 0; i < 3; ++i) {
        path_join(path, sizeof path, d->root, folders[i]);
        assert_int_equal(mkdir(path, 0700), 0);
    }
    for (int k = 0; k < FRAMES; ++k) {
        camera_pose(k, d->truth[k]);
        write_frame(d, k);
    }
    path_join(path, sizeof path, d->root, "intrinsic.json");
    assert_int_equal(o3d_io_write_pinhole_camera_intrinsic(path, &kCamera), O3D_OK);
    /* Two fragments of four frames; keyframes 0, 2, 4, 6 give the loop closures 0-2 and 4-6; voxels of
     * 8/512 m keep the sanitizer build quick. */
    char text[1200];
    snprintf(text, sizeof text,
             "{\"path_dataset\": \"%s/data\", \"path_intrinsic\": \"%s/intrinsic.json\", \"path_output\": \"%s/out\","
             " \"n_frames_per_fragment\": 4, \"n_keyframes_per_n_frame\": 2, \"depth_max\": 4.0,"
             " \"tsdf_cubic_size\": 8.0, \"voxel_size\": 0.05}",
             d->root, d->root, d->root);
    path_join(d->config, sizeof d->config, d->root, "config.json");
    write_text(d->config, text);
    *state = d;
    return 0;
}

static int remove_dataset(void** state) {
    dataset_t* d = *state;
    char command[400];
    snprintf(command, sizeof command, "rm -rf '%s'", d->root);
    assert_int_equal(system(command), 0);
    free(d);
    return 0;
}

typedef struct {
    int calls;
    double last;
    int monotonic;
    int cancel_at; /* cancel on this call (1-based); 0 never */
} progress_log_t;

static int32_t record_progress(double fraction, void* user_data) {
    progress_log_t* log = user_data;
    if (fraction < log->last || fraction < 0 || fraction > 1) log->monotonic = 0;
    log->last = fraction;
    return ++log->calls == log->cancel_at;
}

static o3d_status run(const dataset_t* d, o3d_reconstruction_stage stage, int resume, progress_log_t* log) {
    o3d_reconstruction_options_t o;
    assert_int_equal(o3d_reconstruction_options_init(&o, sizeof o), O3D_OK);
    o.resume = resume;
    if (log) {
        o.progress = record_progress;
        o.user_data = log;
    }
    return o3d_reconstruction_run_stage(d->config, stage, &o);
}

static double modified_time(const dataset_t* d, const char* relative) {
    char path[400];
    path_join(path, sizeof path, d->root, relative);
    struct stat s;
    assert_int_equal(stat(path, &s), 0);
    return (double)s.st_mtim.tv_sec + 1e-9 * (double)s.st_mtim.tv_nsec;
}

static void test_recovers_the_known_trajectory(void** state) {
    const dataset_t* d = *state;
    for (o3d_reconstruction_stage s = O3D_RECONSTRUCTION_STAGE_MAKE_FRAGMENTS;
         s <= O3D_RECONSTRUCTION_STAGE_INTEGRATE_SCENE; ++s) {
        progress_log_t log = {0, 0.0, 1, 0};
        assert_int_equal(run(d, s, 1, &log), O3D_OK);
        assert_true(log.calls >= 1);
        assert_true(log.monotonic);
        assert_true(fabs(log.last - 1.0) < 1e-12);
    }
    /* The trajectory is in frame 0's camera: compare each pose with truth_0^-1 truth_k. */
    char path[400];
    path_join(path, sizeof path, d->root, "out/scene/trajectory.log");
    o3d_camera_trajectory_t* trajectory = NULL;
    assert_int_equal(o3d_io_read_pinhole_camera_trajectory(&trajectory, path, NULL), O3D_OK);
    size_t n = 0;
    assert_int_equal(o3d_camera_trajectory_size(&n, trajectory), O3D_OK);
    assert_int_equal(n, FRAMES);
    double first_inverse[16];
    o3d_test_rigid_inverse(d->truth[0], first_inverse);
    double worst_deg = 0, worst_m = 0;
    for (size_t k = 0; k < n; ++k) {
        o3d_pinhole_intrinsic_t intrinsic;
        double extrinsic[16], expected_pose[16], expected_extrinsic[16], deg, metres;
        assert_int_equal(o3d_camera_trajectory_get(&intrinsic, extrinsic, trajectory, k), O3D_OK);
        o3d_test_mat_mul(first_inverse, d->truth[k], expected_pose);
        o3d_test_rigid_inverse(expected_pose, expected_extrinsic);
        o3d_test_pose_error(extrinsic, expected_extrinsic, &deg, &metres);
        worst_deg = fmax(worst_deg, deg);
        worst_m = fmax(worst_m, metres);
    }
    print_message("worst pose error over %d frames: %.4f deg, %.5f m\n", FRAMES, worst_deg, worst_m);
    assert_true(worst_deg < 0.3);
    assert_true(worst_m < 0.005);
    o3d_camera_trajectory_destroy(trajectory);

    /* The mesh, moved into the room by truth_0, lies on the walls: within a voxel (8/512 m) of the nearest. */
    path_join(path, sizeof path, d->root, "out/scene/integrated.ply");
    o3d_trianglemesh_t* mesh = NULL;
    assert_int_equal(o3d_io_read_triangle_mesh(&mesh, path, NULL, NULL), O3D_OK);
    const double* v = NULL;
    size_t rows = 0;
    assert_int_equal(o3d_trianglemesh_array_view(&v, &rows, mesh, O3D_MESH_VERTICES), O3D_OK);
    assert_true(rows > 1000);
    size_t near = 0;
    for (size_t i = 0; i < rows; ++i) {
        const double* p = v + 3 * i;
        double w[3], wall = INFINITY;
        for (int r = 0; r < 3; ++r)
            w[r] = d->truth[0][4 * r] * p[0] + d->truth[0][4 * r + 1] * p[1] + d->truth[0][4 * r + 2] * p[2] +
                   d->truth[0][4 * r + 3];
        for (int a = 0; a < 3; ++a)
            wall = fmin(wall, fmin(fabs(w[a] - o3d_test_room_lo[a]), fabs(w[a] - o3d_test_room_hi[a])));
        near += wall < 8.0 / 512.0;
    }
    print_message("%zu of %zu vertices within a voxel of a wall\n", near, rows);
    assert_true((double)near > 0.99 * (double)rows);
    o3d_trianglemesh_destroy(mesh);
}

static void test_resume_and_cancel(void** state) {
    const dataset_t* d = *state;
    /* Everything is on disk after the first test: resuming rewrites nothing. */
    const double before = modified_time(d, "out/fragments/fragment_001.ply");
    const double scene_before = modified_time(d, "out/scene/integrated.ply");
    for (o3d_reconstruction_stage s = O3D_RECONSTRUCTION_STAGE_MAKE_FRAGMENTS;
         s <= O3D_RECONSTRUCTION_STAGE_INTEGRATE_SCENE; ++s)
        assert_int_equal(run(d, s, 1, NULL), O3D_OK);
    assert_true(modified_time(d, "out/fragments/fragment_001.ply") == before);
    assert_true(modified_time(d, "out/scene/integrated.ply") == scene_before);

    /* Redo with a cancel on the second report: the stage stops, earlier whole files stay, no partial file. */
    progress_log_t log = {0, 0.0, 1, 2};
    O3D_ASSERT_FAILS(run(d, O3D_RECONSTRUCTION_STAGE_MAKE_FRAGMENTS, 0, &log), O3D_ERROR_CANCELLED);
    assert_non_null(strstr(o3d_last_error_message(), "make fragments"));
    assert_int_equal(log.calls, 2);
    assert_true(modified_time(d, "out/fragments/fragment_001.ply") == before);
    char path[400];
    struct stat s;
    path_join(path, sizeof path, d->root, "out/fragments/fragment_001.ply.partial");
    assert_int_not_equal(stat(path, &s), 0);
}

static void test_errors_name_the_stage_and_frame(void** state) {
    const dataset_t* d = *state;
    char path[400], text[1200];
    /* A corrupt depth image. */
    snprintf(path, sizeof path, "%s/data/depth/%05d.png", d->root, 2);
    write_text(path, "not a png");
    O3D_ASSERT_FAILS(run(d, O3D_RECONSTRUCTION_STAGE_MAKE_FRAGMENTS, 0, NULL), O3D_ERROR_PARSE);
    print_message("%s\n", o3d_last_error_message());
    assert_non_null(strstr(o3d_last_error_message(), "make fragments"));
    assert_non_null(strstr(o3d_last_error_message(), "frame 2 "));
    write_frame(d, 2);

    /* Registration before any fragment exists names the stage to run first. */
    snprintf(text, sizeof text, "{\"path_dataset\": \"%s/data\", \"path_output\": \"%s/empty\"}", d->root, d->root);
    path_join(path, sizeof path, d->root, "empty.json");
    write_text(path, text);
    O3D_ASSERT_FAILS(o3d_reconstruction_run_stage(path, O3D_RECONSTRUCTION_STAGE_REGISTER_FRAGMENTS, NULL), O3D_ERROR_IO);
    assert_non_null(strstr(o3d_last_error_message(), "run the \"make fragments\" stage first"));
    O3D_ASSERT_FAILS(o3d_reconstruction_run_stage(path, O3D_RECONSTRUCTION_STAGE_INTEGRATE_SCENE, NULL), O3D_ERROR_IO);
    assert_non_null(strstr(o3d_last_error_message(), "refine registration"));
}

static void test_bad_arguments_and_configs(void** state) {
    const dataset_t* d = *state;
    o3d_reconstruction_options_t o;
    assert_int_equal(o3d_reconstruction_options_init(&o, sizeof o), O3D_OK);
    assert_int_equal(o.resume, 1);
    assert_int_equal(o.num_threads, 0);
    assert_null(o.progress);
    O3D_ASSERT_FAILS(o3d_reconstruction_options_init(NULL, sizeof o), O3D_ERROR_INVALID_ARGUMENT);
    O3D_ASSERT_FAILS(o3d_reconstruction_run_stage(NULL, O3D_RECONSTRUCTION_STAGE_MAKE_FRAGMENTS, NULL),
                     O3D_ERROR_INVALID_ARGUMENT);
    O3D_ASSERT_FAILS(o3d_reconstruction_run_stage(d->config, 5, NULL), O3D_ERROR_INVALID_ARGUMENT);
    O3D_ASSERT_FAILS(o3d_reconstruction_run_stage(d->config, -1, NULL), O3D_ERROR_INVALID_ARGUMENT);
    o.num_threads = -1;
    O3D_ASSERT_FAILS(o3d_reconstruction_run_stage(d->config, 0, &o), O3D_ERROR_INVALID_ARGUMENT);
    o.num_threads = 0;
    o.struct_size = 3;
    O3D_ASSERT_FAILS(o3d_reconstruction_run_stage(d->config, 0, &o), O3D_ERROR_INVALID_ARGUMENT);

    char path[400], text[600];
    path_join(path, sizeof path, d->root, "missing.json");
    O3D_ASSERT_FAILS(o3d_reconstruction_run_stage(path, 0, NULL), O3D_ERROR_IO);
    static const struct {
        const char* json;
        const char* named; /* the message names this */
    } bad[] = {
        {"{\"path_dataset\": ", "invalid JSON"},
        {"[1, 2]", "expected a JSON object"},
        {"{\"voxel_size\": 0.05}", "path_dataset"},
        {"{\"path_dataset\": \"x\", \"voxel_size\": -0.05}", "voxel_size"},
        {"{\"path_dataset\": \"x\", \"depth_scale\": \"1000\"}", "depth_scale"},
        {"{\"path_dataset\": \"x\", \"n_frames_per_fragment\": 0}", "n_frames_per_fragment"},
        {"{\"path_dataset\": \"x\", \"icp_method\": \"magic\"}", "icp_method"},
        {"{\"path_dataset\": \"x\", \"global_registration\": \"none\"}", "global_registration"},
        {"{\"path_dataset\": \"x\", \"template_fragment_pointcloud\": \"fragments/a.ply\"}", "%d"},
        {"{\"path_dataset\": \"x\", \"tsdf_cubic_size\": 1e999}", "invalid JSON"},
    };
    path_join(path, sizeof path, d->root, "bad.json");
    for (size_t i = 0; i < sizeof bad / sizeof bad[0]; ++i) {
        write_text(path, bad[i].json);
        O3D_ASSERT_FAILS(o3d_reconstruction_run_stage(path, 0, NULL), O3D_ERROR_PARSE);
        assert_non_null(strstr(o3d_last_error_message(), bad[i].named));
    }
    /* A dataset folder that does not exist; one whose colour and depth counts differ. */
    snprintf(text, sizeof text, "{\"path_dataset\": \"%s/nowhere\"}", d->root);
    write_text(path, text);
    O3D_ASSERT_FAILS(o3d_reconstruction_run_stage(path, 0, NULL), O3D_ERROR_IO);
    char extra[400];
    snprintf(extra, sizeof extra, "%s/data/depth/99999.png", d->root);
    write_text(extra, "x");
    O3D_ASSERT_FAILS(run(d, 0, 0, NULL), O3D_ERROR_INVALID_ARGUMENT);
    assert_non_null(strstr(o3d_last_error_message(), "8 colour images but 9 depth images"));
    assert_int_equal(remove(extra), 0);
}

static void test_command_line(void** state) {
    const dataset_t* d = *state;
    char command[1200];
    snprintf(command, sizeof command, "'%s' --config '%s' --make --register --refine --integrate --no-resume --quiet"
             " > /dev/null", O3D_RECONSTRUCTION_CLI, d->config);
    assert_int_equal(system(command), 0);
    assert_true(modified_time(d, "out/scene/trajectory.log") > 0);
    snprintf(command, sizeof command, "'%s' --make 2> /dev/null", O3D_RECONSTRUCTION_CLI);  /* no --config */
    assert_int_equal(WEXITSTATUS(system(command)), 2);
    snprintf(command, sizeof command, "'%s' --config '%s/missing.json' --quiet 2> /dev/null", O3D_RECONSTRUCTION_CLI,
             d->root);
    assert_int_equal(WEXITSTATUS(system(command)), 1);
}

int main(void) {
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_recovers_the_known_trajectory),
        cmocka_unit_test(test_resume_and_cancel),
        cmocka_unit_test(test_errors_name_the_stage_and_frame),
        cmocka_unit_test(test_bad_arguments_and_configs),
        cmocka_unit_test(test_command_line),
    };
    return cmocka_run_group_tests(tests, make_dataset, remove_dataset);
}
