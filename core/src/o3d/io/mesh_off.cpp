// SPDX-License-Identifier: MIT
// OFF (Object File Format) and its variants [ST][C][N][4]OFF: "N" adds vertex normals, "C" vertex colours
// (integers 0..255 or reals 0..1, an optional alpha ignored), "ST" texture coordinates (read, not kept).
// '#' starts a comment. Faces "n i0 .. in-1 [colour]" are fan-triangulated; a face colour is skipped.
#include <string>
#include <string_view>

#include "o3d/io/byte_reader.h"
#include "o3d/io/mesh_io_internal.h"
#include "o3d/io/text_writer.h"

namespace o3d::io::detail {
namespace {

/// @brief Tokens of an OFF file: whitespace-separated, '#' comments skipped, lines visible.
class OffCursor {
public:
    explicit OffCursor(const Input& in) : p_(in.chars()), end_(in.chars_end()) {}

    /// @brief Next token on any line; empty at the end of the text.
    std::string_view token() {
        skip(true);
        return take();
    }
    /// @brief Next token on the current line; empty at its end.
    std::string_view token_on_line() {
        skip(false);
        return take();
    }
    void skip_line() {
        while (p_ < end_ && *p_ != '\n') ++p_;
    }
    size_t remaining() const { return static_cast<size_t>(end_ - p_); }
    size_t offset(const Input& in) const { return static_cast<size_t>(p_ - in.chars()); }

private:
    void skip(bool cross_lines) {
        while (p_ < end_) {
            if (*p_ == '#') {
                while (p_ < end_ && *p_ != '\n') ++p_;
            } else if (*p_ == '\n' ? cross_lines : is_space(*p_)) {
                ++p_;
            } else {
                break;
            }
        }
    }
    std::string_view take() {
        const char* s = p_;
        while (p_ < end_ && !is_space(*p_) && *p_ != '#') ++p_;
        return {s, static_cast<size_t>(p_ - s)};
    }
    const char* p_;
    const char* end_;
};

class OffReader {
public:
    explicit OffReader(const Input& in) : in_(in), cur_(in) {}

    geometry::TriangleMesh read() {
        read_keyword();
        const int64_t nv = count("vertex count");
        const int64_t nf = count("face count");
        count("edge count");
        // Each vertex needs at least 3 numbers of 2 bytes each, each face 4: bound before allocating.
        if (static_cast<uint64_t>(nv) > cur_.remaining() / 6 || static_cast<uint64_t>(nf) > cur_.remaining() / 8)
            parse_error(in_, "OFF: the header declares " + std::to_string(nv) + " vertices and " + std::to_string(nf) +
                                 " faces, more than the " + std::to_string(cur_.remaining()) +
                                 " bytes left can hold (truncated file?)");
        if (nv > INT32_MAX) parse_error(in_, "OFF: more vertices than a mesh can index");
        geometry::TriangleMesh mesh;
        const size_t n = static_cast<size_t>(nv);
        mesh.vertices.resize(n);
        if (normals_) mesh.vertex_normals.resize(n);
        if (colors_) mesh.vertex_colors.resize(n);
        for (size_t i = 0; i < n; ++i) {
            mesh.vertices[i] = vec3("vertex", i);
            if (normals_) mesh.vertex_normals[i] = vec3("vertex normal", i);
            if (colors_) mesh.vertex_colors[i] = color(i);
            if (texcoords_) {
                real("texture coordinate", i);
                real("texture coordinate", i);
            }
            cur_.skip_line();  // whatever else the line holds (alpha, extra columns)
        }
        mesh.triangles.reserve(static_cast<size_t>(nf));
        std::vector<int> corners;
        for (int64_t f = 0; f < nf; ++f) {
            const int64_t k = integer("face", f, cur_.token());
            if (k < 3) parse_error(in_, "OFF: face " + std::to_string(f) + " has " + std::to_string(k) + " corners (< 3)");
            if (static_cast<uint64_t>(k) > cur_.remaining())
                parse_error(in_, "OFF: face " + std::to_string(f) + " declares " + std::to_string(k) +
                                     " corners, more than the text left (truncated file?)");
            corners.clear();
            for (int64_t c = 0; c < k; ++c) {
                const int64_t idx = integer("face", f, cur_.token());
                if (idx < 0 || idx >= nv)
                    parse_error(in_, "OFF: face " + std::to_string(f) + " has the vertex index " + std::to_string(idx) +
                                         ", outside [0, " + std::to_string(nv) + ")");
                corners.push_back(static_cast<int>(idx));
            }
            fan_triangulate(corners.size(), [&](size_t a, size_t b, size_t c) {
                mesh.triangles.emplace_back(corners[a], corners[b], corners[c]);
            });
            cur_.skip_line();  // an optional face colour
        }
        if (!cur_.token().empty()) parse_error(in_, "OFF: text follows the last face (the header's counts are too small)");
        return mesh;
    }

private:
    void read_keyword() {
        std::string_view kw = cur_.token();
        if (kw.size() < 3 || kw.substr(kw.size() - 3) != "OFF")
            parse_error(in_, "OFF: the file does not start with an OFF keyword");
        kw.remove_suffix(3);
        if (kw.substr(0, 2) == "ST") {
            texcoords_ = true;
            kw.remove_prefix(2);
        }
        if (!kw.empty() && kw[0] == 'C') {
            colors_ = true;
            kw.remove_prefix(1);
        }
        if (!kw.empty() && kw[0] == 'N') {
            normals_ = true;
            kw.remove_prefix(1);
        }
        if (!kw.empty()) parse_error(in_, "OFF: unsupported variant '" + std::string(kw) + "OFF'");
    }
    int64_t count(const char* what) {
        const std::string_view tok = cur_.token();
        int64_t v;
        if (!parse_int64(tok, v) || v < 0)
            parse_error(in_, "OFF: bad " + std::string(what) + " '" + std::string(tok.substr(0, 32)) + "' in the header");
        return v;
    }
    int64_t integer(const char* what, int64_t i, std::string_view tok) {
        int64_t v;
        if (tok.empty()) truncated(what, i);
        if (!parse_int64(tok, v))
            parse_error(in_, "OFF: " + std::string(what) + " " + std::to_string(i) + ": '" +
                                 std::string(tok.substr(0, 32)) + "' is not an integer");
        return v;
    }
    double real(const char* what, size_t i) {
        const std::string_view tok = cur_.token_on_line();
        double v;
        if (tok.empty()) truncated(what, static_cast<int64_t>(i));
        if (!parse_double(tok, v))
            parse_error(in_, "OFF: " + std::string(what) + " " + std::to_string(i) + ": '" +
                                 std::string(tok.substr(0, 32)) + "' is not a number");
        return v;
    }
    Eigen::Vector3d vec3(const char* what, size_t i) {
        Eigen::Vector3d v;
        for (int k = 0; k < 3; ++k) {
            // The first coordinate may be on a later line (free-form files); the rest share its line.
            if (k == 0) {
                const std::string_view tok = cur_.token();
                if (tok.empty()) truncated(what, static_cast<int64_t>(i));
                if (!parse_double(tok, v[0]))
                    parse_error(in_, "OFF: " + std::string(what) + " " + std::to_string(i) + ": '" +
                                         std::string(tok.substr(0, 32)) + "' is not a number");
            } else {
                v[k] = real(what, i);
            }
        }
        return v;
    }
    /// @brief Integers are 0..255, reals 0..1; a colour with any real in it is all reals.
    Eigen::Vector3d color(size_t i) {
        std::string_view tok[3];
        bool integers = true;
        for (auto& t : tok) {
            t = cur_.token_on_line();
            if (t.empty()) truncated("vertex colour", static_cast<int64_t>(i));
            int64_t unused;
            integers = integers && parse_int64(t, unused);
        }
        Eigen::Vector3d c;
        for (int k = 0; k < 3; ++k)
            if (!parse_double(tok[k], c[k]))
                parse_error(in_, "OFF: vertex colour " + std::to_string(i) + ": '" + std::string(tok[k].substr(0, 32)) +
                                     "' is not a number");
        return integers ? Eigen::Vector3d(c / 255.0) : c;
    }
    [[noreturn]] void truncated(const char* what, int64_t i) {
        parse_error(in_, "OFF: the text ends inside " + std::string(what) + " " + std::to_string(i) +
                             " (truncated file or wrong count)");
    }

    const Input& in_;
    OffCursor cur_;
    bool normals_ = false, colors_ = false, texcoords_ = false;
};

}  // namespace

geometry::TriangleMesh read_mesh_off(const Input& in) { return OffReader(in).read(); }

std::vector<uint8_t> write_mesh_off(const geometry::TriangleMesh& mesh, const MeshWriteOptions& options) {
    const bool normals = options.write_vertex_normals && mesh.has_vertex_normals();
    const bool colors = options.write_vertex_colors && mesh.has_vertex_colors();
    ByteSink out(64 + mesh.vertices.size() * 96 + mesh.triangles.size() * 32);
    out.put(colors ? "C" : "");
    out.put(normals ? "NOFF\n" : "OFF\n");
    out.put_number(mesh.vertices.size());
    out.put(' ');
    out.put_number(mesh.triangles.size());
    out.put(" 0\n");
    for (size_t i = 0; i < mesh.vertices.size(); ++i) {
        for (int k = 0; k < 3; ++k) {
            if (k) out.put(' ');
            out.put_number(mesh.vertices[i][k]);
        }
        if (normals)
            for (int k = 0; k < 3; ++k) {
                out.put(' ');
                out.put_number(mesh.vertex_normals[i][k]);
            }
        if (colors) {
            for (int k = 0; k < 3; ++k) {
                out.put(' ');
                out.put_number(static_cast<unsigned>(color_to_u8(mesh.vertex_colors[i][k])));
            }
            out.put(" 255");
        }
        out.put('\n');
    }
    for (const Eigen::Vector3i& t : mesh.triangles) {
        out.put('3');
        for (int k = 0; k < 3; ++k) {
            out.put(' ');
            out.put_number(t[k]);
        }
        out.put('\n');
    }
    return out.finish();
}

}  // namespace o3d::io::detail
