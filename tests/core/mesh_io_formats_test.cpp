// SPDX-License-Identifier: MIT
// Format details of the mesh readers, on small hand-written files with known answers.
#include <gtest/gtest.h>

#include <cstring>
#include <string>
#include <vector>

#include "mesh_io_test_util.h"
#include "o3d/io/byte_reader.h"
#include "o3d/io/image_io.h"

namespace {

using o3d::geometry::TriangleMesh;
using o3d::test::read_mesh_text;

TEST(meshIoPly, PolygonsAreFanTriangulated) {
    const TriangleMesh m = read_mesh_text(
        "ply\nformat ascii 1.0\nelement vertex 5\nproperty float x\nproperty float y\nproperty float z\n"
        "element face 2\nproperty list uchar int vertex_indices\nend_header\n"
        "0 0 0\n1 0 0\n1 1 0\n0 1 0\n0.5 2 0\n4 0 1 2 3\n3 3 2 4\n",
        "ply");
    ASSERT_EQ(m.vertices.size(), 5u);
    ASSERT_EQ(m.triangles.size(), 3u);
    EXPECT_EQ(m.triangles[0], Eigen::Vector3i(0, 1, 2));
    EXPECT_EQ(m.triangles[1], Eigen::Vector3i(0, 2, 3));
    EXPECT_EQ(m.triangles[2], Eigen::Vector3i(3, 2, 4));
}

TEST(meshIoPly, BigEndianWithUcharColorsAndVertexIndexName) {
    std::string h =
        "ply\nformat binary_big_endian 1.0\nelement vertex 3\nproperty double x\nproperty double y\nproperty double z\n"
        "property uchar red\nproperty uchar green\nproperty uchar blue\n"
        "element face 1\nproperty list uchar uint vertex_index\nproperty uchar flags\nend_header\n";
    std::vector<uint8_t> b(h.begin(), h.end());
    auto put_be = [&](auto v) {
        v = o3d::io::detail::byte_swap(v);
        const auto* p = reinterpret_cast<const uint8_t*>(&v);
        b.insert(b.end(), p, p + sizeof v);
    };
    for (int i = 0; i < 3; ++i) {
        put_be(1.5 * i);
        put_be(-2.0);
        put_be(0.25);
        b.push_back(static_cast<uint8_t>(51 * i));
        b.push_back(255);
        b.push_back(0);
    }
    b.push_back(3);
    for (uint32_t i : {2u, 1u, 0u}) put_be(i);
    b.push_back(7);  // the skipped per-face property
    const TriangleMesh m = o3d::io::read_triangle_mesh_from_memory(b.data(), b.size(), "ply");
    ASSERT_EQ(m.vertices.size(), 3u);
    EXPECT_EQ(m.vertices[2], Eigen::Vector3d(3.0, -2.0, 0.25));
    EXPECT_DOUBLE_EQ(m.vertex_colors[1][0], 51 / 255.0);
    ASSERT_EQ(m.triangles.size(), 1u);
    EXPECT_EQ(m.triangles[0], Eigen::Vector3i(2, 1, 0));
}

TEST(meshIoPly, PerVertexUvsBecomeCornerUvs) {
    const TriangleMesh m = read_mesh_text(
        "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\nproperty float z\n"
        "property float s\nproperty float t\nelement face 1\nproperty list uchar int vertex_indices\nend_header\n"
        "0 0 0 0 0\n1 0 0 1 0\n0 1 0 0 1\n3 2 0 1\n",
        "ply");
    ASSERT_TRUE(m.has_triangle_uvs());
    EXPECT_EQ(m.triangle_uvs[0], Eigen::Vector2d(0, 1));
    EXPECT_EQ(m.triangle_uvs[1], Eigen::Vector2d(0, 0));
    EXPECT_EQ(m.triangle_uvs[2], Eigen::Vector2d(1, 0));
}

TEST(meshIoStl, AsciiWithSeveralSolids) {
    const TriangleMesh m = read_mesh_text(
        "solid first part\n facet normal 0 0 1\n  outer loop\n   vertex 0 0 0\n   vertex 1 0 0\n   vertex 0 1 0\n"
        "  endloop\n endfacet\nendsolid first part\nsolid second\nfacet normal 0 0 -1\nouter loop\nvertex 0 0 1\n"
        "vertex 0 1 1\nvertex 1 0 1\nendloop\nendfacet\nendsolid second\n",
        "stl");
    ASSERT_EQ(m.triangles.size(), 2u);
    ASSERT_EQ(m.vertices.size(), 6u);
    EXPECT_EQ(m.triangle_normals[1], Eigen::Vector3d(0, 0, -1));
    EXPECT_EQ(m.vertices[4], Eigen::Vector3d(0, 1, 1));
}

TEST(meshIoStl, BinaryWhoseHeaderSaysSolid) {
    std::vector<uint8_t> b(84 + 50, 0);
    std::memcpy(b.data(), "solid but binary", 16);
    b[80] = 1;
    const float f[12] = {0, 0, 1, 0, 0, 0, 2, 0, 0, 0, 3, 0};
    std::memcpy(b.data() + 84, f, sizeof f);
    const TriangleMesh m = o3d::io::read_triangle_mesh_from_memory(b.data(), b.size(), "stl");
    ASSERT_EQ(m.triangles.size(), 1u);
    EXPECT_EQ(m.vertices[2], Eigen::Vector3d(0, 3, 0));
    EXPECT_EQ(m.triangle_normals[0], Eigen::Vector3d(0, 0, 1));
}

TEST(meshIoOff, ColorsCommentsAndPolygons) {
    const TriangleMesh m = read_mesh_text(
        "COFF # coloured\n4 2 0\n# vertices\n0 0 0 255 0 0 255\n1 0 0 0 255 0 255\n1 1 0 0 0 255 255\n"
        "0 1 0 51 51 51 255\n4 0 1 2 3 1 0 0\n3 0 2 3\n",
        "off");
    ASSERT_EQ(m.vertices.size(), 4u);
    ASSERT_EQ(m.triangles.size(), 3u);  // the quad gives two
    EXPECT_EQ(m.triangles[1], Eigen::Vector3i(0, 2, 3));
    EXPECT_DOUBLE_EQ(m.vertex_colors[3][1], 0.2);
    EXPECT_EQ(m.vertex_colors[1], Eigen::Vector3d(0, 1, 0));
    const TriangleMesh f = read_mesh_text("COFF\n3 1 0\n0 0 0 0.5 0.25 1\n1 0 0 0 0 0\n0 1 0 1 1 1\n3 0 1 2\n", "off");
    EXPECT_EQ(f.vertex_colors[0], Eigen::Vector3d(0.5, 0.25, 1));  // reals are taken as [0,1] already
}

TEST(meshIoObj, PolygonsNegativeIndicesAndNormals) {
    const TriangleMesh m = read_mesh_text(
        "# quad and triangle\nv 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nvn 0 0 1\nvt 0 0\nvt 1 0\nvt 1 1\nvt 0 1\n"
        "f 1/1/1 2/2/1 3/3/1 4/4/1\nf -4//1 -2//1 -1//1\n",
        "obj");
    ASSERT_EQ(m.vertices.size(), 4u);
    ASSERT_EQ(m.triangles.size(), 3u);
    EXPECT_EQ(m.triangles[2], Eigen::Vector3i(0, 2, 3));
    ASSERT_TRUE(m.has_vertex_normals());
    EXPECT_EQ(m.vertex_normals[3], Eigen::Vector3d(0, 0, 1));
    // UVs of the corners that have them; the triangle without any gets zeros.
    ASSERT_TRUE(m.has_triangle_uvs());
    EXPECT_EQ(m.triangle_uvs[1], Eigen::Vector2d(1, 0));
    EXPECT_EQ(m.triangle_uvs[8], Eigen::Vector2d(0, 0));
    EXPECT_FALSE(m.has_vertex_colors());
}

TEST(meshIoObj, MemoryInputIgnoresItsMaterialLibrary) {
    const TriangleMesh m = read_mesh_text("mtllib missing.mtl\nusemtl a\nv 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n", "obj");
    EXPECT_EQ(m.triangles.size(), 1u);
    EXPECT_TRUE(m.textures.empty());
}

std::string base64(const std::vector<uint8_t>& b) {
    static const char* k = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
    std::string out;
    for (size_t i = 0; i < b.size(); i += 3) {
        const uint32_t v = (uint32_t(b[i]) << 16) | (i + 1 < b.size() ? uint32_t(b[i + 1]) << 8 : 0) |
                           (i + 2 < b.size() ? b[i + 2] : 0);
        out += k[(v >> 18) & 63];
        out += k[(v >> 12) & 63];
        out += i + 1 < b.size() ? k[(v >> 6) & 63] : '=';
        out += i + 2 < b.size() ? k[v & 63] : '=';
    }
    return out;
}

TEST(meshIoGltf, StripUnderNodeTransformsInMemory) {
    // A quad as a 4-vertex TRIANGLE_STRIP, in a child node scaled by 2 under a parent moved by (10, 0, 0).
    const float xyz[12] = {0, 0, 0, 1, 0, 0, 0, 1, 0, 1, 1, 0};
    const uint16_t idx[4] = {0, 1, 2, 3};
    std::vector<uint8_t> buf(sizeof xyz + sizeof idx);
    std::memcpy(buf.data(), xyz, sizeof xyz);
    std::memcpy(buf.data() + sizeof xyz, idx, sizeof idx);
    const std::string json =
        R"({"asset":{"version":"2.0"},"scene":0,"scenes":[{"nodes":[0]}],)"
        R"("nodes":[{"translation":[10,0,0],"children":[1]},{"scale":[2,2,2],"mesh":0}],)"
        R"("meshes":[{"primitives":[{"attributes":{"POSITION":0},"indices":1,"mode":5}]}],)"
        R"("accessors":[{"bufferView":0,"componentType":5126,"count":4,"type":"VEC3","min":[0,0,0],"max":[1,1,0]},)"
        R"({"bufferView":1,"componentType":5123,"count":4,"type":"SCALAR"}],)"
        R"("bufferViews":[{"buffer":0,"byteOffset":0,"byteLength":48},{"buffer":0,"byteOffset":48,"byteLength":8}],)"
        R"("buffers":[{"byteLength":56,"uri":"data:application/octet-stream;base64,)" +
        base64(buf) + R"("}]})";
    const TriangleMesh m = read_mesh_text(json, "gltf");
    ASSERT_EQ(m.vertices.size(), 4u);
    EXPECT_EQ(m.vertices[3], Eigen::Vector3d(12, 2, 0));
    ASSERT_EQ(m.triangles.size(), 2u);
    EXPECT_EQ(m.triangles[0], Eigen::Vector3i(0, 1, 2));
    EXPECT_EQ(m.triangles[1], Eigen::Vector3i(2, 1, 3));  // odd strip triangles swap to keep the winding
    // An external buffer is not fetched for memory input.
    const std::string external = json.substr(0, json.find("data:application")) + "quad.bin\"}]}";
    EXPECT_NE(o3d::test::mesh_parse_error(external, "gltf"), "");
}

TEST(meshIoGltf, DeepNodeChainsAndCycles) {
    // 50000 nested nodes, each moving by (1, 0, 0): read without recursion, the mesh lands at x = 50000.
    const float xyz[9] = {0, 0, 0, 1, 0, 0, 0, 1, 0};
    const std::vector<uint8_t> buf(reinterpret_cast<const uint8_t*>(xyz), reinterpret_cast<const uint8_t*>(xyz) + 36);
    const int depth = 50000;
    auto gltf = [&](const std::string& last_children) {
        std::string nodes;
        for (int i = 0; i + 1 < depth; ++i) nodes += R"({"translation":[1,0,0],"children":[)" + std::to_string(i + 1) + "]},";
        nodes += R"({"translation":[1,0,0],"mesh":0)" + last_children + "}";
        return R"({"asset":{"version":"2.0"},"scene":0,"scenes":[{"nodes":[0]}],"nodes":[)" + nodes + "]," +
               R"("meshes":[{"primitives":[{"attributes":{"POSITION":0}}]}],)"
               R"("accessors":[{"bufferView":0,"componentType":5126,"count":3,"type":"VEC3","min":[0,0,0],"max":[1,1,0]}],)"
               R"("bufferViews":[{"buffer":0,"byteOffset":0,"byteLength":36}],)"
               R"("buffers":[{"byteLength":36,"uri":"data:application/octet-stream;base64,)" +
               base64(buf) + R"("}]})";
    };
    const TriangleMesh m = read_mesh_text(gltf(""), "gltf");
    ASSERT_EQ(m.vertices.size(), 3u);
    EXPECT_EQ(m.vertices[1], Eigen::Vector3d(depth + 1, 0, 0));
    // The last node naming the first as its child closes a cycle.
    EXPECT_NE(o3d::test::mesh_parse_error(gltf(R"(,"children":[0])"), "gltf").find("reached twice"), std::string::npos);
}

TEST(meshIoGltf, MaterialsGiveTexturesAndTriangleMaterialIds) {
    // Two one-triangle primitives: the first with material 0 (a base colour PNG), the second with material 1
    // (no image). The PNG comes from the image writer, embedded as a data URI.
    o3d::geometry::Image image;
    image.width = 4;
    image.height = 2;
    image.num_channels = 3;
    image.bytes_per_channel = 1;
    for (int i = 0; i < 24; ++i) image.data.push_back(static_cast<uint8_t>(10 * i));
    const std::vector<uint8_t> png = o3d::io::write_image_to_memory(image, "png");
    const float xyz[9] = {0, 0, 0, 1, 0, 0, 0, 1, 0};
    const std::vector<uint8_t> buf(reinterpret_cast<const uint8_t*>(xyz), reinterpret_cast<const uint8_t*>(xyz) + 36);
    auto json = [&](const std::string& image_bytes) {
        return R"({"asset":{"version":"2.0"},"scene":0,"scenes":[{"nodes":[0]}],"nodes":[{"mesh":0}],)"
               R"("meshes":[{"primitives":[{"attributes":{"POSITION":0},"material":0},)"
               R"({"attributes":{"POSITION":0},"material":1}]}],)"
               R"("materials":[{"pbrMetallicRoughness":{"baseColorTexture":{"index":0}}},{}],)"
               R"("textures":[{"source":0}],"images":[{"uri":"data:image/png;base64,)" +
               image_bytes + R"("}],)"
               R"("accessors":[{"bufferView":0,"componentType":5126,"count":3,"type":"VEC3","min":[0,0,0],"max":[1,1,0]}],)"
               R"("bufferViews":[{"buffer":0,"byteOffset":0,"byteLength":36}],)"
               R"("buffers":[{"byteLength":36,"uri":"data:application/octet-stream;base64,)" +
               base64(buf) + R"("}]})";
    };
    const TriangleMesh m = read_mesh_text(json(base64(png)), "gltf");
    ASSERT_EQ(m.triangles.size(), 2u);
    ASSERT_EQ(m.triangle_material_ids, (std::vector<int>{0, 1}));
    ASSERT_EQ(m.textures.size(), 2u);
    EXPECT_EQ(m.textures[0].width, 4);
    EXPECT_EQ(m.textures[0].height, 2);
    EXPECT_EQ(m.textures[0].data, image.data);
    EXPECT_TRUE(m.textures[1].empty());
    // A broken image leaves the geometry readable, without textures.
    const TriangleMesh broken = read_mesh_text(json(base64(std::vector<uint8_t>(png.begin(), png.begin() + 20))), "gltf");
    EXPECT_EQ(broken.triangles.size(), 2u);
    EXPECT_TRUE(broken.textures.empty());
}

TEST(meshIoPostProcessing, MergesDuplicatesAndDropsDegenerateTriangles) {
    // Two triangles sharing an edge through duplicated vertices, plus one that collapses after merging.
    o3d::io::MeshReadOptions pp;
    pp.enable_post_processing = true;
    const std::string off = "OFF\n7 3 0\n0 0 0\n1 0 0\n0 1 0\n1 0 0\n0 1 0\n1 1 0\n0 0 0\n3 0 1 2\n3 3 5 4\n3 0 6 1\n";
    const TriangleMesh raw = read_mesh_text(off, "off");
    EXPECT_EQ(raw.vertices.size(), 7u);
    EXPECT_EQ(raw.triangles.size(), 3u);
    const TriangleMesh m = read_mesh_text(off, "off", pp);
    ASSERT_EQ(m.vertices.size(), 4u);
    ASSERT_EQ(m.triangles.size(), 2u);
    EXPECT_EQ(m.triangles[1], Eigen::Vector3i(1, 3, 2));
}

}  // namespace
