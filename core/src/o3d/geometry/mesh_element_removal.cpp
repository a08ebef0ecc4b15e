// SPDX-License-Identifier: MIT
#include "o3d/geometry/mesh_element_removal.h"

#include <string>

#include "o3d/geometry/mesh_compaction.h"
#include "o3d/geometry/triangle_mesh_basics.h"
#include "o3d/utility/error.h"

namespace o3d::geometry {
namespace {

/// @brief A removal mask from indices into `count` items, each checked.
std::vector<uint8_t> mask_of(const std::vector<int64_t>& indices, size_t count, const char* what) {
    std::vector<uint8_t> mask(count, 0);
    for (int64_t i : indices) {
        if (i < 0 || static_cast<uint64_t>(i) >= count)
            throw InvalidArgument(std::string(what) + " index " + std::to_string(i) + " is out of range [0, " +
                                  std::to_string(count) + ")");
        mask[static_cast<size_t>(i)] = 1;
    }
    return mask;
}

void require_one_per(const std::vector<uint8_t>& mask, size_t count, const char* what) {
    if (mask.size() != count)
        throw InvalidArgument("the mask has " + std::to_string(mask.size()) + " entries but the mesh has " +
                              std::to_string(count) + " " + what);
}

}  // namespace

void remove_vertices_by_mask(TriangleMesh& mesh, const std::vector<uint8_t>& mask) {
    require_one_per(mask, mesh.vertices.size(), "vertices");
    validate_triangles(mesh);
    std::vector<uint8_t> keep_triangle(mesh.triangles.size(), 1);
    for (size_t t = 0; t < mesh.triangles.size(); ++t)
        for (int k = 0; k < 3; ++k)
            if (mask[mesh.triangles[t](k)]) keep_triangle[t] = 0;
    keep_triangles(mesh, keep_triangle);
    std::vector<uint8_t> keep(mask.size());
    std::vector<int> new_index(mask.size(), -1);
    int next = 0;
    for (size_t v = 0; v < mask.size(); ++v) {
        keep[v] = !mask[v];
        if (keep[v]) new_index[v] = next++;
    }
    keep_vertices(mesh, keep, new_index);
}

void remove_vertices_by_index(TriangleMesh& mesh, const std::vector<int64_t>& indices) {
    remove_vertices_by_mask(mesh, mask_of(indices, mesh.vertices.size(), "vertex"));
}

void remove_triangles_by_mask(TriangleMesh& mesh, const std::vector<uint8_t>& mask) {
    require_one_per(mask, mesh.triangles.size(), "triangles");
    std::vector<uint8_t> keep(mask.size());
    for (size_t t = 0; t < mask.size(); ++t) keep[t] = !mask[t];
    keep_triangles(mesh, keep);
}

void remove_triangles_by_index(TriangleMesh& mesh, const std::vector<int64_t>& indices) {
    remove_triangles_by_mask(mesh, mask_of(indices, mesh.triangles.size(), "triangle"));
}

}  // namespace o3d::geometry
