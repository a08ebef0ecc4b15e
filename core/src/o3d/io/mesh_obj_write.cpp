// SPDX-License-Identifier: MIT
// Wavefront OBJ writing: v (with colours), vn, vt per triangle corner, f, and for files a .mtl with one
// material per texture, each texture written as PNG beside the OBJ (flipped vertically as Open3D does).
#include <algorithm>
#include <cstring>
#include <string>

#include "o3d/io/file_bytes.h"
#include "o3d/io/image_io.h"
#include "o3d/io/mesh_io_internal.h"
#include "o3d/io/text_writer.h"

namespace o3d::io::detail {

geometry::Image flipped_vertically(const geometry::Image& image) {
    geometry::Image out = image;
    const size_t row = image.bytes_per_line();
    if (image.data.size() < row * size_t(std::max(image.height, 0))) return out;
    for (int y = 0; y < image.height; ++y)
        std::memcpy(out.data.data() + size_t(y) * row, image.data.data() + size_t(image.height - 1 - y) * row, row);
    return out;
}

namespace {

std::vector<uint8_t> obj_text(const geometry::TriangleMesh& mesh, const MeshWriteOptions& options,
                              const std::string& stem) {
    const bool normals = options.write_vertex_normals && mesh.has_vertex_normals();
    const bool colors = options.write_vertex_colors && mesh.has_vertex_colors();
    const bool uvs = options.write_triangle_uvs && mesh.has_triangle_uvs();
    const bool ids = mesh.has_triangle_material_ids();
    ByteSink out(128 + mesh.vertices.size() * 128 + mesh.triangles.size() * (uvs ? 160 : 48));
    out.put("# Created by o3d\n");
    if (!stem.empty()) out.put("mtllib " + stem + ".mtl\n");
    for (size_t i = 0; i < mesh.vertices.size(); ++i) {
        out.put('v');
        for (int k = 0; k < 3; ++k) {
            out.put(' ');
            out.put_number(mesh.vertices[i][k]);
        }
        if (colors)
            for (int k = 0; k < 3; ++k) {
                out.put(' ');
                out.put_number(mesh.vertex_colors[i][k]);
            }
        out.put('\n');
        if (normals) {
            out.put("vn");
            for (int k = 0; k < 3; ++k) {
                out.put(' ');
                out.put_number(mesh.vertex_normals[i][k]);
            }
            out.put('\n');
        }
    }
    if (uvs)
        for (const Eigen::Vector2d& uv : mesh.triangle_uvs) {
            out.put("vt ");
            out.put_number(uv[0]);
            out.put(' ');
            out.put_number(uv[1]);
            out.put('\n');
        }
    int current = -2;
    for (size_t t = 0; t < mesh.triangles.size(); ++t) {
        const int id = ids ? mesh.triangle_material_ids[t] : 0;
        if (!stem.empty() && id != current && id >= 0) {
            out.put("usemtl " + stem + "_" + std::to_string(id) + "\n");
            current = id;
        }
        out.put('f');
        for (int c = 0; c < 3; ++c) {
            const long v = static_cast<long>(mesh.triangles[t][c]) + 1;
            out.put(' ');
            out.put_number(v);
            if (uvs || normals) out.put('/');
            if (uvs) out.put_number(static_cast<long>(3 * t) + c + 1);
            if (normals) {
                out.put('/');
                out.put_number(v);
            }
        }
        out.put('\n');
    }
    return out.finish();
}

std::string file_name(const std::string& path) {
    const size_t slash = path.find_last_of('/');
    return slash == std::string::npos ? path : path.substr(slash + 1);
}

}  // namespace

std::vector<uint8_t> write_mesh_obj(const geometry::TriangleMesh& mesh, const MeshWriteOptions& options) {
    return obj_text(mesh, options, "");
}

void write_mesh_obj_files(const std::string& path, const geometry::TriangleMesh& mesh,
                          const MeshWriteOptions& options) {
    const std::string name = file_name(path);
    const std::string dir = path.substr(0, path.size() - name.size());
    const size_t dot = name.find_last_of('.');
    const std::string stem = dot == std::string::npos || dot == 0 ? name : name.substr(0, dot);
    write_file(path, obj_text(mesh, options, stem));

    // One material per texture (at least one), named <stem>_<i> as the usemtl lines say.
    const size_t n_materials = std::max<size_t>(1, mesh.textures.size());
    ByteSink mtl(256 * n_materials);
    mtl.put("# Created by o3d\n");
    for (size_t i = 0; i < n_materials; ++i) {
        mtl.put("newmtl " + stem + "_" + std::to_string(i) + "\nKa 1 1 1\nKd 1 1 1\nKs 0 0 0\n");
        if (i < mesh.textures.size() && !mesh.textures[i].empty()) {
            const std::string texture = stem + "_" + std::to_string(i) + ".png";
            write_image(dir + texture, flipped_vertically(mesh.textures[i]), "png");
            mtl.put("map_Kd " + texture + "\n");
        }
    }
    write_file(dir + stem + ".mtl", mtl.finish());
}

}  // namespace o3d::io::detail
