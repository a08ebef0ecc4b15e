/* SPDX-License-Identifier: MIT */
/**
 * @file boundingbox.h
 * @brief Oriented bounding boxes (o3d.geometry.OrientedBoundingBox) and cropping by them.
 *
 * An oriented box is a plain value struct with a frozen layout (never extended): its centre, the
 * row-major 3x3 rotation whose columns are the box axes, and the full edge lengths along those axes.
 * Axis-aligned boxes are (min_bound, max_bound) pairs, as everywhere else in the API.
 */
#ifndef O3D_BOUNDINGBOX_H
#define O3D_BOUNDINGBOX_H

#include "o3d/common.h"

O3D_BEGIN_DECL

/** o3d.geometry.OrientedBoundingBox(center, R, extent). */
typedef struct o3d_obb {
    double center[3];
    double R[9];      /**< row-major; column k is the direction of extent[k] */
    double extent[3]; /**< full edge lengths (>= 0) */
} o3d_obb_t;

/**
 * @brief Oriented box of `n` points (row-major n x 3; n >= 4, not all coplanar unless robust != 0):
 * PCA of the points' convex hull, as Open3D's OrientedBoundingBox.create_from_points(points, robust).
 * robust != 0 joggles the hull input so degenerate (e.g. planar) sets still give a box.
 */
O3D_API o3d_status o3d_obb_create_from_points(o3d_obb_t* out, const double* xyz, size_t n, int32_t robust);
/** @brief The oriented box equal to an axis-aligned one (R = identity). */
O3D_API o3d_status o3d_obb_create_from_axis_aligned_bounding_box(o3d_obb_t* out, const double min_bound[3],
                                                                 const double max_bound[3]);
/** @brief The 8 corners (row-major 8 x 3) in Open3D's get_box_points order. */
O3D_API o3d_status o3d_obb_get_box_points(double out[24], const o3d_obb_t* obb);
/**
 * @brief Indices (ascending, int32) of the `n` points inside the box (boundary included), with the
 * copy-out convention of the point-cloud tools (capacity = n always fits).
 * @see get_point_indices_within_bounding_box
 */
O3D_API o3d_status o3d_obb_get_point_indices_within(int32_t* out_indices, size_t capacity, size_t* out_n,
                                                    const o3d_obb_t* obb, const double* xyz, size_t n);

O3D_END_DECL

#endif /* O3D_BOUNDINGBOX_H */
