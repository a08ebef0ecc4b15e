// SPDX-License-Identifier: MIT
// STL, binary and ascii. Facets share no vertices: like Open3D, each facet gets three vertices of its own
// and its normal becomes the triangle normal (enable_post_processing merges the duplicates).
#include <cstring>
#include <string>
#include <string_view>

#include "o3d/io/byte_reader.h"
#include "o3d/io/file_bytes.h"
#include "o3d/io/mesh_io_internal.h"
#include "o3d/io/text_writer.h"
#include "o3d/utility/error.h"

namespace o3d::io::detail {
namespace {

constexpr size_t kHeaderBytes = 80;
constexpr size_t kFacetBytes = 50;  // normal, three vertices (float32 x 12), uint16 attribute

void allocate_facets(geometry::TriangleMesh& mesh, size_t n) {
    mesh.vertices.resize(3 * n);
    prefault(mesh.vertices.data(), 3 * n * sizeof(Eigen::Vector3d));
    mesh.triangles.resize(n);
    mesh.triangle_normals.resize(n);
}

geometry::TriangleMesh read_binary(const Input& in, size_t n) {
    geometry::TriangleMesh mesh;
    allocate_facets(mesh, n);
    const uint8_t* p = in.data + kHeaderBytes + 4;
    for (size_t f = 0; f < n; ++f, p += kFacetBytes) {
        float v[12];
        std::memcpy(v, p, sizeof v);
        if constexpr (!kHostLittleEndian)
            for (float& x : v) x = byte_swap(x);
        mesh.triangle_normals[f] = Eigen::Vector3d(v[0], v[1], v[2]);
        for (int k = 0; k < 3; ++k) mesh.vertices[3 * f + k] = Eigen::Vector3d(v[3 + 3 * k], v[4 + 3 * k], v[5 + 3 * k]);
        const int i = static_cast<int>(3 * f);
        mesh.triangles[f] = Eigen::Vector3i(i, i + 1, i + 2);
    }
    return mesh;
}

class AsciiStl {
public:
    explicit AsciiStl(const Input& in) : in_(in), cur_(in.chars(), in.chars_end()) {}

    geometry::TriangleMesh read() {
        geometry::TriangleMesh mesh;
        cur_.line();  // "solid <name>": the name may hold anything
        for (;;) {
            const std::string_view kw = cur_.token();
            if (kw.empty()) parse_error(in_, "STL: the text ends before 'endsolid'");
            if (kw == "endsolid") {
                cur_.line();  // its name
                if (cur_.only_whitespace_left()) break;
                if (cur_.token() != "solid") parse_error(in_, "STL: text follows 'endsolid'");
                cur_.line();
                continue;
            }
            if (kw != "facet") fail("expected 'facet' or 'endsolid'", kw);
            expect("normal");
            const Eigen::Vector3d normal = vec();
            expect("outer");
            expect("loop");
            const int base = static_cast<int>(mesh.vertices.size());
            if (mesh.vertices.size() > static_cast<size_t>(INT32_MAX) - 3)
                parse_error(in_, "STL: more vertices than a mesh can index");
            for (int k = 0; k < 3; ++k) {
                expect("vertex");
                mesh.vertices.push_back(vec());
            }
            expect("endloop");
            expect("endfacet");
            mesh.triangles.emplace_back(base, base + 1, base + 2);
            mesh.triangle_normals.push_back(normal);
        }
        return mesh;
    }

private:
    [[noreturn]] void fail(const std::string& what, std::string_view tok) {
        parse_error(in_, "STL: " + what + ", found '" + std::string(tok.substr(0, 32)) + "' at byte " +
                             std::to_string(cur_.pos() - in_.chars()));
    }
    void expect(std::string_view word) {
        const std::string_view t = cur_.token();
        if (t != word) fail("expected '" + std::string(word) + "'", t);
    }
    Eigen::Vector3d vec() {
        Eigen::Vector3d v;
        for (int k = 0; k < 3; ++k) {
            std::string_view tok;
            if (!cur_.number(v[k], tok)) fail("expected a number", tok);
        }
        return v;
    }

    const Input& in_;
    TextCursor cur_;
};

bool starts_with_solid(const Input& in) {
    size_t i = 0;
    while (i < in.size && is_space(in.chars()[i])) ++i;
    return in.size - i >= 5 && std::memcmp(in.chars() + i, "solid", 5) == 0;
}

}  // namespace

geometry::TriangleMesh read_mesh_stl(const Input& in) {
    // A binary file may also begin with "solid": its size, exactly 84 + 50 n bytes, tells it apart.
    if (in.size >= kHeaderBytes + 4) {
        const uint32_t n = load<uint32_t>(in.data + kHeaderBytes, !kHostLittleEndian);
        const size_t body = in.size - kHeaderBytes - 4;
        if (body / kFacetBytes == n && body % kFacetBytes == 0) return read_binary(in, n);
        if (!starts_with_solid(in)) {
            if (body / kFacetBytes < n)
                parse_error(in, "STL: the binary header declares " + std::to_string(n) + " facets but only " +
                                    std::to_string(body / kFacetBytes) + " fit in the file (truncated file?)");
            return read_binary(in, n);  // trailing bytes after the facets: tolerated, as most readers do
        }
    }
    if (!starts_with_solid(in)) parse_error(in, "STL: neither a binary STL (too short) nor an ascii one ('solid')");
    return AsciiStl(in).read();
}

std::vector<uint8_t> write_mesh_stl(const geometry::TriangleMesh& mesh, const MeshWriteOptions& options) {
    const size_t m = mesh.triangles.size();
    const std::vector<Eigen::Vector3d> normals = facet_normals(mesh);
    if (options.write_ascii) {
        ByteSink out(32 + m * 256);
        out.put("solid o3d\n");
        for (size_t t = 0; t < m; ++t) {
            out.put("facet normal");
            for (int k = 0; k < 3; ++k) {
                out.put(' ');
                out.put_number(normals[t][k]);
            }
            out.put("\n outer loop\n");
            for (int c = 0; c < 3; ++c) {
                out.put("  vertex");
                const Eigen::Vector3d& v = mesh.vertices[static_cast<size_t>(mesh.triangles[t][c])];
                for (int k = 0; k < 3; ++k) {
                    out.put(' ');
                    out.put_number(v[k]);
                }
                out.put('\n');
            }
            out.put(" endloop\nendfacet\n");
        }
        out.put("endsolid o3d\n");
        return out.finish();
    }
    if (m > UINT32_MAX) throw InvalidArgument("STL: a binary STL holds at most 2^32 - 1 facets");
    std::vector<uint8_t> out = output_buffer(kHeaderBytes + 4 + m * kFacetBytes);
    static const char kBanner[] = "binary STL written by o3d";
    std::memcpy(out.data(), kBanner, sizeof kBanner - 1);
    store_le(out.data() + kHeaderBytes, static_cast<uint32_t>(m));
    uint8_t* p = out.data() + kHeaderBytes + 4;
    for (size_t t = 0; t < m; ++t, p += kFacetBytes) {
        for (int k = 0; k < 3; ++k) store_le(p + 4 * k, static_cast<float>(normals[t][k]));
        for (int c = 0; c < 3; ++c) {
            const Eigen::Vector3d& v = mesh.vertices[static_cast<size_t>(mesh.triangles[t][c])];
            for (int k = 0; k < 3; ++k) store_le(p + 12 + 12 * c + 4 * k, static_cast<float>(v[k]));
        }
        // the attribute byte count stays 0 (output_buffer zero-fills)
    }
    return out;
}

}  // namespace o3d::io::detail
