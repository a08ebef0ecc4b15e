// SPDX-License-Identifier: MIT
// Removing vertices and triangles by index or mask: what is removed, what follows it, and the errors.
#include <gtest/gtest.h>

#include <Eigen/Geometry>

#include "o3d/geometry/mesh_element_removal.h"
#include "o3d/geometry/mesh_primitives.h"
#include "o3d/geometry/mesh_topology.h"
#include "o3d/geometry/triangle_mesh_ops.h"
#include "o3d/utility/error.h"

namespace g = o3d::geometry;

namespace {

/// A unit sphere with per-vertex colours that encode the vertex's original index (red channel), and triangle
/// normals, so the test can tell which attributes followed which element.
g::TriangleMesh tagged_sphere() {
    g::TriangleMesh mesh = g::create_sphere(1.0, 10);
    mesh.vertex_colors.resize(mesh.vertices.size());
    for (size_t v = 0; v < mesh.vertices.size(); ++v)
        mesh.vertex_colors[v] = Eigen::Vector3d(static_cast<double>(v), 0.0, 0.0);
    g::compute_triangle_normals(mesh);
    return mesh;
}

}  // namespace

TEST(MeshElementRemoval, VerticesByMaskDropTheirTrianglesAndKeepTheRestInOrder) {
    g::TriangleMesh mesh = tagged_sphere();
    const g::TriangleMesh before = mesh;
    // Remove the upper cap (z > 0.5), as a density trim removes a region.
    std::vector<uint8_t> mask(mesh.vertices.size());
    size_t removed = 0;
    for (size_t v = 0; v < mask.size(); ++v) removed += mask[v] = mesh.vertices[v].z() > 0.5;
    ASSERT_GT(removed, 0u);
    g::remove_vertices_by_mask(mesh, mask);
    ASSERT_EQ(mesh.vertices.size(), before.vertices.size() - removed);
    ASSERT_EQ(mesh.vertex_colors.size(), mesh.vertices.size());
    for (const auto& v : mesh.vertices) EXPECT_LE(v.z(), 0.5);
    // Each kept vertex is the original one its colour names, in increasing order.
    for (size_t v = 0; v < mesh.vertices.size(); ++v) {
        const auto original = static_cast<size_t>(mesh.vertex_colors[v].x());
        EXPECT_EQ(mesh.vertices[v], before.vertices[original]);
        if (v > 0) {
            EXPECT_GT(original, static_cast<size_t>(mesh.vertex_colors[v - 1].x()));
        }
    }
    // Exactly the triangles with no removed corner survive, with their normals.
    size_t expected_triangles = 0;
    for (const auto& t : before.triangles) expected_triangles += !mask[t(0)] && !mask[t(1)] && !mask[t(2)];
    ASSERT_EQ(mesh.triangles.size(), expected_triangles);
    ASSERT_EQ(mesh.triangle_normals.size(), expected_triangles);
    for (size_t t = 0; t < mesh.triangles.size(); ++t) {
        const Eigen::Vector3d e1 = mesh.vertices[mesh.triangles[t](1)] - mesh.vertices[mesh.triangles[t](0)];
        const Eigen::Vector3d e2 = mesh.vertices[mesh.triangles[t](2)] - mesh.vertices[mesh.triangles[t](0)];
        EXPECT_GT(e1.cross(e2).normalized().dot(mesh.triangle_normals[t]), 0.999);
    }
    EXPECT_FALSE(g::is_watertight(mesh));  // a hole where the cap was
}

TEST(MeshElementRemoval, VerticesByIndexEqualsByMask) {
    g::TriangleMesh a = tagged_sphere(), b = tagged_sphere();
    const std::vector<int64_t> indices = {3, 7, 7, 20, 0};
    std::vector<uint8_t> mask(a.vertices.size(), 0);
    for (int64_t i : indices) mask[i] = 1;
    g::remove_vertices_by_index(a, indices);
    g::remove_vertices_by_mask(b, mask);
    EXPECT_EQ(a.vertices, b.vertices);
    EXPECT_EQ(a.triangles, b.triangles);
    EXPECT_EQ(a.vertices.size(), tagged_sphere().vertices.size() - 4);
}

TEST(MeshElementRemoval, TrianglesKeepEveryVertex) {
    g::TriangleMesh mesh = g::create_box();
    ASSERT_EQ(mesh.triangles.size(), 12u);
    const auto triangles = mesh.triangles;
    g::remove_triangles_by_index(mesh, {0, 11, 0});
    EXPECT_EQ(mesh.vertices.size(), 8u);
    ASSERT_EQ(mesh.triangles.size(), 10u);
    for (size_t t = 0; t < 10; ++t) EXPECT_EQ(mesh.triangles[t], triangles[t + 1]);
    std::vector<uint8_t> mask(10, 0);
    mask[4] = 1;
    g::remove_triangles_by_mask(mesh, mask);
    ASSERT_EQ(mesh.triangles.size(), 9u);
    EXPECT_EQ(mesh.triangles[4], triangles[6]);
}

TEST(MeshElementRemoval, BadInputIsAnErrorAndChangesNothing) {
    g::TriangleMesh mesh = g::create_box();
    const g::TriangleMesh before = mesh;
    EXPECT_THROW(g::remove_vertices_by_index(mesh, {8}), o3d::InvalidArgument);
    EXPECT_THROW(g::remove_vertices_by_index(mesh, {-1}), o3d::InvalidArgument);
    EXPECT_THROW(g::remove_vertices_by_mask(mesh, std::vector<uint8_t>(7, 0)), o3d::InvalidArgument);
    EXPECT_THROW(g::remove_triangles_by_index(mesh, {12}), o3d::InvalidArgument);
    EXPECT_THROW(g::remove_triangles_by_mask(mesh, std::vector<uint8_t>(13, 0)), o3d::InvalidArgument);
    EXPECT_EQ(mesh.vertices, before.vertices);
    EXPECT_EQ(mesh.triangles, before.triangles);
    // A triangle naming a vertex that does not exist is caught before it is followed.
    mesh.triangles[0] = Eigen::Vector3i(0, 1, 99);
    EXPECT_THROW(g::remove_vertices_by_mask(mesh, std::vector<uint8_t>(8, 0)), o3d::InvalidArgument);
}
