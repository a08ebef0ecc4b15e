// SPDX-License-Identifier: MIT
// Mesh format dispatch, file <-> memory, the checks every reader shares, and the read post-processing.
#include "o3d/io/triangle_mesh_io.h"

#include <Eigen/Geometry>
#include <cstring>
#include <string_view>
#include <unordered_map>

#include "o3d/geometry/triangle_mesh_basics.h"
#include "o3d/io/file_bytes.h"
#include "o3d/io/mesh_io_internal.h"
#include "o3d/utility/error.h"
#include "o3d/io/format_dispatch.h"

namespace o3d::io {
namespace detail {

void check_face_indices(const Input& in, const geometry::TriangleMesh& mesh) {
    const int64_t n = static_cast<int64_t>(mesh.vertices.size());
    for (size_t t = 0; t < mesh.triangles.size(); ++t)
        for (int k = 0; k < 3; ++k) {
            const int v = mesh.triangles[t][k];
            if (v < 0 || v >= n)
                parse_error(in, "triangle " + std::to_string(t) + " has the vertex index " + std::to_string(v) +
                                    ", outside the " + std::to_string(n) + " vertices");
        }
}

std::vector<Eigen::Vector3d> facet_normals(const geometry::TriangleMesh& mesh) {
    if (mesh.has_triangle_normals()) return mesh.triangle_normals;
    std::vector<Eigen::Vector3d> out(mesh.triangles.size());
    for (size_t t = 0; t < out.size(); ++t) {
        const Eigen::Vector3d c = geometry::triangle_cross(mesh, t);
        const double len = c.norm();
        out[t] = len > 0 ? Eigen::Vector3d(c / len) : Eigen::Vector3d::Zero();
    }
    return out;
}

}  // namespace detail

namespace {

enum class Format { Ply, Obj, Stl, Off, Gltf, Glb };

constexpr detail::FormatName<Format> kFormats[] = {
    {"ply", Format::Ply}, {"obj", Format::Obj}, {"stl", Format::Stl}, {"off", Format::Off}, {"gltf", Format::Gltf},
    {"glb", Format::Glb}};

Format resolve(const std::string& format, const std::string* path) {
    return detail::resolve_format(kFormats, "triangle-mesh", format, path);
}

geometry::TriangleMesh parse(Format f, const detail::Input& in, const detail::Sidecars& sidecars) {
    switch (f) {
        case Format::Ply: return detail::read_mesh_ply(in);
        case Format::Obj: return detail::read_mesh_obj(in, sidecars);
        case Format::Stl: return detail::read_mesh_stl(in);
        case Format::Off: return detail::read_mesh_off(in);
        case Format::Gltf: return detail::read_mesh_gltf(in, sidecars, false);
        case Format::Glb: return detail::read_mesh_gltf(in, sidecars, true);
    }
    throw Unsupported("unknown triangle-mesh format");
}

std::vector<uint8_t> encode(Format f, const geometry::TriangleMesh& mesh, const MeshWriteOptions& options) {
    switch (f) {
        case Format::Ply: return detail::write_mesh_ply(mesh, options);
        case Format::Obj: return detail::write_mesh_obj(mesh, options);
        case Format::Stl: return detail::write_mesh_stl(mesh, options);
        case Format::Off: return detail::write_mesh_off(mesh, options);
        case Format::Gltf: return detail::write_mesh_gltf(mesh, options, false);
        case Format::Glb: return detail::write_mesh_gltf(mesh, options, true);
    }
    throw Unsupported("unknown triangle-mesh format");
}

struct VertexKey {
    double x, y, z;
    bool operator==(const VertexKey& o) const { return x == o.x && y == o.y && z == o.z; }
};
struct VertexKeyHash {
    size_t operator()(const VertexKey& k) const {
        // +0.0 folds -0.0 into 0.0, which compares equal.
        const double v[3] = {k.x + 0.0, k.y + 0.0, k.z + 0.0};
        size_t h = 0;
        for (double d : v) {
            uint64_t b;
            std::memcpy(&b, &d, sizeof b);
            h = (h ^ b) * 0x100000001b3ull + (h >> 17);
        }
        return h;
    }
};

/// @brief Merge vertices with identical coordinates (the first one's normal and colour stay), then drop
/// triangles that name a vertex twice (with their normals, UVs and material ids).
void post_process(geometry::TriangleMesh& mesh) {
    const bool normals = mesh.has_vertex_normals();
    const bool colors = mesh.has_vertex_colors();
    std::unordered_map<VertexKey, int, VertexKeyHash> first;
    first.reserve(mesh.vertices.size());
    std::vector<int> remap(mesh.vertices.size());
    size_t kept = 0;
    for (size_t i = 0; i < mesh.vertices.size(); ++i) {
        const Eigen::Vector3d& p = mesh.vertices[i];
        const auto [it, fresh] = first.try_emplace(VertexKey{p.x(), p.y(), p.z()}, static_cast<int>(kept));
        remap[i] = it->second;
        if (!fresh) continue;
        mesh.vertices[kept] = p;
        if (normals) mesh.vertex_normals[kept] = mesh.vertex_normals[i];
        if (colors) mesh.vertex_colors[kept] = mesh.vertex_colors[i];
        ++kept;
    }
    mesh.vertices.resize(kept);
    if (normals) mesh.vertex_normals.resize(kept);
    if (colors) mesh.vertex_colors.resize(kept);

    const bool tri_normals = mesh.has_triangle_normals();
    const bool uvs = mesh.has_triangle_uvs();
    const bool ids = mesh.has_triangle_material_ids();
    size_t out = 0;
    for (size_t t = 0; t < mesh.triangles.size(); ++t) {
        Eigen::Vector3i tri = mesh.triangles[t];
        for (int k = 0; k < 3; ++k) tri[k] = remap[static_cast<size_t>(tri[k])];
        if (tri[0] == tri[1] || tri[1] == tri[2] || tri[0] == tri[2]) continue;
        mesh.triangles[out] = tri;
        if (tri_normals) mesh.triangle_normals[out] = mesh.triangle_normals[t];
        if (uvs)
            for (size_t c = 0; c < 3; ++c) mesh.triangle_uvs[3 * out + c] = mesh.triangle_uvs[3 * t + c];
        if (ids) mesh.triangle_material_ids[out] = mesh.triangle_material_ids[t];
        ++out;
    }
    mesh.triangles.resize(out);
    if (tri_normals) mesh.triangle_normals.resize(out);
    if (uvs) mesh.triangle_uvs.resize(3 * out);
    if (ids) mesh.triangle_material_ids.resize(out);
}

geometry::TriangleMesh finish(geometry::TriangleMesh mesh, const MeshReadOptions& options) {
    if (options.enable_post_processing) post_process(mesh);
    return mesh;
}

std::string directory_of(const std::string& path) {
    const size_t slash = path.find_last_of('/');
    return slash == std::string::npos ? std::string() : path.substr(0, slash + 1);
}

}  // namespace

geometry::TriangleMesh read_triangle_mesh(const std::string& path, const std::string& format,
                                          const MeshReadOptions& options) {
    const Format f = resolve(format, &path);
    const detail::FileBytes bytes(path);
    static const uint8_t kEmpty = 0;
    const detail::Input in{bytes.size() ? bytes.data() : &kEmpty, bytes.size(), path};
    detail::Sidecars sidecars;
    sidecars.from_file = true;
    sidecars.directory = directory_of(path);
    return finish(parse(f, in, sidecars), options);
}

geometry::TriangleMesh read_triangle_mesh_from_memory(const uint8_t* data, size_t size, const std::string& format,
                                                      const MeshReadOptions& options) {
    const Format f = resolve(format, nullptr);
    if (!data && size) throw InvalidArgument("data is NULL but size is " + std::to_string(size));
    static const uint8_t kEmpty = 0;
    static const std::string kMemory = "<memory>";
    const detail::Input in{data ? data : &kEmpty, data ? size : 0, kMemory};
    return finish(parse(f, in, detail::Sidecars{}), options);
}

void write_triangle_mesh(const std::string& path, const geometry::TriangleMesh& mesh, const std::string& format,
                         const MeshWriteOptions& options) {
    const Format f = resolve(format, &path);
    geometry::validate_triangles(mesh);
    if (f == Format::Obj) {
        detail::write_mesh_obj_files(path, mesh, options);
        return;
    }
    detail::write_file(path, encode(f, mesh, options));
}

std::vector<uint8_t> write_triangle_mesh_to_memory(const geometry::TriangleMesh& mesh, const std::string& format,
                                                   const MeshWriteOptions& options) {
    const Format f = resolve(format, nullptr);
    geometry::validate_triangles(mesh);
    return encode(f, mesh, options);
}

}  // namespace o3d::io
