// SPDX-License-Identifier: MIT
// Bad mesh input: every malformed, truncated or lying file is a ParseError naming "<memory>" and the reason,
// out-of-range face indices included; missing files are IoError, unknown formats Unsupported.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "mesh_io_test_util.h"

namespace {

using o3d::test::make_octahedron;
using o3d::test::mesh_parse_error;

void expect_parse_error(const std::string& text, const std::string& format, const std::string& reason) {
    const std::string msg = mesh_parse_error(text, format);
    ASSERT_FALSE(msg.empty()) << format << " accepted:\n" << text;
    EXPECT_EQ(msg.rfind("<memory>: ", 0), 0u) << msg;
    EXPECT_NE(msg.find(reason), std::string::npos) << "message: " << msg << "\nexpected to contain: " << reason;
}

const char* const kPlyHead =
    "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\nproperty float z\n"
    "element face 1\nproperty list uchar int vertex_indices\nend_header\n0 0 0\n1 0 0\n0 1 0\n";

TEST(meshIoMalformed, OutOfRangeFaceIndices) {
    expect_parse_error(std::string(kPlyHead) + "3 0 1 3\n", "ply", "outside the 3 vertices");
    expect_parse_error(std::string(kPlyHead) + "3 0 -1 2\n", "ply", "out of range");
    expect_parse_error("OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 7\n", "off", "outside [0, 3)");
    expect_parse_error("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 4\n", "obj", "outside the 3 defined");
    expect_parse_error("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 -9\n", "obj", "vertex outside");
    expect_parse_error("v 0 0 0\nv 1 0 0\nv 0 1 0\nvn 0 0 1\nf 1//1 2//2 3//1\n", "obj", "normal outside");
    expect_parse_error("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 0\n", "obj", "bad face corner");
}

TEST(meshIoMalformed, TruncatedFilesOfEveryFormat) {
    const auto mesh = make_octahedron();
    for (const char* f : {"ply", "stl", "off", "glb", "gltf", "obj"}) {
        for (bool ascii : {false, true}) {
            o3d::io::MeshWriteOptions w;
            w.write_ascii = ascii;
            const std::vector<uint8_t> full = o3d::io::write_triangle_mesh_to_memory(mesh, f, w);
            // Cut at many points: each prefix either reads (a valid shorter file, possible for OBJ lines) or is a
            // ParseError; anything else fails the test. The halfway cut must be an error for every format but OBJ.
            for (size_t cut = 0; cut < full.size(); cut += 1 + full.size() / 97) {
                const std::vector<uint8_t> part(full.begin(), full.begin() + static_cast<long>(cut));
                try {
                    o3d::io::read_triangle_mesh_from_memory(part.data(), part.size(), f);
                } catch (const o3d::ParseError& e) {
                    EXPECT_EQ(std::string(e.what()).rfind("<memory>: ", 0), 0u) << e.what();
                }
            }
            if (std::string(f) != "obj") {
                const std::vector<uint8_t> half(full.begin(), full.begin() + static_cast<long>(full.size() / 2));
                EXPECT_NE(mesh_parse_error(half, f), "") << f << (ascii ? " ascii" : "");
            }
        }
    }
}

TEST(meshIoMalformed, MalformedContent) {
    expect_parse_error(std::string(kPlyHead) + "2 0 1\n", "ply", "2 corners");
    expect_parse_error(std::string(kPlyHead) + "3 0 1 x\n", "ply", "is not a number");
    expect_parse_error("ply\nformat ascii 1.0\nelement face 1\nproperty list uchar int vertex_indices\nend_header\n3 0 1 2\n",
                       "ply", "no vertex element");
    expect_parse_error("ply\nformat ascii 1.0\nelement vertex 1\nproperty float x\nproperty float y\nproperty float z\n"
                       "element face 1\nproperty uchar n\nend_header\n0 0 0\n1\n",
                       "ply", "no vertex_indices");
    expect_parse_error("solid x\nfacet normal 0 0 1\nouter loop\nvertex 0 0\nendloop\n", "stl", "expected a number");
    expect_parse_error("solid x\nfacet normal 0 0 1\nouter loop\nvertex 0 0 0\n", "stl", "expected 'vertex'");
    expect_parse_error("hello", "stl", "neither a binary STL");
    std::vector<uint8_t> stl(84, 0);
    stl[80] = 5;  // five facets announced, none present
    EXPECT_NE(mesh_parse_error(stl, "stl").find("declares 5 facets"), std::string::npos);
    expect_parse_error("FOO\n", "off", "OFF keyword");
    expect_parse_error("OFF\n3 1 0\n0 0 0\n1 0\n0 1 0\n3 0 1 2\n", "off", "ends inside vertex 1");
    expect_parse_error("OFF\n3 1 0\n0 0 0\n1 0 y\n0 1 0\n3 0 1 2\n", "off", "is not a number");
    expect_parse_error("OFF\n99999999 1 0\n0 0 0\n", "off", "more than the");
    expect_parse_error("OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n3 0 1 2\n", "off", "text follows");
    expect_parse_error("v 0 0\n", "obj", "needs 3 numbers");
    expect_parse_error("v 0 0 zero\n", "obj", "is not a number");
    expect_parse_error("v 0 0 0\nv 1 0 0\nf 1 2\n", "obj", "needs 3 corners");
    expect_parse_error("{\"asset\":{\"version\":\"2.0\"},", "gltf", "glTF");
    expect_parse_error("glTF\x02", "glb", "GLB");
    expect_parse_error(
        R"({"asset":{"version":"2.0"},"meshes":[{"primitives":[{"attributes":{"POSITION":0}}]}],)"
        R"("accessors":[{"bufferView":0,"componentType":5126,"count":100,"type":"VEC3"}],)"
        R"("bufferViews":[{"buffer":0,"byteLength":12}],)"
        R"("buffers":[{"byteLength":12,"uri":"data:application/octet-stream;base64,AAAAAAAAAAAAAAAA"}]})",
        "gltf", "reaches past its buffer");
}

TEST(meshIoMalformed, FilesFormatsAndArguments) {
    EXPECT_THROW(o3d::io::read_triangle_mesh("/nonexistent/dir/mesh.ply"), o3d::IoError);
    EXPECT_THROW(o3d::io::read_triangle_mesh("/nonexistent/dir/mesh.obj"), o3d::IoError);
    EXPECT_THROW(o3d::io::read_triangle_mesh("mesh.xyz"), o3d::Unsupported);
    EXPECT_THROW(o3d::io::read_triangle_mesh("mesh"), o3d::Unsupported);
    EXPECT_THROW(o3d::io::read_triangle_mesh_from_memory(nullptr, 0, "fbx"), o3d::Unsupported);
    EXPECT_THROW(o3d::io::read_triangle_mesh_from_memory(nullptr, 0, "auto"), o3d::InvalidArgument);
    EXPECT_THROW(o3d::io::write_triangle_mesh_to_memory(make_octahedron(), "vrml"), o3d::Unsupported);
    auto bad = make_octahedron();
    bad.triangles[3][1] = 6;  // one past the last vertex
    for (const char* f : {"ply", "obj", "stl", "off", "glb"})
        EXPECT_THROW(o3d::io::write_triangle_mesh_to_memory(bad, f), o3d::InvalidArgument) << f;
    EXPECT_THROW(o3d::io::write_triangle_mesh("/nonexistent/dir/out.ply", make_octahedron()), o3d::IoError);
    // An empty input is malformed for every format but OBJ, where it is an empty mesh.
    for (const char* f : {"ply", "stl", "off", "glb", "gltf"}) EXPECT_NE(mesh_parse_error("", f), "") << f;
    EXPECT_TRUE(o3d::io::read_triangle_mesh_from_memory(nullptr, 0, "obj").vertices.empty());
}

}  // namespace
