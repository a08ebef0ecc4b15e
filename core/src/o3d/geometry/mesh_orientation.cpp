// SPDX-License-Identifier: MIT
#include "o3d/geometry/mesh_orientation.h"

#include <utility>
#include <vector>

#include "o3d/geometry/mesh_topology_detail.h"
#include "o3d/geometry/triangle_mesh_basics.h"

namespace o3d::geometry {

bool orient_triangles(TriangleMesh& mesh) {
    validate_triangles(mesh);
    std::vector<int> flipped;
    // The same solver as is_orientable, so the two always agree; nothing is touched before it succeeds.
    if (!detail::consistent_orientation(mesh, flipped)) return false;
    const bool normals = mesh.has_triangle_normals(), uvs = mesh.has_triangle_uvs();
    for (size_t t = 0; t < mesh.triangles.size(); ++t) {
        if (!flipped[t]) continue;
        std::swap(mesh.triangles[t](1), mesh.triangles[t](2));
        if (normals) mesh.triangle_normals[t] = -mesh.triangle_normals[t];
        if (uvs) std::swap(mesh.triangle_uvs[3 * t + 1], mesh.triangle_uvs[3 * t + 2]);
    }
    return true;
}

}  // namespace o3d::geometry
