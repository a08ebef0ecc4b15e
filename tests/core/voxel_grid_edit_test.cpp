// SPDX-License-Identifier: MIT
// Dense voxel grids, single-voxel edits, cell geometry and mesh voxelization within bounds: analytic cases,
// and Open3D 0.20's numbers recorded by tools/reference/record_voxel_edit_octree.py.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <limits>

#include "o3d/geometry/voxel_grid_edit.h"
#include "o3d/geometry/voxel_grid_mesh_bounds.h"
#include "o3d/geometry/voxel_grid_ops.h"
#include "o3d/utility/error.h"

using namespace o3d::geometry;

namespace {

/// The recording script's checksum: sum over rank r of (r + 1) * (i + 1009 j + 1009^2 k).
int64_t index_checksum(const VoxelGrid& g) {
    int64_t sum = 0;
    for (size_t r = 0; r < g.voxels.size(); ++r) {
        const Eigen::Vector3i& v = g.voxels[r].grid_index;
        sum += static_cast<int64_t>(r + 1) * (v(0) + 1009LL * v(1) + 1009LL * 1009LL * v(2));
    }
    return sum;
}

bool sorted_unique(const VoxelGrid& g) {
    for (size_t i = 1; i < g.voxels.size(); ++i)
        if (!voxel_index_less(g.voxels[i - 1].grid_index, g.voxels[i].grid_index)) return false;
    return true;
}

/// The record script's mesh: an irregular tetrahedron and a sliver triangle.
TriangleMesh tetra_and_sliver() {
    TriangleMesh m;
    m.vertices = {{0.13, 0.07, 0.21}, {1.07, 0.29, 0.33}, {0.41, 1.03, 0.17},
                  {0.52, 0.46, 0.97}, {0.9, 0.9, 0.6},    {0.95, 0.85, 0.62}};
    m.triangles = {{0, 1, 2}, {0, 1, 3}, {1, 2, 3}, {0, 2, 3}, {3, 4, 5}};
    return m;
}

}  // namespace

TEST(VoxelGridEdit, DenseCountsOriginAndCentres) {
    // Open3D 0.20: create_dense((1, 2, 3), c, 0.3, 1.0, 0.95, 0.44) has 9 voxels, max index (2, 2, 0).
    const Eigen::Vector3d color(0.1, 0.2, 0.3);
    const VoxelGrid g = voxel_grid_create_dense({1, 2, 3}, color, 0.3, 1.0, 0.95, 0.44);
    EXPECT_EQ(g.origin, Eigen::Vector3d(1, 2, 3));
    EXPECT_DOUBLE_EQ(g.voxel_size, 0.3);
    ASSERT_EQ(g.voxels.size(), 9u);
    ASSERT_TRUE(sorted_unique(g));
    EXPECT_EQ(g.voxels.front().grid_index, Eigen::Vector3i(0, 0, 0));
    EXPECT_EQ(g.voxels.back().grid_index, Eigen::Vector3i(2, 2, 0));
    for (const Voxel& v : g.voxels) {
        EXPECT_EQ(v.color, color);
        // Cell (i, j, k) is centred at origin + (i + 0.5, j + 0.5, k + 0.5) * 0.3.
        const Eigen::Vector3d c = voxel_center_coordinate(g, v.grid_index);
        for (int a = 0; a < 3; ++a) EXPECT_NEAR(c(a), g.origin(a) + (v.grid_index(a) + 0.5) * 0.3, 1e-15);
    }
    // round(extent / voxel_size), halves away from zero (Open3D 0.20: 0.75 -> 3, 0.749 -> 2, 0.14 -> 0, 0.16 -> 1).
    const Eigen::Vector3d o = Eigen::Vector3d::Zero();
    EXPECT_EQ(voxel_grid_create_dense(o, o, 0.3, 0.75, 0.3, 0.3).voxels.size(), 3u);
    EXPECT_EQ(voxel_grid_create_dense(o, o, 0.3, 0.749, 0.3, 0.3).voxels.size(), 2u);
    EXPECT_EQ(voxel_grid_create_dense(o, o, 0.3, 0.14, 0.3, 0.3).voxels.size(), 0u);
    EXPECT_EQ(voxel_grid_create_dense(o, o, 0.3, 0.16, 0.3, 0.3).voxels.size(), 1u);
    EXPECT_EQ(voxel_grid_create_dense(o, o, 0.25, 1.0, 0.5, 0.75).voxels.size(), 4u * 2u * 3u);
    // A dense grid agrees with voxelizing its own cell centres.
    const VoxelGrid big = voxel_grid_create_dense({-1, 0.5, 2}, o, 0.1, 0.7, 0.4, 0.5);
    ASSERT_EQ(big.voxels.size(), 7u * 4u * 5u);
    std::vector<Eigen::Vector3d> centres;
    for (const Voxel& v : big.voxels) centres.push_back(voxel_center_coordinate(big, v.grid_index));
    for (size_t i = 0; i < centres.size(); ++i) EXPECT_EQ(voxel_index_of(big, centres[i]), big.voxels[i].grid_index);
    EXPECT_EQ(voxels_include(big, {{-0.95, 0.55, 2.05}, {-0.25, 0.55, 2.05}, {-1.05, 0.55, 2.05}}),
              (std::vector<bool>{true, false, false}));
}

TEST(VoxelGridEdit, AddReplacesAndRemoveKeepsOrder) {
    VoxelGrid g = voxel_grid_create_dense(Eigen::Vector3d::Zero(), Eigen::Vector3d::Zero(), 0.5, 1, 1, 1);
    ASSERT_EQ(g.voxels.size(), 8u);
    // Same index: the color is replaced, nothing is added (Open3D 0.20 too).
    add_voxel(g, {{0, 0, 0}, {1, 1, 1}});
    EXPECT_EQ(g.voxels.size(), 8u);
    EXPECT_EQ(g.voxels[0].color, Eigen::Vector3d(1, 1, 1));
    // New indices land in sorted position, negative ones included.
    add_voxel(g, {{-3, 9, 0}, {0.5, 0.5, 0.5}});
    add_voxel(g, {{1, 0, -1}, {0.2, 0.2, 0.2}});
    add_voxel(g, {{5, -7, 2}, {0.3, 0.3, 0.3}});
    ASSERT_EQ(g.voxels.size(), 11u);
    EXPECT_TRUE(sorted_unique(g));
    EXPECT_EQ(g.voxels.front().grid_index, Eigen::Vector3i(-3, 9, 0));
    EXPECT_EQ(g.voxels.back().grid_index, Eigen::Vector3i(5, -7, 2));
    ASSERT_NE(find_voxel(g, {1, 0, -1}), nullptr);
    EXPECT_EQ(find_voxel(g, {1, 0, -1})->color, Eigen::Vector3d(0.2, 0.2, 0.2));
    EXPECT_EQ(find_voxel(g, {2, 0, 0}), nullptr);
    // Removing an existing voxel, then a missing one (a no-op, as Open3D).
    remove_voxel(g, {-3, 9, 0});
    EXPECT_EQ(g.voxels.size(), 10u);
    remove_voxel(g, {-3, 9, 0});
    EXPECT_EQ(g.voxels.size(), 10u);
    remove_voxel(g, {1, 1, 0});
    EXPECT_EQ(g.voxels.size(), 9u);
    EXPECT_EQ(find_voxel(g, {1, 1, 0}), nullptr);
    EXPECT_TRUE(sorted_unique(g));
    EXPECT_THROW(add_voxel(g, {{0, 0, 0}, {NAN, 0, 0}}), o3d::InvalidArgument);
    EXPECT_EQ(g.voxels[0].color, Eigen::Vector3d(1, 1, 1));
}

TEST(VoxelGridEdit, BoundingPointsInOpen3DOrder) {
    // Open3D 0.20, create_dense(0, 0, 0.5, 1, 1, 1).get_voxel_bounding_points([1, 0, 1]).
    const VoxelGrid g = voxel_grid_create_dense(Eigen::Vector3d::Zero(), Eigen::Vector3d::Zero(), 0.5, 1, 1, 1);
    const double open3d[8][3] = {{0.5, 0.0, 0.5}, {0.5, 0.0, 1.0}, {1.0, 0.0, 0.5}, {1.0, 0.0, 1.0},
                                 {0.5, 0.5, 0.5}, {0.5, 0.5, 1.0}, {1.0, 0.5, 0.5}, {1.0, 0.5, 1.0}};
    const std::array<Eigen::Vector3d, 8> p = voxel_bounding_points(g, {1, 0, 1});
    for (int k = 0; k < 8; ++k) EXPECT_EQ(p[k], Eigen::Vector3d(open3d[k][0], open3d[k][1], open3d[k][2])) << k;
    // Analytic on an odd grid, at any cell (occupied or not): the corners are the cell's box.
    VoxelGrid h;
    h.voxel_size = 0.3;
    h.origin = {0.1, -2.0, 7.5};
    const Eigen::Vector3i idx(-4, 11, 2);
    const Eigen::Vector3d lo = h.origin + idx.cast<double>() * 0.3, hi = lo + Eigen::Vector3d::Constant(0.3);
    const Eigen::Vector3d centre = voxel_center_coordinate(h, idx);
    EXPECT_TRUE(centre.isApprox((lo + hi) / 2, 1e-14));
    const std::array<Eigen::Vector3d, 8> q = voxel_bounding_points(h, idx);
    for (int k = 0; k < 8; ++k) {
        const Eigen::Vector3d expect((k & 2) ? hi.x() : lo.x(), (k & 4) ? hi.y() : lo.y(), (k & 1) ? hi.z() : lo.z());
        EXPECT_TRUE(q[k].isApprox(expect, 1e-14)) << k;
        EXPECT_NEAR((q[k] - centre).norm(), 0.15 * std::sqrt(3.0), 1e-14);
    }
}

TEST(VoxelGridEdit, MeshWithinBoundsMatchesOpen3D) {
    const TriangleMesh m = tetra_and_sliver();
    // Open3D 0.20 (record_voxel_edit_octree.py): bounds holding the mesh, 234 voxels.
    VoxelGrid g = voxel_grid_from_triangle_mesh_within_bounds(m, 0.1, {-0.2, -0.1, 0.05}, {1.3, 1.2, 1.1});
    EXPECT_EQ(g.origin, Eigen::Vector3d(-0.2, -0.1, 0.05));
    EXPECT_DOUBLE_EQ(g.voxel_size, 0.1);
    ASSERT_TRUE(sorted_unique(g));
    EXPECT_EQ(g.voxels.size(), 234u);
    EXPECT_EQ(index_checksum(g), 104725704751LL);
    ASSERT_FALSE(g.voxels.empty());
    EXPECT_EQ(g.voxels.front().grid_index.x(), 3);
    for (const Voxel& v : g.voxels) EXPECT_TRUE(v.color.isZero());
    // Asking for 2 threads changes nothing.
    const VoxelGrid two = voxel_grid_from_triangle_mesh_within_bounds(m, 0.1, {-0.2, -0.1, 0.05}, {1.3, 1.2, 1.1}, 2);
    EXPECT_EQ(index_checksum(two), index_checksum(g));

    // Bounds cutting the mesh: Open3D 0.20 keeps all 244 cells it touches; the 108 of them with indices in
    // [0, floor((max - min) / 0.1)] = [0, (5, 4, 4)] are what o3d keeps.
    g = voxel_grid_from_triangle_mesh_within_bounds(m, 0.1, {0.3, 0.25, 0.2}, {0.8, 0.7, 0.65});
    EXPECT_EQ(g.voxels.size(), 108u);
    EXPECT_EQ(index_checksum(g), 11053528968LL);
    for (const Voxel& v : g.voxels) {
        EXPECT_TRUE((v.grid_index.array() >= 0).all());
        EXPECT_TRUE((v.grid_index.array() <= Eigen::Array3i(5, 4, 4)).all());
    }
}

TEST(VoxelGridEdit, MeshWithinBoundsAgreesWithTheMeshGrid) {
    // With min_bound = the mesh's min - voxel/2 and max_bound = the max + voxel/2, the grid is
    // voxel_grid_from_triangle_mesh's.
    const TriangleMesh m = tetra_and_sliver();
    const double s = 0.07;
    const VoxelGrid ref = voxel_grid_from_triangle_mesh(m, s);
    Eigen::Vector3d lo = m.vertices[0], hi = m.vertices[0];
    for (const Eigen::Vector3d& v : m.vertices) lo = lo.cwiseMin(v), hi = hi.cwiseMax(v);
    const Eigen::Vector3d half = Eigen::Vector3d::Constant(s / 2);
    const VoxelGrid g = voxel_grid_from_triangle_mesh_within_bounds(m, s, lo - half, hi + half);
    EXPECT_TRUE(g.origin.isApprox(ref.origin));
    ASSERT_EQ(g.voxels.size(), ref.voxels.size());
    EXPECT_EQ(index_checksum(g), index_checksum(ref));
    // A triangle lying in the plane z = 0.3, one voxel layer: cell (i, j) overlaps iff i + j <= 8
    // (its lower-left corner (0.25 i, 0.25 j) has x + y <= 2; touching counts), as Open3D 0.20 (45 voxels).
    TriangleMesh flat;
    flat.vertices = {{0, 0, 0.3}, {2, 0, 0.3}, {0, 2, 0.3}};
    flat.triangles = {{0, 1, 2}};
    const VoxelGrid f = voxel_grid_from_triangle_mesh_within_bounds(flat, 0.25, {0, 0, 0}, {2.5, 2.5, 1});
    EXPECT_EQ(f.voxels.size(), 45u);
    for (const Voxel& v : f.voxels) {
        EXPECT_EQ(v.grid_index.z(), 1);
        EXPECT_LE(v.grid_index.x() + v.grid_index.y(), 8);
    }
}

TEST(VoxelGridEdit, MeshWithinBoundsThreadCountDoesNotMatter) {
    // A wavy 36 x 36 grid of quads: 2592 triangles, enough for the parallel path.
    TriangleMesh m;
    const int n = 36;
    for (int j = 0; j <= n; ++j)
        for (int i = 0; i <= n; ++i)
            m.vertices.emplace_back(i / double(n), j / double(n), 0.5 + 0.2 * std::sin(6.0 * i / n) * std::cos(5.0 * j / n));
    for (int j = 0; j < n; ++j)
        for (int i = 0; i < n; ++i) {
            const int a = j * (n + 1) + i;
            m.triangles.push_back({a, a + 1, a + n + 2});
            m.triangles.push_back({a, a + n + 2, a + n + 1});
        }
    const VoxelGrid one = voxel_grid_from_triangle_mesh_within_bounds(m, 0.02, {0, 0, 0}, {1, 1, 1}, 1);
    const VoxelGrid two = voxel_grid_from_triangle_mesh_within_bounds(m, 0.02, {0, 0, 0}, {1, 1, 1}, 2);
    // Open3D 0.20 on the same mesh (numpy's sin and cos): 4661 voxels, all inside the bounds.
    EXPECT_EQ(one.voxels.size(), 4661u);
    EXPECT_EQ(index_checksum(one), 278295295205643LL);
    ASSERT_EQ(one.voxels.size(), two.voxels.size());
    EXPECT_EQ(index_checksum(one), index_checksum(two));
    EXPECT_TRUE(sorted_unique(two));
}

TEST(VoxelGridEdit, BadInputsAreErrors) {
    const Eigen::Vector3d o = Eigen::Vector3d::Zero();
    const double inf = std::numeric_limits<double>::infinity();
    EXPECT_THROW(voxel_grid_create_dense(o, o, 0.0, 1, 1, 1), o3d::InvalidArgument);
    EXPECT_THROW(voxel_grid_create_dense(o, o, -0.5, 1, 1, 1), o3d::InvalidArgument);
    EXPECT_THROW(voxel_grid_create_dense(o, o, NAN, 1, 1, 1), o3d::InvalidArgument);
    EXPECT_THROW(voxel_grid_create_dense(o, o, 0.5, -1, 1, 1), o3d::InvalidArgument);
    EXPECT_THROW(voxel_grid_create_dense(o, o, 0.5, 1, inf, 1), o3d::InvalidArgument);
    EXPECT_THROW(voxel_grid_create_dense(o, o, 0.5, 1, 1, NAN), o3d::InvalidArgument);
    EXPECT_THROW(voxel_grid_create_dense({NAN, 0, 0}, o, 0.5, 1, 1, 1), o3d::InvalidArgument);
    EXPECT_THROW(voxel_grid_create_dense(o, {0, inf, 0}, 0.5, 1, 1, 1), o3d::InvalidArgument);
    // 2048^3 = 2^33 voxels, and an extent whose voxel count alone overflows: refused before allocating.
    EXPECT_THROW(voxel_grid_create_dense(o, o, 1.0, 2048, 2048, 2048), o3d::InvalidArgument);
    EXPECT_THROW(voxel_grid_create_dense(o, o, 1e-300, 1, 1, 1), o3d::InvalidArgument);
    // A zero extent is an empty grid (as Open3D).
    EXPECT_TRUE(voxel_grid_create_dense(o, o, 1.0, 0, 2048, 2048).voxels.empty());

    TriangleMesh m = tetra_and_sliver();
    const Eigen::Vector3d lo(0, 0, 0), hi(1, 1, 1);
    EXPECT_THROW(voxel_grid_from_triangle_mesh_within_bounds(m, 0.0, lo, hi), o3d::InvalidArgument);
    EXPECT_THROW(voxel_grid_from_triangle_mesh_within_bounds(m, NAN, lo, hi), o3d::InvalidArgument);
    EXPECT_THROW(voxel_grid_from_triangle_mesh_within_bounds(m, 0.1, hi, lo), o3d::InvalidArgument);
    EXPECT_THROW(voxel_grid_from_triangle_mesh_within_bounds(m, 0.1, {NAN, 0, 0}, hi), o3d::InvalidArgument);
    EXPECT_THROW(voxel_grid_from_triangle_mesh_within_bounds(m, 1e-12, lo, hi), o3d::InvalidArgument);
    // Bounds far from the mesh at a fine voxel: the triangles' cells are beyond int32 but clipped away.
    EXPECT_TRUE(voxel_grid_from_triangle_mesh_within_bounds(m, 1e-6, {100, 100, 100}, {100.001, 100.001, 100.001})
                    .voxels.empty());
    m.triangles.push_back({0, 1, 6});
    EXPECT_THROW(voxel_grid_from_triangle_mesh_within_bounds(m, 0.1, lo, hi), o3d::InvalidArgument);
    m.triangles.pop_back();
    m.vertices[2].x() = inf;
    EXPECT_THROW(voxel_grid_from_triangle_mesh_within_bounds(m, 0.1, lo, hi), o3d::InvalidArgument);
    EXPECT_THROW(voxel_grid_from_triangle_mesh_within_bounds(TriangleMesh{}, 0.1, lo, hi), o3d::InvalidArgument);
}
