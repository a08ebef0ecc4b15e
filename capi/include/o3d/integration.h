/* SPDX-License-Identifier: MIT */
/**
 * @file integration.h
 * @brief TSDF integration (Open3D's o3d.pipelines.integration): RGB-D frames fused into a truncated signed
 * distance volume (Curless & Levoy 1996), the surface extracted by marching cubes.
 *
 * One handle type serves Open3D's two volumes: a uniform volume (UniformTSDFVolume: resolution^3 voxels
 * allocated at creation) and a scalable one (ScalableTSDFVolume: blocks of volume_unit_resolution^3 voxels in a
 * hash map, opened around the surface each frame sees, so memory grows with the surface).
 *
 * The frames are Open3D's integration input: an RGB-D image (o3d_rgbd_image_create_from_color_and_depth) whose
 * depth is 1-channel float metres and whose colour is 3-channel uint8 (convert_rgb_to_intensity off) for
 * O3D_TSDF_VOLUME_COLOR_TYPE_RGB8, or 1-channel float intensity for _GRAY32; a _NO_COLOR volume ignores colour.
 *
 * **Thread safety:** extraction and getters take a const volume and may run concurrently; integrate and reset
 * need exclusive access. Integration and extraction are parallel inside (o3d_set_num_threads); their results do
 * not depend on the thread count.
 *
 * **Out of memory:** any function here that allocates may also return O3D_ERROR_OUT_OF_MEMORY (a uniform volume of
 * a large resolution); the per-function `@return` lists do not repeat it.
 */
#ifndef O3D_INTEGRATION_H
#define O3D_INTEGRATION_H

#include "o3d/camera.h"
#include "o3d/common.h"
#include "o3d/rgbd.h"
#include "o3d/types.h"

O3D_BEGIN_DECL

/** What colour each voxel keeps (Open3D's TSDFVolumeColorType; O3D_TSDF_VOLUME_COLOR_TYPE_*). */
typedef int32_t o3d_tsdf_volume_color_type;
#define O3D_TSDF_VOLUME_COLOR_TYPE_NO_COLOR 0 /**< no colour */
#define O3D_TSDF_VOLUME_COLOR_TYPE_RGB8 1     /**< the frames' 8-bit RGB colour */
#define O3D_TSDF_VOLUME_COLOR_TYPE_GRAY32 2   /**< the frames' float intensity, kept as a grey colour */

/**
 * @brief A uniform volume (UniformTSDFVolume): a cube of edge `length` whose first corner is `origin`, cut into
 * resolution^3 voxels of edge length / resolution, all allocated now (20 bytes each with colour, 8 without).
 *
 * Threads: any thread.
 * Ownership: `*out` is the caller's, to free with o3d_tsdf_volume_destroy(); left NULL on failure.
 * @param out receives the new handle (NULL on failure)
 * @param length the cube's edge in metres (> 0)
 * @param resolution voxels along each edge (1..2048)
 * @param sdf_trunc the truncation distance in metres (> 0; Open3D's tutorials use 0.04)
 * @param color_type O3D_TSDF_VOLUME_COLOR_TYPE_*
 * @param origin the cube's minimum corner (NULL: the origin)
 * @return O3D_OK, or O3D_ERROR_INVALID_ARGUMENT on a NULL `out`, a non-finite or non-positive length or sdf_trunc,
 *   a resolution out of range, an unknown colour type or a non-finite origin.
 */
O3D_API o3d_status o3d_tsdf_volume_create_uniform(o3d_tsdf_volume_t** out, double length, int32_t resolution,
                                                  double sdf_trunc, o3d_tsdf_volume_color_type color_type,
                                                  const double origin[3]);
/**
 * @brief A scalable volume (ScalableTSDFVolume): voxels of edge `voxel_length` in blocks of
 * volume_unit_resolution^3, opened where frames see a surface. Open3D's defaults: 16 and 4.
 *
 * Threads: any thread.
 * Ownership: `*out` is the caller's, to free with o3d_tsdf_volume_destroy(); left NULL on failure.
 * @param out receives the new handle (NULL on failure)
 * @param voxel_length the voxel edge in metres (> 0; Open3D's tutorials use 4.0 / 512)
 * @param sdf_trunc the truncation distance in metres (> 0)
 * @param color_type O3D_TSDF_VOLUME_COLOR_TYPE_*
 * @param volume_unit_resolution voxels along a block's edge (2..256)
 * @param depth_sampling_stride every stride-th pixel of each row and column opens blocks (>= 1)
 * @return O3D_OK, or O3D_ERROR_INVALID_ARGUMENT on a NULL `out`, a non-finite or non-positive voxel_length or
 *   sdf_trunc, an unknown colour type, or a block resolution or stride out of range.
 */
O3D_API o3d_status o3d_tsdf_volume_create_scalable(o3d_tsdf_volume_t** out, double voxel_length, double sdf_trunc,
                                                   o3d_tsdf_volume_color_type color_type,
                                                   int32_t volume_unit_resolution, int32_t depth_sampling_stride);
/**
 * @brief Destroy. NULL is a no-op.
 *
 * Threads: needs exclusive access to `volume`: no other call may use it during or after.
 * @param volume the handle to destroy (NULL is a no-op)
 */
O3D_API void o3d_tsdf_volume_destroy(o3d_tsdf_volume_t* volume);

/**
 * @brief Fuse one frame seen by `intrinsic` from `extrinsic` (world to camera): each voxel in view takes the
 * running average of its truncated distance (and colour), and its weight grows by one.
 *
 * Depth that is 0, negative, NaN or infinite is a hole, not a surface.
 * Threads: needs exclusive access to `volume`; the image is only read.
 * @param volume the volume
 * @param image the frame (see the file comment for its formats)
 * @param intrinsic the camera (its size must be the images')
 * @param extrinsic world-to-camera transformation, row-major 4x4
 * @return O3D_OK; O3D_ERROR_INVALID_ARGUMENT on a NULL pointer, a depth that is not 1-channel float, a colour the
 *   volume's colour type cannot use, images of another size than the intrinsic, fx or fy <= 0, or a non-finite
 *   (or, for a scalable volume, singular) extrinsic. The volume is unchanged then.
 */
O3D_API o3d_status o3d_tsdf_volume_integrate(o3d_tsdf_volume_t* volume, const o3d_rgbd_image_t* image,
                                             const o3d_pinhole_intrinsic_t* intrinsic, const double extrinsic[16]);
/**
 * @brief Forget every frame (a scalable volume frees its blocks).
 *
 * Threads: needs exclusive access to `volume`.
 * @param volume the volume
 * @return O3D_OK, or O3D_ERROR_INVALID_ARGUMENT on a NULL pointer.
 */
O3D_API o3d_status o3d_tsdf_volume_reset(o3d_tsdf_volume_t* volume);

/**
 * @brief The surface by marching cubes over every cube of 8 observed voxels: a vertex on each crossed edge (with
 * the interpolated colour unless the volume keeps none), triangles wound toward free space. @see extract_triangle_mesh
 *
 * Threads: any thread; concurrent calls on the same handles are safe (all read-only).
 * Ownership: `*out` is the caller's, to free with o3d_trianglemesh_destroy(); left NULL on failure.
 * @param out receives the new mesh (NULL on failure); empty when nothing was integrated
 * @param volume the volume
 * @return O3D_OK, or O3D_ERROR_INVALID_ARGUMENT on a NULL pointer.
 */
O3D_API o3d_status o3d_tsdf_volume_extract_triangle_mesh(o3d_trianglemesh_t** out, const o3d_tsdf_volume_t* volume);
/**
 * @brief The zero crossings between neighbouring observed voxels (|tsdf| < 0.98), with normals along the distance's
 * gradient (toward free space) and colours. @see extract_point_cloud
 *
 * Threads: any thread; concurrent calls on the same handles are safe (all read-only).
 * Ownership: `*out` is the caller's, to free with o3d_pointcloud_destroy(); left NULL on failure.
 * @param out receives the new cloud (NULL on failure)
 * @param volume the volume
 * @return O3D_OK, or O3D_ERROR_INVALID_ARGUMENT on a NULL pointer.
 */
O3D_API o3d_status o3d_tsdf_volume_extract_point_cloud(o3d_pointcloud_t** out, const o3d_tsdf_volume_t* volume);
/**
 * @brief The centre of every observed voxel with |tsdf| < 0.98, coloured grey by (tsdf + 1) / 2 (Open3D's debug
 * view). @see extract_voxel_point_cloud
 *
 * Threads: any thread; concurrent calls on the same handles are safe (all read-only).
 * Ownership: `*out` is the caller's, to free with o3d_pointcloud_destroy(); left NULL on failure.
 * @param out receives the new cloud (NULL on failure)
 * @param volume the volume
 * @return O3D_OK, or O3D_ERROR_INVALID_ARGUMENT on a NULL pointer.
 */
O3D_API o3d_status o3d_tsdf_volume_extract_voxel_point_cloud(o3d_pointcloud_t** out, const o3d_tsdf_volume_t* volume);
/**
 * @brief The same voxels as a voxel grid of edge voxel_length (origin: the uniform volume's; the world origin for a
 * scalable volume). @see extract_voxel_grid
 *
 * Threads: any thread; concurrent calls on the same handles are safe (all read-only).
 * Ownership: `*out` is the caller's, to free with o3d_voxelgrid_destroy(); left NULL on failure.
 * @param out receives the new grid (NULL on failure)
 * @param volume the volume
 * @return O3D_OK, or O3D_ERROR_INVALID_ARGUMENT on a NULL pointer.
 */
O3D_API o3d_status o3d_tsdf_volume_extract_voxel_grid(o3d_voxelgrid_t** out, const o3d_tsdf_volume_t* volume);
/**
 * @brief A uniform volume's tsdf and weight of every voxel, two floats each, voxel (x, y, z) at row
 * (x * resolution + y) * resolution + z. @see extract_volume_tsdf
 *
 * Call with `out` NULL to learn the row count (resolution^3).
 * Threads: any thread; concurrent calls on the same handles are safe (all read-only).
 * @param out receives the rows (2 floats each; NULL: only count)
 * @param capacity how many rows `out` holds (ignored when it is NULL)
 * @param out_rows receives the row count
 * @param volume a uniform volume
 * @return O3D_OK; O3D_ERROR_INVALID_ARGUMENT on a NULL `out_rows` or `volume`, or a scalable volume;
 *   O3D_ERROR_BUFFER_TOO_SMALL when `capacity` is short (the count is still reported).
 */
O3D_API o3d_status o3d_tsdf_volume_extract_volume_tsdf(float* out, size_t capacity, size_t* out_rows,
                                                       const o3d_tsdf_volume_t* volume);
/**
 * @brief A uniform volume's colour of every voxel, three floats in [0, 1] each (zeros without colour), rows as
 * o3d_tsdf_volume_extract_volume_tsdf. @see extract_volume_color
 *
 * Threads: any thread; concurrent calls on the same handles are safe (all read-only).
 * @param out receives the rows (3 floats each; NULL: only count)
 * @param capacity how many rows `out` holds (ignored when it is NULL)
 * @param out_rows receives the row count
 * @param volume a uniform volume
 * @return O3D_OK; O3D_ERROR_INVALID_ARGUMENT on a NULL `out_rows` or `volume`, or a scalable volume;
 *   O3D_ERROR_BUFFER_TOO_SMALL when `capacity` is short (the count is still reported).
 */
O3D_API o3d_status o3d_tsdf_volume_extract_volume_color(float* out, size_t capacity, size_t* out_rows,
                                                        const o3d_tsdf_volume_t* volume);

/**
 * @brief Whether the volume is scalable (1) or uniform (0).
 *
 * Threads: any thread; concurrent calls on the same handles are safe (all read-only).
 * @param out receives 1 (true) or 0 (false)
 * @param volume the volume
 * @return O3D_OK, or O3D_ERROR_INVALID_ARGUMENT on a NULL pointer.
 */
O3D_API o3d_status o3d_tsdf_volume_is_scalable(o3d_bool* out, const o3d_tsdf_volume_t* volume);
/**
 * @brief The voxel edge in metres.
 *
 * Threads: any thread; concurrent calls on the same handles are safe (all read-only).
 * @param out receives the length
 * @param volume the volume
 * @return O3D_OK, or O3D_ERROR_INVALID_ARGUMENT on a NULL pointer.
 */
O3D_API o3d_status o3d_tsdf_volume_get_voxel_length(double* out, const o3d_tsdf_volume_t* volume);
/**
 * @brief The truncation distance in metres.
 *
 * Threads: any thread; concurrent calls on the same handles are safe (all read-only).
 * @param out receives the distance
 * @param volume the volume
 * @return O3D_OK, or O3D_ERROR_INVALID_ARGUMENT on a NULL pointer.
 */
O3D_API o3d_status o3d_tsdf_volume_get_sdf_trunc(double* out, const o3d_tsdf_volume_t* volume);
/**
 * @brief The colour type (O3D_TSDF_VOLUME_COLOR_TYPE_*).
 *
 * Threads: any thread; concurrent calls on the same handles are safe (all read-only).
 * @param out receives the type
 * @param volume the volume
 * @return O3D_OK, or O3D_ERROR_INVALID_ARGUMENT on a NULL pointer.
 */
O3D_API o3d_status o3d_tsdf_volume_get_color_type(o3d_tsdf_volume_color_type* out, const o3d_tsdf_volume_t* volume);
/**
 * @brief Voxel blocks allocated: always 1 for a uniform volume; for a scalable one, what its memory follows.
 *
 * Threads: any thread; concurrent calls on the same handles are safe (all read-only).
 * @param out_n receives the count
 * @param volume the volume
 * @return O3D_OK, or O3D_ERROR_INVALID_ARGUMENT on a NULL pointer.
 */
O3D_API o3d_status o3d_tsdf_volume_block_count(size_t* out_n, const o3d_tsdf_volume_t* volume);
/**
 * @brief A uniform volume's edge length in metres.
 *
 * Threads: any thread; concurrent calls on the same handles are safe (all read-only).
 * @param out receives the length
 * @param volume a uniform volume
 * @return O3D_OK, or O3D_ERROR_INVALID_ARGUMENT on a NULL pointer or a scalable volume.
 */
O3D_API o3d_status o3d_tsdf_volume_get_length(double* out, const o3d_tsdf_volume_t* volume);
/**
 * @brief A uniform volume's voxels along an edge.
 *
 * Threads: any thread; concurrent calls on the same handles are safe (all read-only).
 * @param out receives the resolution
 * @param volume a uniform volume
 * @return O3D_OK, or O3D_ERROR_INVALID_ARGUMENT on a NULL pointer or a scalable volume.
 */
O3D_API o3d_status o3d_tsdf_volume_get_resolution(int32_t* out, const o3d_tsdf_volume_t* volume);
/**
 * @brief A uniform volume's minimum corner.
 *
 * Threads: any thread; concurrent calls on the same handles are safe (all read-only).
 * @param out receives the corner
 * @param volume a uniform volume
 * @return O3D_OK, or O3D_ERROR_INVALID_ARGUMENT on a NULL pointer or a scalable volume.
 */
O3D_API o3d_status o3d_tsdf_volume_get_origin(double out[3], const o3d_tsdf_volume_t* volume);
/**
 * @brief A scalable volume's voxels along a block's edge.
 *
 * Threads: any thread; concurrent calls on the same handles are safe (all read-only).
 * @param out receives the resolution
 * @param volume a scalable volume
 * @return O3D_OK, or O3D_ERROR_INVALID_ARGUMENT on a NULL pointer or a uniform volume.
 */
O3D_API o3d_status o3d_tsdf_volume_get_volume_unit_resolution(int32_t* out, const o3d_tsdf_volume_t* volume);
/**
 * @brief A scalable volume's depth sampling stride.
 *
 * Threads: any thread; concurrent calls on the same handles are safe (all read-only).
 * @param out receives the stride
 * @param volume a scalable volume
 * @return O3D_OK, or O3D_ERROR_INVALID_ARGUMENT on a NULL pointer or a uniform volume.
 */
O3D_API o3d_status o3d_tsdf_volume_get_depth_sampling_stride(int32_t* out, const o3d_tsdf_volume_t* volume);

O3D_END_DECL

#endif /* O3D_INTEGRATION_H */
