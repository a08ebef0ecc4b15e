// SPDX-License-Identifier: MIT
// The ellipsoid is laid out ring by ring with the arithmetic of Open3D's sphere (angles as multiples of
// pi / resolution, each coordinate a product of sines and cosines times its radius), so it matches the
// wheel to the last bit; create_sphere's own arithmetic rounds differently.
#include "o3d/geometry/mesh_primitives_bounded.h"

#include <cmath>
#include <cstdint>
#include <string>

#include "o3d/geometry/mesh_primitives.h"
#include "o3d/geometry/mesh_primitives_checks.h"
#include "o3d/utility/error.h"

namespace o3d::geometry {
namespace {

constexpr double kPi = 3.14159265358979323846;

/// @brief UVs of the ellipsoid's corners: ring vertices at (ring / r, column / 2r), the seam column again
/// at v = 1 where a triangle closes the ring, the poles at u = 0 / 1 in the middle of their triangle's column.
struct EllipsoidUv {
    int resolution;
    Eigen::Vector2d ring(int i, int j, bool seam) const {
        return {(1.0 / resolution) * i, seam ? 1.0 : (1.0 / (2.0 * resolution)) * j};
    }
    Eigen::Vector2d pole(double u, int j) const {
        const double width = 1.0 / (2.0 * resolution);
        return {u, width / 2.0 + width * j};
    }
};

void require_finite(const Eigen::Vector3d& v, const char* name) {
    if (!v.allFinite()) throw InvalidArgument(std::string(name) + " has a non-finite entry");
}

}  // namespace

TriangleMesh create_ellipsoid(double radius_x, double radius_y, double radius_z, int resolution, bool create_uv_map) {
    detail::require_positive(radius_x, "radius_x");
    detail::require_positive(radius_y, "radius_y");
    detail::require_positive(radius_z, "radius_z");
    detail::require_at_least(resolution, 2, "resolution");
    const int64_t r = resolution, per_ring64 = 2 * r;
    detail::require_indexable(2 + per_ring64 * (r - 1), "create_ellipsoid");
    const int n = static_cast<int>(per_ring64);

    TriangleMesh m;
    m.vertices.reserve(static_cast<size_t>(2 + per_ring64 * (r - 1)));
    m.vertices.emplace_back(0.0, 0.0, radius_z);
    m.vertices.emplace_back(0.0, 0.0, -radius_z);
    const double step = kPi / static_cast<double>(resolution);
    for (int i = 1; i < resolution; ++i) {
        const double alpha = step * i;
        for (int j = 0; j < n; ++j) {
            const double theta = step * j;
            m.vertices.emplace_back(std::sin(alpha) * std::cos(theta) * radius_x,
                                    std::sin(alpha) * std::sin(theta) * radius_y, std::cos(alpha) * radius_z);
        }
    }

    // Ring i (1 .. r-1) starts at vertex 2 + n (i - 1). Pole fans first, top and bottom interleaved, then the
    // bands between consecutive rings; UVs follow the same order, three per triangle.
    const EllipsoidUv uv{resolution};
    auto ring_start = [n](int i) { return 2 + n * (i - 1); };
    const int last = resolution - 1;
    m.triangles.reserve(static_cast<size_t>(2 * per_ring64 * (r - 1)));
    if (create_uv_map) m.triangle_uvs.reserve(static_cast<size_t>(6 * per_ring64 * (r - 1)));
    for (int j = 0; j < n; ++j) {
        const int j1 = (j + 1) % n;
        const bool seam = j1 == 0;
        m.triangles.emplace_back(0, ring_start(1) + j, ring_start(1) + j1);
        m.triangles.emplace_back(1, ring_start(last) + j1, ring_start(last) + j);
        if (create_uv_map) {
            m.triangle_uvs.insert(m.triangle_uvs.end(), {uv.pole(0.0, j), uv.ring(1, j, false), uv.ring(1, j1, seam)});
            m.triangle_uvs.insert(m.triangle_uvs.end(),
                                  {uv.pole(1.0, j), uv.ring(last, j1, seam), uv.ring(last, j, false)});
        }
    }
    for (int i = 1; i < last; ++i) {
        const int upper = ring_start(i), lower = ring_start(i + 1);
        for (int j = 0; j < n; ++j) {
            const int j1 = (j + 1) % n;
            const bool seam = j1 == 0;
            m.triangles.emplace_back(lower + j, upper + j1, upper + j);
            m.triangles.emplace_back(lower + j, lower + j1, upper + j1);
            if (create_uv_map) {
                m.triangle_uvs.insert(m.triangle_uvs.end(),
                                      {uv.ring(i + 1, j, false), uv.ring(i, j1, seam), uv.ring(i, j, false)});
                m.triangle_uvs.insert(m.triangle_uvs.end(),
                                      {uv.ring(i + 1, j, false), uv.ring(i + 1, j1, seam), uv.ring(i, j1, seam)});
            }
        }
    }
    return m;
}

TriangleMesh mesh_from_oriented_bounding_box(const OrientedBoundingBox& box, const Eigen::Vector3d& scale,
                                             bool create_uv_map) {
    validate_obb(box);
    require_finite(scale, "scale");
    const Eigen::Vector3d size = scale.asDiagonal() * box.extent;
    TriangleMesh m = create_box(size.x(), size.y(), size.z());  // throws on a size <= 0
    // Turned about the box's middle, then moved onto the centre: Open3D's two steps, in its order.
    const Eigen::Vector3d middle = size / 2.0, shift = box.center - size / 2.0;
    for (Eigen::Vector3d& v : m.vertices) {
        v = box.R * (v - middle) + middle;
        v += shift;
    }
    if (create_uv_map) {
        // A cube net on the texture, three corners per triangle in create_box's triangle order.
        static const double kUv[36][2] = {
            {0.5, 0.5},   {0.75, 0.75}, {0.5, 0.75},  {0.5, 0.5},   {0.75, 0.5},  {0.75, 0.75},
            {0.25, 0.5},  {0.25, 0.25}, {0.5, 0.5},   {0.25, 0.25}, {0.5, 0.25},  {0.5, 0.5},
            {0.25, 0.5},  {0.25, 0.75}, {0.0, 0.5},   {0.25, 0.75}, {0.0, 0.75},  {0.0, 0.5},
            {0.25, 0.75}, {0.5, 0.75},  {0.5, 1.0},   {0.25, 0.75}, {0.5, 1.0},   {0.25, 1.0},
            {0.25, 0.25}, {0.25, 0.0},  {0.5, 0.0},   {0.25, 0.25}, {0.5, 0.0},   {0.5, 0.25},
            {0.25, 0.5},  {0.5, 0.5},   {0.25, 0.75}, {0.25, 0.75}, {0.5, 0.5},   {0.5, 0.75}};
        for (const auto& c : kUv) m.triangle_uvs.emplace_back(c[0], c[1]);
    }
    return m;
}

TriangleMesh mesh_from_oriented_bounding_ellipsoid(const OrientedBoundingEllipsoid& ellipsoid,
                                                   const Eigen::Vector3d& scale, int resolution, bool create_uv_map) {
    require_finite(ellipsoid.center, "the ellipsoid's center");
    if (!ellipsoid.R.allFinite()) throw InvalidArgument("the ellipsoid's R has a non-finite entry");
    if (!(ellipsoid.R.transpose() * ellipsoid.R).isApprox(Eigen::Matrix3d::Identity(), 1e-6))
        throw InvalidArgument("the ellipsoid's R is not orthonormal");
    require_finite(scale, "scale");
    const Eigen::Vector3d radii = scale.asDiagonal() * ellipsoid.radii;
    TriangleMesh m = create_ellipsoid(radii.x(), radii.y(), radii.z(), resolution, create_uv_map);
    for (Eigen::Vector3d& v : m.vertices) v = ellipsoid.R * v + ellipsoid.center;
    m.vertex_colors.assign(m.vertices.size(), Eigen::Vector3d::Ones());
    return m;
}

}  // namespace o3d::geometry
