// SPDX-License-Identifier: MIT
#pragma once
// Small meshes built by hand for the mesh-processing tests (tools/reference/record_mesh_processing.py builds
// the same ones for Open3D), and checks of their topology.
#include <Eigen/Geometry>
#include <cmath>
#include <map>
#include <utility>
#include <vector>

#include "o3d/geometry/triangle_mesh.h"
#include "o3d/geometry/triangle_mesh_basics.h"

namespace o3d_test {

using o3d::geometry::TriangleMesh;

/// Open3D's create_sphere(radius, resolution) layout (checked against it by the recording script).
inline TriangleMesh uv_sphere(double r, int res) {
    TriangleMesh m;
    m.vertices.emplace_back(0, 0, r);
    m.vertices.emplace_back(0, 0, -r);
    const double step = M_PI / res;
    for (int i = 1; i < res; ++i)
        for (int j = 0; j < 2 * res; ++j) {
            const double a = step * i, t = step * j;
            m.vertices.emplace_back(std::sin(a) * std::cos(t) * r, std::sin(a) * std::sin(t) * r, std::cos(a) * r);
        }
    for (int j = 0; j < 2 * res; ++j) {
        const int j1 = (j + 1) % (2 * res), b = 2 + 2 * res * (res - 2);
        m.triangles.emplace_back(0, 2 + j, 2 + j1);
        m.triangles.emplace_back(1, b + j1, b + j);
    }
    for (int i = 1; i < res - 1; ++i) {
        const int b1 = 2 + 2 * res * (i - 1), b2 = b1 + 2 * res;
        for (int j = 0; j < 2 * res; ++j) {
            const int j1 = (j + 1) % (2 * res);
            m.triangles.emplace_back(b2 + j, b1 + j1, b1 + j);
            m.triangles.emplace_back(b2 + j, b2 + j1, b1 + j1);
        }
    }
    return m;
}

/// n x n vertices on [0, n-1]^2 with height z(x, y); each cell split along its (i,j)-(i+1,j+1) diagonal.
template <typename Height>
TriangleMesh grid(int n, Height z) {
    TriangleMesh m;
    for (int j = 0; j < n; ++j)
        for (int i = 0; i < n; ++i) m.vertices.emplace_back(i, j, z(double(i), double(j)));
    for (int j = 0; j + 1 < n; ++j)
        for (int i = 0; i + 1 < n; ++i) {
            const int a = j * n + i;
            m.triangles.emplace_back(a, a + 1, a + n + 1);
            m.triangles.emplace_back(a, a + n + 1, a + n);
        }
    return m;
}

/// The script's bumpy_grid(): 5 x 5, z = 0.3 sin(1.7 x) cos(1.3 y) + 0.05 x y, colors (x/4, y/4, 0.5).
inline TriangleMesh bumpy_grid() {
    TriangleMesh m =
        grid(5, [](double x, double y) { return 0.3 * std::sin(1.7 * x) * std::cos(1.3 * y) + 0.05 * x * y; });
    for (const auto& v : m.vertices) m.vertex_colors.emplace_back(v.x() / 4, v.y() / 4, 0.5);
    return m;
}

inline TriangleMesh octahedron() {
    TriangleMesh m;
    m.vertices = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
    m.triangles = {{0, 2, 4}, {2, 1, 4}, {1, 3, 4}, {3, 0, 4}, {2, 0, 5}, {1, 2, 5}, {3, 1, 5}, {0, 3, 5}};
    return m;
}

/// Regular tetrahedron, outward triangles.
inline TriangleMesh tetrahedron() {
    TriangleMesh m;
    m.vertices = {{1, 1, 1}, {1, -1, -1}, {-1, 1, -1}, {-1, -1, 1}};
    m.triangles = {{0, 1, 2}, {0, 3, 1}, {0, 2, 3}, {1, 3, 2}};
    return m;
}

/// Unit cube [0,1]^3, 8 vertices, 12 outward triangles.
inline TriangleMesh unit_cube() {
    TriangleMesh m;
    m.vertices = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {1, 1, 0}, {0, 0, 1}, {1, 0, 1}, {0, 1, 1}, {1, 1, 1}};
    m.triangles = {{0, 2, 1}, {1, 2, 3}, {4, 5, 6}, {5, 7, 6}, {0, 1, 4}, {1, 5, 4},
                   {2, 6, 3}, {3, 6, 7}, {0, 4, 2}, {2, 4, 6}, {1, 3, 5}, {3, 7, 5}};
    return m;
}

inline double surface_area(const TriangleMesh& m) {
    double a = 0;
    for (size_t t = 0; t < m.triangles.size(); ++t) a += o3d::geometry::triangle_area(m, t);
    return a;
}

/// Signed volume (divergence theorem); meaningful for a closed, consistently oriented mesh.
inline double signed_volume(const TriangleMesh& m) {
    double v = 0;
    for (const auto& t : m.triangles) v += m.vertices[t(0)].dot(m.vertices[t(1)].cross(m.vertices[t(2)])) / 6;
    return v;
}

/// Triangles on each undirected edge.
inline std::map<std::pair<int, int>, int> edge_use(const TriangleMesh& m) {
    std::map<std::pair<int, int>, int> use;
    for (const auto& t : m.triangles)
        for (int k = 0; k < 3; ++k) {
            const int a = t(k), b = t((k + 1) % 3);
            ++use[{std::min(a, b), std::max(a, b)}];
        }
    return use;
}

/// Every edge in exactly two triangles, used once in each direction (closed and consistently oriented).
inline bool closed_and_oriented(const TriangleMesh& m) {
    std::map<std::pair<int, int>, int> directed;
    for (const auto& t : m.triangles)
        for (int k = 0; k < 3; ++k) ++directed[{t(k), t((k + 1) % 3)}];
    for (const auto& [e, n] : directed) {
        if (n != 1) return false;
        const auto back = directed.find({e.second, e.first});
        if (back == directed.end() || back->second != 1) return false;
    }
    return !m.triangles.empty();
}

/// V - E + F over the vertices used by triangles.
inline long euler_characteristic(const TriangleMesh& m) {
    std::vector<char> used(m.vertices.size(), 0);
    for (const auto& t : m.triangles) used[t(0)] = used[t(1)] = used[t(2)] = 1;
    long v = 0;
    for (char u : used) v += u;
    return v - static_cast<long>(edge_use(m).size()) + static_cast<long>(m.triangles.size());
}

/// The recording script's checksums: sum_i (i + 1) (x + 2y + 3z), and sum_i |v_i|^2.
inline std::pair<double, double> checksums(const std::vector<Eigen::Vector3d>& a) {
    double w = 0, s = 0;
    for (size_t i = 0; i < a.size(); ++i) {
        w += double(i + 1) * (a[i].x() + 2 * a[i].y() + 3 * a[i].z());
        s += a[i].squaredNorm();
    }
    return {w, s};
}

}  // namespace o3d_test
