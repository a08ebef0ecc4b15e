/* SPDX-License-Identifier: MIT */
/**
 * @file image.h
 * @brief 2D images: 1, 3 or 4 channels of uint8, uint16 or float32, rows top to bottom, channels
 * interleaved (numpy's (height, width, channels) C order). Mirrors o3d.geometry.Image.
 *
 * **Ownership:** handles written through `o3d_image_t** out` belong to the caller (o3d_image_destroy).
 * The data view is borrowed: valid until the next mutating call on the image or its destruction.
 * Every function writing a new image leaves the input unchanged.
 *
 * **Out of memory:** any function here that allocates may also return O3D_ERROR_OUT_OF_MEMORY; the
 * per-function `@return` lists do not repeat it.
 */
#ifndef O3D_IMAGE_H
#define O3D_IMAGE_H

#include "o3d/common.h"
#include "o3d/types.h"

O3D_BEGIN_DECL


/**
 * @brief New zero-filled image. width, height >= 1; num_channels 1, 3 or 4; bytes_per_channel 1 (uint8),
 * 2 (uint16) or 4 (float32).
 *
 * Threads: any thread.
 * Ownership: `*out` is the caller's, to free with o3d_image_destroy(); left NULL on failure.
 * @param out receives the new handle (NULL on failure)
 * @param width the width
 * @param height the height
 * @param num_channels channels: 1, 3 or 4
 * @param bytes_per_channel 1 (uint8), 2 (uint16) or 4 (float32)
 * @return O3D_OK, or O3D_ERROR_INVALID_ARGUMENT on a NULL pointer.
 */
O3D_API o3d_status o3d_image_create(o3d_image_t** out, int32_t width, int32_t height, int32_t num_channels,
                                    int32_t bytes_per_channel);
/**
 * @brief New image holding a copy of `data`, which must be exactly
 * width * height * num_channels * bytes_per_channel bytes (native byte order). @see Image(numpy array)
 *
 * Threads: any thread.
 * Ownership: `*out` is the caller's, to free with o3d_image_destroy(); left NULL on failure.
 * @param out receives the new handle (NULL on failure)
 * @param width the width
 * @param height the height
 * @param num_channels channels: 1, 3 or 4
 * @param bytes_per_channel 1 (uint8), 2 (uint16) or 4 (float32)
 * @param data the input values, copied
 * @param size number of bytes at `data`
 * @return O3D_OK, or O3D_ERROR_INVALID_ARGUMENT on a NULL pointer.
 */
O3D_API o3d_status o3d_image_create_from_data(o3d_image_t** out, int32_t width, int32_t height,
                                              int32_t num_channels, int32_t bytes_per_channel, const uint8_t* data,
                                              size_t size);
/**
 * @brief Destroy. NULL is a no-op.
 *
 * Threads: needs exclusive access to `image`: no other call may use it during or after.
 * @param image the handle to destroy (NULL is a no-op)
 */
O3D_API void o3d_image_destroy(o3d_image_t* image);
/**
 * @brief Deep copy.
 *
 * Threads: any thread; concurrent calls on the same handles are safe (all read-only).
 * Ownership: `*out` is the caller's, to free with o3d_image_destroy(); left NULL on failure.
 * @param out receives the new handle (NULL on failure)
 * @param src the handle to copy
 * @return O3D_OK, or O3D_ERROR_INVALID_ARGUMENT on a NULL pointer.
 */
O3D_API o3d_status o3d_image_clone(o3d_image_t** out, const o3d_image_t* src);

/**
 * @brief Width in pixels.
 *
 * Threads: any thread; concurrent calls on the same handles are safe (all read-only).
 * @param out receives the result
 * @param image the image
 * @return O3D_OK, or O3D_ERROR_INVALID_ARGUMENT on a NULL pointer.
 */
O3D_API o3d_status o3d_image_width(int32_t* out, const o3d_image_t* image);
/**
 * @brief Height in pixels.
 *
 * Threads: any thread; concurrent calls on the same handles are safe (all read-only).
 * @param out receives the result
 * @param image the image
 * @return O3D_OK, or O3D_ERROR_INVALID_ARGUMENT on a NULL pointer.
 */
O3D_API o3d_status o3d_image_height(int32_t* out, const o3d_image_t* image);
/**
 * @brief Channels per pixel (1, 3 or 4).
 *
 * Threads: any thread; concurrent calls on the same handles are safe (all read-only).
 * @param out receives the result
 * @param image the image
 * @return O3D_OK, or O3D_ERROR_INVALID_ARGUMENT on a NULL pointer.
 */
O3D_API o3d_status o3d_image_num_channels(int32_t* out, const o3d_image_t* image);
/**
 * @brief Bytes per channel (1, 2 or 4).
 *
 * Threads: any thread; concurrent calls on the same handles are safe (all read-only).
 * @param out receives the result
 * @param image the image
 * @return O3D_OK, or O3D_ERROR_INVALID_ARGUMENT on a NULL pointer.
 */
O3D_API o3d_status o3d_image_bytes_per_channel(int32_t* out, const o3d_image_t* image);

/* ---- Arrays: the same functions for every geometry (docs/conventions.md, "Arrays") ----
 * `which` names the array; rows are counted in items (a point, a line, a descriptor), never in
 * values. Copy-outs take the caller's capacity in rows and always report the rows needed;
 * views are borrowed, valid until the next mutating call on the handle or its destruction. */
/** The arrays of an image (O3D_IMAGE_*: its pixel bytes). */
typedef int32_t o3d_image_array;
#define O3D_IMAGE_DATA 0 /**< the pixels: height x width x channels values of bytes_per_channel bytes, in bytes (one byte a row); set_array needs exactly that many */

/**
 * @brief Whether array `which` counts (the image has pixels).
 *
 * Threads: any thread; concurrent calls on the same handles are safe (all read-only).
 * @param out receives 1 (true) or 0 (false)
 * @param image the image
 * @param which the array: one of this header's `which` constants
 * @return O3D_OK, or O3D_ERROR_INVALID_ARGUMENT on a NULL pointer or an unknown `which`.
 */
O3D_API o3d_status o3d_image_has_array(int32_t* out, const o3d_image_t* image, o3d_image_array which);
/**
 * @brief Rows and columns (values per row) of array `which`: e.g. N x 3 for points, num x dimension for a
 * feature.
 *
 * Threads: any thread; concurrent calls on the same handles are safe (all read-only).
 * @param out_rows receives the rows (items)
 * @param out_cols receives the values per row
 * @param image the image
 * @param which the array: one of this header's `which` constants
 * @return O3D_OK, or O3D_ERROR_INVALID_ARGUMENT on a NULL pointer or an unknown `which`.
 */
O3D_API o3d_status o3d_image_array_shape(size_t* out_rows, size_t* out_cols, const o3d_image_t* image, o3d_image_array which);
/**
 * @brief Replace array `which` with `rows` rows of `data`, copied once (`data` may be NULL when rows == 0).
 *
 * Threads: needs exclusive access to `image`.
 * @param image the image
 * @param which the array: one of this header's `which` constants
 * @param data `rows` rows of values, copied once (NULL allowed when rows == 0)
 * @param rows number of rows in `data`
 * @return O3D_OK, or O3D_ERROR_INVALID_ARGUMENT on a NULL handle, an unknown `which`, NULL `data` with rows > 0, an
 *   unknown `which` (or one of the other type) or a byte count other than the image's size.
 */
O3D_API o3d_status o3d_image_set_array(o3d_image_t* image, o3d_image_array which, const uint8_t* data, size_t rows);
/**
 * @brief Copy array `which` into `out`, which holds `capacity` rows; `*out_rows` always gets the rows
 * needed. `out` NULL only reports them.
 *
 * Threads: any thread; concurrent calls on the same handles are safe (all read-only).
 * @param out caller buffer of `capacity` rows (NULL: only report the row count)
 * @param capacity rows `out` holds
 * @param out_rows receives the rows of the array (always, also when `out` is NULL or too small)
 * @param image the image
 * @param which the array: one of this header's `which` constants
 * @return O3D_OK, or O3D_ERROR_INVALID_ARGUMENT on a NULL handle or `out_rows` or an unknown `which`;
 *   O3D_ERROR_BUFFER_TOO_SMALL when `capacity` is short (the count is still reported).
 */
O3D_API o3d_status o3d_image_get_array(uint8_t* out, size_t capacity, size_t* out_rows, const o3d_image_t* image,
                                       o3d_image_array which);
/**
 * @brief Borrowed read-only view of array `which` (`*out_data` NULL when empty).
 *
 * Threads: any thread; concurrent calls on the same handles are safe (all read-only).
 * Ownership: `*out_data` points into `image` (the library's memory, never to be freed): valid until the next mutating
 * call on `image` or its destruction.
 * @param out_data receives the address of row 0 (NULL when the array is empty)
 * @param out_rows receives the row count
 * @param image the image
 * @param which the array: one of this header's `which` constants
 * @return O3D_OK, or O3D_ERROR_INVALID_ARGUMENT on a NULL handle, `out_data` or `out_rows` or an unknown `which`.
 */
O3D_API o3d_status o3d_image_array_view(const uint8_t** out_data, size_t* out_rows, const o3d_image_t* image,
                                        o3d_image_array which);
/**
 * @brief Borrowed writable view of array `which`: as o3d_image_array_view; writing through it is a mutating call.
 *
 * Threads: needs exclusive access to `image`, also while the view is written through.
 * Ownership: `*out_data` points into `image` (the library's memory, never to be freed): valid until the next mutating
 * call on `image` or its destruction.
 * @param out_data receives the address of row 0 (NULL when the array is empty)
 * @param out_rows receives the row count
 * @param image the image
 * @param which the array: one of this header's `which` constants
 * @return O3D_OK, or O3D_ERROR_INVALID_ARGUMENT on a NULL handle, `out_data` or `out_rows` or an unknown `which`.
 */
O3D_API o3d_status o3d_image_array_mutable_view(uint8_t** out_data, size_t* out_rows, o3d_image_t* image,
                                                o3d_image_array which);

/** The filters of Image.filter (O3D_IMAGE_FILTER_*). */
typedef int32_t o3d_image_filter_type;
#define O3D_IMAGE_FILTER_GAUSSIAN3 0 /**< 3x3 Gaussian */
#define O3D_IMAGE_FILTER_GAUSSIAN5 1 /**< 5x5 Gaussian */
#define O3D_IMAGE_FILTER_GAUSSIAN7 2 /**< 7x7 Gaussian */
#define O3D_IMAGE_FILTER_SOBEL3_DX 3 /**< horizontal derivative */
#define O3D_IMAGE_FILTER_SOBEL3_DY 4 /**< vertical derivative */
/**
 * @brief Filtered copy of a 1-channel float32 image (Open3D's Image.filter; borders replicate the edge
 * pixel). Other formats fail with INVALID_ARGUMENT: convert with o3d_image_create_float_image first.
 *
 * Threads: any thread; concurrent calls on the same handles are safe (all read-only).
 * Ownership: `*out` is the caller's, to free with o3d_image_destroy(); left NULL on failure.
 * @param out receives the new handle (NULL on failure)
 * @param image the image
 * @param filter_type O3D_IMAGE_FILTER_*
 * @return O3D_OK, or O3D_ERROR_INVALID_ARGUMENT on a NULL pointer.
 */
O3D_API o3d_status o3d_image_filter(o3d_image_t** out, const o3d_image_t* image, o3d_image_filter_type filter_type);
/**
 * @brief Half-size 1-channel float32 image, each pixel the mean of a 2x2 block (a pyramid step).
 *
 * Threads: any thread; concurrent calls on the same handles are safe (all read-only).
 * Ownership: `*out` is the caller's, to free with o3d_image_destroy(); left NULL on failure.
 * @param out receives the new handle (NULL on failure)
 * @param image the image
 * @return O3D_OK, or O3D_ERROR_INVALID_ARGUMENT on a NULL pointer.
 */
O3D_API o3d_status o3d_image_downsample(o3d_image_t** out, const o3d_image_t* image);
/**
 * @brief Copy flipped upside down.
 *
 * Threads: any thread; concurrent calls on the same handles are safe (all read-only).
 * Ownership: `*out` is the caller's, to free with o3d_image_destroy(); left NULL on failure.
 * @param out receives the new handle (NULL on failure)
 * @param image the image
 * @return O3D_OK, or O3D_ERROR_INVALID_ARGUMENT on a NULL pointer.
 */
O3D_API o3d_status o3d_image_flip_vertical(o3d_image_t** out, const o3d_image_t* image);
/**
 * @brief Copy flipped left to right.
 *
 * Threads: any thread; concurrent calls on the same handles are safe (all read-only).
 * Ownership: `*out` is the caller's, to free with o3d_image_destroy(); left NULL on failure.
 * @param out receives the new handle (NULL on failure)
 * @param image the image
 * @return O3D_OK, or O3D_ERROR_INVALID_ARGUMENT on a NULL pointer.
 */
O3D_API o3d_status o3d_image_flip_horizontal(o3d_image_t** out, const o3d_image_t* image);

/** How Image.create_float_image turns color into gray (O3D_IMAGE_CONVERT_*). */
typedef int32_t o3d_image_convert;
#define O3D_IMAGE_CONVERT_EQUAL 0    /**< gray = mean of R, G, B */
#define O3D_IMAGE_CONVERT_WEIGHTED 1 /**< gray = 0.2990 R + 0.5870 G + 0.1140 B */
/**
 * @brief 1-channel float32 copy: 8-bit values divided by 255, 16-bit values as they are, float kept;
 * 3/4 channels averaged by `convert_type`.
 *
 * Threads: any thread; concurrent calls on the same handles are safe (all read-only).
 * Ownership: `*out` is the caller's, to free with o3d_image_destroy(); left NULL on failure.
 * @param out receives the new handle (NULL on failure)
 * @param image the image
 * @param convert_type O3D_IMAGE_CONVERT_*
 * @return O3D_OK, or O3D_ERROR_INVALID_ARGUMENT on a NULL pointer.
 */
O3D_API o3d_status o3d_image_create_float_image(o3d_image_t** out, const o3d_image_t* image,
                                                o3d_image_convert convert_type);
/**
 * @brief Depth in metres: a 1-channel uint16 or float32 depth image divided by `depth_scale` (> 0), with
 * values at or above `depth_trunc` (and non-finite ones) set to 0. Output is 1-channel float32.
 *
 * Threads: any thread; concurrent calls on the same handles are safe (all read-only).
 * Ownership: `*out` is the caller's, to free with o3d_image_destroy(); left NULL on failure.
 * @param out receives the new handle (NULL on failure)
 * @param image the image
 * @param depth_scale raw units per metre (> 0)
 * @param depth_trunc depths at or above it become 0 (metres)
 * @return O3D_OK, or O3D_ERROR_INVALID_ARGUMENT on a NULL pointer.
 */
O3D_API o3d_status o3d_image_convert_depth_to_float(o3d_image_t** out, const o3d_image_t* image,
                                                    double depth_scale, double depth_trunc);

O3D_END_DECL

#endif /* O3D_IMAGE_H */
