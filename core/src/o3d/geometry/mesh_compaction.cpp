// SPDX-License-Identifier: MIT
#include "o3d/geometry/mesh_compaction.h"

namespace o3d::geometry {

void keep_triangles(TriangleMesh& mesh, const std::vector<uint8_t>& keep) {
    const bool normals = mesh.has_triangle_normals(), uvs = mesh.has_triangle_uvs(),
               ids = mesh.has_triangle_material_ids();
    if (normals) compact(mesh.triangle_normals, keep);
    if (uvs) compact(mesh.triangle_uvs, keep, 3);
    if (ids) compact(mesh.triangle_material_ids, keep);
    compact(mesh.triangles, keep);
}

void keep_vertices(TriangleMesh& mesh, const std::vector<uint8_t>& keep, const std::vector<int>& new_index) {
    const bool normals = mesh.has_vertex_normals(), colors = mesh.has_vertex_colors();
    if (normals) compact(mesh.vertex_normals, keep);
    if (colors) compact(mesh.vertex_colors, keep);
    compact(mesh.vertices, keep);
    for (Eigen::Vector3i& tri : mesh.triangles)
        for (int k = 0; k < 3; ++k) tri(k) = new_index[tri(k)];
}

}  // namespace o3d::geometry
