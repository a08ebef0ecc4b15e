// SPDX-License-Identifier: MIT
#pragma once
/// @file triangle_mesh_io.h
/// @brief Triangle-mesh reading and writing: PLY, OBJ (+ .mtl and textures), STL, OFF, glTF 2.0 (.gltf, .glb),
/// to files or memory. Formats use Open3D's names; "auto" (or "") picks the format from the path's extension.
/// Errors: o3d::IoError (cannot open/read/write), o3d::ParseError (malformed input, including a face index
/// outside the vertices; the message names the file or "<memory>"), o3d::Unsupported (unknown format),
/// o3d::InvalidArgument (writing a mesh whose triangles index outside its vertices).
#include <cstdint>
#include <string>
#include <vector>

#include "o3d/geometry/triangle_mesh.h"

namespace o3d::io {

struct MeshReadOptions {
    /// Merge vertices with identical coordinates, then drop triangles that repeat a vertex.
    bool enable_post_processing = false;
};

struct MeshWriteOptions {
    bool write_ascii = false;  ///< PLY and STL: text instead of binary
    bool compressed = false;   ///< accepted for Open3D compatibility; no format here compresses
    bool write_vertex_normals = true;
    bool write_vertex_colors = true;
    bool write_triangle_uvs = true;
};

geometry::TriangleMesh read_triangle_mesh(const std::string& path, const std::string& format = "auto",
                                          const MeshReadOptions& options = {});
/// @brief Formats: ply, stl, off, obj (no materials), glb and gltf (embedded data only).
geometry::TriangleMesh read_triangle_mesh_from_memory(const uint8_t* data, size_t size, const std::string& format,
                                                      const MeshReadOptions& options = {});
/// @brief OBJ also writes <stem>.mtl and the textures as <stem>_<i>.png beside the file.
void write_triangle_mesh(const std::string& path, const geometry::TriangleMesh& mesh,
                         const std::string& format = "auto", const MeshWriteOptions& options = {});
std::vector<uint8_t> write_triangle_mesh_to_memory(const geometry::TriangleMesh& mesh, const std::string& format,
                                                   const MeshWriteOptions& options = {});

}  // namespace o3d::io
