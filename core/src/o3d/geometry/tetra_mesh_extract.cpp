// SPDX-License-Identifier: MIT
// Marching tetrahedra (extract_triangle_mesh of tetra_mesh.h).
#include <Eigen/Geometry>
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <string>

#include "o3d/geometry/tetra_mesh.h"
#include "o3d/geometry/tetra_mesh_ops.h"
#include "o3d/utility/error.h"

namespace o3d::geometry {
namespace {

uint64_t edge_key(int a, int b) {
    if (a > b) std::swap(a, b);
    return (static_cast<uint64_t>(static_cast<uint32_t>(a)) << 32) | static_cast<uint32_t>(b);
}

}  // namespace

TriangleMesh extract_triangle_mesh(const TetraMesh& tetra_mesh, const std::vector<double>& values, double level) {
    const std::vector<Eigen::Vector3d>& pos = tetra_mesh.vertices;
    if (values.size() != pos.size())
        throw InvalidArgument("extract_triangle_mesh: " + std::to_string(values.size()) + " values for " +
                              std::to_string(pos.size()) + " vertices");
    if (!std::isfinite(level)) throw InvalidArgument("extract_triangle_mesh: level is not finite");
    for (size_t i = 0; i < values.size(); ++i)
        if (!std::isfinite(values[i]))
            throw InvalidArgument("extract_triangle_mesh: value " + std::to_string(i) + " is not finite");
    validate_tetras(tetra_mesh);

    // Pass 1: every crossed edge, so that each surface vertex is made once and shared.
    std::vector<uint64_t> keys;
    for (const Eigen::Vector4i& t : tetra_mesh.tetras)
        for (int i = 0; i < 4; ++i)
            for (int j = i + 1; j < 4; ++j)
                if ((values[static_cast<size_t>(t(i))] < level) != (values[static_cast<size_t>(t(j))] < level))
                    keys.push_back(edge_key(t(i), t(j)));
    std::sort(keys.begin(), keys.end());
    keys.erase(std::unique(keys.begin(), keys.end()), keys.end());

    TriangleMesh mesh;
    mesh.vertices.resize(keys.size());
    for (size_t k = 0; k < keys.size(); ++k) {
        const size_t a = static_cast<size_t>(keys[k] >> 32), b = static_cast<size_t>(keys[k] & 0xffffffffu);
        // Interpolate from the smaller index so the point does not depend on which tetra asks for it.
        const double t = (level - values[a]) / (values[b] - values[a]);
        mesh.vertices[k] = pos[a] + t * (pos[b] - pos[a]);
    }
    auto vertex_on = [&](int a, int b) {
        return static_cast<int>(std::lower_bound(keys.begin(), keys.end(), edge_key(a, b)) - keys.begin());
    };

    // Pass 2: one triangle (a corner alone on its side) or a quad split in two (two and two).
    for (const Eigen::Vector4i& t : tetra_mesh.tetras) {
        std::array<int, 4> below, above;
        int nb = 0, na = 0;
        for (int i = 0; i < 4; ++i) {
            if (values[static_cast<size_t>(t(i))] < level)
                below[nb++] = t(i);
            else
                above[na++] = t(i);
        }
        if (nb == 0 || na == 0) continue;
        // The field is linear in the tetra, so the surface piece is planar and separates the corners:
        // (mean of the corners above - mean of those below) has a positive component along the gradient.
        Eigen::Vector3d up = Eigen::Vector3d::Zero(), down = Eigen::Vector3d::Zero();
        for (int i = 0; i < na; ++i) up += pos[static_cast<size_t>(above[i])];
        for (int i = 0; i < nb; ++i) down += pos[static_cast<size_t>(below[i])];
        const Eigen::Vector3d gradient_side = up / na - down / nb;
        const auto& P = mesh.vertices;
        if (nb == 2) {
            // Quad around the edges a0-b0, a0-b1, a1-b1, a1-b0 (a = below, b = above), in cyclic order.
            const int q0 = vertex_on(below[0], above[0]), q1 = vertex_on(below[0], above[1]);
            const int q2 = vertex_on(below[1], above[1]), q3 = vertex_on(below[1], above[0]);
            const Eigen::Vector3d normal = (P[static_cast<size_t>(q2)] - P[static_cast<size_t>(q0)])
                                               .cross(P[static_cast<size_t>(q3)] - P[static_cast<size_t>(q1)]);
            if (normal.dot(gradient_side) >= 0.0) {
                mesh.triangles.emplace_back(q0, q1, q2);
                mesh.triangles.emplace_back(q0, q2, q3);
            } else {
                mesh.triangles.emplace_back(q0, q2, q1);
                mesh.triangles.emplace_back(q0, q3, q2);
            }
            continue;
        }
        // One corner alone: its three edges.
        const bool lone_below = nb == 1;
        const int lone = lone_below ? below[0] : above[0];
        const std::array<int, 4>& others = lone_below ? above : below;
        Eigen::Vector3i tri(vertex_on(lone, others[0]), vertex_on(lone, others[1]), vertex_on(lone, others[2]));
        const Eigen::Vector3d normal = (P[static_cast<size_t>(tri(1))] - P[static_cast<size_t>(tri(0))])
                                           .cross(P[static_cast<size_t>(tri(2))] - P[static_cast<size_t>(tri(0))]);
        if (normal.dot(gradient_side) < 0.0) std::swap(tri(1), tri(2));
        mesh.triangles.push_back(tri);
    }
    return mesh;
}

}  // namespace o3d::geometry
