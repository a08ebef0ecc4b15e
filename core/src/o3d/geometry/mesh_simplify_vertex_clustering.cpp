// SPDX-License-Identifier: MIT
#include "o3d/geometry/mesh_simplify_vertex_clustering.h"

#include <Eigen/Geometry>  // cross(), used by triangle_cross
#include <algorithm>
#include <climits>
#include <cmath>
#include <string>
#include <tuple>
#include <unordered_set>
#include <utility>
#include <vector>

#include "o3d/geometry/error_quadric.h"
#include "o3d/geometry/mesh_adjacency.h"
#include "o3d/geometry/mesh_normals_util.h"
#include "o3d/geometry/radix_sort.h"
#include "o3d/geometry/triangle_mesh_basics.h"
#include "o3d/utility/error.h"

namespace o3d::geometry {
namespace {

int bit_width(uint64_t v) {
    int bits = 0;
    for (; v; v >>= 1) ++bits;
    return bits;
}

struct TriangleKey {
    size_t operator()(const Eigen::Vector3i& t) const {
        return (static_cast<size_t>(t(0)) * 73856093u) ^ (static_cast<size_t>(t(1)) * 19349663u) ^
               (static_cast<size_t>(t(2)) * 83492791u);
    }
};

}  // namespace

TriangleMesh simplify_vertex_clustering(const TriangleMesh& mesh, double voxel_size,
                                        SimplificationContraction contraction) {
    validate_triangles(mesh);
    if (!std::isfinite(voxel_size) || voxel_size <= 0)
        throw InvalidArgument("voxel_size must be finite and > 0, got " + std::to_string(voxel_size));
    if (contraction != SimplificationContraction::Average && contraction != SimplificationContraction::Quadric)
        throw InvalidArgument("unknown contraction " + std::to_string(static_cast<int>(contraction)));
    const size_t nv = mesh.vertices.size();
    if (nv == 0) throw InvalidArgument("the mesh has no vertices");
    Eigen::Vector3d lo = mesh.vertices[0], hi = mesh.vertices[0];
    for (size_t v = 0; v < nv; ++v) {
        if (!mesh.vertices[v].allFinite()) throw InvalidArgument("vertex " + std::to_string(v) + " is not finite");
        lo = lo.cwiseMin(mesh.vertices[v]);
        hi = hi.cwiseMax(mesh.vertices[v]);
    }
    const Eigen::Vector3d origin = lo - Eigen::Vector3d::Constant(0.5 * voxel_size);
    const double extent = (hi - lo).maxCoeff() + voxel_size;
    if (voxel_size * static_cast<double>(INT_MAX) < extent)
        throw InvalidArgument("voxel_size " + std::to_string(voxel_size) + " is too small for a mesh of extent " +
                              std::to_string(extent));

    // Voxel of each vertex as one linear key; dims fit in 32 bits each, so the key fits in 96 bits at most:
    // sort by (z, y, x) in three stable passes when the product overflows 64 bits.
    std::vector<Eigen::Array3i> cell(nv);
    Eigen::Array3i dims(1, 1, 1);
    for (size_t v = 0; v < nv; ++v) {
        const Eigen::Vector3d r = (mesh.vertices[v] - origin) / voxel_size;
        for (int a = 0; a < 3; ++a) cell[v](a) = static_cast<int>(std::floor(r(a)));
        dims = dims.max(cell[v] + 1);
    }
    std::vector<std::pair<uint64_t, size_t>> keyed(nv);
    for (size_t v = 0; v < nv; ++v) keyed[v] = {static_cast<uint64_t>(cell[v](0)), v};
    radix_sort_by_key(keyed, bit_width(static_cast<uint64_t>(dims(0))));
    for (int a = 1; a < 3; ++a) {
        for (auto& k : keyed) k.first = static_cast<uint64_t>(cell[k.second](a));
        radix_sort_by_key(keyed, bit_width(static_cast<uint64_t>(dims(a))));
    }
    // Runs of one voxel hold ascending vertex indices (stable passes); its first vertex numbers the cluster.
    std::vector<int> run_of_vertex(nv);
    std::vector<size_t> run_start;
    for (size_t i = 0; i < nv; ++i) {
        if (i == 0 || (cell[keyed[i].second] != cell[keyed[i - 1].second]).any()) run_start.push_back(i);
        run_of_vertex[keyed[i].second] = static_cast<int>(run_start.size() - 1);
    }
    run_start.push_back(nv);
    const size_t clusters = run_start.size() - 1;
    std::vector<int> cluster_of_run(clusters, -1), cluster_of_vertex(nv);
    std::vector<int> run_of_cluster(clusters);
    int next = 0;
    for (size_t v = 0; v < nv; ++v) {
        const int r = run_of_vertex[v];
        if (cluster_of_run[r] < 0) {
            run_of_cluster[next] = r;
            cluster_of_run[r] = next++;
        }
        cluster_of_vertex[v] = cluster_of_run[r];
    }

    const bool normals = mesh.has_vertex_normals(), colors = mesh.has_vertex_colors();
    TriangleMesh out;
    out.vertices.resize(clusters);
    if (normals) out.vertex_normals.resize(clusters);
    if (colors) out.vertex_colors.resize(clusters);
    VertexTriangles around;
    std::vector<Eigen::Vector3d> plane_normal;
    std::vector<double> plane_offset, plane_area;
    if (contraction == SimplificationContraction::Quadric) {
        around = vertex_triangles(mesh);
        const size_t nt = mesh.triangles.size();
        plane_normal.resize(nt);
        plane_offset.resize(nt);
        plane_area.resize(nt);
        for (size_t t = 0; t < nt; ++t) {
            const Eigen::Vector3i& tri = mesh.triangles[t];
            plane_area[t] = triangle_area(mesh, t);
            if (!triangle_plane(mesh.vertices[tri(0)], mesh.vertices[tri(1)], mesh.vertices[tri(2)], plane_normal[t],
                                plane_offset[t]))
                plane_area[t] = 0;  // no plane: contributes nothing
        }
    }
    for (size_t c = 0; c < clusters; ++c) {
        const size_t begin = run_start[run_of_cluster[c]], end = run_start[run_of_cluster[c] + 1];
        Eigen::Vector3d p = Eigen::Vector3d::Zero(), nrm = Eigen::Vector3d::Zero(), col = Eigen::Vector3d::Zero();
        ErrorQuadric q;
        for (size_t j = begin; j < end; ++j) {
            const size_t v = keyed[j].second;
            p += mesh.vertices[v];
            if (normals) nrm += mesh.vertex_normals[v];
            if (colors) col += mesh.vertex_colors[v];
            if (contraction == SimplificationContraction::Quadric)
                for (int k = around.offsets[v]; k < around.offsets[v + 1]; ++k) {
                    const int t = around.triangles[k];
                    if (plane_area[t] > 0) q += ErrorQuadric::plane(plane_normal[t], plane_offset[t], plane_area[t]);
                }
        }
        const double count = static_cast<double>(end - begin);
        Eigen::Vector3d best;
        out.vertices[c] = contraction == SimplificationContraction::Quadric && q.minimum(best) ? best : p / count;
        if (normals) out.vertex_normals[c] = nrm / count;
        if (colors) out.vertex_colors[c] = col / count;
    }

    std::unordered_set<Eigen::Vector3i, TriangleKey> seen;
    seen.reserve(mesh.triangles.size());
    for (const Eigen::Vector3i& tri : mesh.triangles) {
        int a = cluster_of_vertex[tri(0)], b = cluster_of_vertex[tri(1)], c = cluster_of_vertex[tri(2)];
        if (a == b || b == c || c == a) continue;
        // Rotate (orientation kept) so the smallest index leads: equal faces then compare equal.
        if (b < a && b < c) {
            std::tie(a, b, c) = std::make_tuple(b, c, a);
        } else if (c < a && c < b) {
            std::tie(a, b, c) = std::make_tuple(c, a, b);
        }
        const Eigen::Vector3i face(a, b, c);
        if (seen.insert(face).second) out.triangles.push_back(face);
    }
    if (mesh.has_triangle_normals()) out.triangle_normals = unit_triangle_normals(out);
    return out;
}

}  // namespace o3d::geometry
