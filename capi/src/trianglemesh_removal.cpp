// SPDX-License-Identifier: MIT
// C API: trianglemesh.h's removal of vertices and triangles by index or mask.
#include <vector>

#include "internal.h"
#include "o3d/geometry/mesh_element_removal.h"
#include "o3d/trianglemesh.h"

using o3d::capi::guard;
using o3d::capi::require;

namespace {

template <typename T>
std::vector<T> copy_in(const T* data, size_t n, const char* name) {
    if (n > 0) require(data, name);
    return std::vector<T>(data, data + n);
}

std::vector<int64_t> widen(const std::vector<int32_t>& indices) { return {indices.begin(), indices.end()}; }

}  // namespace

extern "C" {

O3D_API o3d_status o3d_trianglemesh_remove_vertices_by_index(o3d_trianglemesh_t* mesh, const int32_t* indices,
                                                             size_t num_indices) {
    return guard(__func__, [&] {
        auto& m = require(mesh, "mesh")->mesh;
        o3d::geometry::remove_vertices_by_index(m, widen(copy_in(indices, num_indices, "indices")));
    });
}

O3D_API o3d_status o3d_trianglemesh_remove_vertices_by_mask(o3d_trianglemesh_t* mesh, const uint8_t* mask,
                                                            size_t num_mask) {
    return guard(__func__, [&] {
        auto& m = require(mesh, "mesh")->mesh;
        o3d::geometry::remove_vertices_by_mask(m, copy_in(mask, num_mask, "mask"));
    });
}

O3D_API o3d_status o3d_trianglemesh_remove_triangles_by_index(o3d_trianglemesh_t* mesh, const int32_t* indices,
                                                              size_t num_indices) {
    return guard(__func__, [&] {
        auto& m = require(mesh, "mesh")->mesh;
        o3d::geometry::remove_triangles_by_index(m, widen(copy_in(indices, num_indices, "indices")));
    });
}

O3D_API o3d_status o3d_trianglemesh_remove_triangles_by_mask(o3d_trianglemesh_t* mesh, const uint8_t* mask,
                                                             size_t num_mask) {
    return guard(__func__, [&] {
        auto& m = require(mesh, "mesh")->mesh;
        o3d::geometry::remove_triangles_by_mask(m, copy_in(mask, num_mask, "mask"));
    });
}

}  // extern "C"
