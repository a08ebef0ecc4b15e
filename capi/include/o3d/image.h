/* SPDX-License-Identifier: MIT */
/**
 * @file image.h
 * @brief 2D images: 1, 3 or 4 channels of uint8, uint16 or float32, rows top to bottom, channels
 * interleaved (numpy's (height, width, channels) C order). Mirrors o3d.geometry.Image.
 *
 * **Ownership:** handles written through `o3d_image_t** out` belong to the caller (o3d_image_destroy).
 * The data view is borrowed: valid until the next mutating call on the image or its destruction.
 * Every function writing a new image leaves the input unchanged.
 */
#ifndef O3D_IMAGE_H
#define O3D_IMAGE_H

#include "o3d/common.h"

O3D_BEGIN_DECL

typedef struct o3d_image o3d_image_t;

/**
 * @brief New zero-filled image. width, height >= 1; num_channels 1, 3 or 4; bytes_per_channel 1 (uint8),
 * 2 (uint16) or 4 (float32).
 */
O3D_API o3d_status o3d_image_create(o3d_image_t** out, int32_t width, int32_t height, int32_t num_channels,
                                    int32_t bytes_per_channel);
/**
 * @brief New image holding a copy of `data`, which must be exactly
 * width * height * num_channels * bytes_per_channel bytes (native byte order). @see Image(numpy array)
 */
O3D_API o3d_status o3d_image_create_from_data(o3d_image_t** out, int32_t width, int32_t height,
                                              int32_t num_channels, int32_t bytes_per_channel, const uint8_t* data,
                                              size_t size);
/** @brief Destroy. NULL is a no-op. */
O3D_API void o3d_image_destroy(o3d_image_t* image);
/** @brief Deep copy. */
O3D_API o3d_status o3d_image_clone(o3d_image_t** out, const o3d_image_t* src);

O3D_API o3d_status o3d_image_width(const o3d_image_t* image, int32_t* out);
O3D_API o3d_status o3d_image_height(const o3d_image_t* image, int32_t* out);
O3D_API o3d_status o3d_image_num_channels(const o3d_image_t* image, int32_t* out);
O3D_API o3d_status o3d_image_bytes_per_channel(const o3d_image_t* image, int32_t* out);

/** @brief Borrowed read-only view of the pixel bytes (`*out_size` bytes). */
O3D_API o3d_status o3d_image_data_view(const o3d_image_t* image, const uint8_t** out_data, size_t* out_size);
/** @brief Borrowed writable view of the pixel bytes; writing through it is a mutating call. */
O3D_API o3d_status o3d_image_data_mutable_view(o3d_image_t* image, uint8_t** out_data, size_t* out_size);
/** @brief Copy the pixel bytes into `out` (capacity bytes); `*out_size` always gets the size. */
O3D_API o3d_status o3d_image_get_data(const o3d_image_t* image, uint8_t* out, size_t capacity, size_t* out_size);

#define O3D_IMAGE_FILTER_GAUSSIAN3 0 /**< 3x3 Gaussian */
#define O3D_IMAGE_FILTER_GAUSSIAN5 1
#define O3D_IMAGE_FILTER_GAUSSIAN7 2
#define O3D_IMAGE_FILTER_SOBEL3_DX 3 /**< horizontal derivative */
#define O3D_IMAGE_FILTER_SOBEL3_DY 4 /**< vertical derivative */
/**
 * @brief Filtered copy of a 1-channel float32 image (Open3D's Image.filter; borders replicate the edge
 * pixel). Other formats fail with INVALID_ARGUMENT: convert with o3d_image_create_float_image first.
 */
O3D_API o3d_status o3d_image_filter(o3d_image_t** out, const o3d_image_t* image, int32_t filter_type);
/** @brief Half-size 1-channel float32 image, each pixel the mean of a 2x2 block (a pyramid step). */
O3D_API o3d_status o3d_image_downsample(o3d_image_t** out, const o3d_image_t* image);
/** @brief Copy flipped upside down. */
O3D_API o3d_status o3d_image_flip_vertical(o3d_image_t** out, const o3d_image_t* image);
/** @brief Copy flipped left to right. */
O3D_API o3d_status o3d_image_flip_horizontal(o3d_image_t** out, const o3d_image_t* image);

#define O3D_IMAGE_CONVERT_EQUAL 0    /**< gray = mean of R, G, B */
#define O3D_IMAGE_CONVERT_WEIGHTED 1 /**< gray = 0.2990 R + 0.5870 G + 0.1140 B */
/**
 * @brief 1-channel float32 copy: 8-bit values divided by 255, 16-bit values as they are, float kept;
 * 3/4 channels averaged by `convert_type`.
 */
O3D_API o3d_status o3d_image_create_float_image(o3d_image_t** out, const o3d_image_t* image,
                                                int32_t convert_type);
/**
 * @brief Depth in metres: a 1-channel uint16 or float32 depth image divided by `depth_scale` (> 0), with
 * values at or above `depth_trunc` (and non-finite ones) set to 0. Output is 1-channel float32.
 */
O3D_API o3d_status o3d_image_convert_depth_to_float(o3d_image_t** out, const o3d_image_t* image,
                                                    double depth_scale, double depth_trunc);

O3D_END_DECL

#endif /* O3D_IMAGE_H */
