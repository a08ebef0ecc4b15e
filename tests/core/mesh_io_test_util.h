// SPDX-License-Identifier: MIT
#pragma once
/// @file mesh_io_test_util.h
/// @brief Helpers shared by the mesh I/O tests: a synthetic mesh, reading text, expecting parse errors.
#include <gtest/gtest.h>

#include <cstdint>
#include <string>
#include <vector>

#include "o3d/geometry/triangle_mesh.h"
#include "o3d/io/triangle_mesh_io.h"
#include "o3d/utility/error.h"

namespace o3d::test {

/// @brief An octahedron (6 vertices, 8 triangles) with coordinates that are not float-exact, unit
/// normals, colours on the 1/255 grid and three UVs per triangle.
inline geometry::TriangleMesh make_octahedron(bool normals = true, bool colors = true, bool uvs = true) {
    geometry::TriangleMesh m;
    const double r = 1.1;
    const Eigen::Vector3d c(0.1, -0.2, 0.3);
    const Eigen::Vector3d dirs[6] = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
    for (int i = 0; i < 6; ++i) {
        m.vertices.push_back(c + r * dirs[i]);
        if (normals) m.vertex_normals.push_back(dirs[i]);
        if (colors) m.vertex_colors.emplace_back(i * 40 / 255.0, (255 - i * 30) / 255.0, 17 / 255.0);
    }
    const int tris[8][3] = {{0, 2, 4}, {2, 1, 4}, {1, 3, 4}, {3, 0, 4}, {2, 0, 5}, {1, 2, 5}, {3, 1, 5}, {0, 3, 5}};
    for (int t = 0; t < 8; ++t) {
        m.triangles.emplace_back(tris[t][0], tris[t][1], tris[t][2]);
        if (uvs)
            for (int k = 0; k < 3; ++k) m.triangle_uvs.emplace_back(0.125 * t + 0.01 * k, 0.3 + 0.1 * k);
    }
    return m;
}

inline geometry::TriangleMesh read_mesh_text(const std::string& text, const std::string& format,
                                             const io::MeshReadOptions& options = {}) {
    return io::read_triangle_mesh_from_memory(reinterpret_cast<const uint8_t*>(text.data()), text.size(), format,
                                              options);
}

/// @brief The ParseError message reading `bytes` as `format` raises ("" when it raises none).
inline std::string mesh_parse_error(const std::vector<uint8_t>& bytes, const std::string& format) {
    try {
        io::read_triangle_mesh_from_memory(bytes.data(), bytes.size(), format);
    } catch (const ParseError& e) {
        return e.what();
    }
    return "";
}

inline std::string mesh_parse_error(const std::string& text, const std::string& format) {
    return mesh_parse_error(std::vector<uint8_t>(text.begin(), text.end()), format);
}

inline void expect_vec3_near(const std::vector<Eigen::Vector3d>& a, const std::vector<Eigen::Vector3d>& b, double tol,
                             const char* what) {
    ASSERT_EQ(a.size(), b.size()) << what;
    for (size_t i = 0; i < a.size(); ++i)
        for (int k = 0; k < 3; ++k) ASSERT_NEAR(a[i][k], b[i][k], tol) << what << " " << i << "," << k;
}

}  // namespace o3d::test
