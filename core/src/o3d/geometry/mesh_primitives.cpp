// SPDX-License-Identifier: MIT
// The box and the surfaces of revolution (sphere, cylinder, cone, torus). Vertex rings are laid out and
// triangles emitted in Open3D 0.20's order, with every triangle wound counter-clockwise seen from outside.
#include "o3d/geometry/mesh_primitives.h"

#include <cmath>

#include "o3d/geometry/mesh_primitives_checks.h"

namespace o3d::geometry {
namespace {

constexpr double kPi = 3.14159265358979323846;

/// @brief `count` points of a circle of `radius` at height z, starting on +x, counter-clockwise about z.
void add_ring(TriangleMesh& m, double radius, double z, int count) {
    for (int j = 0; j < count; ++j) {
        const double theta = 2.0 * kPi * j / count;
        m.vertices.emplace_back(radius * std::cos(theta), radius * std::sin(theta), z);
    }
}

/// @brief The quads between ring `upper` and the ring `lower` below it (both of `count` vertices), as two
/// triangles each, outward for a ring order that runs counter-clockwise about z.
void add_band(TriangleMesh& m, int upper, int lower, int count) {
    for (int j = 0; j < count; ++j) {
        const int j1 = (j + 1) % count;
        m.triangles.emplace_back(lower + j, upper + j1, upper + j);
        m.triangles.emplace_back(lower + j, lower + j1, upper + j1);
    }
}

}  // namespace

TriangleMesh create_box(double width, double height, double depth) {
    detail::require_positive(width, "width");
    detail::require_positive(height, "height");
    detail::require_positive(depth, "depth");
    TriangleMesh m;
    // Vertex i has x = bit 0, z = bit 1, y = bit 2.
    for (int i = 0; i < 8; ++i)
        m.vertices.emplace_back((i & 1) ? width : 0.0, (i & 4) ? height : 0.0, (i & 2) ? depth : 0.0);
    static const int kTriangles[12][3] = {{4, 7, 5}, {4, 6, 7}, {0, 2, 4}, {2, 6, 4}, {0, 1, 2}, {1, 3, 2},
                                          {1, 5, 7}, {1, 7, 3}, {2, 3, 7}, {2, 7, 6}, {0, 4, 1}, {1, 4, 5}};
    for (const auto& t : kTriangles) m.triangles.emplace_back(t[0], t[1], t[2]);
    return m;
}

TriangleMesh create_sphere(double radius, int resolution) {
    detail::require_positive(radius, "radius");
    // Resolution 1 would have no ring between the poles.
    detail::require_at_least(resolution, 2, "resolution");
    const int64_t r = resolution, per_ring = 2 * r;
    detail::require_indexable(2 + per_ring * (r - 1), "create_sphere");
    TriangleMesh m;
    m.vertices.reserve(static_cast<size_t>(2 + per_ring * (r - 1)));
    m.vertices.emplace_back(0.0, 0.0, radius);
    m.vertices.emplace_back(0.0, 0.0, -radius);
    for (int i = 1; i < resolution; ++i) {
        const double phi = kPi * i / resolution;
        const double s = std::sin(phi), c = std::cos(phi);
        for (int j = 0; j < per_ring; ++j) {
            const double theta = 2.0 * kPi * j / static_cast<double>(per_ring);
            m.vertices.emplace_back(radius * s * std::cos(theta), radius * s * std::sin(theta), radius * c);
        }
    }
    const int n = static_cast<int>(per_ring);
    const int bottom = 2 + n * (resolution - 2);
    m.triangles.reserve(static_cast<size_t>(2 * per_ring * (r - 1)));
    for (int j = 0; j < n; ++j) {
        const int j1 = (j + 1) % n;
        m.triangles.emplace_back(0, 2 + j, 2 + j1);
        m.triangles.emplace_back(1, bottom + j1, bottom + j);
    }
    for (int i = 1; i + 1 < resolution; ++i) add_band(m, 2 + n * (i - 1), 2 + n * i, n);
    return m;
}

TriangleMesh create_cylinder(double radius, double height, int resolution, int split) {
    detail::require_positive(radius, "radius");
    detail::require_positive(height, "height");
    detail::require_at_least(resolution, 1, "resolution");
    detail::require_at_least(split, 1, "split");
    detail::require_indexable(2 + int64_t{resolution} * (int64_t{split} + 1), "create_cylinder");
    TriangleMesh m;
    m.vertices.reserve(static_cast<size_t>(2 + int64_t{resolution} * (split + 1)));
    m.vertices.emplace_back(0.0, 0.0, height * 0.5);
    m.vertices.emplace_back(0.0, 0.0, -height * 0.5);
    for (int i = 0; i <= split; ++i) add_ring(m, radius, height * 0.5 - height * i / split, resolution);
    const int bottom = 2 + resolution * split;
    for (int j = 0; j < resolution; ++j) {
        const int j1 = (j + 1) % resolution;
        m.triangles.emplace_back(0, 2 + j, 2 + j1);
        m.triangles.emplace_back(1, bottom + j1, bottom + j);
    }
    for (int i = 0; i < split; ++i) add_band(m, 2 + resolution * i, 2 + resolution * (i + 1), resolution);
    return m;
}

TriangleMesh create_cone(double radius, double height, int resolution, int split) {
    detail::require_positive(radius, "radius");
    detail::require_positive(height, "height");
    detail::require_at_least(resolution, 1, "resolution");
    detail::require_at_least(split, 1, "split");
    detail::require_indexable(2 + int64_t{resolution} * split, "create_cone");
    TriangleMesh m;
    m.vertices.emplace_back(0.0, 0.0, 0.0);
    m.vertices.emplace_back(0.0, 0.0, height);
    // Ring i sits at height i/split, shrinking linearly towards the apex.
    for (int i = 0; i < split; ++i)
        add_ring(m, radius * (split - i) / split, height * i / split, resolution);
    const int top = 2 + resolution * (split - 1);
    for (int j = 0; j < resolution; ++j) {
        const int j1 = (j + 1) % resolution;
        m.triangles.emplace_back(0, 2 + j1, 2 + j);
        m.triangles.emplace_back(1, top + j, top + j1);
    }
    for (int i = 0; i + 1 < split; ++i) {
        const int lower = 2 + resolution * i, upper = lower + resolution;
        for (int j = 0; j < resolution; ++j) {
            const int j1 = (j + 1) % resolution;
            m.triangles.emplace_back(upper + j1, lower + j, lower + j1);
            m.triangles.emplace_back(upper + j1, upper + j, lower + j);
        }
    }
    return m;
}

TriangleMesh create_torus(double torus_radius, double tube_radius, int radial_resolution, int tubular_resolution) {
    detail::require_positive(torus_radius, "torus_radius");
    detail::require_positive(tube_radius, "tube_radius");
    detail::require_at_least(radial_resolution, 1, "radial_resolution");
    detail::require_at_least(tubular_resolution, 1, "tubular_resolution");
    detail::require_indexable(int64_t{radial_resolution} * tubular_resolution, "create_torus");
    const int nr = radial_resolution, nt = tubular_resolution;
    TriangleMesh m;
    m.vertices.reserve(static_cast<size_t>(int64_t{nr} * nt));
    for (int i = 0; i < nr; ++i) {
        const double u = 2.0 * kPi * i / nr;
        const double cu = std::cos(u), su = std::sin(u);
        for (int j = 0; j < nt; ++j) {
            const double v = 2.0 * kPi * j / nt;
            const double w = torus_radius + tube_radius * std::cos(v);
            m.vertices.emplace_back(w * cu, w * su, tube_radius * std::sin(v));
        }
    }
    m.triangles.reserve(static_cast<size_t>(2 * int64_t{nr} * nt));
    for (int i = 0; i < nr; ++i) {
        const int a = i * nt, b = ((i + 1) % nr) * nt;
        for (int j = 0; j < nt; ++j) {
            const int j1 = (j + 1) % nt;
            m.triangles.emplace_back(b + j, b + j1, a + j);
            m.triangles.emplace_back(a + j, b + j1, a + j1);
        }
    }
    return m;
}

TriangleMesh create_mobius(int length_split, int width_split, int twists, double radius, double flatness,
                           double width, double scale) {
    detail::require_at_least(length_split, 3, "length_split");
    detail::require_at_least(width_split, 2, "width_split");
    detail::require_at_least(twists, 0, "twists");
    detail::require_positive(radius, "radius");
    detail::require_positive(width, "width");
    detail::require_positive(scale, "scale");
    if (!std::isfinite(flatness)) throw InvalidArgument("flatness must be finite");
    detail::require_indexable(int64_t{length_split} * width_split, "create_mobius");
    const int nl = length_split, nw = width_split;
    TriangleMesh m;
    m.vertices.reserve(static_cast<size_t>(int64_t{nl} * nw));
    // Column i is the segment across the band at angle u; it turns by twists * u / 2 about the circle's tangent.
    for (int i = 0; i < nl; ++i) {
        const double u = 2.0 * kPi * i / nl;
        const double turn = 0.5 * twists * u;
        for (int j = 0; j < nw; ++j) {
            const double v = width * (static_cast<double>(j) / (nw - 1) - 0.5);
            const double r = radius + v * std::cos(turn);
            m.vertices.emplace_back(scale * r * std::cos(u), scale * r * std::sin(u),
                                    scale * flatness * v * std::sin(turn));
        }
    }
    // After a full turn an odd number of twists lands each vertex on the opposite edge of column 0.
    const bool flipped = twists % 2 == 1;
    m.triangles.reserve(static_cast<size_t>(2 * int64_t{nl} * (nw - 1)));
    for (int i = 0; i < nl; ++i) {
        const bool seam = i == nl - 1;
        const int a = i * nw, b = seam ? 0 : (i + 1) * nw;
        for (int j = 0; j + 1 < nw; ++j) {
            const int bj = b + (seam && flipped ? nw - 1 - j : j);
            const int bj1 = b + (seam && flipped ? nw - 2 - j : j + 1);
            m.triangles.emplace_back(a + j, bj, bj1);
            m.triangles.emplace_back(a + j, bj1, a + j + 1);
        }
    }
    return m;
}

}  // namespace o3d::geometry
