// SPDX-License-Identifier: MIT
// C API: tetramesh.h (the TetraMesh container, its Delaunay constructor and iso-surface extraction).
#include <memory>
#include <string>
#include <vector>

#include "array_family.h"
#include "internal.h"
#include "o3d/geometry/tetra_mesh.h"
#include "o3d/tetramesh.h"

using o3d::capi::guard;
using o3d::capi::require;
using o3d::geometry::TetraMesh;

namespace {

TetraMesh& tetras_of(o3d_tetramesh_t* t, const char* name = "tetramesh") { return require(t, name)->mesh; }
const TetraMesh& tetras_of(const o3d_tetramesh_t* t, const char* name = "tetramesh") {
    return require(t, name)->mesh;
}

o3d::capi::ArraySlot<double> tetramesh_slot(o3d_tetramesh_t* h, int32_t which) {
    TetraMesh& t = tetras_of(h);
    if (which != O3D_TETRAMESH_VERTICES) o3d::capi::bad_which(which, "a float64 tetra-mesh array (O3D_TETRAMESH_VERTICES)");
    return o3d::capi::eigen_slot(t.vertices, !t.vertices.empty());
}

o3d::capi::ArraySlot<int32_t> tetramesh_index_slot(o3d_tetramesh_t* h, int32_t which) {
    TetraMesh& t = tetras_of(h);
    if (which != O3D_TETRAMESH_TETRAS) o3d::capi::bad_which(which, "an int32 tetra-mesh array (O3D_TETRAMESH_TETRAS)");
    return o3d::capi::eigen_slot(t.tetras, !t.vertices.empty() && !t.tetras.empty());
}

template <typename Handle>
Handle** require_out(Handle** out) {
    require(out, "out");
    *out = nullptr;
    return out;
}

void give(o3d_tetramesh_t** out, TetraMesh mesh) {
    auto handle = std::make_unique<o3d_tetramesh>();
    handle->mesh = std::move(mesh);
    *out = handle.release();
}

}  // namespace

extern "C" {

O3D_CAPI_ARRAYS_F64(tetramesh, o3d_tetramesh_t, tetramesh_slot)
O3D_CAPI_ARRAY_QUERIES(tetramesh, o3d_tetramesh_t, tetramesh_slot, tetramesh_index_slot)
O3D_CAPI_INDEX_ARRAYS(tetramesh, o3d_tetramesh_t, tetramesh_index_slot)

O3D_API o3d_status o3d_tetramesh_create(o3d_tetramesh_t** out) {
    return guard(__func__, [&] { give(require_out(out), TetraMesh{}); });
}

O3D_API void o3d_tetramesh_destroy(o3d_tetramesh_t* tetramesh) { delete tetramesh; }

O3D_API o3d_status o3d_tetramesh_clone(o3d_tetramesh_t** out, const o3d_tetramesh_t* src) {
    return guard(__func__, [&] {
        require_out(out);
        give(out, tetras_of(src, "src"));
    });
}

O3D_API o3d_status o3d_tetramesh_num_vertices(size_t* out_n, const o3d_tetramesh_t* tetramesh) {
    return guard(__func__, [&] { *require(out_n, "out_n") = tetras_of(tetramesh).vertices.size(); });
}

O3D_API o3d_status o3d_tetramesh_num_tetras(size_t* out_n, const o3d_tetramesh_t* tetramesh) {
    return guard(__func__, [&] { *require(out_n, "out_n") = tetras_of(tetramesh).tetras.size(); });
}

O3D_API o3d_status o3d_tetramesh_create_from_point_cloud(o3d_tetramesh_t** out, int32_t* out_point_map,
                                                         size_t capacity, size_t* out_n, const o3d_pointcloud_t* pc) {
    return guard(__func__, [&] {
        require_out(out);
        if (out_point_map) require(out_n, "out_n");
        auto made = o3d::geometry::create_tetra_mesh_from_points(require(pc, "pc")->cloud.points);
        // Indices first, so BUFFER_TOO_SMALL leaves *out NULL.
        const std::vector<int32_t> map(made.point_map.begin(), made.point_map.end());
        o3d::capi::copy_out(map.data(), map.size(), out_point_map, capacity, out_n);
        give(out, std::move(made.mesh));
    });
}

O3D_API o3d_status o3d_tetramesh_extract_triangle_mesh(o3d_trianglemesh_t** out, const o3d_tetramesh_t* tetramesh,
                                                       const double* values, size_t num_values, double level) {
    return guard(__func__, [&] {
        require_out(out);
        const TetraMesh& t = tetras_of(tetramesh);
        if (num_values > 0) require(values, "values");
        auto handle = std::make_unique<o3d_trianglemesh>();
        handle->mesh = o3d::geometry::extract_triangle_mesh(t, std::vector<double>(values, values + num_values), level);
        *out = handle.release();
    });
}

}  // extern "C"
