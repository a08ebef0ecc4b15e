/* SPDX-License-Identifier: MIT */
/**
 * @file io.h
 * @brief Reading and writing point clouds: PLY, PCD, XYZ, XYZN, XYZRGB, PTS, to files or memory.
 *
 * Formats are named as in Open3D: "ply", "pcd", "xyz", "xyzn", "xyzrgb", "pts". A NULL, "" or "auto"
 * format means: from the file extension (case-insensitive). Paths are UTF-8.
 * A malformed, truncated or inconsistent input fails with O3D_ERROR_PARSE and a message naming the
 * file (or "<memory>") and the reason; a missing file fails with O3D_ERROR_IO.
 */
#ifndef O3D_IO_H
#define O3D_IO_H

#include "o3d/common.h"
#include "o3d/pointcloud.h"

O3D_BEGIN_DECL

/** Read options (o3d.io.read_point_cloud keyword arguments). */
typedef struct o3d_read_options {
    uint32_t struct_size;           /**< sizeof(o3d_read_options_t) */
    int32_t remove_nan_points;      /**< drop points with a NaN coordinate; default 0 */
    int32_t remove_infinite_points; /**< drop points with an infinite coordinate; default 0 */
} o3d_read_options_t;

/** Write options (o3d.io.write_point_cloud keyword arguments). */
typedef struct o3d_write_options {
    uint32_t struct_size; /**< sizeof(o3d_write_options_t) */
    int32_t write_ascii;  /**< PLY/PCD: text instead of binary; default 0 */
    int32_t compressed;   /**< PCD: binary_compressed (LZF); default 0 */
} o3d_write_options_t;

/** @brief Fill defaults. */
O3D_API o3d_status o3d_read_options_init(o3d_read_options_t* opts, uint32_t struct_size);
O3D_API o3d_status o3d_write_options_init(o3d_write_options_t* opts, uint32_t struct_size);

/** @brief Read a cloud from `path` (NULL opts: defaults). @see o3d.io.read_point_cloud */
O3D_API o3d_status o3d_io_read_point_cloud(o3d_pointcloud_t** out, const char* path, const char* format,
                                           const o3d_read_options_t* opts);
/** @brief Write `pc` to `path`. @see o3d.io.write_point_cloud */
O3D_API o3d_status o3d_io_write_point_cloud(const char* path, const o3d_pointcloud_t* pc, const char* format,
                                            const o3d_write_options_t* opts);
/** @brief Read a cloud from `size` bytes at `data`; `format` is required (no extension to look at). */
O3D_API o3d_status o3d_io_read_point_cloud_from_memory(o3d_pointcloud_t** out, const uint8_t* data, size_t size,
                                                       const char* format, const o3d_read_options_t* opts);
/**
 * @brief Encode `pc` in `format` into a new buffer.
 * **Ownership:** `*out` belongs to the caller (o3d_buffer_destroy).
 */
O3D_API o3d_status o3d_io_write_point_cloud_to_memory(o3d_buffer_t** out, const o3d_pointcloud_t* pc,
                                                      const char* format, const o3d_write_options_t* opts);

O3D_END_DECL

#endif /* O3D_IO_H */
