// SPDX-License-Identifier: MIT
// Triangle-mesh container and basic operations: attributes, append, transforms, bounds, normals, area.
// Reference numbers for knot.ply come from tools/reference/record_mesh.py (Open3D 0.20).
#include <Eigen/Geometry>
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "o3d/geometry/triangle_mesh_ops.h"
#include "o3d/utility/error.h"
#include "o3d/utility/parallel.h"
#include "test_data.h"
#include "triangle_mesh_test_util.h"

using namespace o3d::geometry;
using o3d::test::unit_cube;

namespace {

void expect_vec(const Eigen::Vector3d& got, const Eigen::Vector3d& want, double tol = 1e-12) {
    EXPECT_NEAR(got.x(), want.x(), tol);
    EXPECT_NEAR(got.y(), want.y(), tol);
    EXPECT_NEAR(got.z(), want.z(), tol);
}

TriangleMesh knot_or_empty(const std::string& path) {
    TriangleMesh m;
    EXPECT_TRUE(o3d::test::read_simple_ply(path, m));
    return m;
}

}  // namespace

TEST(TriangleMesh, AttributesCountOnlyWithMatchingRows) {
    TriangleMesh m = unit_cube();
    EXPECT_TRUE(m.has_vertices());
    EXPECT_TRUE(m.has_triangles());
    EXPECT_FALSE(m.has_vertex_normals());
    m.vertex_normals.assign(7, Eigen::Vector3d::UnitZ());
    EXPECT_FALSE(m.has_vertex_normals());
    m.vertex_normals.resize(8);
    EXPECT_TRUE(m.has_vertex_normals());
    m.triangle_uvs.assign(35, Eigen::Vector2d::Zero());
    EXPECT_FALSE(m.has_triangle_uvs());
    m.triangle_uvs.resize(36);
    EXPECT_TRUE(m.has_triangle_uvs());
}

TEST(TriangleMesh, AppendReindexesAndKeepsSharedAttributes) {
    TriangleMesh a = unit_cube();
    a.vertex_colors.assign(8, Eigen::Vector3d(1, 0, 0));
    a.vertex_normals.assign(8, Eigen::Vector3d(0, 0, 1));
    TriangleMesh b = o3d::test::corner_tetrahedron(Eigen::Vector3d(5, 0, 0));
    b.vertex_colors.assign(4, Eigen::Vector3d(0, 1, 0));
    b.textures.resize(1);
    b.triangle_material_ids.assign(4, 0);
    append(a, b);
    ASSERT_EQ(a.vertices.size(), 12u);
    ASSERT_EQ(a.triangles.size(), 16u);
    EXPECT_EQ(a.triangles[12], Eigen::Vector3i(8, 10, 9));  // (0,2,1) shifted by 8
    EXPECT_TRUE(a.has_vertex_colors());
    EXPECT_EQ(a.vertex_colors[11], Eigen::Vector3d(0, 1, 0));
    EXPECT_TRUE(a.vertex_normals.empty());  // only one side had them
    EXPECT_EQ(a.textures.size(), 1u);
    EXPECT_FALSE(a.has_triangle_material_ids());  // the cube had none

    TriangleMesh empty;
    append(empty, b);  // an empty target takes everything
    EXPECT_TRUE(empty.has_triangle_material_ids());
    EXPECT_EQ(empty.triangles, b.triangles);

    TriangleMesh bad = unit_cube();
    bad.triangles[3](1) = 8;
    TriangleMesh target = unit_cube();
    EXPECT_THROW(append(target, bad), o3d::InvalidArgument);
    EXPECT_EQ(target.triangles.size(), 12u);
}

TEST(TriangleMesh, BoundsAndCenter) {
    TriangleMesh m = unit_cube();
    expect_vec(min_bound(m), Eigen::Vector3d::Zero());
    expect_vec(max_bound(m), Eigen::Vector3d::Ones());
    expect_vec(center(m), Eigen::Vector3d::Constant(0.5));
    TriangleMesh empty;
    expect_vec(min_bound(empty), Eigen::Vector3d::Zero());
    expect_vec(center(empty), Eigen::Vector3d::Zero());
}

TEST(TriangleMesh, TransformsMoveVerticesAndRotateNormals) {
    TriangleMesh m = unit_cube();
    compute_vertex_normals(m);
    const Eigen::Matrix3d R = Eigen::AngleAxisd(M_PI / 2, Eigen::Vector3d::UnitZ()).toRotationMatrix();
    rotate(m, R, Eigen::Vector3d::Zero());
    expect_vec(m.vertices[1], Eigen::Vector3d(0, 1, 0));
    expect_vec(m.triangle_normals[0], Eigen::Vector3d(0, 0, -1));
    expect_vec(m.triangle_normals[4], Eigen::Vector3d(1, 0, 0));  // the y = 0 face now faces +x

    Eigen::Matrix4d T = Eigen::Matrix4d::Identity();
    T.block<3, 1>(0, 3) = Eigen::Vector3d(1, 2, 3);
    TriangleMesh t = unit_cube();
    transform(t, T);
    expect_vec(center(t), Eigen::Vector3d(1.5, 2.5, 3.5));
    translate(t, Eigen::Vector3d::Zero(), false);
    expect_vec(center(t), Eigen::Vector3d::Zero());
    scale(t, 2.0, Eigen::Vector3d::Zero());
    expect_vec(max_bound(t), Eigen::Vector3d::Ones());
    T(0, 0) = std::numeric_limits<double>::quiet_NaN();
    EXPECT_THROW(transform(t, T), o3d::InvalidArgument);
    EXPECT_THROW(scale(t, INFINITY, Eigen::Vector3d::Zero()), o3d::InvalidArgument);
}

TEST(TriangleMesh, PaintClipsToUnitRange) {
    TriangleMesh m = unit_cube();
    paint_uniform_color(m, Eigen::Vector3d(2, 0.5, -1));
    ASSERT_EQ(m.vertex_colors.size(), 8u);
    expect_vec(m.vertex_colors[7], Eigen::Vector3d(1, 0.5, 0));
}

TEST(TriangleMesh, NormalsOfABox) {
    TriangleMesh m = unit_cube();
    compute_triangle_normals(m, false);
    expect_vec(m.triangle_normals[0], Eigen::Vector3d(0, 0, -1));  // (b-a)x(c-a), |.| = twice the area = 1
    compute_vertex_normals(m, false);
    // Corner 0 touches two bottom, two front and one left triangle, each contributing its area-weighted normal.
    expect_vec(m.vertex_normals[0], Eigen::Vector3d(-1, -2, -2));
    compute_vertex_normals(m, true);
    expect_vec(m.vertex_normals[0], Eigen::Vector3d(-1, -2, -2) / 3.0);  // record_mesh.py cube.vertex_normal0
    expect_vec(m.vertex_normals[6], Eigen::Vector3d(2, 1, 2) / 3.0);  // two top, two right, one back

    m.vertex_normals[1] = Eigen::Vector3d::Zero();
    m.vertex_normals[2] = Eigen::Vector3d(std::nan(""), 0, 0);
    normalize_normals(m);
    expect_vec(m.vertex_normals[1], Eigen::Vector3d::Zero());
    expect_vec(m.vertex_normals[2], Eigen::Vector3d(0, 0, 1));
}

TEST(TriangleMesh, SurfaceArea) {
    EXPECT_DOUBLE_EQ(surface_area(unit_cube()), 6.0);
    EXPECT_DOUBLE_EQ(surface_area(o3d::test::corner_tetrahedron()), 1.5 + std::sqrt(3.0) / 2);
    EXPECT_EQ(surface_area(TriangleMesh{}), 0.0);
    TriangleMesh bad = unit_cube();
    bad.triangles[0](0) = -1;
    EXPECT_THROW(surface_area(bad), o3d::InvalidArgument);
    EXPECT_THROW(compute_vertex_normals(bad), o3d::InvalidArgument);
}

TEST(TriangleMesh, SameBitsForAnyThreadCount) {
    const TriangleMesh torus = o3d::test::grid_torus(400, 150);  // 120k triangles: the parallel path
    o3d::utility::set_default_num_threads(1);
    TriangleMesh one = torus;
    compute_vertex_normals(one);
    const double area_one = surface_area(one);
    o3d::utility::set_default_num_threads(4);
    TriangleMesh four = torus;
    compute_vertex_normals(four);
    const double area_four = surface_area(four);
    o3d::utility::set_default_num_threads(0);
    EXPECT_EQ(area_one, area_four);
    EXPECT_EQ(one.vertex_normals, four.vertex_normals);
    EXPECT_EQ(one.triangle_normals, four.triangle_normals);
    EXPECT_NEAR(area_one, 4 * M_PI * M_PI * 3, 0.01 * 4 * M_PI * M_PI * 3);  // torus area 4 pi^2 R r
}

TEST(TriangleMesh, KnotMatchesOpen3D) {
    O3D_TEST_DATA_OR_SKIP(path, "open3d/knot.ply");
    TriangleMesh m = knot_or_empty(path);
    ASSERT_EQ(m.vertices.size(), 1440u);
    ASSERT_EQ(m.triangles.size(), 2880u);
    EXPECT_NEAR(surface_area(m), 112072.277931022, 1e-9 * 112072.277931022);
    expect_vec(center(m), Eigen::Vector3d(-51.8151261387367, 2.687409812804415e-05, -76.56766093440561), 1e-9);
    expect_vec(min_bound(m), Eigen::Vector3d(-149.29086303710938, -66.8590087890625, -167.22898864746094), 0);
    expect_vec(max_bound(m), Eigen::Vector3d(21.443805694580078, 66.8602294921875, 14.094596862792969), 0);
    TriangleMesh raw = m;
    compute_vertex_normals(raw, false);
    EXPECT_NEAR(o3d::test::fingerprint(raw.vertex_normals), -3075471.028409105, 1e-9 * 3075471.0);
    compute_vertex_normals(m);
    EXPECT_NEAR(o3d::test::fingerprint(m.vertex_normals), 1491.6937938045387, 1e-9 * 1491.7);
    EXPECT_NEAR(o3d::test::fingerprint(m.triangle_normals), 1622.1241900170207, 1e-9 * 1622.1);
}
