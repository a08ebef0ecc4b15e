// SPDX-License-Identifier: MIT
#pragma once
/// @file io.hpp
/// @brief Reading and writing point clouds, triangle meshes, images and camera models (files and memory).
#include <cstdint>
#include <string>
#include <vector>

#include "o3d/io.h"
#include "o3dpp/camera.hpp"
#include "o3dpp/common.hpp"
#include "o3dpp/error.hpp"
#include "o3dpp/generated/options.hpp"
#include "o3dpp/image.hpp"
#include "o3dpp/pointcloud.hpp"
#include "o3dpp/trianglemesh.hpp"

namespace o3dpp {

/// @brief Read a cloud; an empty `format` means: from the extension.
inline PointCloud read_point_cloud(const std::string& path, const std::string& format = "",
                                   const ReadOptions& options = {}) {
    const o3d_read_options_t c = options.to_c();
    return PointCloud::create(&o3d_io_read_point_cloud, path.c_str(), format.c_str(), &c);
}

inline void write_point_cloud(const std::string& path, const PointCloud& cloud, const std::string& format = "",
                              const WriteOptions& options = {}) {
    const o3d_write_options_t c = options.to_c();
    check(o3d_io_write_point_cloud(path.c_str(), cloud.get(), format.c_str(), &c));
}

/// @brief Read from `size` bytes at `data`; `format` is required.
inline PointCloud read_point_cloud_from_memory(const uint8_t* data, std::size_t size, const std::string& format,
                                               const ReadOptions& options = {}) {
    const o3d_read_options_t c = options.to_c();
    return PointCloud::create(&o3d_io_read_point_cloud_from_memory, data, size, format.c_str(), &c);
}
inline PointCloud read_point_cloud_from_memory(const std::vector<uint8_t>& bytes, const std::string& format,
                                               const ReadOptions& options = {}) {
    return read_point_cloud_from_memory(bytes.data(), bytes.size(), format, options);
}
inline PointCloud read_point_cloud_from_memory(const std::string& bytes, const std::string& format,
                                               const ReadOptions& options = {}) {
    return read_point_cloud_from_memory(reinterpret_cast<const uint8_t*>(bytes.data()), bytes.size(), format,
                                        options);
}

/// @brief Encode `cloud` in `format` into a new Buffer.
inline Buffer write_point_cloud_to_memory(const PointCloud& cloud, const std::string& format,
                                          const WriteOptions& options = {}) {
    const o3d_write_options_t c = options.to_c();
    return Buffer::create(&o3d_io_write_point_cloud_to_memory, cloud.get(), format.c_str(), &c);
}

// ---- triangle meshes: "ply", "obj", "stl", "off", "gltf", "glb" ----

/// @brief Read a mesh; an empty `format` means: from the extension.
inline TriangleMesh read_triangle_mesh(const std::string& path, const std::string& format = "",
                                       const MeshReadOptions& options = {}) {
    const o3d_mesh_read_options_t c = options.to_c();
    return TriangleMesh::create(&o3d_io_read_triangle_mesh, path.c_str(), format.c_str(), &c);
}

inline void write_triangle_mesh(const std::string& path, const TriangleMesh& mesh, const std::string& format = "",
                                const MeshWriteOptions& options = {}) {
    const o3d_mesh_write_options_t c = options.to_c();
    check(o3d_io_write_triangle_mesh(path.c_str(), mesh.get(), format.c_str(), &c));
}

/// @brief Read a mesh from memory: "ply", "stl", "off", "obj" (no materials) or "glb".
inline TriangleMesh read_triangle_mesh_from_memory(const uint8_t* data, std::size_t size, const std::string& format,
                                                   const MeshReadOptions& options = {}) {
    const o3d_mesh_read_options_t c = options.to_c();
    return TriangleMesh::create(&o3d_io_read_triangle_mesh_from_memory, data, size, format.c_str(), &c);
}
inline TriangleMesh read_triangle_mesh_from_memory(const std::vector<uint8_t>& bytes, const std::string& format,
                                                   const MeshReadOptions& options = {}) {
    return read_triangle_mesh_from_memory(bytes.data(), bytes.size(), format, options);
}

/// @brief Encode `mesh` in `format` into a new Buffer.
inline Buffer write_triangle_mesh_to_memory(const TriangleMesh& mesh, const std::string& format,
                                            const MeshWriteOptions& options = {}) {
    const o3d_mesh_write_options_t c = options.to_c();
    return Buffer::create(&o3d_io_write_triangle_mesh_to_memory, mesh.get(), format.c_str(), &c);
}

// ---- images: "png", "jpg"/"jpeg", "ppm", "pgm" ----

/// @brief Read an image; an empty `format` means: from the extension.
inline Image read_image(const std::string& path, const std::string& format = "") {
    return Image::create(&o3d_io_read_image, path.c_str(), format.c_str());
}
/// @brief Write an image; `quality` is the JPEG quality 1..100 (-1: 90), ignored by other formats.
inline void write_image(const std::string& path, const Image& image, const std::string& format = "",
                        int quality = -1) {
    check(o3d_io_write_image(path.c_str(), image.get(), format.c_str(), quality));
}
inline Image read_image_from_memory(const uint8_t* data, std::size_t size, const std::string& format) {
    return Image::create(&o3d_io_read_image_from_memory, data, size, format.c_str());
}
inline Image read_image_from_memory(const std::vector<uint8_t>& bytes, const std::string& format) {
    return read_image_from_memory(bytes.data(), bytes.size(), format);
}
inline Buffer write_image_to_memory(const Image& image, const std::string& format, int quality = -1) {
    return Buffer::create(&o3d_io_write_image_to_memory, image.get(), format.c_str(), quality);
}

// ---- camera models (Open3D's JSON layouts; trajectories also as .log) ----

inline PinholeIntrinsic read_pinhole_camera_intrinsic(const std::string& path) {
    PinholeIntrinsic k;
    check(o3d_io_read_pinhole_camera_intrinsic(&k, path.c_str()));
    return k;
}
inline void write_pinhole_camera_intrinsic(const std::string& path, const PinholeIntrinsic& intrinsic) {
    check(o3d_io_write_pinhole_camera_intrinsic(path.c_str(), &intrinsic));
}
inline PinholeCameraParameters read_pinhole_camera_parameters(const std::string& path) {
    PinholeCameraParameters p;
    check(o3d_io_read_pinhole_camera_parameters(&p.intrinsic, p.extrinsic.data(), path.c_str()));
    return p;
}
inline void write_pinhole_camera_parameters(const std::string& path, const PinholeCameraParameters& parameters) {
    check(o3d_io_write_pinhole_camera_parameters(path.c_str(), &parameters.intrinsic, parameters.extrinsic.data()));
}
/// @brief Read a trajectory: "json" or "log"; empty: from the extension.
inline CameraTrajectory read_pinhole_camera_trajectory(const std::string& path, const std::string& format = "") {
    return CameraTrajectory::create(&o3d_io_read_pinhole_camera_trajectory, path.c_str(), format.c_str());
}
inline void write_pinhole_camera_trajectory(const std::string& path, const CameraTrajectory& trajectory,
                                            const std::string& format = "") {
    check(o3d_io_write_pinhole_camera_trajectory(path.c_str(), trajectory.get(), format.c_str()));
}

}  // namespace o3dpp
