/* SPDX-License-Identifier: MIT */
/*
 * o3d-reconstruction: the scene reconstruction system from the command line, over the C API
 * (o3d/reconstruction.h). The flags follow Open3D's run_system.py:
 *
 *   o3d-reconstruction --config CONFIG.json [--make] [--register] [--refine] [--integrate] [--color_map]
 *                      [--no-resume] [--threads N] [--quiet]
 *
 * Without a stage flag it runs make, register, refine and integrate. Each stage shows a progress bar on stderr
 * and its time; Ctrl-C cancels at the next unit of work and keeps what is finished, so running the same command
 * again resumes. Exit status: 0 done, 1 a stage failed (the message names the stage and the frame or fragment),
 * 2 bad usage, 130 cancelled.
 */
#include <signal.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "o3d/o3d.h"

static volatile sig_atomic_t g_interrupted = 0;

static void on_sigint(int signal_number) {
    (void)signal_number;
    g_interrupted = 1;
}

struct Bar {
    const char* stage;
    int last_percent;
    int quiet;
};

static int32_t show_progress(double fraction, void* user_data) {
    struct Bar* bar = (struct Bar*)user_data;
    const int percent = (int)(fraction * 100.0 + 0.5);
    if (!bar->quiet && percent != bar->last_percent) {
        char cells[21];
        const int filled = percent / 5;
        for (int i = 0; i < 20; ++i) cells[i] = i < filled ? '#' : '.';
        cells[20] = '\0';
        fprintf(stderr, "\r%-20s [%s] %3d%%", bar->stage, cells, percent);
        fflush(stderr);
        bar->last_percent = percent;
    }
    return g_interrupted ? 1 : 0; /* non-zero cancels */
}

static double seconds_now(void) {
    struct timespec t;
    clock_gettime(CLOCK_MONOTONIC, &t);
    return (double)t.tv_sec + (double)t.tv_nsec * 1e-9;
}

static int usage(const char* program) {
    fprintf(stderr,
            "usage: %s --config CONFIG.json [--make] [--register] [--refine] [--integrate] [--color_map]\n"
            "       [--no-resume] [--threads N] [--quiet]\n"
            "Runs the stages asked for, in order (make, register, refine and integrate when none is named).\n",
            program);
    return 2;
}

int main(int argc, char** argv) {
    static const struct {
        const char* flag;
        o3d_reconstruction_stage stage;
        const char* name;
    } kStages[] = {
        {"--make", O3D_RECONSTRUCTION_STAGE_MAKE_FRAGMENTS, "make fragments"},
        {"--register", O3D_RECONSTRUCTION_STAGE_REGISTER_FRAGMENTS, "register fragments"},
        {"--refine", O3D_RECONSTRUCTION_STAGE_REFINE_REGISTRATION, "refine registration"},
        {"--integrate", O3D_RECONSTRUCTION_STAGE_INTEGRATE_SCENE, "integrate scene"},
        {"--color_map", O3D_RECONSTRUCTION_STAGE_COLOR_MAP, "color map"},
    };
    enum { kStageCount = sizeof kStages / sizeof kStages[0] };
    int wanted[kStageCount] = {0};
    int any_stage = 0, quiet = 0;
    const char* config = NULL;
    o3d_reconstruction_options_t options;
    o3d_reconstruction_options_init(&options, sizeof options);

    for (int i = 1; i < argc; ++i) {
        int matched = 0;
        for (int s = 0; s < kStageCount; ++s)
            if (strcmp(argv[i], kStages[s].flag) == 0) wanted[s] = any_stage = matched = 1;
        if (matched) continue;
        if (strcmp(argv[i], "--config") == 0 && i + 1 < argc) {
            config = argv[++i];
        } else if (strcmp(argv[i], "--threads") == 0 && i + 1 < argc) {
            char* end = NULL;
            const long n = strtol(argv[++i], &end, 10);
            if (*end != '\0' || n < 0 || n > 4096) return usage(argv[0]);
            options.num_threads = (o3d_count)n;
        } else if (strcmp(argv[i], "--no-resume") == 0) {
            options.resume = 0;
        } else if (strcmp(argv[i], "--quiet") == 0) {
            quiet = 1;
        } else {
            return usage(argv[0]);
        }
    }
    if (!config) return usage(argv[0]);
    if (!any_stage)
        for (int s = 0; s < kStageCount; ++s) wanted[s] = kStages[s].stage != O3D_RECONSTRUCTION_STAGE_COLOR_MAP;
    signal(SIGINT, on_sigint);

    for (int s = 0; s < kStageCount; ++s) {
        if (!wanted[s]) continue;
        struct Bar bar = {kStages[s].name, -1, quiet};
        options.progress = show_progress;
        options.user_data = &bar;
        const double start = seconds_now();
        const o3d_status status = o3d_reconstruction_run_stage(config, kStages[s].stage, &options);
        if (!quiet && bar.last_percent >= 0) fputc('\n', stderr);
        if (status == O3D_ERROR_CANCELLED) {
            fprintf(stderr, "%s: cancelled; finished outputs are kept, run again to resume\n", kStages[s].name);
            return 130;
        }
        if (status != O3D_OK) {
            fprintf(stderr, "error: %s\n", o3d_last_error_message());
            return 1;
        }
        printf("%s: %.2f s\n", kStages[s].name, seconds_now() - start);
        fflush(stdout);
    }
    return 0;
}
