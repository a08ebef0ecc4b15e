// SPDX-License-Identifier: MIT
#pragma once
/// @file mesh_io_internal.h
/// @brief The per-format mesh readers and writers the dispatcher (triangle_mesh_io.cpp) calls, and what
/// they share: triangulating polygons, checking face indices, per-facet normals.
#include <cstdint>
#include <string>
#include <vector>

#include "o3d/geometry/triangle_mesh.h"
#include "o3d/io/io_internal.h"
#include "o3d/io/triangle_mesh_io.h"

namespace o3d::io::detail {

/// @brief Where a reader may look for the files an input refers to (OBJ's .mtl and textures, glTF's
/// buffers). `directory` is empty for memory input, which must then be self-contained.
struct Sidecars {
    bool from_file = false;
    std::string directory;  ///< with a trailing '/', or "" for the current directory
};

geometry::TriangleMesh read_mesh_ply(const Input& in);
geometry::TriangleMesh read_mesh_stl(const Input& in);
geometry::TriangleMesh read_mesh_off(const Input& in);
geometry::TriangleMesh read_mesh_obj(const Input& in, const Sidecars& sidecars);
geometry::TriangleMesh read_mesh_gltf(const Input& in, const Sidecars& sidecars, bool binary);

std::vector<uint8_t> write_mesh_ply(const geometry::TriangleMesh& mesh, const MeshWriteOptions& options);
std::vector<uint8_t> write_mesh_stl(const geometry::TriangleMesh& mesh, const MeshWriteOptions& options);
std::vector<uint8_t> write_mesh_off(const geometry::TriangleMesh& mesh, const MeshWriteOptions& options);
std::vector<uint8_t> write_mesh_gltf(const geometry::TriangleMesh& mesh, const MeshWriteOptions& options, bool binary);

/// @brief OBJ text without a material library (memory output).
std::vector<uint8_t> write_mesh_obj(const geometry::TriangleMesh& mesh, const MeshWriteOptions& options);
/// @brief OBJ file plus <stem>.mtl and the textures as <stem>_<i>.png beside it.
void write_mesh_obj_files(const std::string& path, const geometry::TriangleMesh& mesh,
                          const MeshWriteOptions& options);

/// @brief The image upside down (OBJ textures: Open3D stores them flipped relative to the file).
geometry::Image flipped_vertically(const geometry::Image& image);

/// @brief Append the fan (c0, ci, ci+1) of a polygon with `n` >= 3 corners, by corner position.
template <typename Emit>
inline void fan_triangulate(size_t n, Emit&& emit) {
    for (size_t i = 1; i + 1 < n; ++i) emit(size_t{0}, i, i + 1);
}

/// @brief ParseError naming the first triangle with an index outside [0, vertices).
void check_face_indices(const Input& in, const geometry::TriangleMesh& mesh);

/// @brief Unit normal of each triangle (zero for a degenerate one); the mesh's own when it has them.
std::vector<Eigen::Vector3d> facet_normals(const geometry::TriangleMesh& mesh);

}  // namespace o3d::io::detail
