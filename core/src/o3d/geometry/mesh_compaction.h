// SPDX-License-Identifier: MIT
#pragma once
/// @file mesh_compaction.h
/// @brief Keeping a flagged subset of a mesh's vertices or triangles with the attributes that go with them: the one
/// place every removal (clean-up, removal by index or mask) compacts the arrays, so none forgets an attribute.
#include <cstdint>
#include <vector>

#include "o3d/geometry/triangle_mesh.h"

namespace o3d::geometry {

/// @brief Keep the items flagged in `keep` (`rows_per_item` rows each), in order; an array whose size does not
/// match (an absent attribute) is left alone.
template <typename T>
void compact(std::vector<T>& values, const std::vector<uint8_t>& keep, size_t rows_per_item = 1) {
    if (values.size() != keep.size() * rows_per_item) return;
    size_t k = 0;
    for (size_t i = 0; i < keep.size(); ++i) {
        if (!keep[i]) continue;
        for (size_t r = 0; r < rows_per_item; ++r) values[k * rows_per_item + r] = values[i * rows_per_item + r];
        ++k;
    }
    values.resize(k * rows_per_item);
}

/// @brief Keep the triangles flagged in `keep`, with their normals, UVs and material ids.
void keep_triangles(TriangleMesh& mesh, const std::vector<uint8_t>& keep);

/// @brief Keep the vertices flagged in `keep` (with normals and colors) and renumber the triangles through
/// `new_index` (old vertex -> new vertex, valid for every vertex a triangle uses).
void keep_vertices(TriangleMesh& mesh, const std::vector<uint8_t>& keep, const std::vector<int>& new_index);

}  // namespace o3d::geometry
