// SPDX-License-Identifier: MIT
#include "o3d/geometry/mesh_subdivision.h"

#include <climits>
#include <string>
#include <vector>

#include "o3d/geometry/mesh_adjacency.h"
#include "o3d/geometry/mesh_normals_util.h"
#include "o3d/geometry/triangle_mesh_basics.h"
#include "o3d/utility/error.h"

namespace o3d::geometry {
namespace {

/// @brief The per-vertex arrays a subdivision carries along (normals and colors only when they count).
struct VertexData {
    std::vector<Eigen::Vector3d>* arrays[3];
    int count;
};

VertexData vertex_data(TriangleMesh& mesh, bool normals, bool colors) {
    VertexData d{{&mesh.vertices, nullptr, nullptr}, 1};
    if (normals) d.arrays[d.count++] = &mesh.vertex_normals;
    if (colors) d.arrays[d.count++] = &mesh.vertex_colors;
    return d;
}

/// @brief Old vertices under Loop's rule (see the header), written into `out` (same layout as `in`).
void loop_vertex_rule(const MeshEdges& edges, size_t nv, const VertexData& in, const VertexData& out) {
    const VertexNeighbours around = vertex_neighbours(edges, nv);
    std::vector<int> boundary_count(nv, 0);
    std::vector<std::vector<Eigen::Vector3d>> boundary_sum(
        in.count, std::vector<Eigen::Vector3d>(nv, Eigen::Vector3d::Zero()));
    for (size_t e = 0; e < edges.size(); ++e) {
        const int a = edges.endpoints[e](0), b = edges.endpoints[e](1);
        if (a == b || edges.triangle_count(e) != 1) continue;
        ++boundary_count[a];
        ++boundary_count[b];
        for (int k = 0; k < in.count; ++k) {
            boundary_sum[k][a] += (*in.arrays[k])[b];
            boundary_sum[k][b] += (*in.arrays[k])[a];
        }
    }
    for (size_t v = 0; v < nv; ++v) {
        const int n = around.count(v);
        for (int k = 0; k < in.count; ++k) {
            const std::vector<Eigen::Vector3d>& src = *in.arrays[k];
            Eigen::Vector3d& dst = (*out.arrays[k])[v];
            if (boundary_count[v] >= 2) {
                dst = (1.0 - boundary_count[v] / 8.0) * src[v] + boundary_sum[k][v] / 8.0;
            } else if (n == 0) {
                dst = src[v];
            } else {
                const double beta = n == 3 ? 3.0 / 16.0 : 3.0 / (8.0 * n);
                Eigen::Vector3d sum = Eigen::Vector3d::Zero();
                for (const int* j = around.begin(v); j != around.end(v); ++j) sum += src[*j];
                dst = (1.0 - n * beta) * src[v] + beta * sum;
            }
        }
    }
}

TriangleMesh subdivide(const TriangleMesh& mesh, int number_of_iterations, bool loop) {
    validate_triangles(mesh);
    if (mesh.vertices.empty()) throw InvalidArgument("the mesh has no vertices");
    if (number_of_iterations < 0)
        throw InvalidArgument("number_of_iterations must be >= 0, got " + std::to_string(number_of_iterations));
    // Refuse up front (not after building 4^k-fold meshes) when the triangle count cannot fit an int.
    double final_triangles = static_cast<double>(mesh.triangles.size());
    for (int it = 0; it < number_of_iterations && final_triangles > 0 && final_triangles <= INT_MAX; ++it)
        final_triangles *= 4;
    if (final_triangles > INT_MAX)
        throw InvalidArgument(std::to_string(number_of_iterations) + " subdivisions of " +
                              std::to_string(mesh.triangles.size()) +
                              " triangles would make more than the 2^31 - 1 supported");
    const bool normals = mesh.has_vertex_normals(), colors = mesh.has_vertex_colors();
    const bool uvs = mesh.has_triangle_uvs(), material_ids = mesh.has_triangle_material_ids();
    TriangleMesh cur = mesh;
    cur.triangle_normals.clear();
    if (!normals) cur.vertex_normals.clear();
    if (!colors) cur.vertex_colors.clear();
    if (!uvs) cur.triangle_uvs.clear();
    if (!material_ids) cur.triangle_material_ids.clear();

    for (int it = 0; it < number_of_iterations; ++it) {
        const MeshEdges edges = mesh_edges(cur);
        const size_t nv = cur.vertices.size(), ne = edges.size(), nt = cur.triangles.size();
        if (nv + ne > static_cast<size_t>(INT_MAX) || 4 * nt > static_cast<size_t>(INT_MAX))
            throw InvalidArgument("subdivision iteration " + std::to_string(it + 1) + " would make " +
                                  std::to_string(nv + ne) + " vertices and " + std::to_string(4 * nt) +
                                  " triangles, more than the 2^31 - 1 supported");
        TriangleMesh next;
        next.vertices.resize(nv + ne);
        if (normals) next.vertex_normals.resize(nv + ne);
        if (colors) next.vertex_colors.resize(nv + ne);
        const VertexData in = vertex_data(cur, normals, colors), out = vertex_data(next, normals, colors);

        if (loop) {
            loop_vertex_rule(edges, nv, in, out);
        } else {
            for (int k = 0; k < in.count; ++k)
                std::copy(in.arrays[k]->begin(), in.arrays[k]->end(), out.arrays[k]->begin());
        }
        for (size_t e = 0; e < ne; ++e) {
            const int a = edges.endpoints[e](0), b = edges.endpoints[e](1);
            const bool smooth = loop && edges.triangle_count(e) != 1;
            for (int k = 0; k < in.count; ++k) {
                const std::vector<Eigen::Vector3d>& src = *in.arrays[k];
                Eigen::Vector3d& dst = (*out.arrays[k])[nv + e];
                if (!smooth) {
                    dst = 0.5 * (src[a] + src[b]);
                    continue;
                }
                dst = 3.0 / 8.0 * (src[a] + src[b]);
                for (int i = edges.triangle_offsets[e]; i < edges.triangle_offsets[e + 1]; ++i) {
                    const Eigen::Vector3i& tri = cur.triangles[edges.triangles[i]];
                    const int c = tri(0) != a && tri(0) != b ? tri(0) : (tri(1) != a && tri(1) != b ? tri(1) : tri(2));
                    dst += 1.0 / 8.0 * src[c];
                }
            }
        }

        next.triangles.resize(4 * nt);
        if (uvs) next.triangle_uvs.resize(12 * nt);
        if (material_ids) next.triangle_material_ids.resize(4 * nt);
        for (size_t t = 0; t < nt; ++t) {
            const Eigen::Vector3i& tri = cur.triangles[t];
            const int ab = static_cast<int>(nv) + edges.side_edge[3 * t];
            const int bc = static_cast<int>(nv) + edges.side_edge[3 * t + 1];
            const int ca = static_cast<int>(nv) + edges.side_edge[3 * t + 2];
            next.triangles[4 * t] = Eigen::Vector3i(tri(0), ab, ca);
            next.triangles[4 * t + 1] = Eigen::Vector3i(ab, tri(1), bc);
            next.triangles[4 * t + 2] = Eigen::Vector3i(bc, tri(2), ca);
            next.triangles[4 * t + 3] = Eigen::Vector3i(ab, bc, ca);
            if (uvs) {
                const Eigen::Vector2d* uv = &cur.triangle_uvs[3 * t];
                const Eigen::Vector2d uv_ab = 0.5 * (uv[0] + uv[1]), uv_bc = 0.5 * (uv[1] + uv[2]),
                                      uv_ca = 0.5 * (uv[2] + uv[0]);
                const Eigen::Vector2d corners[12] = {uv[0], uv_ab, uv_ca, uv_ab, uv[1], uv_bc,
                                                     uv_bc, uv[2], uv_ca, uv_ab, uv_bc, uv_ca};
                std::copy(corners, corners + 12, next.triangle_uvs.begin() + 12 * t);
            }
            if (material_ids)
                for (int k = 0; k < 4; ++k) next.triangle_material_ids[4 * t + k] = cur.triangle_material_ids[t];
        }
        next.textures = std::move(cur.textures);
        cur = std::move(next);
    }
    if (mesh.has_triangle_normals()) cur.triangle_normals = unit_triangle_normals(cur);
    return cur;
}

}  // namespace

TriangleMesh subdivide_midpoint(const TriangleMesh& mesh, int number_of_iterations) {
    return subdivide(mesh, number_of_iterations, false);
}

TriangleMesh subdivide_loop(const TriangleMesh& mesh, int number_of_iterations) {
    return subdivide(mesh, number_of_iterations, true);
}

}  // namespace o3d::geometry
