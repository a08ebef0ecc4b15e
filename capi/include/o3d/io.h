/* SPDX-License-Identifier: MIT */
/**
 * @file io.h
 * @brief Reading and writing point clouds (PLY, PCD, XYZ, XYZN, XYZRGB, PTS), triangle meshes (PLY, OBJ,
 * STL, OFF, glTF/GLB), images (PNG, JPEG, PPM, PGM) and camera models (JSON, .log), to files or memory.
 *
 * Formats are named as in Open3D: "ply", "pcd", "xyz", "xyzn", "xyzrgb", "pts". A NULL, "" or "auto"
 * format means: from the file extension (case-insensitive). Paths are UTF-8.
 * A malformed, truncated or inconsistent input fails with O3D_ERROR_PARSE and a message naming the
 * file (or "<memory>") and the reason; a missing file fails with O3D_ERROR_IO.
 *
 * **Out of memory:** any function here that allocates may also return O3D_ERROR_OUT_OF_MEMORY; the
 * per-function `@return` lists do not repeat it.
 */
#ifndef O3D_IO_H
#define O3D_IO_H

#include "o3d/common.h"
#include "o3d/types.h"
#include "o3d/camera.h"
#include "o3d/feature.h"
#include "o3d/image.h"
#include "o3d/pointcloud.h"
#include "o3d/posegraph.h"
#include "o3d/trianglemesh.h"

O3D_BEGIN_DECL

/** Read options (o3d.io.read_point_cloud keyword arguments). */
typedef struct o3d_read_options {
    uint32_t struct_size;           /**< sizeof(o3d_read_options_t) */
    o3d_bool remove_nan_points;     /**< drop points with a NaN coordinate; default 0 */
    o3d_bool remove_infinite_points; /**< drop points with an infinite coordinate; default 0 */
} o3d_read_options_t;

/** Write options (o3d.io.write_point_cloud keyword arguments). */
typedef struct o3d_write_options {
    uint32_t struct_size; /**< sizeof(o3d_write_options_t) */
    o3d_bool write_ascii; /**< PLY/PCD: text instead of binary; default 0 */
    o3d_bool compressed;  /**< PCD: binary_compressed (LZF); default 0 */
} o3d_write_options_t;

/**
 * @brief Fill defaults.
 *
 * Threads: any thread.
 * @param opts the struct to fill
 * @param struct_size sizeof the struct as the caller knows it (an older, smaller size is accepted)
 * @return O3D_OK, or O3D_ERROR_INVALID_ARGUMENT on a NULL pointer or a `struct_size` this library does not know.
 */
O3D_API o3d_status o3d_read_options_init(o3d_read_options_t* opts, uint32_t struct_size);
/**
 * @brief Fill defaults.
 *
 * Threads: any thread.
 * @param opts the struct to fill
 * @param struct_size sizeof the struct as the caller knows it (an older, smaller size is accepted)
 * @return O3D_OK, or O3D_ERROR_INVALID_ARGUMENT on a NULL pointer or a `struct_size` this library does not know.
 */
O3D_API o3d_status o3d_write_options_init(o3d_write_options_t* opts, uint32_t struct_size);

/**
 * @brief Read a cloud from `path` (NULL opts: defaults). @see o3d.io.read_point_cloud
 *
 * Threads: any thread.
 * Ownership: `*out` is the caller's, to free with o3d_pointcloud_destroy(); left NULL on failure.
 * @param out receives the new handle (NULL on failure)
 * @param path the file path (UTF-8)
 * @param format the format name (NULL, "" or "auto": from the file extension)
 * @param opts options (NULL: the defaults of the matching `*_init`)
 * @return O3D_OK, or O3D_ERROR_INVALID_ARGUMENT on a NULL pointer or a bad `opts->struct_size`; O3D_ERROR_IO when the
 *   file cannot be opened, read or written; O3D_ERROR_PARSE on malformed, truncated or inconsistent data;
 *   O3D_ERROR_UNSUPPORTED on an unknown format (or a variant of it this library does not handle).
 */
O3D_API o3d_status o3d_io_read_point_cloud(o3d_pointcloud_t** out, const char* path, const char* format,
                                           const o3d_read_options_t* opts);
/**
 * @brief Write `pc` to `path`. @see o3d.io.write_point_cloud
 *
 * Threads: any thread; concurrent calls on the same handles are safe (all read-only).
 * @param path the file path (UTF-8)
 * @param pc the point cloud
 * @param format the format name (NULL, "" or "auto": from the file extension)
 * @param opts options (NULL: the defaults of the matching `*_init`)
 * @return O3D_OK, or O3D_ERROR_INVALID_ARGUMENT on a NULL pointer or a bad `opts->struct_size`; O3D_ERROR_IO when the
 *   file cannot be opened, read or written; O3D_ERROR_UNSUPPORTED on an unknown format (or a variant of it this library
 *   does not handle).
 */
O3D_API o3d_status o3d_io_write_point_cloud(const char* path, const o3d_pointcloud_t* pc, const char* format,
                                            const o3d_write_options_t* opts);
/**
 * @brief Read a cloud from `size` bytes at `data`; `format` is required (no extension to look at).
 *
 * Threads: any thread.
 * Ownership: `*out` is the caller's, to free with o3d_pointcloud_destroy(); left NULL on failure.
 * @param out receives the new handle (NULL on failure)
 * @param data the encoded bytes (NULL allowed when size == 0)
 * @param size number of bytes at `data`
 * @param format the format name (required)
 * @param opts options (NULL: the defaults of the matching `*_init`)
 * @return O3D_OK, or O3D_ERROR_INVALID_ARGUMENT on a NULL pointer or a bad `opts->struct_size`; O3D_ERROR_PARSE on
 *   malformed, truncated or inconsistent data; O3D_ERROR_UNSUPPORTED on an unknown format (or a variant of it this
 *   library does not handle).
 */
O3D_API o3d_status o3d_io_read_point_cloud_from_memory(o3d_pointcloud_t** out, const uint8_t* data, size_t size,
                                                       const char* format, const o3d_read_options_t* opts);
/**
 * @brief Encode `pc` in `format` into a new buffer.
 *
 * Threads: any thread; concurrent calls on the same handles are safe (all read-only).
 * Ownership: `*out` is the caller's, to free with o3d_buffer_destroy(); left NULL on failure.
 * @param out receives the new handle (NULL on failure)
 * @param pc the point cloud
 * @param format the format name (required)
 * @param opts options (NULL: the defaults of the matching `*_init`)
 * @return O3D_OK, or O3D_ERROR_INVALID_ARGUMENT on a NULL pointer or a bad `opts->struct_size`; O3D_ERROR_UNSUPPORTED
 *   on an unknown format (or a variant of it this library does not handle).
 */
O3D_API o3d_status o3d_io_write_point_cloud_to_memory(o3d_buffer_t** out, const o3d_pointcloud_t* pc,
                                                      const char* format, const o3d_write_options_t* opts);

/* ---- Triangle meshes: "ply", "obj", "stl", "off", "gltf", "glb" ---- */

/** o3d.io.read_triangle_mesh keyword arguments. */
typedef struct o3d_mesh_read_options {
    uint32_t struct_size;           /**< sizeof(o3d_mesh_read_options_t) */
    o3d_bool enable_post_processing; /**< merge duplicated vertices and drop degenerate triangles; default 0 */
} o3d_mesh_read_options_t;

/** o3d.io.write_triangle_mesh keyword arguments. */
typedef struct o3d_mesh_write_options {
    uint32_t struct_size;         /**< sizeof(o3d_mesh_write_options_t) */
    o3d_bool write_ascii;         /**< PLY/STL: text instead of binary; default 0 */
    o3d_bool compressed;          /**< accepted for Open3D compatibility; no format here compresses; default 0 */
    o3d_bool write_vertex_normals; /**< write the vertex normals when the mesh has them; default 1 */
    o3d_bool write_vertex_colors; /**< write the vertex colors when the mesh has them; default 1 */
    o3d_bool write_triangle_uvs;  /**< write the triangle UVs (and textures) when the mesh has them; default 1 */
} o3d_mesh_write_options_t;

/**
 * @brief Fill defaults.
 *
 * Threads: any thread.
 * @param opts the struct to fill
 * @param struct_size sizeof the struct as the caller knows it (an older, smaller size is accepted)
 * @return O3D_OK, or O3D_ERROR_INVALID_ARGUMENT on a NULL pointer or a `struct_size` this library does not know.
 */
O3D_API o3d_status o3d_mesh_read_options_init(o3d_mesh_read_options_t* opts, uint32_t struct_size);
/**
 * @brief Fill defaults.
 *
 * Threads: any thread.
 * @param opts the struct to fill
 * @param struct_size sizeof the struct as the caller knows it (an older, smaller size is accepted)
 * @return O3D_OK, or O3D_ERROR_INVALID_ARGUMENT on a NULL pointer or a `struct_size` this library does not know.
 */
O3D_API o3d_status o3d_mesh_write_options_init(o3d_mesh_write_options_t* opts, uint32_t struct_size);

/**
 * @brief Read a mesh. OBJ reads its .mtl and texture images (paths relative to the OBJ); glTF reads its
 * buffers and images. @see o3d.io.read_triangle_mesh
 *
 * Threads: any thread.
 * Ownership: `*out` is the caller's, to free with o3d_trianglemesh_destroy(); left NULL on failure.
 * @param out receives the new handle (NULL on failure)
 * @param path the file path (UTF-8)
 * @param format the format name (NULL, "" or "auto": from the file extension)
 * @param opts options (NULL: the defaults of the matching `*_init`)
 * @return O3D_OK, or O3D_ERROR_INVALID_ARGUMENT on a NULL pointer or a bad `opts->struct_size`; O3D_ERROR_IO when the
 *   file cannot be opened, read or written; O3D_ERROR_PARSE on malformed, truncated or inconsistent data;
 *   O3D_ERROR_UNSUPPORTED on an unknown format (or a variant of it this library does not handle).
 */
O3D_API o3d_status o3d_io_read_triangle_mesh(o3d_trianglemesh_t** out, const char* path, const char* format,
                                             const o3d_mesh_read_options_t* opts);
/**
 * @brief Write a mesh (OBJ also writes a .mtl and PNG textures beside it). @see o3d.io.write_triangle_mesh
 *
 * Threads: any thread; concurrent calls on the same handles are safe (all read-only).
 * @param path the file path (UTF-8)
 * @param mesh the mesh
 * @param format the format name (NULL, "" or "auto": from the file extension)
 * @param opts options (NULL: the defaults of the matching `*_init`)
 * @return O3D_OK, or O3D_ERROR_INVALID_ARGUMENT on a NULL pointer or a bad `opts->struct_size`; O3D_ERROR_IO when the
 *   file cannot be opened, read or written; O3D_ERROR_UNSUPPORTED on an unknown format (or a variant of it this library
 *   does not handle).
 */
O3D_API o3d_status o3d_io_write_triangle_mesh(const char* path, const o3d_trianglemesh_t* mesh, const char* format,
                                              const o3d_mesh_write_options_t* opts);
/**
 * @brief Read a mesh from memory: "ply", "stl", "off", "obj" (no materials) or "glb" (embedded data).
 *
 * Threads: any thread.
 * Ownership: `*out` is the caller's, to free with o3d_trianglemesh_destroy(); left NULL on failure.
 * @param out receives the new handle (NULL on failure)
 * @param data the encoded bytes (NULL allowed when size == 0)
 * @param size number of bytes at `data`
 * @param format the format name (required)
 * @param opts options (NULL: the defaults of the matching `*_init`)
 * @return O3D_OK, or O3D_ERROR_INVALID_ARGUMENT on a NULL pointer or a bad `opts->struct_size`; O3D_ERROR_PARSE on
 *   malformed, truncated or inconsistent data; O3D_ERROR_UNSUPPORTED on an unknown format (or a variant of it this
 *   library does not handle).
 */
O3D_API o3d_status o3d_io_read_triangle_mesh_from_memory(o3d_trianglemesh_t** out, const uint8_t* data,
                                                         size_t size, const char* format,
                                                         const o3d_mesh_read_options_t* opts);
/**
 * @brief Encode a mesh in one of the formats of read_triangle_mesh_from_memory into a new buffer.
 *
 * Threads: any thread; concurrent calls on the same handles are safe (all read-only).
 * Ownership: `*out` is the caller's, to free with o3d_buffer_destroy(); left NULL on failure.
 * @param out receives the new handle (NULL on failure)
 * @param mesh the mesh
 * @param format the format name (required)
 * @param opts options (NULL: the defaults of the matching `*_init`)
 * @return O3D_OK, or O3D_ERROR_INVALID_ARGUMENT on a NULL pointer or a bad `opts->struct_size`; O3D_ERROR_UNSUPPORTED
 *   on an unknown format (or a variant of it this library does not handle).
 */
O3D_API o3d_status o3d_io_write_triangle_mesh_to_memory(o3d_buffer_t** out, const o3d_trianglemesh_t* mesh,
                                                        const char* format, const o3d_mesh_write_options_t* opts);

/* ---- Images: "png", "jpg"/"jpeg", "ppm", "pgm" (binary P6/P5, 8 or 16 bit) ---- */

/**
 * @brief Read an image (format from the extension when NULL/""/"auto"). @see o3d.io.read_image
 *
 * Threads: any thread.
 * Ownership: `*out` is the caller's, to free with o3d_image_destroy(); left NULL on failure.
 * @param out receives the new handle (NULL on failure)
 * @param path the file path (UTF-8)
 * @param format the format name (NULL, "" or "auto": from the file extension)
 * @return O3D_OK, or O3D_ERROR_INVALID_ARGUMENT on a NULL pointer; O3D_ERROR_IO when the file cannot be opened, read
 *   or written; O3D_ERROR_PARSE on malformed, truncated or inconsistent data; O3D_ERROR_UNSUPPORTED on an unknown
 *   format (or a variant of it this library does not handle).
 */
O3D_API o3d_status o3d_io_read_image(o3d_image_t** out, const char* path, const char* format);
/**
 * @brief Write an image. `quality` is JPEG quality 1..100, or -1 for the default (90); others ignore it.
 * PNG and PGM take 8/16-bit 1 channel, PNG and PPM 8/16-bit 3 channels, PNG 4 channels, JPEG 8-bit 1 or 3.
 * Float images are not written (convert first). @see o3d.io.write_image
 *
 * Threads: any thread; concurrent calls on the same handles are safe (all read-only).
 * @param path the file path (UTF-8)
 * @param image the image
 * @param format the format name (NULL, "" or "auto": from the file extension)
 * @param quality JPEG quality 1..100, -1 for the default (90); other formats ignore it
 * @return O3D_OK, or O3D_ERROR_INVALID_ARGUMENT on a NULL pointer or an image the format cannot hold (e.g. float32);
 *   O3D_ERROR_IO when the file cannot be opened, read or written; O3D_ERROR_UNSUPPORTED on an unknown format (or a
 *   variant of it this library does not handle).
 */
O3D_API o3d_status o3d_io_write_image(const char* path, const o3d_image_t* image, const char* format,
                                      int32_t quality);
/**
 * @brief Decode an image from `size` bytes at `data`. @see o3d.io.read_image
 *
 * Threads: any thread.
 * Ownership: `*out` is the caller's, to free with o3d_image_destroy(); left NULL on failure.
 * @param out receives the new handle (NULL on failure)
 * @param data the encoded bytes (NULL allowed when size == 0)
 * @param size number of bytes at `data`
 * @param format the format name (required)
 * @return O3D_OK, or O3D_ERROR_INVALID_ARGUMENT on a NULL pointer; O3D_ERROR_PARSE on malformed, truncated or
 *   inconsistent data; O3D_ERROR_UNSUPPORTED on an unknown format (or a variant of it this library does not handle).
 */
O3D_API o3d_status o3d_io_read_image_from_memory(o3d_image_t** out, const uint8_t* data, size_t size,
                                                 const char* format);
/**
 * @brief Encode `image` into a new buffer, with the rules of o3d_io_write_image.
 *
 * Threads: any thread; concurrent calls on the same handles are safe (all read-only).
 * Ownership: `*out` is the caller's, to free with o3d_buffer_destroy(); left NULL on failure.
 * @param out receives the new handle (NULL on failure)
 * @param image the image
 * @param format the format name (required)
 * @param quality JPEG quality 1..100, -1 for the default (90); other formats ignore it
 * @return O3D_OK, or O3D_ERROR_INVALID_ARGUMENT on a NULL pointer or an image the format cannot hold (e.g. float32);
 *   O3D_ERROR_UNSUPPORTED on an unknown format (or a variant of it this library does not handle).
 */
O3D_API o3d_status o3d_io_write_image_to_memory(o3d_buffer_t** out, const o3d_image_t* image, const char* format,
                                                int32_t quality);

/* ---- Camera models: Open3D's JSON layouts; trajectories also as .log ---- */

/**
 * @brief Read a PinholeCameraIntrinsic JSON file. @see o3d.io.read_pinhole_camera_intrinsic
 *
 * Threads: any thread.
 * @param out receives the result
 * @param path the file path (UTF-8)
 * @return O3D_OK, or O3D_ERROR_INVALID_ARGUMENT on a NULL pointer; O3D_ERROR_IO when the file cannot be opened, read
 *   or written; O3D_ERROR_PARSE on malformed, truncated or inconsistent data.
 */
O3D_API o3d_status o3d_io_read_pinhole_camera_intrinsic(o3d_pinhole_intrinsic_t* out, const char* path);
/**
 * @brief Write a PinholeCameraIntrinsic JSON file. @see o3d.io.write_pinhole_camera_intrinsic
 *
 * Threads: any thread.
 * @param path the file path (UTF-8)
 * @param intrinsic the camera intrinsic
 * @return O3D_OK, or O3D_ERROR_INVALID_ARGUMENT on a NULL pointer; O3D_ERROR_IO when the file cannot be opened, read
 *   or written.
 */
O3D_API o3d_status o3d_io_write_pinhole_camera_intrinsic(const char* path, const o3d_pinhole_intrinsic_t* intrinsic);
/**
 * @brief Read a PinholeCameraParameters JSON file (either output may be NULL).
 *
 * Threads: any thread.
 * @param out_intrinsic receives the intrinsic (may be NULL)
 * @param out_extrinsic receives the row-major 4x4 extrinsic (may be NULL)
 * @param path the file path (UTF-8)
 * @return O3D_OK, or O3D_ERROR_INVALID_ARGUMENT on a NULL pointer; O3D_ERROR_IO when the file cannot be opened, read
 *   or written; O3D_ERROR_PARSE on malformed, truncated or inconsistent data.
 */
O3D_API o3d_status o3d_io_read_pinhole_camera_parameters(o3d_pinhole_intrinsic_t* out_intrinsic,
                                                         double out_extrinsic[16], const char* path);
/**
 * @brief Write a PinholeCameraParameters JSON file.
 *
 * Threads: any thread.
 * @param path the file path (UTF-8)
 * @param intrinsic the camera intrinsic
 * @param extrinsic row-major 4x4 world-to-camera matrix (NULL: identity)
 * @return O3D_OK, or O3D_ERROR_INVALID_ARGUMENT on a NULL pointer; O3D_ERROR_IO when the file cannot be opened, read
 *   or written.
 */
O3D_API o3d_status o3d_io_write_pinhole_camera_parameters(const char* path, const o3d_pinhole_intrinsic_t* intrinsic,
                                                          const double extrinsic[16]);
/**
 * @brief Read a trajectory: "json" (PinholeCameraTrajectory) or "log" (camera-to-world poses; each
 * extrinsic is the pose's inverse and the intrinsic the PrimeSense default), NULL/"auto": by extension.
 *
 * Threads: any thread.
 * Ownership: `*out` is the caller's, to free with o3d_camera_trajectory_destroy(); left NULL on failure.
 * @param out receives the new handle (NULL on failure)
 * @param path the file path (UTF-8)
 * @param format the format name (NULL, "" or "auto": from the file extension)
 * @return O3D_OK, or O3D_ERROR_INVALID_ARGUMENT on a NULL pointer; O3D_ERROR_IO when the file cannot be opened, read
 *   or written; O3D_ERROR_PARSE on malformed, truncated or inconsistent data; O3D_ERROR_UNSUPPORTED on an unknown
 *   format (or a variant of it this library does not handle).
 */
O3D_API o3d_status o3d_io_read_pinhole_camera_trajectory(o3d_camera_trajectory_t** out, const char* path,
                                                         const char* format);
/**
 * @brief Write a trajectory as "json" or "log" (NULL/"auto": by extension).
 *
 * Threads: any thread; concurrent calls on the same handles are safe (all read-only).
 * @param path the file path (UTF-8)
 * @param trajectory the trajectory
 * @param format the format name (NULL, "" or "auto": from the file extension)
 * @return O3D_OK, or O3D_ERROR_INVALID_ARGUMENT on a NULL pointer; O3D_ERROR_IO when the file cannot be opened, read
 *   or written; O3D_ERROR_UNSUPPORTED on an unknown format (or a variant of it this library does not handle).
 */
O3D_API o3d_status o3d_io_write_pinhole_camera_trajectory(const char* path,
                                                          const o3d_camera_trajectory_t* trajectory,
                                                          const char* format);

/* ---- Feature files ---- */

/**
 * @brief Read a feature file in Open3D's binary layout: int32 dimension, int32 num, then num x dimension
 * float64 (descriptor by descriptor). Truncated or inconsistent files → O3D_ERROR_PARSE.
 *
 * Threads: any thread.
 * Ownership: `*out` is the caller's, to free with o3d_feature_destroy(); left NULL on failure.
 * @param out receives the new handle (NULL on failure)
 * @param path the file path (UTF-8)
 * @return O3D_OK, or O3D_ERROR_INVALID_ARGUMENT on a NULL pointer; O3D_ERROR_IO when the file cannot be opened, read
 *   or written; O3D_ERROR_PARSE on malformed, truncated or inconsistent data.
 */
O3D_API o3d_status o3d_io_read_feature(o3d_feature_t** out, const char* path);
/**
 * @brief Write `feature` in the layout o3d_io_read_feature reads.
 *
 * Threads: any thread; concurrent calls on the same handles are safe (all read-only).
 * @param path the file path (UTF-8)
 * @param feature the feature
 * @return O3D_OK, or O3D_ERROR_INVALID_ARGUMENT on a NULL pointer; O3D_ERROR_IO when the file cannot be opened, read
 *   or written.
 */
O3D_API o3d_status o3d_io_write_feature(const char* path, const o3d_feature_t* feature);

/* ---- Pose graphs (Open3D's JSON layout) ---- */

/**
 * @brief Read Open3D's JSON pose graph ("class_name": "PoseGraph"; matrices column-major in the file).
 *
 * Threads: any thread.
 * Ownership: `*out` is the caller's, to free with o3d_pose_graph_destroy(); left NULL on failure.
 * @param out receives the new handle (NULL on failure)
 * @param path the file path (UTF-8)
 * @return O3D_OK, or O3D_ERROR_INVALID_ARGUMENT on a NULL pointer; O3D_ERROR_IO when the file cannot be opened, read
 *   or written; O3D_ERROR_PARSE on malformed, truncated or inconsistent data.
 */
O3D_API o3d_status o3d_io_read_pose_graph(o3d_pose_graph_t** out, const char* path);
/**
 * @brief Write `graph` in Open3D's JSON layout.
 *
 * Threads: any thread; concurrent calls on the same handles are safe (all read-only).
 * @param path the file path (UTF-8)
 * @param graph the pose graph
 * @return O3D_OK, or O3D_ERROR_INVALID_ARGUMENT on a NULL pointer; O3D_ERROR_IO when the file cannot be opened, read
 *   or written.
 */
O3D_API o3d_status o3d_io_write_pose_graph(const char* path, const o3d_pose_graph_t* graph);

O3D_END_DECL

#endif /* O3D_IO_H */
