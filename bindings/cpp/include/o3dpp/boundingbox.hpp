// SPDX-License-Identifier: MIT
#pragma once
/// @file boundingbox.hpp
/// @brief o3dpp::OrientedBoundingBox, a value struct (centre, row-major rotation, extents) over o3d_obb_t, and
/// o3dpp::OrientedBoundingEllipsoid (centre, rotation, radii) over o3d_obe_t. PointCloud and TriangleMesh get
/// theirs and crop by boxes through members (get_oriented_bounding_box, get_minimal_oriented_bounding_box,
/// get_oriented_bounding_ellipsoid, crop).
#include <array>
#include <cstdint>
#include <vector>

#include "o3d/boundingbox.h"
#include "o3dpp/error.hpp"
#include "o3dpp/span.hpp"

namespace o3dpp {

/// @brief o3d.geometry.OrientedBoundingBox: column k of the row-major `R` is the direction of `extent[k]`,
/// the full edge length along it. Axis-aligned boxes are {min, max} pairs, as elsewhere in the wrapper.
struct OrientedBoundingBox {
    Vec3 center{0, 0, 0};
    Mat3 R{1, 0, 0, 0, 1, 0, 0, 0, 1};
    Vec3 extent{0, 0, 0};

    /// @brief PCA box of the points' convex hull (>= 4 points, not all coplanar unless `robust`, which
    /// joggles the hull input).
    static OrientedBoundingBox create_from_points(const double* xyz, std::size_t n, bool robust = false) {
        o3d_obb_t c{};
        check(o3d_obb_create_from_points(&c, xyz, n, robust ? 1 : 0));
        return from_c(c);
    }
    static OrientedBoundingBox create_from_points(const std::vector<Vec3>& points, bool robust = false) {
        return create_from_points(points.empty() ? nullptr : points.front().data(), points.size(), robust);
    }
    /// @brief The minimum-volume oriented box of the points (>= 4, not all coplanar unless `robust`, which joggles
    /// them); axes the right-handed order closest to the identity.
    static OrientedBoundingBox create_from_points_minimal(const std::vector<Vec3>& points, bool robust = false) {
        o3d_obb_t c{};
        check(o3d_obb_create_from_points_minimal(&c, points.empty() ? nullptr : points.front().data(), points.size(),
                                                 robust ? 1 : 0));
        return from_c(c);
    }
    /// @brief The box equal to [min_bound, max_bound] (R = identity).
    static OrientedBoundingBox create_from_axis_aligned_bounding_box(const Vec3& min_bound, const Vec3& max_bound) {
        o3d_obb_t c{};
        check(o3d_obb_create_from_axis_aligned_bounding_box(&c, min_bound.data(), max_bound.data()));
        return from_c(c);
    }

    /// @brief The 8 corners in Open3D's get_box_points order.
    std::array<Vec3, 8> get_box_points() const {
        const o3d_obb_t c = to_c();
        std::array<Vec3, 8> out{};
        static_assert(sizeof(out) == 24 * sizeof(double), "std::array<Vec3, 8> must be 24 packed doubles");
        check(o3d_obb_get_box_points(out.front().data(), &c));
        return out;
    }
    /// @brief Indices (ascending) of the points inside the box, boundary included.
    std::vector<int32_t> get_point_indices_within_bounding_box(const std::vector<Vec3>& points) const {
        const o3d_obb_t c = to_c();
        std::vector<int32_t> out(points.size());
        size_t n = 0;
        check(o3d_obb_get_point_indices_within(out.data(), out.size(), &n, &c,
                                               points.empty() ? nullptr : points.front().data(), points.size()));
        out.resize(n < out.size() ? n : out.size());
        return out;
    }
    double volume() const { return extent[0] * extent[1] * extent[2]; }
    Vec3 get_center() const { return center; }

    o3d_obb_t to_c() const {
        o3d_obb_t c{};
        for (int i = 0; i < 3; ++i) c.center[i] = center[i];
        for (int i = 0; i < 9; ++i) c.R[i] = R[i];
        for (int i = 0; i < 3; ++i) c.extent[i] = extent[i];
        return c;
    }
    static OrientedBoundingBox from_c(const o3d_obb_t& c) {
        OrientedBoundingBox b;
        for (int i = 0; i < 3; ++i) b.center[i] = c.center[i];
        for (int i = 0; i < 9; ++i) b.R[i] = c.R[i];
        for (int i = 0; i < 3; ++i) b.extent[i] = c.extent[i];
        return b;
    }
};

/// @brief o3d.geometry.OrientedBoundingEllipsoid: the solid {center + R diag(radii) u : |u| <= 1}; column k of
/// the row-major `R` is the direction of semi-axis `radii[k]`.
struct OrientedBoundingEllipsoid {
    Vec3 center{0, 0, 0};
    Mat3 R{1, 0, 0, 0, 1, 0, 0, 0, 1};
    Vec3 radii{0, 0, 0};

    /// @brief The minimum-volume enclosing ellipsoid of the points (>= 4, not all coplanar; Khachiyan's algorithm
    /// with Open3D's tolerance, so a point may lie up to about 0.2% outside). `robust` joggles the hull's input.
    static OrientedBoundingEllipsoid create_from_points(const std::vector<Vec3>& points, bool robust = false) {
        o3d_obe_t c{};
        check(o3d_obe_create_from_points(&c, points.empty() ? nullptr : points.front().data(), points.size(),
                                         robust ? 1 : 0));
        return from_c(c);
    }
    /// @brief 4/3 pi times the product of the radii.
    double volume() const { return 4.0 / 3.0 * 3.14159265358979323846 * radii[0] * radii[1] * radii[2]; }
    Vec3 get_center() const { return center; }

    o3d_obe_t to_c() const {
        o3d_obe_t c{};
        for (int i = 0; i < 3; ++i) c.center[i] = center[i];
        for (int i = 0; i < 9; ++i) c.R[i] = R[i];
        for (int i = 0; i < 3; ++i) c.radii[i] = radii[i];
        return c;
    }
    static OrientedBoundingEllipsoid from_c(const o3d_obe_t& c) {
        OrientedBoundingEllipsoid e;
        for (int i = 0; i < 3; ++i) e.center[i] = c.center[i];
        for (int i = 0; i < 9; ++i) e.R[i] = c.R[i];
        for (int i = 0; i < 3; ++i) e.radii[i] = c.radii[i];
        return e;
    }
};

}  // namespace o3dpp
