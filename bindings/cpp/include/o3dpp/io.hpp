// SPDX-License-Identifier: MIT
#pragma once
/// @file io.hpp
/// @brief Reading and writing point clouds, triangle meshes, images and camera models (files and memory).
#include <cstdint>
#include <string>
#include <vector>

#include "o3d/io.h"
#include "o3dpp/common.hpp"
#include "o3dpp/error.hpp"
#include "o3dpp/camera.hpp"
#include "o3dpp/image.hpp"
#include "o3dpp/pointcloud.hpp"
#include "o3dpp/trianglemesh.hpp"

namespace o3dpp {

/// @brief o3d.io.read_point_cloud keyword arguments.
struct ReadOptions {
    bool remove_nan_points = false;
    bool remove_infinite_points = false;

    o3d_read_options_t to_c() const {
        o3d_read_options_t c;
        check(o3d_read_options_init(&c, sizeof c));
        c.remove_nan_points = remove_nan_points ? 1 : 0;
        c.remove_infinite_points = remove_infinite_points ? 1 : 0;
        return c;
    }
};

/// @brief o3d.io.write_point_cloud keyword arguments.
struct WriteOptions {
    bool write_ascii = false;
    bool compressed = false;

    o3d_write_options_t to_c() const {
        o3d_write_options_t c;
        check(o3d_write_options_init(&c, sizeof c));
        c.write_ascii = write_ascii ? 1 : 0;
        c.compressed = compressed ? 1 : 0;
        return c;
    }
};

/// @brief Read a cloud; an empty `format` means: from the extension.
inline PointCloud read_point_cloud(const std::string& path, const std::string& format = "",
                                   const ReadOptions& options = {}) {
    const o3d_read_options_t c = options.to_c();
    return PointCloud::adopt(
        [&](o3d_pointcloud_t** o) { return o3d_io_read_point_cloud(o, path.c_str(), format.c_str(), &c); });
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
    return PointCloud::adopt([&](o3d_pointcloud_t** o) {
        return o3d_io_read_point_cloud_from_memory(o, data, size, format.c_str(), &c);
    });
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
    o3d_buffer_t* b = nullptr;
    check(o3d_io_write_point_cloud_to_memory(&b, cloud.get(), format.c_str(), &c));
    return Buffer(b);
}

// ---- triangle meshes: "ply", "obj", "stl", "off", "gltf", "glb" ----

/// @brief o3d.io.read_triangle_mesh keyword arguments.
struct MeshReadOptions {
    bool enable_post_processing = false;

    o3d_mesh_read_options_t to_c() const {
        o3d_mesh_read_options_t c;
        check(o3d_mesh_read_options_init(&c, sizeof c));
        c.enable_post_processing = enable_post_processing ? 1 : 0;
        return c;
    }
};

/// @brief o3d.io.write_triangle_mesh keyword arguments.
struct MeshWriteOptions {
    bool write_ascii = false;
    bool compressed = false;  ///< accepted for Open3D compatibility; no format here compresses
    bool write_vertex_normals = true;
    bool write_vertex_colors = true;
    bool write_triangle_uvs = true;

    o3d_mesh_write_options_t to_c() const {
        o3d_mesh_write_options_t c;
        check(o3d_mesh_write_options_init(&c, sizeof c));
        c.write_ascii = write_ascii ? 1 : 0;
        c.compressed = compressed ? 1 : 0;
        c.write_vertex_normals = write_vertex_normals ? 1 : 0;
        c.write_vertex_colors = write_vertex_colors ? 1 : 0;
        c.write_triangle_uvs = write_triangle_uvs ? 1 : 0;
        return c;
    }
};

/// @brief Read a mesh; an empty `format` means: from the extension.
inline TriangleMesh read_triangle_mesh(const std::string& path, const std::string& format = "",
                                       const MeshReadOptions& options = {}) {
    const o3d_mesh_read_options_t c = options.to_c();
    return TriangleMesh::adopt(
        [&](o3d_trianglemesh_t** o) { return o3d_io_read_triangle_mesh(o, path.c_str(), format.c_str(), &c); });
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
    return TriangleMesh::adopt([&](o3d_trianglemesh_t** o) {
        return o3d_io_read_triangle_mesh_from_memory(o, data, size, format.c_str(), &c);
    });
}
inline TriangleMesh read_triangle_mesh_from_memory(const std::vector<uint8_t>& bytes, const std::string& format,
                                                   const MeshReadOptions& options = {}) {
    return read_triangle_mesh_from_memory(bytes.data(), bytes.size(), format, options);
}

/// @brief Encode `mesh` in `format` into a new Buffer.
inline Buffer write_triangle_mesh_to_memory(const TriangleMesh& mesh, const std::string& format,
                                            const MeshWriteOptions& options = {}) {
    const o3d_mesh_write_options_t c = options.to_c();
    o3d_buffer_t* b = nullptr;
    check(o3d_io_write_triangle_mesh_to_memory(&b, mesh.get(), format.c_str(), &c));
    return Buffer(b);
}

// ---- images: "png", "jpg"/"jpeg", "ppm", "pgm" ----

/// @brief Read an image; an empty `format` means: from the extension.
inline Image read_image(const std::string& path, const std::string& format = "") {
    return Image::adopt([&](o3d_image_t** o) { return o3d_io_read_image(o, path.c_str(), format.c_str()); });
}
/// @brief Write an image; `quality` is the JPEG quality 1..100 (-1: 90), ignored by other formats.
inline void write_image(const std::string& path, const Image& image, const std::string& format = "",
                        int quality = -1) {
    check(o3d_io_write_image(path.c_str(), image.get(), format.c_str(), quality));
}
inline Image read_image_from_memory(const uint8_t* data, std::size_t size, const std::string& format) {
    return Image::adopt([&](o3d_image_t** o) { return o3d_io_read_image_from_memory(o, data, size, format.c_str()); });
}
inline Image read_image_from_memory(const std::vector<uint8_t>& bytes, const std::string& format) {
    return read_image_from_memory(bytes.data(), bytes.size(), format);
}
inline Buffer write_image_to_memory(const Image& image, const std::string& format, int quality = -1) {
    o3d_buffer_t* b = nullptr;
    check(o3d_io_write_image_to_memory(&b, image.get(), format.c_str(), quality));
    return Buffer(b);
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
    o3d_camera_trajectory_t* t = nullptr;
    check(o3d_io_read_pinhole_camera_trajectory(&t, path.c_str(), format.c_str()));
    return CameraTrajectory(t);
}
inline void write_pinhole_camera_trajectory(const std::string& path, const CameraTrajectory& trajectory,
                                            const std::string& format = "") {
    check(o3d_io_write_pinhole_camera_trajectory(path.c_str(), trajectory.get(), format.c_str()));
}

}  // namespace o3dpp
