/* SPDX-License-Identifier: MIT */
/**
 * @file boundingbox.h
 * @brief Oriented bounding boxes (o3d.geometry.OrientedBoundingBox) and cropping by them.
 *
 * An oriented box is a plain value struct with a frozen layout (never extended): its centre, the
 * row-major 3x3 rotation whose columns are the box axes, and the full edge lengths along those axes.
 * Axis-aligned boxes are (min_bound, max_bound) pairs, as everywhere else in the API.
 *
 * **Out of memory:** any function here that allocates may also return O3D_ERROR_OUT_OF_MEMORY; the
 * per-function `@return` lists do not repeat it.
 */
#ifndef O3D_BOUNDINGBOX_H
#define O3D_BOUNDINGBOX_H

#include "o3d/common.h"

O3D_BEGIN_DECL

/** o3d.geometry.OrientedBoundingBox(center, R, extent). */
typedef struct o3d_obb {
    double center[3]; /**< the box centre */
    double R[9];      /**< row-major; column k is the direction of extent[k] */
    double extent[3]; /**< full edge lengths (>= 0) */
} o3d_obb_t;

/**
 * @brief Oriented box of `n` points (row-major n x 3; n >= 4, not all coplanar unless robust != 0):
 * PCA of the points' convex hull, as Open3D's OrientedBoundingBox.create_from_points(points, robust).
 * robust != 0 joggles the hull input so degenerate (e.g. planar) sets still give a box.
 *
 * Threads: any thread.
 * @param out receives the box
 * @param xyz points, row-major n x 3 (may be NULL when n == 0)
 * @param n number of points (rows of 3 doubles) in `xyz`
 * @param robust non-zero joggles the input so degenerate (e.g. planar) point sets still give a box
 * @return O3D_OK, or O3D_ERROR_INVALID_ARGUMENT on a NULL pointer, fewer than 4 points, non-finite coordinates or
 *   coplanar points when robust == 0.
 */
O3D_API o3d_status o3d_obb_create_from_points(o3d_obb_t* out, const double* xyz, size_t n, int32_t robust);
/**
 * @brief The oriented box equal to an axis-aligned one (R = identity).
 *
 * Threads: any thread.
 * @param out receives the box
 * @param min_bound minimum corner (x, y, z)
 * @param max_bound maximum corner (x, y, z)
 * @return O3D_OK, or O3D_ERROR_INVALID_ARGUMENT on a NULL pointer or non-finite bounds or min > max.
 */
O3D_API o3d_status o3d_obb_create_from_axis_aligned_bounding_box(o3d_obb_t* out, const double min_bound[3],
                                                                 const double max_bound[3]);
/**
 * @brief The 8 corners (row-major 8 x 3) in Open3D's get_box_points order.
 *
 * Threads: any thread.
 * @param out receives the 8 corners, row-major 8 x 3
 * @param obb the oriented box
 * @return O3D_OK, or O3D_ERROR_INVALID_ARGUMENT on a NULL pointer.
 */
O3D_API o3d_status o3d_obb_get_box_points(double out[24], const o3d_obb_t* obb);
/**
 * @brief Indices (ascending, int32) of the `n` points inside the box (boundary included), with the
 * copy-out convention of the point-cloud tools (capacity = n always fits).
 * @see get_point_indices_within_bounding_box
 *
 * Threads: any thread.
 * @param out_indices receives the indices (`capacity` int32; NULL skips them)
 * @param capacity how many items the output buffer holds (ignored when it is NULL)
 * @param out_n receives the item count (always, also when the buffer is NULL or too small)
 * @param obb the oriented box
 * @param xyz points, row-major n x 3 (may be NULL when n == 0)
 * @param n number of points (rows of 3 doubles) in `xyz`
 * @return O3D_OK, or O3D_ERROR_INVALID_ARGUMENT on a NULL `obb` or `out_n`, or NULL `xyz` with n > 0;
 *   O3D_ERROR_BUFFER_TOO_SMALL when `capacity` is short (the count is still reported).
 */
O3D_API o3d_status o3d_obb_get_point_indices_within(int32_t* out_indices, size_t capacity, size_t* out_n,
                                                    const o3d_obb_t* obb, const double* xyz, size_t n);

/**
 * @brief The minimum-volume oriented box of `n` points (Open3D's OrientedBoundingBox.create_from_points_minimal):
 * searched over the directions of the convex hull's faces, each paired with the smallest rectangle of the hull
 * projected along it, then refined; never larger than Open3D's on its tests (not proven exact). Axes are the
 * right-handed order closest to the identity.
 *
 * Threads: any thread.
 * @param out receives the box
 * @param xyz points, row-major n x 3 (may be NULL when n == 0)
 * @param n number of points (rows of 3 doubles) in `xyz`
 * @param robust joggles the input so degenerate (e.g. planar) point sets still give a box
 * @return O3D_OK, or O3D_ERROR_INVALID_ARGUMENT on a NULL pointer, fewer than 4 points, non-finite coordinates or
 *   coplanar points without `robust`.
 */
O3D_API o3d_status o3d_obb_create_from_points_minimal(o3d_obb_t* out, const double* xyz, size_t n, o3d_bool robust);

/** o3d.geometry.OrientedBoundingEllipsoid(center, R, radii): the solid {center + R diag(radii) u : |u| <= 1}. */
typedef struct o3d_obe {
    double center[3]; /**< the ellipsoid's centre */
    double R[9];      /**< row-major; column k is the direction of semi-axis k */
    double radii[3];  /**< the semi-axis lengths (>= 0) */
} o3d_obe_t;

/**
 * @brief The minimum-volume enclosing ellipsoid of `n` points (Open3D 0.20's
 * OrientedBoundingEllipsoid.create_from_points): Khachiyan's algorithm over the convex hull's vertices, with
 * Open3D's tolerance (so a point may lie up to about 0.2% outside), axes as close to the identity as a rotation
 * allows.
 *
 * Threads: any thread.
 * @param out receives the ellipsoid
 * @param xyz points, row-major n x 3 (may be NULL when n == 0)
 * @param n number of points (rows of 3 doubles) in `xyz`
 * @param robust joggles the hull's input (a flat set still fails: its ellipsoid has no volume)
 * @return O3D_OK, or O3D_ERROR_INVALID_ARGUMENT on a NULL pointer, fewer than 4 points, non-finite coordinates or
 *   coplanar points.
 */
O3D_API o3d_status o3d_obe_create_from_points(o3d_obe_t* out, const double* xyz, size_t n, o3d_bool robust);

O3D_END_DECL

#endif /* O3D_BOUNDINGBOX_H */
