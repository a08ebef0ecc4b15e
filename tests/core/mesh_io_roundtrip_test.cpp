// SPDX-License-Identifier: MIT
// Mesh round trips: write, read back, compare with the attributes each format can hold.
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cmath>
#include <cstdio>
#include <string>

#include "mesh_io_test_util.h"

namespace {

using o3d::geometry::TriangleMesh;
using o3d::io::MeshReadOptions;
using o3d::io::MeshWriteOptions;
using o3d::test::expect_vec3_near;
using o3d::test::make_octahedron;

TriangleMesh round_trip(const TriangleMesh& m, const std::string& format, const MeshWriteOptions& w = {},
                        const MeshReadOptions& r = {}) {
    const std::vector<uint8_t> bytes = o3d::io::write_triangle_mesh_to_memory(m, format, w);
    return o3d::io::read_triangle_mesh_from_memory(bytes.data(), bytes.size(), format, r);
}

void expect_same_triangles(const TriangleMesh& a, const TriangleMesh& b) {
    ASSERT_EQ(a.triangles.size(), b.triangles.size());
    for (size_t t = 0; t < a.triangles.size(); ++t) EXPECT_EQ(a.triangles[t], b.triangles[t]) << t;
}

void expect_uvs(const TriangleMesh& a, const TriangleMesh& b, double tol) {
    ASSERT_EQ(a.triangle_uvs.size(), b.triangle_uvs.size());
    for (size_t i = 0; i < a.triangle_uvs.size(); ++i)
        for (int k = 0; k < 2; ++k) EXPECT_NEAR(a.triangle_uvs[i][k], b.triangle_uvs[i][k], tol) << i;
}

TEST(meshIoRoundTrip, PlyBinaryAndAsciiAreExact) {
    const TriangleMesh m = make_octahedron();
    for (bool ascii : {false, true}) {
        SCOPED_TRACE(ascii ? "ascii" : "binary");
        MeshWriteOptions w;
        w.write_ascii = ascii;
        const TriangleMesh r = round_trip(m, "ply", w);
        expect_vec3_near(r.vertices, m.vertices, 0.0, "vertices");
        expect_vec3_near(r.vertex_normals, m.vertex_normals, 0.0, "normals");
        expect_vec3_near(r.vertex_colors, m.vertex_colors, 0.0, "colors");  // on the 1/255 grid
        expect_same_triangles(r, m);
        expect_uvs(r, m, 0.0);
    }
}

TEST(meshIoRoundTrip, WriteOptionsLeaveAttributesOut) {
    const TriangleMesh m = make_octahedron();
    MeshWriteOptions w;
    w.write_vertex_normals = w.write_vertex_colors = w.write_triangle_uvs = false;
    for (const char* f : {"ply", "obj", "off", "glb"}) {
        SCOPED_TRACE(f);
        const TriangleMesh r = round_trip(m, f, w);
        EXPECT_EQ(r.vertices.size(), 6u);
        EXPECT_EQ(r.triangles.size(), 8u);
        EXPECT_FALSE(r.has_vertex_normals());
        EXPECT_FALSE(r.has_vertex_colors());
        EXPECT_FALSE(r.has_triangle_uvs());
    }
}

TEST(meshIoRoundTrip, ObjKeepsNormalsColorsAndUvs) {
    const TriangleMesh m = make_octahedron();
    const TriangleMesh r = round_trip(m, "obj");
    // Numbers are written as the shortest text that reads back to the same double, and read with from_chars.
    expect_vec3_near(r.vertices, m.vertices, 1e-12, "vertices");
    expect_vec3_near(r.vertex_normals, m.vertex_normals, 1e-12, "normals");
    expect_vec3_near(r.vertex_colors, m.vertex_colors, 1e-12, "colors");
    expect_same_triangles(r, m);
    expect_uvs(r, m, 1e-12);
}

TEST(meshIoRoundTrip, OffKeepsNormalsAndColors) {
    const TriangleMesh m = make_octahedron();
    const TriangleMesh r = round_trip(m, "off");
    expect_vec3_near(r.vertices, m.vertices, 0.0, "vertices");
    expect_vec3_near(r.vertex_normals, m.vertex_normals, 0.0, "normals");
    expect_vec3_near(r.vertex_colors, m.vertex_colors, 1e-15, "colors");
    expect_same_triangles(r, m);
}

TEST(meshIoRoundTrip, GltfAndGlbKeepFloatPrecision) {
    const TriangleMesh m = make_octahedron();
    for (const char* f : {"gltf", "glb"}) {
        SCOPED_TRACE(f);
        const TriangleMesh r = round_trip(m, f);
        expect_vec3_near(r.vertices, m.vertices, 1e-6, "vertices");
        expect_vec3_near(r.vertex_normals, m.vertex_normals, 1e-6, "normals");
        expect_vec3_near(r.vertex_colors, m.vertex_colors, 1e-6, "colors");
        expect_same_triangles(r, m);
    }
}

TEST(meshIoRoundTrip, StlGivesEachFacetItsVerticesAndNormal) {
    const TriangleMesh m = make_octahedron();
    for (bool ascii : {false, true}) {
        SCOPED_TRACE(ascii ? "ascii" : "binary");
        MeshWriteOptions w;
        w.write_ascii = ascii;
        const TriangleMesh r = round_trip(m, "stl", w);
        ASSERT_EQ(r.vertices.size(), 3 * m.triangles.size());
        ASSERT_EQ(r.triangles.size(), m.triangles.size());
        ASSERT_TRUE(r.has_triangle_normals());
        const double tol = ascii ? 1e-15 : 1e-6;
        for (size_t t = 0; t < m.triangles.size(); ++t) {
            for (int k = 0; k < 3; ++k) {
                EXPECT_EQ(r.triangles[t][k], static_cast<int>(3 * t) + k);
                for (int c = 0; c < 3; ++c)
                    EXPECT_NEAR(r.vertices[3 * t + k][c], m.vertices[m.triangles[t][k]][c], tol);
            }
            // The facet normal of an octahedron face points along (±1, ±1, ±1) / sqrt 3.
            const Eigen::Vector3d a = m.vertices[m.triangles[t][0]], b = m.vertices[m.triangles[t][1]],
                                  c = m.vertices[m.triangles[t][2]];
            const Eigen::Vector3d n = (b - a).cross(c - a).normalized();
            for (int k = 0; k < 3; ++k) EXPECT_NEAR(r.triangle_normals[t][k], n[k], 1e-6);
            EXPECT_NEAR(std::abs(n[0]), 1 / std::sqrt(3.0), 1e-12);
        }
        // Post-processing merges the corners back into the six shared vertices.
        MeshReadOptions pp;
        pp.enable_post_processing = true;
        const TriangleMesh merged = round_trip(m, "stl", w, pp);
        EXPECT_EQ(merged.vertices.size(), 6u);
        EXPECT_EQ(merged.triangles.size(), 8u);
        EXPECT_EQ(merged.triangle_normals.size(), 8u);
    }
}

TEST(meshIoRoundTrip, FilesByExtension) {
    const TriangleMesh m = make_octahedron();
    const std::string dir = ::testing::TempDir();
    for (const char* ext : {"ply", "obj", "stl", "off", "gltf", "glb", "PLY"}) {
        SCOPED_TRACE(ext);
        const std::string path = dir + "/o3d_mesh_roundtrip." + ext;
        o3d::io::write_triangle_mesh(path, m);
        const TriangleMesh r = o3d::io::read_triangle_mesh(path);
        EXPECT_EQ(r.triangles.size(), 8u);
        EXPECT_EQ(r.vertices.size(), std::string(ext) == "stl" ? 24u : 6u);
        std::remove(path.c_str());
    }
}

TEST(meshIoRoundTrip, EmptyMesh) {
    const TriangleMesh empty;
    for (const char* f : {"ply", "obj", "stl", "off", "glb", "gltf"}) {
        SCOPED_TRACE(f);
        const TriangleMesh r = round_trip(empty, f);
        EXPECT_TRUE(r.vertices.empty());
        EXPECT_TRUE(r.triangles.empty());
    }
}

}  // namespace
