/* SPDX-License-Identifier: MIT */
/**
 * @file selection.h
 * @brief Open3D's SelectionPolygonVolume: a prism whose cross-section is a polygon in the plane of two axes
 * and whose extent along the third (the orthogonal axis) is [axis_min, axis_max]; cropping keeps what lies
 * inside. Its JSON (class_name "SelectionPolygonVolume") reads as Open3D's read_selection_polygon_volume.
 *
 * Threads: a volume may be read from several threads at once; a call that changes it needs exclusive
 * access.
 */
#ifndef O3D_SELECTION_H
#define O3D_SELECTION_H

#include "o3d/types.h"

O3D_BEGIN_DECL

/** A coordinate axis (O3D_AXIS_*). */
typedef int32_t o3d_axis;
#define O3D_AXIS_X 0 /**< x */
#define O3D_AXIS_Y 1 /**< y */
#define O3D_AXIS_Z 2 /**< z */

/**
 * @brief An empty volume: orthogonal axis Y, range [0, 0], no polygon (set one before cropping).
 *
 * Threads: any thread.
 * Ownership: `*out` belongs to the caller (o3d_selection_polygon_volume_destroy).
 * @param out receives the handle
 * @return O3D_OK, or O3D_ERROR_INVALID_ARGUMENT on a NULL `out`.
 */
O3D_API o3d_status o3d_selection_polygon_volume_create(o3d_selection_polygon_volume_t** out);
/**
 * @brief Free a volume. NULL is a no-op.
 *
 * Threads: needs exclusive access to `volume`.
 * @param volume the handle to destroy
 */
O3D_API void o3d_selection_polygon_volume_destroy(o3d_selection_polygon_volume_t* volume);
/**
 * @brief read_selection_polygon_volume: a volume from Open3D's JSON file (also what a VisualizerWithEditing
 * crop is described by).
 *
 * Threads: any thread.
 * Ownership: `*out` belongs to the caller; left NULL on failure.
 * @param out receives the new handle
 * @param path the JSON file
 * @return O3D_OK; O3D_ERROR_INVALID_ARGUMENT on a NULL pointer; O3D_ERROR_IO when the file cannot be read;
 *   O3D_ERROR_PARSE when it is not a valid SelectionPolygonVolume (the message says what is wrong).
 */
O3D_API o3d_status o3d_selection_polygon_volume_read_json(o3d_selection_polygon_volume_t** out, const char* path);
/**
 * @brief SelectionPolygonVolume.orthogonal_axis.
 *
 * Threads: any thread.
 * @param out receives O3D_AXIS_X, _Y or _Z
 * @param volume the volume
 * @return O3D_OK, or O3D_ERROR_INVALID_ARGUMENT on a NULL pointer.
 */
O3D_API o3d_status o3d_selection_polygon_volume_get_orthogonal_axis(o3d_axis* out,
                                                                    const o3d_selection_polygon_volume_t* volume);
/**
 * @brief Set the orthogonal axis: the prism runs along it, the polygon lies across it.
 *
 * Threads: needs exclusive access to `volume`.
 * @param volume the volume
 * @param axis O3D_AXIS_X, _Y or _Z
 * @return O3D_OK, or O3D_ERROR_INVALID_ARGUMENT on a NULL pointer or another axis.
 */
O3D_API o3d_status o3d_selection_polygon_volume_set_orthogonal_axis(o3d_selection_polygon_volume_t* volume,
                                                                    o3d_axis axis);
/**
 * @brief SelectionPolygonVolume.axis_min: where the prism starts along the orthogonal axis.
 *
 * Threads: any thread.
 * @param out receives the value
 * @param volume the volume
 * @return O3D_OK, or O3D_ERROR_INVALID_ARGUMENT on a NULL pointer.
 */
O3D_API o3d_status o3d_selection_polygon_volume_get_axis_min(double* out, const o3d_selection_polygon_volume_t* volume);
/**
 * @brief Set axis_min (checked against axis_max when cropping, so the two may be set in either order).
 *
 * Threads: needs exclusive access to `volume`.
 * @param volume the volume
 * @param value a finite coordinate
 * @return O3D_OK, or O3D_ERROR_INVALID_ARGUMENT on a NULL pointer or a value that is not finite.
 */
O3D_API o3d_status o3d_selection_polygon_volume_set_axis_min(o3d_selection_polygon_volume_t* volume, double value);
/**
 * @brief SelectionPolygonVolume.axis_max: where the prism ends along the orthogonal axis.
 *
 * Threads: any thread.
 * @param out receives the value
 * @param volume the volume
 * @return O3D_OK, or O3D_ERROR_INVALID_ARGUMENT on a NULL pointer.
 */
O3D_API o3d_status o3d_selection_polygon_volume_get_axis_max(double* out, const o3d_selection_polygon_volume_t* volume);
/**
 * @brief Set axis_max (checked against axis_min when cropping).
 *
 * Threads: needs exclusive access to `volume`.
 * @param volume the volume
 * @param value a finite coordinate
 * @return O3D_OK, or O3D_ERROR_INVALID_ARGUMENT on a NULL pointer or a value that is not finite.
 */
O3D_API o3d_status o3d_selection_polygon_volume_set_axis_max(o3d_selection_polygon_volume_t* volume, double value);
/**
 * @brief SelectionPolygonVolume.bounding_polygon: the corners (N x 3, row-major); the coordinate along
 * the orthogonal axis is ignored.
 *
 * Threads: any thread.
 * @param out receives 3 * N doubles (NULL: only the count)
 * @param capacity how many corners `out` holds
 * @param out_rows receives N (always)
 * @param volume the volume
 * @return O3D_OK; O3D_ERROR_INVALID_ARGUMENT on a NULL `out_rows` or `volume`; O3D_ERROR_BUFFER_TOO_SMALL
 *   when `capacity` < N (N is still reported).
 */
O3D_API o3d_status o3d_selection_polygon_volume_get_bounding_polygon(double* out, size_t capacity, size_t* out_rows,
                                                                     const o3d_selection_polygon_volume_t* volume);
/**
 * @brief Set the corners, in order around the polygon (N x 3, row-major, copied).
 *
 * Threads: needs exclusive access to `volume`.
 * @param volume the volume
 * @param corners 3 * `rows` doubles (may be NULL when `rows` is 0)
 * @param rows how many corners (0 clears them; cropping needs 3 or more)
 * @return O3D_OK, or O3D_ERROR_INVALID_ARGUMENT on a NULL pointer or a value that is not finite.
 */
O3D_API o3d_status o3d_selection_polygon_volume_set_bounding_polygon(o3d_selection_polygon_volume_t* volume,
                                                                     const double* corners, size_t rows);
/**
 * @brief crop_in_polygon: indices of the points inside the volume, ascending.
 *
 * Threads: any thread.
 * @param out receives the indices (`capacity` int32; NULL: only the count)
 * @param capacity how many indices `out` holds
 * @param out_n receives the count (always)
 * @param volume the volume
 * @param pc the points
 * @return O3D_OK; O3D_ERROR_INVALID_ARGUMENT on a NULL pointer or a volume that cannot crop (fewer than 3
 *   corners, axis_min > axis_max); O3D_ERROR_BUFFER_TOO_SMALL when `capacity` is short.
 */
O3D_API o3d_status o3d_selection_polygon_volume_crop_in_polygon(int32_t* out, size_t capacity, size_t* out_n,
                                                                const o3d_selection_polygon_volume_t* volume,
                                                                const o3d_pointcloud_t* pc);
/**
 * @brief crop_point_cloud: the points inside, with their normals, colors and covariances.
 *
 * Threads: any thread.
 * Ownership: `*out` belongs to the caller (o3d_pointcloud_destroy); left NULL on failure.
 * @param out receives the new cloud
 * @param volume the volume
 * @param pc the cloud
 * @return O3D_OK; O3D_ERROR_INVALID_ARGUMENT on a NULL pointer or a volume that cannot crop.
 */
O3D_API o3d_status o3d_selection_polygon_volume_crop_point_cloud(o3d_pointcloud_t** out,
                                                                 const o3d_selection_polygon_volume_t* volume,
                                                                 const o3d_pointcloud_t* pc);
/**
 * @brief crop_triangle_mesh: the triangles whose three vertices are inside, with the vertices they use.
 *
 * Threads: any thread.
 * Ownership: `*out` belongs to the caller (o3d_trianglemesh_destroy); left NULL on failure.
 * @param out receives the new mesh
 * @param volume the volume
 * @param input the mesh
 * @return O3D_OK; O3D_ERROR_INVALID_ARGUMENT on a NULL pointer, a volume that cannot crop or a triangle
 *   index out of range.
 */
O3D_API o3d_status o3d_selection_polygon_volume_crop_triangle_mesh(o3d_trianglemesh_t** out,
                                                                   const o3d_selection_polygon_volume_t* volume,
                                                                   const o3d_trianglemesh_t* input);

O3D_END_DECL

#endif /* O3D_SELECTION_H */
