/* SPDX-License-Identifier: MIT */
/**
 * @file reconstruction.h
 * @brief The scene reconstruction system (Choi, Zhou and Koltun, "Robust Reconstruction of Indoor Scenes", CVPR
 * 2015, as Open3D's tutorial reconstruction system runs it): a folder of RGB-D frames and a JSON config in, a scene
 * mesh and a camera trajectory out, in stages that each read the previous stages' files.
 *
 * The config has the layout of Open3D's reconstruction-system config (path_dataset, path_intrinsic, depth_scale,
 * depth_max, voxel_size, depth_diff_max, n_frames_per_fragment, n_keyframes_per_n_frame,
 * preference_loop_closure_odometry, preference_loop_closure_registration, tsdf_cubic_size, icp_method,
 * global_registration, python_multi_threading and the template_* output names), with Open3D's defaults; an Open3D
 * config runs unchanged. o3d adds "path_output" (where fragments/ and scene/ go; default path_dataset),
 * "loop_closure_odometry" (default true) and "color_map_maximum_iteration" (default 100). The dataset folder holds
 * colour images in image/, rgb/ or color/ and depth images in depth/, paired by sorted file name.
 *
 * Stages, in order (O3D_RECONSTRUCTION_STAGE_*):
 * - MAKE_FRAGMENTS: per n_frames_per_fragment frames, hybrid RGB-D odometry between neighbours and between
 *   keyframes, a pose graph optimized with the line process, and the fragment's TSDF surface written as a point
 *   cloud (fragments/fragment_NNN.ply, fragment_NNN.json, fragment_optimized_NNN.json);
 * - REGISTER_FRAGMENTS: FPFH + RANSAC (or FGR) between every pair of fragments, ICP between neighbours, a global
 *   pose graph optimized with the line process (scene/global_registration*.json);
 * - REFINE_REGISTRATION: multi-scale ICP (coloured by default) on every kept edge, the graph optimized again
 *   (scene/refined_registration*.json);
 * - INTEGRATE_SCENE: every frame into one scalable TSDF; scene/integrated.ply and scene/trajectory.log;
 * - COLOR_MAP (optional): the rigid colour-map optimizer recolours the scene mesh from the keyframes
 *   (scene/color_map_optimized.ply).
 *
 * Each stage resumes: with `resume` set, work whose output files exist is skipped (each fragment in
 * MAKE_FRAGMENTS, the whole stage in the others). Files are written whole (through a rename), so a cancelled or
 * failed run leaves only complete outputs. Results do not depend on the thread count.
 *
 * **Out of memory:** any function here may also return O3D_ERROR_OUT_OF_MEMORY; the `@return` lists do not repeat it.
 */
#ifndef O3D_RECONSTRUCTION_H
#define O3D_RECONSTRUCTION_H

#include "o3d/common.h"
#include "o3d/types.h"

O3D_BEGIN_DECL

/** A stage of the reconstruction system (O3D_RECONSTRUCTION_STAGE_*). */
typedef int32_t o3d_reconstruction_stage;
#define O3D_RECONSTRUCTION_STAGE_MAKE_FRAGMENTS 0      /**< odometry, fragment pose graphs and clouds */
#define O3D_RECONSTRUCTION_STAGE_REGISTER_FRAGMENTS 1  /**< global registration of the fragments */
#define O3D_RECONSTRUCTION_STAGE_REFINE_REGISTRATION 2 /**< multi-scale ICP between fragments */
#define O3D_RECONSTRUCTION_STAGE_INTEGRATE_SCENE 3     /**< the scene mesh and trajectory */
#define O3D_RECONSTRUCTION_STAGE_COLOR_MAP 4           /**< colour-map optimization of the scene mesh */

/** How a stage runs. */
typedef struct o3d_reconstruction_options {
    uint32_t struct_size;           /**< sizeof(o3d_reconstruction_options_t) */
    o3d_bool resume;                /**< non-zero: skip work whose output files exist; default 1 */
    o3d_count num_threads;          /**< 0 = library default; the result does not depend on it */
    o3d_progress_callback progress; /**< called with the fraction of the stage done; may be NULL */
    void* user_data;                /**< passed to `progress` */
} o3d_reconstruction_options_t;

/**
 * @brief Fill defaults (resume, library-default threads, no progress callback).
 *
 * Threads: any thread.
 * @param opts the struct to fill
 * @param struct_size sizeof the struct as the caller knows it (an older, smaller size is accepted)
 * @return O3D_OK, or O3D_ERROR_INVALID_ARGUMENT on a NULL pointer or a `struct_size` this library does not know;
 *   (O3D_ERROR_CANCELLED is what o3d_reconstruction_run_stage returns when the progress callback set here returns
 *   non-zero; this function never does).
 */
O3D_API o3d_status o3d_reconstruction_options_init(o3d_reconstruction_options_t* opts, uint32_t struct_size);

/**
 * @brief Run one stage of the reconstruction system on the dataset a config file names (Open3D's run_system.py
 * --make / --register / --refine / --integrate).
 *
 * Threads: any thread; runs on several threads itself; the progress callback runs on the calling thread.
 * @param config_path the JSON config (UTF-8 path); relative paths in it are relative to the working directory
 * @param stage O3D_RECONSTRUCTION_STAGE_*
 * @param opts options (NULL: o3d_reconstruction_options_init's defaults)
 * @return O3D_OK; O3D_ERROR_INVALID_ARGUMENT on a NULL path, an unknown stage, negative num_threads, a bad
 *   `struct_size`, a dataset without frames or with unequal colour and depth counts, or frames that do not pair
 *   (the message names the stage and the frame); O3D_ERROR_IO when the config, the dataset folders, a frame or a
 *   previous stage's output is missing or unreadable, or an output cannot be written (a missing input names the
 *   stage that writes it); O3D_ERROR_PARSE on a malformed config (naming the key) or a malformed frame or
 *   intermediate file; O3D_ERROR_CANCELLED when the progress callback returns non-zero (finished outputs are
 *   kept, so running the stage again resumes).
 */
O3D_API o3d_status o3d_reconstruction_run_stage(const char* config_path, o3d_reconstruction_stage stage,
                                                const o3d_reconstruction_options_t* opts);

O3D_END_DECL

#endif /* O3D_RECONSTRUCTION_H */
