// SPDX-License-Identifier: MIT
#include "o3d/geometry/triangle_mesh_basics.h"

#include <string>

#include "o3d/utility/error.h"

namespace o3d::geometry {

void validate_triangles(const TriangleMesh& mesh) {
    const long long n = static_cast<long long>(mesh.vertices.size());
    for (size_t t = 0; t < mesh.triangles.size(); ++t) {
        for (int k = 0; k < 3; ++k) {
            const long long v = mesh.triangles[t](k);
            if (v < 0 || v >= n)
                throw InvalidArgument("triangle " + std::to_string(t) + " refers to vertex " + std::to_string(v) +
                                      " but the mesh has " + std::to_string(n) + " vertices");
        }
    }
}

}  // namespace o3d::geometry
