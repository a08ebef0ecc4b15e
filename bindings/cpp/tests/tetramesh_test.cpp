// SPDX-License-Identifier: MIT
// TetraMesh through the wrapper: its arrays and views, the Delaunay tetrahedralization of a cube (its tetras fill
// the cube exactly), the iso-surface of a linear field (a plane cutting the cube), errors as exceptions.
#include <algorithm>
#include <cmath>
#include <numeric>
#include <vector>

#include "test_util.hpp"

using o3dpp::PointCloud;
using o3dpp::Tetra;
using o3dpp::TetraMesh;
using o3dpp::TetraMeshArray;
using o3dpp::Vec3;

namespace {
/// Corners of the unit cube.
std::vector<Vec3> cube_corners() {
    std::vector<Vec3> pts;
    for (double x : {0.0, 1.0})
        for (double y : {0.0, 1.0})
            for (double z : {0.0, 1.0}) pts.push_back({x, y, z});
    return pts;
}

/// |det(b - a, c - a, d - a)| / 6.
double tetra_volume(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d) {
    const Vec3 u{b[0] - a[0], b[1] - a[1], b[2] - a[2]}, v{c[0] - a[0], c[1] - a[1], c[2] - a[2]},
        w{d[0] - a[0], d[1] - a[1], d[2] - a[2]};
    return std::fabs(u[0] * (v[1] * w[2] - v[2] * w[1]) - u[1] * (v[0] * w[2] - v[2] * w[0]) +
                     u[2] * (v[0] * w[1] - v[1] * w[0])) / 6.0;
}

double total_volume(const TetraMesh& mesh) {
    const auto v = mesh.get_vertices();
    double total = 0;
    for (const Tetra& t : mesh.get_tetras()) total += tetra_volume(v[t[0]], v[t[1]], v[t[2]], v[t[3]]);
    return total;
}
}  // namespace

TEST(TetraMesh, ArraysViewsAndClone) {
    TetraMesh mesh({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {1, 1, 1}}, {{0, 1, 2, 3}, {1, 2, 3, 4}});
    EXPECT_EQ(mesh.num_vertices(), 5u);
    EXPECT_EQ(mesh.num_tetras(), 2u);
    EXPECT_TRUE(mesh.has_vertices());
    EXPECT_TRUE(mesh.has_tetras());
    EXPECT_EQ(mesh.get_tetras(), (std::vector<Tetra>{{0, 1, 2, 3}, {1, 2, 3, 4}}));
    EXPECT_EQ(mesh.array_shape(TetraMeshArray::Tetras), (std::array<std::size_t, 2>{2, 4}));
    const auto tetras = mesh.tetras();
    ASSERT_EQ(tetras.size(), 2u);
    EXPECT_EQ(tetras.cols(), 4u);
    EXPECT_EQ(tetras[1][3], 4);
    EXPECT_EQ(mesh.vertices()[4][2], 1.0);
    EXPECT_NEAR(total_volume(mesh), 1.0 / 6.0 + 1.0 / 3.0, 1e-12);

    const TetraMesh copy = mesh.clone();
    mesh.vertices_mutable()[4][2] = 7.0;
    mesh.tetras_mutable()[0][0] = 4;
    EXPECT_EQ(mesh.get_vertices()[4], (Vec3{1, 1, 7}));
    EXPECT_EQ(mesh.get_tetras()[0], (Tetra{4, 1, 2, 3}));
    EXPECT_EQ(copy.get_vertices()[4], (Vec3{1, 1, 1}));
    EXPECT_EQ(copy.get_tetras()[0], (Tetra{0, 1, 2, 3}));

    const TetraMesh empty;
    EXPECT_EQ(empty.num_vertices(), 0u);
    EXPECT_FALSE(empty.has_tetras());
    EXPECT_O3D_ERROR(mesh.set_array(TetraMeshArray::Tetras, std::vector<o3dpp::Triangle>{{0, 1, 2}}),
                     O3D_ERROR_INVALID_ARGUMENT);
}

TEST(TetraMesh, DelaunayOfACubeFillsIt) {
    const auto corners = cube_corners();
    const auto [mesh, point_map] = TetraMesh::create_from_point_cloud(PointCloud(corners));
    EXPECT_EQ(mesh.num_vertices(), 8u);
    EXPECT_GE(mesh.num_tetras(), 5u);
    EXPECT_LE(mesh.num_tetras(), 6u);
    EXPECT_NEAR(total_volume(mesh), 1.0, 1e-12);
    // The point map is a permutation of the input points, and says which point each vertex is.
    ASSERT_EQ(point_map.size(), 8u);
    auto sorted = point_map;
    std::sort(sorted.begin(), sorted.end());
    std::vector<int32_t> identity(8);
    std::iota(identity.begin(), identity.end(), 0);
    EXPECT_EQ(sorted, identity);
    const auto v = mesh.get_vertices();
    for (std::size_t i = 0; i < v.size(); ++i) EXPECT_EQ(v[i], corners[point_map[i]]);
}

TEST(TetraMesh, DelaunayOfScatteredPointsFillsTheirHull) {
    auto pts = o3dpp_test::random_points(60, 0.05, 0.95, 7);
    const auto corners = cube_corners();
    pts.insert(pts.end(), corners.begin(), corners.end());
    const auto [mesh, point_map] = TetraMesh::create_from_point_cloud(PointCloud(pts));
    EXPECT_EQ(mesh.num_vertices(), pts.size());
    EXPECT_EQ(point_map.size(), pts.size());
    EXPECT_GT(mesh.num_tetras(), pts.size());
    EXPECT_NEAR(total_volume(mesh), 1.0, 1e-9);
}

TEST(TetraMesh, IsoSurfaceOfALinearFieldIsAPlane) {
    auto pts = o3dpp_test::random_points(40, 0.05, 0.95, 11);
    const auto corners = cube_corners();
    pts.insert(pts.end(), corners.begin(), corners.end());
    const auto [mesh, point_map] = TetraMesh::create_from_point_cloud(PointCloud(pts));
    // f = x + 2 y + 3 z, level 3: the plane through (1, 1, 0) and (0, 0, 1) cutting the cube.
    std::vector<double> values;
    for (const auto& p : mesh.get_vertices()) values.push_back(p[0] + 2 * p[1] + 3 * p[2]);
    const auto surface = mesh.extract_triangle_mesh(values, 3.0);
    ASSERT_GT(surface.num_triangles(), 0u);
    for (const auto& p : surface.get_vertices()) {
        EXPECT_NEAR(p[0] + 2 * p[1] + 3 * p[2], 3.0, 1e-9);
        for (double c : p) {
            EXPECT_GE(c, -1e-12);
            EXPECT_LE(c, 1 + 1e-12);
        }
    }
    // Cut by the plane z = 0.5 instead, the cube's section is the unit square.
    std::vector<double> z;
    for (const auto& p : mesh.get_vertices()) z.push_back(p[2]);
    const auto square = mesh.extract_triangle_mesh(z, 0.5);
    EXPECT_NEAR(square.get_surface_area(), 1.0, 1e-9);
    for (const auto& p : square.get_vertices()) EXPECT_NEAR(p[2], 0.5, 1e-12);
    // Shared edges give shared vertices: no duplicates to merge.
    auto merged = square.clone();
    merged.remove_duplicated_vertices();
    EXPECT_EQ(merged.num_vertices(), square.num_vertices());
    // A level above every value cuts nothing.
    EXPECT_EQ(mesh.extract_triangle_mesh(z, 2.0).num_triangles(), 0u);
}

TEST(TetraMesh, BadInputThrows) {
    const std::vector<Vec3> three{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
    EXPECT_O3D_ERROR(TetraMesh::create_from_point_cloud(PointCloud(three)), O3D_ERROR_INVALID_ARGUMENT);
    const std::vector<Vec3> flat{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {1, 1, 0}, {0.3, 0.6, 0}};
    EXPECT_O3D_ERROR(TetraMesh::create_from_point_cloud(PointCloud(flat)), O3D_ERROR_INVALID_ARGUMENT);
    auto nan_points = cube_corners();
    nan_points[3][1] = std::nan("");
    EXPECT_O3D_ERROR(TetraMesh::create_from_point_cloud(PointCloud(nan_points)), O3D_ERROR_INVALID_ARGUMENT);

    const auto [mesh, point_map] = TetraMesh::create_from_point_cloud(PointCloud(cube_corners()));
    EXPECT_O3D_ERROR(mesh.extract_triangle_mesh(std::vector<double>(7, 0.0), 0.5), O3D_ERROR_INVALID_ARGUMENT);
    EXPECT_O3D_ERROR(mesh.extract_triangle_mesh(std::vector<double>(8, 0.0), std::nan("")),
                     O3D_ERROR_INVALID_ARGUMENT);
    std::vector<double> with_nan(8, 0.0);
    with_nan[2] = std::nan("");
    EXPECT_O3D_ERROR(mesh.extract_triangle_mesh(with_nan, 0.5), O3D_ERROR_INVALID_ARGUMENT);
    // A tetra naming a vertex that does not exist is refused, not followed.
    TetraMesh broken = mesh.clone();
    broken.tetras_mutable()[0][2] = 8;
    EXPECT_O3D_ERROR(broken.extract_triangle_mesh(std::vector<double>(8, 1.0), 0.5), O3D_ERROR_INVALID_ARGUMENT);
}
