// SPDX-License-Identifier: MIT
// As-rigid-as-possible deformation. The bar references come from open3d 0.20 on the same input:
//   m = o3d.geometry.TriangleMesh.create_cylinder(0.3, 2.0, 8, 6); P = np.asarray(m.vertices)
//   ci = [i for i in range(len(P)) if abs(abs(P[i, 2]) - 1) < 1e-9]
//   cp = P[ci].copy(); cp[cp[:, 2] > 0] += [0.6, 0.0, -0.2]
//   Q = np.asarray(m.deform_as_rigid_as_possible(o3d.utility.IntVector(ci),
//           o3d.utility.Vector3dVector(cp), 10, energy, alpha).vertices)
//   print(Q.mean(0), (Q ** 2).sum(), Q[5], Q[20], Q[33])
// with (Spokes, 0.01) and (Smoothed, 0.05).
#include <Eigen/Geometry>
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <vector>

#include "o3d/geometry/mesh_adjacency.h"
#include "o3d/geometry/mesh_deform_arap.h"
#include "o3d/geometry/mesh_primitives.h"
#include "o3d/utility/error.h"

using namespace o3d::geometry;
using V = Eigen::Vector3d;

namespace {

struct Bar {
    TriangleMesh mesh = create_cylinder(0.3, 2.0, 8, 6);
    std::vector<int> indices;
    std::vector<V> positions;
    Bar() {
        for (int i = 0; i < static_cast<int>(mesh.vertices.size()); ++i)
            if (std::abs(std::abs(mesh.vertices[i].z()) - 1) < 1e-9) {
                indices.push_back(i);
                positions.push_back(mesh.vertices[i] + (mesh.vertices[i].z() > 0 ? V(0.6, 0, -0.2) : V::Zero()));
            }
    }
};

double max_distance(const std::vector<V>& a, const std::vector<V>& b) {
    double d = 0;
    for (size_t i = 0; i < a.size(); ++i) d = std::max(d, (a[i] - b[i]).norm());
    return d;
}

/// @brief Root mean square of the relative change of the edge lengths.
double edge_strain(const TriangleMesh& before, const TriangleMesh& after) {
    const MeshEdges edges = mesh_edges(before);
    double sum = 0;
    for (const Eigen::Vector2i& e : edges.endpoints) {
        const double l0 = (before.vertices[e(0)] - before.vertices[e(1)]).norm();
        const double l1 = (after.vertices[e(0)] - after.vertices[e(1)]).norm();
        sum += (l1 / l0 - 1) * (l1 / l0 - 1);
    }
    return std::sqrt(sum / edges.size());
}

}  // namespace

TEST(DeformArap, RigidMotionOfTheConstraintsMovesTheMeshRigidly) {
    const TriangleMesh sphere = create_sphere(1.0, 8);
    const Eigen::Matrix3d r = Eigen::AngleAxisd(0.6, V(1, 2, 3).normalized()).toRotationMatrix();
    const V t(0.4, -1.0, 2.0);
    std::vector<int> indices;
    std::vector<V> positions;
    for (int i = 0; i < static_cast<int>(sphere.vertices.size()); ++i)
        if (std::abs(sphere.vertices[i].z()) > 0.5) {
            indices.push_back(i);
            positions.push_back(r * sphere.vertices[i] + t);
        }
    const TriangleMesh out = deform_as_rigid_as_possible(sphere, indices, positions, 60);
    std::vector<V> expected;
    for (const V& p : sphere.vertices) expected.push_back(r * p + t);
    EXPECT_LT(max_distance(out.vertices, expected), 1e-6);
    EXPECT_EQ(out.triangles, sphere.triangles);
}

TEST(DeformArap, ConstraintsInPlaceLeaveTheMeshUnchanged) {
    const TriangleMesh sphere = create_sphere(1.0, 6);
    const std::vector<int> indices = {0, 1, 17};
    std::vector<V> positions;
    for (const int i : indices) positions.push_back(sphere.vertices[i]);
    for (const ArapEnergy energy : {ArapEnergy::Spokes, ArapEnergy::Smoothed}) {
        const TriangleMesh out = deform_as_rigid_as_possible(sphere, indices, positions, 5, energy);
        EXPECT_LT(max_distance(out.vertices, sphere.vertices), 1e-12);
    }
    // No iteration: the input positions, constraints not applied (as Open3D).
    const TriangleMesh zero = deform_as_rigid_as_possible(sphere, {0}, {V(5, 5, 5)}, 0);
    EXPECT_EQ(zero.vertices, sphere.vertices);
}

TEST(DeformArap, BarMatchesOpen3DAndKeepsEdgeLengths) {
    const Bar bar;
    ASSERT_EQ(bar.mesh.vertices.size(), 58u);
    ASSERT_EQ(bar.indices.size(), 18u);
    TriangleMesh input = bar.mesh;
    input.vertex_colors.assign(input.vertices.size(), V(1, 0, 0));
    const TriangleMesh out = deform_as_rigid_as_possible(input, bar.indices, bar.positions, 10);
    // open3d 0.20
    V mean = V::Zero();
    double sumsq = 0;
    for (const V& p : out.vertices) {
        mean += p;
        sumsq += p.squaredNorm();
    }
    mean /= static_cast<double>(out.vertices.size());
    EXPECT_LT((mean - V(0.3, 0.0, -0.1)).norm(), 1e-9);
    EXPECT_NEAR(sumsq, 35.121503507095, 1e-9);
    EXPECT_LT((out.vertices[5] - V(0.387867965644, 0.212132034356, 0.800000000000)).norm(), 1e-9);
    EXPECT_LT((out.vertices[20] - V(0.426828197454, 0.300819335080, 0.192082018493)).norm(), 1e-9);
    EXPECT_LT((out.vertices[33] - V(0.501735005531, -0.212448965706, -0.165252282554)).norm(), 1e-9);
    // Only vertices and triangles come back (as Open3D).
    EXPECT_TRUE(out.vertex_colors.empty());
    EXPECT_EQ(out.triangles, bar.mesh.triangles);
    for (size_t k = 0; k < bar.indices.size(); ++k) EXPECT_LT((out.vertices[bar.indices[k]] - bar.positions[k]).norm(), 1e-15);

}

TEST(DeformArap, BendingKeepsEdgeLengthsBetterThanALaplacianSolve) {
    // The bar bent by 90 degrees about the y axis into a quarter circle of its own length: the top cap is
    // placed and turned where that arc ends, the bottom held. One iteration is the plain Laplacian solve
    // (every rotation the identity), which shears and squashes the bar; ARAP keeps the edge lengths better.
    Bar bar;
    const Eigen::Matrix3d turn = Eigen::AngleAxisd(M_PI / 2, V::UnitY()).toRotationMatrix();
    const double radius = 2.0 / (M_PI / 2);
    const V arc_end(radius, 0, -1 + radius), top(0, 0, 1);
    for (size_t k = 0; k < bar.indices.size(); ++k)
        if (bar.mesh.vertices[bar.indices[k]].z() > 0)
            bar.positions[k] = arc_end + turn * (bar.mesh.vertices[bar.indices[k]] - top);
    const TriangleMesh laplacian = deform_as_rigid_as_possible(bar.mesh, bar.indices, bar.positions, 1);
    const TriangleMesh arap = deform_as_rigid_as_possible(bar.mesh, bar.indices, bar.positions, 30);
    // Measured: 0.10 against 0.21.
    EXPECT_LT(edge_strain(bar.mesh, arap), 0.6 * edge_strain(bar.mesh, laplacian));
}

TEST(DeformArap, SmoothedEnergyMatchesOpen3DAndDiffersFromSpokes) {
    const Bar bar;
    const TriangleMesh spokes = deform_as_rigid_as_possible(bar.mesh, bar.indices, bar.positions, 10);
    const TriangleMesh smoothed =
        deform_as_rigid_as_possible(bar.mesh, bar.indices, bar.positions, 10, ArapEnergy::Smoothed, 0.05);
    EXPECT_GT(max_distance(spokes.vertices, smoothed.vertices), 1e-2);
    double sumsq = 0;
    for (const V& p : smoothed.vertices) sumsq += p.squaredNorm();
    // open3d 0.20
    EXPECT_NEAR(sumsq, 35.070278882656, 1e-9);
    EXPECT_LT((smoothed.vertices[20] - V(0.408048210028, 0.300037033202, 0.198310911563)).norm(), 1e-9);
    EXPECT_LT((smoothed.vertices[33] - V(0.507671795145, -0.212167184153, -0.141999483479)).norm(), 1e-9);
    // alpha = 0 is the spokes energy.
    const TriangleMesh zero_alpha =
        deform_as_rigid_as_possible(bar.mesh, bar.indices, bar.positions, 10, ArapEnergy::Smoothed, 0.0);
    EXPECT_LT(max_distance(spokes.vertices, zero_alpha.vertices), 1e-12);
}

TEST(DeformArap, DeterministicForAnyThreadCount) {
    // Large enough (762 vertices) for the per-vertex loops to run in parallel.
    const TriangleMesh sphere = create_sphere(1.0, 20);
    ASSERT_GE(sphere.vertices.size(), 512u);
    const std::vector<int> indices = {0, 1};
    const std::vector<V> positions = {V(0.3, 0, 1.2), sphere.vertices[1]};
    const TriangleMesh one = deform_as_rigid_as_possible(sphere, indices, positions, 3, ArapEnergy::Smoothed, 0.01, 1);
    EXPECT_GT(max_distance(one.vertices, sphere.vertices), 0.1);
    for (const int threads : {2, 4}) {
        const TriangleMesh many =
            deform_as_rigid_as_possible(sphere, indices, positions, 3, ArapEnergy::Smoothed, 0.01, threads);
        EXPECT_EQ(one.vertices, many.vertices);
    }
}

TEST(DeformArap, UnconstrainedPartsStayInPlace) {
    // A bar and a far-away tetrahedron (plus an unreferenced vertex); only the bar is constrained.
    Bar bar;
    TriangleMesh mesh = bar.mesh;
    const int base = static_cast<int>(mesh.vertices.size());
    for (const V& p : {V(5, 0, 0), V(6, 0, 0), V(5, 1, 0), V(5, 0, 1), V(9, 9, 9)}) mesh.vertices.push_back(p);
    for (const Eigen::Vector3i& t : {Eigen::Vector3i(0, 2, 1), Eigen::Vector3i(0, 1, 3), Eigen::Vector3i(0, 3, 2),
                                     Eigen::Vector3i(1, 2, 3)})
        mesh.triangles.push_back(t + Eigen::Vector3i::Constant(base));
    const TriangleMesh out = deform_as_rigid_as_possible(mesh, bar.indices, bar.positions, 10);
    const TriangleMesh alone = deform_as_rigid_as_possible(bar.mesh, bar.indices, bar.positions, 10);
    for (int i = 0; i < base; ++i) EXPECT_LT((out.vertices[i] - alone.vertices[i]).norm(), 1e-12);
    for (int i = base; i < base + 5; ++i) EXPECT_EQ(out.vertices[i], mesh.vertices[i]);
}

TEST(DeformArap, BadInputThrows) {
    const Bar bar;
    const TriangleMesh& m = bar.mesh;
    const double nan = std::numeric_limits<double>::quiet_NaN();
    EXPECT_THROW(deform_as_rigid_as_possible(m, {99}, {V::Zero()}, 5), o3d::InvalidArgument);
    EXPECT_THROW(deform_as_rigid_as_possible(m, {-1}, {V::Zero()}, 5), o3d::InvalidArgument);
    EXPECT_THROW(deform_as_rigid_as_possible(m, {0, 0}, {V::Zero(), V::Zero()}, 5), o3d::InvalidArgument);
    EXPECT_THROW(deform_as_rigid_as_possible(m, {0}, {V::Zero(), V::Zero()}, 5), o3d::InvalidArgument);
    EXPECT_THROW(deform_as_rigid_as_possible(m, {0}, {V(nan, 0, 0)}, 5), o3d::InvalidArgument);
    EXPECT_THROW(deform_as_rigid_as_possible(m, {0}, {V::Zero()}, -1), o3d::InvalidArgument);
    EXPECT_THROW(deform_as_rigid_as_possible(m, {0}, {V::Zero()}, 5, ArapEnergy::Smoothed, nan), o3d::InvalidArgument);
    EXPECT_THROW(deform_as_rigid_as_possible(m, {0}, {V::Zero()}, 5, static_cast<ArapEnergy>(2)), o3d::InvalidArgument);
    // Open3D solves a singular system and returns garbage; here it is refused.
    EXPECT_THROW(deform_as_rigid_as_possible(m, {}, {}, 5), o3d::InvalidArgument);
    EXPECT_THROW(deform_as_rigid_as_possible(TriangleMesh{}, {0}, {V::Zero()}, 5), o3d::InvalidArgument);
    TriangleMesh bad = m;
    bad.triangles[0](1) = 1000;
    EXPECT_THROW(deform_as_rigid_as_possible(bad, {0}, {V::Zero()}, 5), o3d::InvalidArgument);
    bad = m;
    bad.vertices[3].x() = std::numeric_limits<double>::infinity();
    EXPECT_THROW(deform_as_rigid_as_possible(bad, {0}, {V::Zero()}, 5), o3d::InvalidArgument);
}
