// SPDX-License-Identifier: MIT
#include "o3d/geometry/mesh_sharpen.h"

#include <cmath>
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include "o3d/geometry/mesh_adjacency.h"
#include "o3d/geometry/mesh_normals_util.h"
#include "o3d/geometry/triangle_mesh_basics.h"
#include "o3d/utility/error.h"
#include "o3d/utility/parallel.h"

namespace o3d::geometry {

TriangleMesh filter_sharpen(const TriangleMesh& mesh, int number_of_iterations, double strength, FilterScope scope,
                            int num_threads) {
    validate_triangles(mesh);
    if (mesh.vertices.empty()) throw InvalidArgument("the mesh has no vertices");
    if (number_of_iterations < 0)
        throw InvalidArgument("number_of_iterations must be >= 0, got " + std::to_string(number_of_iterations));
    const int s = static_cast<int>(scope);
    if (s < 0 || s > 3) throw InvalidArgument("unknown filter scope " + std::to_string(s) + " (expected 0..3)");
    if (!std::isfinite(strength)) throw InvalidArgument("strength must be finite, got " + std::to_string(strength));

    TriangleMesh out = mesh;
    const bool positions = scope == FilterScope::All || scope == FilterScope::Vertex;
    const bool normals = (scope == FilterScope::All || scope == FilterScope::Normal) && mesh.has_vertex_normals();
    const bool colors = (scope == FilterScope::All || scope == FilterScope::Color) && mesh.has_vertex_colors();
    if (number_of_iterations == 0 || (!positions && !normals && !colors)) return out;

    const size_t nv = mesh.vertices.size();
    const VertexNeighbours around = vertex_neighbours(mesh_edges(mesh), nv);
    const int threads = utility::resolve_num_threads(num_threads);
    // Every vertex of an iteration reads the previous state only: double buffers, swapped after each.
    std::vector<Eigen::Vector3d> next_p = out.vertices, next_n = out.vertex_normals, next_c = out.vertex_colors;
    // v + strength (|N| v - sum), in Open3D's order of operations.
    auto sharpen = [&](const std::vector<Eigen::Vector3d>& x, size_t v) {
        Eigen::Vector3d sum = Eigen::Vector3d::Zero();
        for (const int* j = around.begin(v); j != around.end(v); ++j) sum += x[*j];
        return Eigen::Vector3d(x[v] + strength * (x[v] * static_cast<double>(around.count(v)) - sum));
    };
    for (int it = 0; it < number_of_iterations; ++it) {
#pragma omp parallel for schedule(static) num_threads(threads)
        for (int64_t vi = 0; vi < static_cast<int64_t>(nv); ++vi) {
            const size_t v = static_cast<size_t>(vi);
            if (positions) next_p[v] = sharpen(out.vertices, v);
            if (normals) next_n[v] = sharpen(out.vertex_normals, v);
            if (colors) next_c[v] = sharpen(out.vertex_colors, v);
        }
        if (positions) std::swap(out.vertices, next_p);
        if (normals) std::swap(out.vertex_normals, next_n);
        if (colors) std::swap(out.vertex_colors, next_c);
    }
    if (positions && mesh.has_triangle_normals()) out.triangle_normals = unit_triangle_normals(out);
    return out;
}

}  // namespace o3d::geometry
