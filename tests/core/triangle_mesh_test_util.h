// SPDX-License-Identifier: MIT
#pragma once
/// @file triangle_mesh_test_util.h
/// @brief Meshes built by hand for the triangle-mesh tests, and a reader for knot.ply's simple binary PLY
/// (so these tests do not depend on the mesh I/O module).
#include <Eigen/Core>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <sstream>
#include <string>

#include "o3d/geometry/triangle_mesh.h"

namespace o3d::test {

/// @brief Unit cube [0,1]^3, 8 shared corners, 12 outward-facing triangles (as record_mesh.py builds it).
inline geometry::TriangleMesh unit_cube() {
    geometry::TriangleMesh m;
    m.vertices = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, {0, 0, 1}, {1, 0, 1}, {1, 1, 1}, {0, 1, 1}};
    m.triangles = {{0, 2, 1}, {0, 3, 2}, {4, 5, 6}, {4, 6, 7}, {0, 1, 5}, {0, 5, 4},
                   {1, 2, 6}, {1, 6, 5}, {2, 3, 7}, {2, 7, 6}, {3, 0, 4}, {3, 4, 7}};
    return m;
}

/// @brief The corner tetrahedron (0,0,0), e_x, e_y, e_z, outward-facing: volume 1/6.
inline geometry::TriangleMesh corner_tetrahedron(const Eigen::Vector3d& shift = Eigen::Vector3d::Zero()) {
    geometry::TriangleMesh m;
    m.vertices = {shift, shift + Eigen::Vector3d(1, 0, 0), shift + Eigen::Vector3d(0, 1, 0),
                  shift + Eigen::Vector3d(0, 0, 1)};
    m.triangles = {{0, 2, 1}, {0, 1, 3}, {0, 3, 2}, {1, 2, 3}};
    return m;
}

/// @brief A torus of n x k quads (2 n k triangles), closed and watertight; R = 3, r = 1.
inline geometry::TriangleMesh grid_torus(int n, int k) {
    geometry::TriangleMesh m;
    for (int i = 0; i < n; ++i)
        for (int j = 0; j < k; ++j) {
            const double u = 2 * M_PI * i / n, v = 2 * M_PI * j / k;
            m.vertices.emplace_back((3 + std::cos(v)) * std::cos(u), (3 + std::cos(v)) * std::sin(u), std::sin(v));
        }
    for (int i = 0; i < n; ++i)
        for (int j = 0; j < k; ++j) {
            const int a = i * k + j, b = ((i + 1) % n) * k + j, c = ((i + 1) % n) * k + (j + 1) % k,
                      d = i * k + (j + 1) % k;
            m.triangles.emplace_back(a, b, c);
            m.triangles.emplace_back(a, c, d);
        }
    return m;
}

/// @brief sum_i (i + 1) * a_i over the flattened rows (record_mesh.py's fp()).
template <typename Vec>
double fingerprint(const std::vector<Vec>& rows) {
    double sum = 0;
    size_t i = 0;
    for (const Vec& r : rows)
        for (int k = 0; k < r.size(); ++k) sum += static_cast<double>(++i) * static_cast<double>(r(k));
    return sum;
}

/// @brief Reads binary little-endian PLY with float x y z vertices and uchar-count int faces (knot.ply).
inline bool read_simple_ply(const std::string& path, geometry::TriangleMesh& mesh) {
    std::ifstream in(path, std::ios::binary);
    std::string line;
    size_t nv = 0, nf = 0;
    while (std::getline(in, line)) {
        std::istringstream words(line);
        std::string a, b;
        words >> a >> b;
        if (a == "element" && b == "vertex") words >> nv;
        if (a == "element" && b == "face") words >> nf;
        if (a == "end_header") break;
    }
    mesh = {};
    for (size_t i = 0; i < nv; ++i) {
        float xyz[3];
        if (!in.read(reinterpret_cast<char*>(xyz), sizeof xyz)) return false;
        mesh.vertices.emplace_back(xyz[0], xyz[1], xyz[2]);
    }
    for (size_t i = 0; i < nf; ++i) {
        uint8_t count = 0;
        int32_t idx[3];
        if (!in.read(reinterpret_cast<char*>(&count), 1) || count != 3) return false;
        if (!in.read(reinterpret_cast<char*>(idx), sizeof idx)) return false;
        mesh.triangles.emplace_back(idx[0], idx[1], idx[2]);
    }
    return true;
}

}  // namespace o3d::test
