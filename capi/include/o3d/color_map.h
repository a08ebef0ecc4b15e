/* SPDX-License-Identifier: MIT */
/**
 * @file color_map.h
 * @brief Colour-map optimization (Open3D's o3d.pipelines.color_map; Zhou & Koltun, "Color Map Optimization for 3D
 * Reconstruction with Consumer Depth Cameras", SIGGRAPH 2014): refine the poses of the RGB-D images a mesh was
 * reconstructed from until the images agree on every vertex's colour, then colour the mesh from them.
 *
 * Each image `i` was taken by the trajectory's pose `i` (intrinsic + world-to-camera extrinsic). Its color is
 * 8-bit RGB (o3d_rgbd_image_create_from_color_and_depth with convert_rgb_to_intensity = 0, as Open3D's color map
 * examples make them), 8-bit gray, or a 1-channel float intensity in [0, 1] (the default conversion; the mesh is
 * then gray); its depth is 1-channel float metres; both are the size the pose's intrinsic says. Only the mesh's
 * vertices are used; the output mesh is a copy of it with new vertex colours.
 *
 * Which vertices an image sees is decided once, at the given poses; then each iteration moves every image's pose
 * (and warp) by one Gauss-Newton step towards the vertex intensities, and sets each vertex intensity to the mean of
 * the images that see it. Finally each vertex gets the mean colour of those images at the refined poses; a vertex
 * none sees gets the mean colour of its `invisible_vertex_color_knn` nearest seen vertices. Results are bitwise
 * identical for any thread count.
 *
 * **Out of memory:** any function here may also return O3D_ERROR_OUT_OF_MEMORY; the `@return` lists do not repeat it.
 */
#ifndef O3D_COLOR_MAP_H
#define O3D_COLOR_MAP_H

#include "o3d/camera.h"
#include "o3d/common.h"
#include "o3d/rgbd.h"
#include "o3d/trianglemesh.h"
#include "o3d/types.h"

O3D_BEGIN_DECL

/** RigidOptimizerOption (Open3D's C++ defaults), plus threads and progress. */
typedef struct o3d_color_map_rigid_options {
    uint32_t struct_size;                    /**< sizeof(o3d_color_map_rigid_options_t) */
    o3d_count maximum_iteration;             /**< alternations of pose and vertex-intensity update (>= 0); default 300 */
    double maximum_allowable_depth;          /**< metres (> 0): deeper pixels see nothing (drops background); default 2.5 */
    double depth_threshold_for_visibility_check; /**< metres (> 0): a vertex is seen only when its depth and the
                                                      image's differ by at most this; default 0.03 */
    double depth_threshold_for_discontinuity_check; /**< (> 0) pixels whose depth Sobel magnitude (unscaled 3x3) is
                                                         larger are depth edges; default 0.1 */
    o3d_count half_dilation_kernel_size_for_discontinuity_map; /**< pixels (>= 0) around a depth edge that see
                                                                    nothing; default 3 */
    o3d_count image_boundary_margin;         /**< pixels (>= 0) at the image border that see nothing; default 10 */
    o3d_count invisible_vertex_color_knn;    /**< (>= 1) seen neighbours an unseen vertex takes its colour from; default 3 */
    o3d_count num_threads;                   /**< 0 = library default; the result does not depend on it */
    o3d_progress_callback progress;          /**< called after each iteration with (iteration+1)/maximum_iteration; may be NULL */
    void* user_data;                         /**< passed to `progress` */
} o3d_color_map_rigid_options_t;

/** NonRigidOptimizerOption (Open3D's C++ defaults), plus threads and progress. */
typedef struct o3d_color_map_non_rigid_options {
    uint32_t struct_size;                    /**< sizeof(o3d_color_map_non_rigid_options_t) */
    o3d_count number_of_vertical_anchors;    /**< (>= 2) rows of each image's anchor grid; its columns keep the same
                                                  spacing; default 16 */
    double non_rigid_anchor_point_weight;    /**< lambda (>= 0) of the regulariser lambda^2 * sum ||offset||^2 (offsets in
                                                  pixels, intensities in [0, 1]): larger keeps the warp smaller; default 0.316 */
    o3d_count maximum_iteration;             /**< alternations of pose and vertex-intensity update (>= 0); default 300 */
    double maximum_allowable_depth;          /**< metres (> 0): deeper pixels see nothing (drops background); default 2.5 */
    double depth_threshold_for_visibility_check; /**< metres (> 0): a vertex is seen only when its depth and the
                                                      image's differ by at most this; default 0.03 */
    double depth_threshold_for_discontinuity_check; /**< (> 0) pixels whose depth Sobel magnitude (unscaled 3x3) is
                                                         larger are depth edges; default 0.1 */
    o3d_count half_dilation_kernel_size_for_discontinuity_map; /**< pixels (>= 0) around a depth edge that see
                                                                    nothing; default 3 */
    o3d_count image_boundary_margin;         /**< pixels (>= 0) at the image border that see nothing; default 10 */
    o3d_count invisible_vertex_color_knn;    /**< (>= 1) seen neighbours an unseen vertex takes its colour from; default 3 */
    o3d_count num_threads;                   /**< 0 = library default; the result does not depend on it */
    o3d_progress_callback progress;          /**< called after each iteration with (iteration+1)/maximum_iteration; may be NULL */
    void* user_data;                         /**< passed to `progress` */
} o3d_color_map_non_rigid_options_t;

/**
 * @brief Fill defaults (Open3D's RigidOptimizerOption).
 *
 * Threads: any thread.
 * @param opts the struct to fill
 * @param struct_size sizeof the struct as the caller knows it (an older, smaller size is accepted)
 * @return O3D_OK, or O3D_ERROR_INVALID_ARGUMENT on a NULL pointer or a `struct_size` this library does not know;
 *   O3D_ERROR_CANCELLED when the progress callback returns non-zero.
 */
O3D_API o3d_status o3d_color_map_rigid_options_init(o3d_color_map_rigid_options_t* opts, uint32_t struct_size);

/**
 * @brief Fill defaults (Open3D's NonRigidOptimizerOption).
 *
 * Threads: any thread.
 * @param opts the struct to fill
 * @param struct_size sizeof the struct as the caller knows it (an older, smaller size is accepted)
 * @return O3D_OK, or O3D_ERROR_INVALID_ARGUMENT on a NULL pointer or a `struct_size` this library does not know;
 *   O3D_ERROR_CANCELLED when the progress callback returns non-zero.
 */
O3D_API o3d_status o3d_color_map_non_rigid_options_init(o3d_color_map_non_rigid_options_t* opts,
                                                        uint32_t struct_size);

/**
 * @brief run_rigid_optimizer: refine each image's 6-DoF pose, then colour the mesh.
 * @see o3d.pipelines.color_map.run_rigid_optimizer
 *
 * Threads: any thread; the inputs are only read; the progress callback runs on the calling thread.
 * Ownership: `*out_colored_mesh` and `*out_refined_trajectory` are the caller's, to free with o3d_trianglemesh_destroy() and
 * o3d_camera_trajectory_destroy(); both are left NULL on failure.
 * @param out_colored_mesh receives a copy of `mesh` with the optimized vertex colours (NULL on failure)
 * @param out_refined_trajectory receives `trajectory` with the refined extrinsics (NULL on failure)
 * @param mesh the mesh to colour (at least one vertex, all finite)
 * @param images `num_images` RGB-D images (see the file comment for their formats)
 * @param num_images how many images; must equal the trajectory's size (>= 1)
 * @param trajectory one pose per image, in the same order
 * @param opts options (NULL: o3d_color_map_rigid_options_init's defaults)
 * @return O3D_OK; O3D_ERROR_INVALID_ARGUMENT on a NULL pointer (or NULL image), a mesh without vertices or with a
 *   non-finite one, no images, a count of images other than the trajectory's, an image of another format or size,
 *   an intrinsic with fx or fy 0 or non-finite, an extrinsic that is not finite with last row (0, 0, 0, 1), or bad
 *   options (out of range or NaN, or a bad `struct_size`); O3D_ERROR_CANCELLED when the progress callback returns
 *   non-zero.
 */
O3D_API o3d_status o3d_color_map_run_rigid_optimizer(o3d_trianglemesh_t** out_colored_mesh,
                                                     o3d_camera_trajectory_t** out_refined_trajectory,
                                                     const o3d_trianglemesh_t* mesh,
                                                     const o3d_rgbd_image_t* const* images, size_t num_images,
                                                     const o3d_camera_trajectory_t* trajectory,
                                                     const o3d_color_map_rigid_options_t* opts);

/**
 * @brief run_non_rigid_optimizer: refine each image's pose and a grid of anchor offsets (pixels) that warps where
 * vertices land in it, then colour the mesh through the warps. The trajectory returned holds the poses only.
 * @see o3d.pipelines.color_map.run_non_rigid_optimizer
 *
 * Threads: any thread; the inputs are only read; the progress callback runs on the calling thread.
 * Ownership: `*out_colored_mesh` and `*out_refined_trajectory` are the caller's, to free with o3d_trianglemesh_destroy() and
 * o3d_camera_trajectory_destroy(); both are left NULL on failure.
 * @param out_colored_mesh receives a copy of `mesh` with the optimized vertex colours (NULL on failure)
 * @param out_refined_trajectory receives `trajectory` with the refined extrinsics (NULL on failure)
 * @param mesh the mesh to colour (at least one vertex, all finite)
 * @param images `num_images` RGB-D images (see the file comment for their formats)
 * @param num_images how many images; must equal the trajectory's size (>= 1)
 * @param trajectory one pose per image, in the same order
 * @param opts options (NULL: o3d_color_map_non_rigid_options_init's defaults)
 * @return O3D_OK; O3D_ERROR_INVALID_ARGUMENT as o3d_color_map_run_rigid_optimizer, and on fewer than 2 vertical
 *   anchors or a negative or NaN anchor weight; O3D_ERROR_CANCELLED when the progress callback returns non-zero.
 */
O3D_API o3d_status o3d_color_map_run_non_rigid_optimizer(o3d_trianglemesh_t** out_colored_mesh,
                                                         o3d_camera_trajectory_t** out_refined_trajectory,
                                                         const o3d_trianglemesh_t* mesh,
                                                         const o3d_rgbd_image_t* const* images, size_t num_images,
                                                         const o3d_camera_trajectory_t* trajectory,
                                                         const o3d_color_map_non_rigid_options_t* opts);

O3D_END_DECL

#endif /* O3D_COLOR_MAP_H */
