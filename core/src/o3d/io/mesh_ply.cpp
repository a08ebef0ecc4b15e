// SPDX-License-Identifier: MIT
// PLY meshes: the vertex element as for clouds, the face element fan-triangulated. Written like Open3D:
// double x y z, nx ny nz, uchar red green blue, a "list uchar uint vertex_indices" face list, plus (which
// Open3D leaves out) a "list uchar double texcoord" of the corners' UVs.
#include <cstring>
#include <string>

#include "o3d/io/mesh_io_internal.h"
#include "o3d/io/ply_format.h"
#include "o3d/io/text_writer.h"

namespace o3d::io::detail {

geometry::TriangleMesh read_mesh_ply(const Input& in) {
    geometry::TriangleMesh mesh;
    std::vector<Eigen::Vector2d> vertex_uvs;
    PlyVertexSink vs;
    vs.points = &mesh.vertices;
    vs.normals = &mesh.vertex_normals;
    vs.colors = &mesh.vertex_colors;
    vs.uvs = &vertex_uvs;
    PlyFaceSink fs;
    fs.triangles = &mesh.triangles;
    fs.corner_uvs = &mesh.triangle_uvs;
    read_ply_elements(in, vs, &fs);
    check_face_indices(in, mesh);
    if (mesh.triangle_uvs.empty() && !vertex_uvs.empty()) {
        // Per-vertex UVs become per-corner ones, the only kind a TriangleMesh holds.
        mesh.triangle_uvs.reserve(3 * mesh.triangles.size());
        for (const Eigen::Vector3i& t : mesh.triangles)
            for (int k = 0; k < 3; ++k) mesh.triangle_uvs.push_back(vertex_uvs[static_cast<size_t>(t[k])]);
    }
    return mesh;
}

std::vector<uint8_t> write_mesh_ply(const geometry::TriangleMesh& mesh, const MeshWriteOptions& options) {
    const size_t n = mesh.vertices.size();
    const size_t m = mesh.triangles.size();
    const bool normals = options.write_vertex_normals && mesh.has_vertex_normals();
    const bool colors = options.write_vertex_colors && mesh.has_vertex_colors();
    const bool uvs = options.write_triangle_uvs && mesh.has_triangle_uvs();

    std::string header = "ply\nformat ";
    header += options.write_ascii ? "ascii" : "binary_little_endian";
    header += " 1.0\ncomment Created by o3d\nelement vertex " + std::to_string(n) +
              "\nproperty double x\nproperty double y\nproperty double z\n";
    if (normals) header += "property double nx\nproperty double ny\nproperty double nz\n";
    if (colors) header += "property uchar red\nproperty uchar green\nproperty uchar blue\n";
    header += "element face " + std::to_string(m) + "\nproperty list uchar uint vertex_indices\n";
    if (uvs) header += "property list uchar double texcoord\n";
    header += "end_header\n";

    if (options.write_ascii) {
        ByteSink out(header.size() + n * (normals ? 128 : 64) + m * (uvs ? 160 : 32));
        out.put(header);
        for (size_t i = 0; i < n; ++i) {
            for (int k = 0; k < 3; ++k) {
                if (k) out.put(' ');
                out.put_number(mesh.vertices[i][k]);
            }
            if (normals)
                for (int k = 0; k < 3; ++k) {
                    out.put(' ');
                    out.put_number(mesh.vertex_normals[i][k]);
                }
            if (colors)
                for (int k = 0; k < 3; ++k) {
                    out.put(' ');
                    out.put_number(static_cast<unsigned>(color_to_u8(mesh.vertex_colors[i][k])));
                }
            out.put('\n');
        }
        for (size_t t = 0; t < m; ++t) {
            out.put('3');
            for (int k = 0; k < 3; ++k) {
                out.put(' ');
                out.put_number(mesh.triangles[t][k]);
            }
            if (uvs) {
                out.put(" 6");
                for (int k = 0; k < 3; ++k)
                    for (int c = 0; c < 2; ++c) {
                        out.put(' ');
                        out.put_number(mesh.triangle_uvs[3 * t + static_cast<size_t>(k)][c]);
                    }
            }
            out.put('\n');
        }
        return out.finish();
    }

    const size_t vrecord = 24 + (normals ? 24 : 0) + (colors ? 3 : 0);
    const size_t frecord = 13 + (uvs ? 49 : 0);
    std::vector<uint8_t> out = output_buffer(header.size() + n * vrecord + m * frecord);
    std::memcpy(out.data(), header.data(), header.size());
    uint8_t* p = out.data() + header.size();
    p = write_ply_vertex_records(p, mesh.vertices, normals ? &mesh.vertex_normals : nullptr,
                                 colors ? &mesh.vertex_colors : nullptr);
    for (size_t t = 0; t < m; ++t) {
        p[0] = 3;
        for (int k = 0; k < 3; ++k) store_le(p + 1 + 4 * k, static_cast<uint32_t>(mesh.triangles[t][k]));
        p += 13;
        if (uvs) {
            p[0] = 6;
            for (int k = 0; k < 3; ++k)
                for (int c = 0; c < 2; ++c) store_le(p + 1 + 8 * (2 * k + c), mesh.triangle_uvs[3 * t + static_cast<size_t>(k)][c]);
            p += 49;
        }
    }
    return out;
}

}  // namespace o3d::io::detail
