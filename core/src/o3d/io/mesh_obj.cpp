// SPDX-License-Identifier: MIT
// Wavefront OBJ reading, mapped onto a TriangleMesh as Open3D does: one vertex per 'v' (with its colour when
// every 'v' has one), a 'vn' per vertex (the last one a corner names wins), UVs per triangle corner, a material
// id per triangle, one texture per material (its map_Kd image, flipped vertically; empty without one).
// The geometry is parsed here in one pass (the benchmark's 11 MB file in a fraction of tinyobjloader's time,
// and every number and index checked); the .mtl material libraries go through tinyobjloader's LoadMtl.
// Polygons are fan-triangulated. Lines other than v, vn, vt, f, usemtl and mtllib (o, g, s, l, p, ...) are
// ignored.
#include <tiny_obj_loader.h>

#include <charconv>
#include <fstream>
#include <map>
#include <string>
#include <string_view>

#include "o3d/io/byte_reader.h"
#include "o3d/io/image_io.h"
#include "o3d/io/mesh_io_internal.h"
#include "o3d/utility/logging.h"

namespace o3d::io::detail {
namespace {

/// @brief One face corner as written: 1-based or negative (relative) indices, 0 = absent.
struct Corner {
    int64_t v = 0, vt = 0, vn = 0;
};

class ObjReader {
public:
    ObjReader(const Input& in, const Sidecars& sidecars) : in_(in), sidecars_(sidecars) {}

    geometry::TriangleMesh read() {
        const char* p = in_.chars();
        const char* const end = in_.chars_end();
        while (p < end) {
            ++line_no_;
            const char* nl = static_cast<const char*>(std::memchr(p, '\n', static_cast<size_t>(end - p)));
            const char* eol = nl ? nl : end;
            line(p, eol);
            p = nl ? nl + 1 : end;
        }
        return finish();
    }

private:
    [[noreturn]] void fail(const std::string& why) {
        parse_error(in_, "OBJ line " + std::to_string(line_no_) + ": " + why);
    }

    static const char* skip_blanks(const char* p, const char* e) {
        while (p < e && is_blank(*p)) ++p;
        return p;
    }

    /// @brief Parse up to `max` numbers separated by blanks into `out`; returns how many.
    int numbers(const char* p, const char* e, double* out, int max) {
        int n = 0;
        for (p = skip_blanks(p, e); p < e; p = skip_blanks(p, e)) {
            if (n == max) fail("too many numbers");
            const char* s = p;
            if (*p == '+') ++p;
            double v;
            const auto [q, ec] = std::from_chars(p, e, v);
            if (ec != std::errc() || (q < e && !is_blank(*q))) {
                const char* t = s;
                while (t < e && !is_blank(*t)) ++t;
                fail("'" + std::string(s, static_cast<size_t>(std::min<ptrdiff_t>(t - s, 32))) + "' is not a number");
            }
            out[n++] = v;
            p = q;
        }
        return n;
    }

    void line(const char* p, const char* e) {
        p = skip_blanks(p, e);
        if (p == e || *p == '#') return;
        const char* k = p;
        while (p < e && !is_blank(*p)) ++p;
        const std::string_view kw(k, static_cast<size_t>(p - k));
        if (kw == "v") {
            double x[7];
            const int n = numbers(p, e, x, 7);
            if (n < 3) fail("'v' needs 3 numbers, has " + std::to_string(n));
            vertices_.emplace_back(x[0], x[1], x[2]);
            if (n >= 6) colors_.emplace_back(x[3], x[4], x[5]);
        } else if (kw == "vn") {
            double x[3];
            const int n = numbers(p, e, x, 3);
            if (n < 3) fail("'vn' needs 3 numbers, has " + std::to_string(n));
            normals_.emplace_back(x[0], x[1], x[2]);
        } else if (kw == "vt") {
            double x[3] = {0, 0, 0};
            const int n = numbers(p, e, x, 3);
            if (n < 1) fail("'vt' needs 1 numbers, has 0");
            texcoords_.emplace_back(x[0], x[1]);
        } else if (kw == "f") {
            face(p, e);
        } else if (kw == "usemtl") {
            const std::string name = trimmed(p, e);
            const auto it = material_ids_.find(name);
            material_ = it == material_ids_.end() ? -1 : it->second;
        } else if (kw == "mtllib") {
            load_materials(trimmed(p, e));
        }
    }

    static std::string trimmed(const char* p, const char* e) {
        p = skip_blanks(p, e);
        while (e > p && is_blank(e[-1])) --e;
        return std::string(p, static_cast<size_t>(e - p));
    }

    /// @brief A 1-based (or negative, relative) index; false when the text is not one.
    static bool index(const char*& p, const char* e, int64_t& out) {
        bool negative = false;
        if (p < e && (*p == '-' || *p == '+')) negative = *p++ == '-';
        const char* s = p;
        int64_t v = 0;
        while (p < e && *p >= '0' && *p <= '9' && p - s < 11) v = 10 * v + (*p++ - '0');
        if (p == s || v == 0 || v > INT32_MAX) return false;
        out = negative ? -v : v;
        return true;
    }

    /// @brief Resolve a corner index against the `count` items defined so far (negative ones count back).
    int64_t resolve(int64_t i, size_t count) const { return i < 0 ? static_cast<int64_t>(count) + i : i - 1; }

    void face(const char* p, const char* e) {
        corners_.clear();
        for (p = skip_blanks(p, e); p < e; p = skip_blanks(p, e)) {
            const char* s = p;
            Corner c;
            bool ok = index(p, e, c.v);
            if (ok && p < e && *p == '/') {
                ++p;
                if (p < e && *p != '/') ok = index(p, e, c.vt);
                if (ok && p < e && *p == '/') {
                    ++p;
                    ok = index(p, e, c.vn);
                }
            }
            if (!ok || (p < e && !is_blank(*p))) {
                while (p < e && !is_blank(*p)) ++p;
                fail("bad face corner '" + std::string(s, static_cast<size_t>(std::min<ptrdiff_t>(p - s, 32))) + "'");
            }
            c.v = resolve(c.v, vertices_.size());
            if (c.v < 0) fail("a face names a vertex outside the " + std::to_string(vertices_.size()) + " defined");
            if (c.vt) {
                c.vt = resolve(c.vt, texcoords_.size());
                if (c.vt < 0 || static_cast<size_t>(c.vt) >= texcoords_.size())
                    fail("a face names a texture coordinate outside the " + std::to_string(texcoords_.size()) +
                         " defined");
                any_uv_ = true;
            } else {
                c.vt = -1;
            }
            if (c.vn) {
                c.vn = resolve(c.vn, normals_.size());
                if (c.vn < 0 || static_cast<size_t>(c.vn) >= normals_.size())
                    fail("a face names a normal outside the " + std::to_string(normals_.size()) + " defined");
            } else {
                c.vn = -1;
            }
            corners_.push_back(c);
        }
        if (corners_.size() < 3) fail("a face needs 3 corners, has " + std::to_string(corners_.size()));
        fan_triangulate(corners_.size(), [&](size_t a, size_t b, size_t c) {
            for (size_t k : {a, b, c}) face_corners_.push_back(corners_[k]);
            face_materials_.push_back(material_);
        });
    }

    void load_materials(const std::string& name) {
        if (!sidecars_.from_file || name.empty()) return;
        std::ifstream f(sidecars_.directory + name, std::ios::binary);
        if (!f) {
            utility::log_warning(in_.name + ": OBJ: material library '" + name + "' not found beside the file");
            return;
        }
        std::map<std::string, int> ids;
        std::vector<tinyobj::material_t> loaded;
        std::string warn;
        tinyobj::LoadMtl(&ids, &loaded, &f, &warn, nullptr);
        for (const auto& [n, id] : ids)
            if (id >= 0 && static_cast<size_t>(id) < loaded.size())
                material_ids_.emplace(n, static_cast<int>(materials_.size()) + id);
        materials_.insert(materials_.end(), loaded.begin(), loaded.end());
    }

    geometry::TriangleMesh finish() {
        const size_t nv = vertices_.size();
        if (nv > static_cast<size_t>(INT32_MAX)) parse_error(in_, "OBJ: more vertices than a mesh can index");
        geometry::TriangleMesh mesh;
        const size_t nt = face_corners_.size() / 3;
        mesh.triangles.resize(nt);
        if (!normals_.empty()) mesh.vertex_normals.assign(nv, Eigen::Vector3d::Zero());
        if (any_uv_) mesh.triangle_uvs.resize(3 * nt);
        for (size_t t = 0; t < nt; ++t)
            for (int k = 0; k < 3; ++k) {
                const Corner& c = face_corners_[3 * t + static_cast<size_t>(k)];
                // Positive indices may name vertices defined later in the file: checked now.
                if (static_cast<size_t>(c.v) >= nv)
                    parse_error(in_, "OBJ: triangle " + std::to_string(t) + " names a vertex outside the " +
                                         std::to_string(nv) + " defined");
                mesh.triangles[t][k] = static_cast<int>(c.v);
                if (c.vn >= 0) mesh.vertex_normals[static_cast<size_t>(c.v)] = normals_[static_cast<size_t>(c.vn)];
                if (any_uv_)
                    mesh.triangle_uvs[3 * t + static_cast<size_t>(k)] =
                        c.vt >= 0 ? texcoords_[static_cast<size_t>(c.vt)] : Eigen::Vector2d::Zero();
            }
        if (!materials_.empty()) mesh.triangle_material_ids = std::move(face_materials_);
        if (colors_.size() == nv && nv > 0) mesh.vertex_colors = std::move(colors_);
        mesh.vertices = std::move(vertices_);

        bool any_texture = false;
        for (const auto& m : materials_) any_texture |= !m.diffuse_texname.empty();
        if (any_texture)
            for (const auto& m : materials_)
                mesh.textures.push_back(m.diffuse_texname.empty() ? geometry::Image()
                                                                  : load_texture(sidecars_.directory + m.diffuse_texname));
        return mesh;
    }

    geometry::Image load_texture(const std::string& path) {
        try {
            return flipped_vertically(read_image(path));
        } catch (const std::exception& e) {
            // A missing or broken texture does not make the geometry unreadable.
            utility::log_warning(in_.name + ": OBJ: texture not read: " + std::string(e.what()));
            return geometry::Image();
        }
    }

    const Input& in_;
    const Sidecars& sidecars_;
    size_t line_no_ = 0;
    std::vector<Eigen::Vector3d> vertices_, colors_, normals_;
    std::vector<Eigen::Vector2d> texcoords_;
    std::vector<Corner> corners_, face_corners_;
    std::vector<int> face_materials_;
    std::vector<tinyobj::material_t> materials_;
    std::map<std::string, int> material_ids_;
    int material_ = -1;
    bool any_uv_ = false;
};

}  // namespace

geometry::TriangleMesh read_mesh_obj(const Input& in, const Sidecars& sidecars) { return ObjReader(in, sidecars).read(); }

}  // namespace o3d::io::detail
