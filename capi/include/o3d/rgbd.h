/* SPDX-License-Identifier: MIT */
/**
 * @file rgbd.h
 * @brief RGB-D images (a color or intensity image and a float depth image in metres) and their
 * back-projection to point clouds. Mirrors o3d.geometry.RGBDImage and
 * PointCloud.create_from_depth_image / create_from_rgbd_image.
 *
 * **Ownership:** as for images. The readers copy their inputs and never modify them.
 *
 * **Out of memory:** any function here that allocates may also return O3D_ERROR_OUT_OF_MEMORY; the
 * per-function `@return` lists do not repeat it.
 */
#ifndef O3D_RGBD_H
#define O3D_RGBD_H

#include "o3d/common.h"
#include "o3d/types.h"
#include "o3d/image.h"

O3D_BEGIN_DECL


/** RGBDImage.create_from_color_and_depth keyword arguments. */
typedef struct o3d_rgbd_options {
    uint32_t struct_size;             /**< sizeof(o3d_rgbd_options_t) */
    double depth_scale;               /**< raw depth units per metre; default 1000 */
    double depth_trunc;               /**< depths at or beyond this (metres) become 0; default 3.0 */
    o3d_bool convert_rgb_to_intensity; /**< color → 1-channel float intensity in [0,1]; default 1 */
} o3d_rgbd_options_t;

/**
 * @brief Fill defaults.
 *
 * Threads: any thread.
 * @param opts the struct to fill
 * @param struct_size sizeof the struct as the caller knows it (an older, smaller size is accepted)
 * @return O3D_OK, or O3D_ERROR_INVALID_ARGUMENT on a NULL pointer or a `struct_size` this library does not know.
 */
O3D_API o3d_status o3d_rgbd_options_init(o3d_rgbd_options_t* opts, uint32_t struct_size);

/**
 * @brief Pair a color image (8-bit, 1 or 3 channels) with a depth image (uint16 or float32, 1 channel)
 * of the same size; depth is converted to float metres. @see RGBDImage.create_from_color_and_depth
 *
 * Threads: any thread; concurrent calls on the same handles are safe (all read-only).
 * Ownership: `*out` is the caller's, to free with o3d_rgbd_image_destroy(); left NULL on failure.
 * @param out receives the new handle (NULL on failure)
 * @param color the color image
 * @param depth the depth image
 * @param opts options (NULL: the defaults of the matching `*_init`)
 * @return O3D_OK, or O3D_ERROR_INVALID_ARGUMENT on a NULL pointer or a bad `opts->struct_size`.
 */
O3D_API o3d_status o3d_rgbd_image_create_from_color_and_depth(o3d_rgbd_image_t** out, const o3d_image_t* color,
                                                              const o3d_image_t* depth,
                                                              const o3d_rgbd_options_t* opts);

/** The dataset layouts of RGBDImage.create_from_{redwood,tum,sun,nyu}_format (O3D_RGBD_FORMAT_*). */
typedef int32_t o3d_rgbd_format;
#define O3D_RGBD_FORMAT_REDWOOD 0 /**< depth in mm (uint16), truncated at 4 m */
#define O3D_RGBD_FORMAT_TUM 1     /**< depth scale 5000, truncated at 4 m */
#define O3D_RGBD_FORMAT_SUN 2     /**< SUN RGB-D: depth bits rotated right by 3, in mm, truncated at 7 m */
#define O3D_RGBD_FORMAT_NYU 3     /**< NYU raw PGM: byte-swapped disparity → metres, truncated at 7 m */
/**
 * @brief The dataset readers of the Open3D paper: create_from_{redwood,tum,sun,nyu}_format.
 *
 * Threads: any thread; concurrent calls on the same handles are safe (all read-only).
 * Ownership: `*out` is the caller's, to free with o3d_rgbd_image_destroy(); left NULL on failure.
 * @param out receives the new handle (NULL on failure)
 * @param format O3D_RGBD_FORMAT_*
 * @param color the color image
 * @param depth the depth image
 * @param convert_rgb_to_intensity non-zero converts color to 1-channel float intensity
 * @return O3D_OK, or O3D_ERROR_INVALID_ARGUMENT on a NULL pointer.
 */
O3D_API o3d_status o3d_rgbd_image_create_from_dataset_format(o3d_rgbd_image_t** out, o3d_rgbd_format format,
                                                             const o3d_image_t* color, const o3d_image_t* depth,
                                                             int32_t convert_rgb_to_intensity);
/**
 * @brief Destroy. NULL is a no-op.
 *
 * Threads: needs exclusive access to `rgbd`: no other call may use it during or after.
 * @param rgbd the handle to destroy (NULL is a no-op)
 */
O3D_API void o3d_rgbd_image_destroy(o3d_rgbd_image_t* rgbd);
/**
 * @brief A copy of the color (or intensity) image.
 *
 * Threads: any thread; concurrent calls on the same handles are safe (all read-only).
 * Ownership: `*out` is the caller's, to free with o3d_image_destroy(); left NULL on failure.
 * @param out receives the new handle (NULL on failure)
 * @param rgbd the RGB-D image
 * @return O3D_OK, or O3D_ERROR_INVALID_ARGUMENT on a NULL pointer.
 */
O3D_API o3d_status o3d_rgbd_image_get_color(o3d_image_t** out, const o3d_rgbd_image_t* rgbd);
/**
 * @brief A copy of the depth image (1-channel float32, metres).
 *
 * Threads: any thread; concurrent calls on the same handles are safe (all read-only).
 * Ownership: `*out` is the caller's, to free with o3d_image_destroy(); left NULL on failure.
 * @param out receives the new handle (NULL on failure)
 * @param rgbd the RGB-D image
 * @return O3D_OK, or O3D_ERROR_INVALID_ARGUMENT on a NULL pointer.
 */
O3D_API o3d_status o3d_rgbd_image_get_depth(o3d_image_t** out, const o3d_rgbd_image_t* rgbd);

O3D_END_DECL

#endif /* O3D_RGBD_H */
