// SPDX-License-Identifier: MIT
#include "o3d/geometry/mesh_crop.h"

#include <vector>

#include "o3d/geometry/crop.h"
#include "o3d/geometry/triangle_mesh_basics.h"
#include "o3d/utility/error.h"

namespace o3d::geometry {

TriangleMesh keep_triangles_inside(const TriangleMesh& mesh, const std::vector<uint8_t>& inside) {
    const bool triangle_normals = mesh.has_triangle_normals(), uvs = mesh.has_triangle_uvs(),
               material_ids = mesh.has_triangle_material_ids();
    std::vector<int> index(mesh.vertices.size(), -1);
    std::vector<size_t> kept;
    for (size_t t = 0; t < mesh.triangles.size(); ++t) {
        const Eigen::Vector3i& tri = mesh.triangles[t];
        if (!inside[tri(0)] || !inside[tri(1)] || !inside[tri(2)]) continue;
        kept.push_back(t);
        for (int k = 0; k < 3; ++k) index[tri(k)] = 0;  // used; numbered below, in vertex order
    }
    TriangleMesh out;
    const bool normals = mesh.has_vertex_normals(), colors = mesh.has_vertex_colors();
    for (size_t v = 0; v < mesh.vertices.size(); ++v) {
        if (index[v] < 0) continue;
        index[v] = static_cast<int>(out.vertices.size());
        out.vertices.push_back(mesh.vertices[v]);
        if (normals) out.vertex_normals.push_back(mesh.vertex_normals[v]);
        if (colors) out.vertex_colors.push_back(mesh.vertex_colors[v]);
    }
    for (size_t t : kept) {
        const Eigen::Vector3i& tri = mesh.triangles[t];
        out.triangles.emplace_back(index[tri(0)], index[tri(1)], index[tri(2)]);
        if (triangle_normals) out.triangle_normals.push_back(mesh.triangle_normals[t]);
        if (uvs)
            for (int k = 0; k < 3; ++k) out.triangle_uvs.push_back(mesh.triangle_uvs[3 * t + k]);
        if (material_ids) out.triangle_material_ids.push_back(mesh.triangle_material_ids[t]);
    }
    out.textures = mesh.textures;
    return out;
}

TriangleMesh crop_aabb(const TriangleMesh& mesh, const Eigen::Vector3d& min_bound, const Eigen::Vector3d& max_bound) {
    validate_triangles(mesh);
    if (mesh.vertices.empty()) throw InvalidArgument("the mesh has no vertices");
    PointCloud corners;
    corners.points = mesh.vertices;
    const std::vector<int64_t> inside_list = indices_in_aabb(corners, min_bound, max_bound);  // checks the box
    std::vector<uint8_t> inside(mesh.vertices.size(), 0);
    for (int64_t v : inside_list) inside[static_cast<size_t>(v)] = 1;
    return keep_triangles_inside(mesh, inside);
}

}  // namespace o3d::geometry
