// SPDX-License-Identifier: MIT
// Screened Poisson reconstruction: analytic sphere/torus accuracy, topology, volume, Open3D 0.20.0 counts
// (tools/reference/record_poisson.py), densities, determinism, progress/cancel and bad input.
#include "o3d/geometry/poisson_reconstruction.h"

#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <map>
#include <random>

#include "o3d/geometry/mesh_topology.h"
#include "o3d/utility/error.h"

using namespace o3d::geometry;

namespace {

// The same deterministic lattices as tools/reference/record_poisson.py.
PointCloud fibonacci_sphere(int n, double radius = 1.0) {
    PointCloud pc;
    const double golden = M_PI * (3.0 - std::sqrt(5.0));
    for (int i = 0; i < n; ++i) {
        const double z = 1.0 - (2.0 * i + 1.0) / n, r = std::sqrt(std::max(0.0, 1.0 - z * z));
        const Eigen::Vector3d p(r * std::cos(golden * i), r * std::sin(golden * i), z);
        pc.points.push_back(radius * p);
        pc.normals.push_back(p);
    }
    return pc;
}

PointCloud lattice_torus(int n, double big = 1.0, double small = 0.4) {
    PointCloud pc;
    const double golden = (std::sqrt(5.0) - 1.0) / 2.0;
    for (int i = 0; i < n; ++i) {
        const double u = 2.0 * M_PI * (i + 0.5) / n, t = std::fmod(i * golden, 1.0);
        double v = 2.0 * M_PI * t;
        for (int k = 0; k < 30; ++k)
            v -= (v + (small / big) * std::sin(v) - 2.0 * M_PI * t) / (1.0 + (small / big) * std::cos(v));
        const Eigen::Vector3d c(std::cos(u), std::sin(u), 0.0);
        const Eigen::Vector3d nv = std::cos(v) * c + Eigen::Vector3d(0, 0, std::sin(v));
        pc.points.push_back(big * c + small * nv);
        pc.normals.push_back(nv);
    }
    return pc;
}

double torus_distance(const Eigen::Vector3d& p, double big, double small) {
    const double q = std::hypot(p.x(), p.y()) - big;
    return std::abs(std::hypot(q, p.z()) - small);
}

struct Stats {
    double mean = 0, p99 = 0;
};
template <class F>
Stats distance_stats(const TriangleMesh& m, F dist) {
    std::vector<double> d;
    for (const auto& v : m.vertices) d.push_back(dist(v));
    Stats s;
    for (double x : d) s.mean += x;
    s.mean /= double(d.size());
    std::sort(d.begin(), d.end());
    s.p99 = d[size_t(0.99 * double(d.size() - 1))];
    return s;
}

// Finest cell width of a reconstruction of a cloud whose bounding cube has side `extent`.
double cell_width(double extent, int depth, double scale = 1.1) { return scale * extent / std::ldexp(1.0, depth); }

// Edges used by one triangle, as vertex pairs.
std::vector<std::pair<int, int>> boundary_edges(const TriangleMesh& m) {
    std::map<std::pair<int, int>, int> count;
    for (const auto& t : m.triangles)
        for (int j = 0; j < 3; ++j) {
            const int a = t[j], b = t[(j + 1) % 3];
            ++count[{std::min(a, b), std::max(a, b)}];
        }
    std::vector<std::pair<int, int>> out;
    for (const auto& [e, c] : count)
        if (c == 1) out.push_back(e);
    return out;
}

// Whether p lies on the boundary of the reconstruction cube of `pc` (scale 1.1, as PoissonOptions).
bool on_domain_boundary(const PointCloud& pc, const Eigen::Vector3d& p) {
    Eigen::Vector3d lo = pc.points[0], hi = pc.points[0];
    for (const auto& q : pc.points) lo = lo.cwiseMin(q), hi = hi.cwiseMax(q);
    const double side = 1.1 * (hi - lo).maxCoeff();
    const Eigen::Vector3d c = 0.5 * (lo + hi);
    for (int a = 0; a < 3; ++a)
        if (std::abs(std::abs(p[a] - c[a]) - 0.5 * side) < 1e-9 * side) return true;
    return false;
}

// A sphere sampled 10x more densely above the equator than below (normals outward).
PointCloud two_density_sphere(int upper_n, int lower_n, uint64_t seed) {
    std::mt19937_64 rng(seed);
    std::normal_distribution<double> g;
    PointCloud pc;
    int upper = 0, lower = 0;
    while (upper < upper_n || lower < lower_n) {
        const Eigen::Vector3d d = Eigen::Vector3d(g(rng), g(rng), g(rng)).normalized();
        if (d.z() >= 0 ? upper++ >= upper_n : lower++ >= lower_n) continue;
        pc.points.push_back(d);
        pc.normals.push_back(d);
    }
    return pc;
}

// Mean length of the triangle edges whose midpoints satisfy `where`.
template <class F>
double mean_edge_length(const TriangleMesh& m, F where) {
    double sum = 0;
    int n = 0;
    for (const auto& t : m.triangles)
        for (int j = 0; j < 3; ++j) {
            const Eigen::Vector3d a = m.vertices[size_t(t[j])], b = m.vertices[size_t(t[(j + 1) % 3])];
            if (!where(0.5 * (a + b))) continue;
            sum += (a - b).norm();
            ++n;
        }
    return n ? sum / n : 0.0;
}

}  // namespace

TEST(PoissonReconstruction, SphereIsAccurateClosedAndManifold) {
    const PointCloud pc = fibonacci_sphere(20000);
    PoissonOptions o;
    o.depth = 7;
    const PoissonResult r = create_from_point_cloud_poisson(pc, o);
    const double h = cell_width(2.0, 7);
    const Stats s = distance_stats(r.mesh, [](const Eigen::Vector3d& p) { return std::abs(p.norm() - 1.0); });
    std::printf("sphere: V=%zu T=%zu mean=%.4g p99=%.4g (cell %.4g)\n", r.mesh.vertices.size(),
                r.mesh.triangles.size(), s.mean, s.p99, h);
    EXPECT_LT(s.mean, 0.1 * h);
    EXPECT_LT(s.p99, 0.3 * h);
    EXPECT_TRUE(is_edge_manifold(r.mesh, false));
    EXPECT_TRUE(is_vertex_manifold(r.mesh));
    EXPECT_TRUE(is_watertight(r.mesh));
    const double vol = volume(r.mesh);
    std::printf("sphere volume %.5f vs %.5f\n", vol, 4.0 / 3.0 * M_PI);
    EXPECT_NEAR(vol, 4.0 / 3.0 * M_PI, 0.01 * 4.0 / 3.0 * M_PI);
    // Outward orientation: the signed volume of the triangles as stored is positive.
    double signed_vol = 0;
    for (const auto& t : r.mesh.triangles)
        signed_vol += r.mesh.vertices[size_t(t[0])].dot(
                          r.mesh.vertices[size_t(t[1])].cross(r.mesh.vertices[size_t(t[2])])) / 6.0;
    EXPECT_GT(signed_vol, 0.0);
    // Open3D 0.20.0 on the same lattice, depth 7: 63864 vertices, 127724 triangles.
    EXPECT_NEAR(double(r.mesh.vertices.size()), 63864.0, 0.05 * 63864.0);
    EXPECT_NEAR(double(r.mesh.triangles.size()), 127724.0, 0.05 * 127724.0);
    // Open3D 0.20.0 densities there: min 6.042, median 6.117, max 6.171.
    ASSERT_EQ(r.densities.size(), r.mesh.vertices.size());
    std::vector<double> d = r.densities;
    std::sort(d.begin(), d.end());
    std::printf("sphere densities min %.3f median %.3f max %.3f\n", d.front(), d[d.size() / 2], d.back());
    EXPECT_NEAR(d[d.size() / 2], 6.117, 0.25);
    EXPECT_GT(d.front(), 6.042 - 0.5);
    EXPECT_LT(d.back(), 6.171 + 0.5);
}

TEST(PoissonReconstruction, TorusIsAccurateClosedAndManifold) {
    const double big = 1.0, small = 0.4;
    const PointCloud pc = lattice_torus(30000, big, small);
    PoissonOptions o;
    o.depth = 7;
    const PoissonResult r = create_from_point_cloud_poisson(pc, o);
    const double h = cell_width(2.0 * (big + small), 7);
    const Stats s =
        distance_stats(r.mesh, [&](const Eigen::Vector3d& p) { return torus_distance(p, big, small); });
    std::printf("torus: V=%zu T=%zu mean=%.4g p99=%.4g (cell %.4g)\n", r.mesh.vertices.size(),
                r.mesh.triangles.size(), s.mean, s.p99, h);
    EXPECT_LT(s.mean, 0.1 * h);
    EXPECT_LT(s.p99, 0.3 * h);
    EXPECT_TRUE(is_edge_manifold(r.mesh, false));
    EXPECT_TRUE(is_vertex_manifold(r.mesh));
    EXPECT_TRUE(is_watertight(r.mesh));
    // Genus 1: V - E + F = 0.
    EXPECT_EQ(euler_poincare_characteristic(r.mesh), 0);
    const double truth = 2.0 * M_PI * M_PI * big * small * small;
    std::printf("torus volume %.5f vs %.5f\n", volume(r.mesh), truth);
    EXPECT_NEAR(volume(r.mesh), truth, 0.01 * truth);
    // Open3D 0.20.0 on the same lattice, depth 7: 39402 vertices, 78804 triangles.
    EXPECT_NEAR(double(r.mesh.vertices.size()), 39402.0, 0.05 * 39402.0);
    EXPECT_NEAR(double(r.mesh.triangles.size()), 78804.0, 0.05 * 78804.0);
}

TEST(PoissonReconstruction, NoisySphereStaysWithinBounds) {
    std::mt19937_64 rng(7);
    std::normal_distribution<double> g;
    PointCloud pc;
    for (int i = 0; i < 30000; ++i) {
        const Eigen::Vector3d d = Eigen::Vector3d(g(rng), g(rng), g(rng)).normalized();
        pc.points.push_back(d * (1.0 + 0.005 * g(rng)));
        pc.normals.push_back(d);
    }
    PoissonOptions o;
    o.depth = 7;
    const PoissonResult r = create_from_point_cloud_poisson(pc, o);
    const double h = cell_width(2.0, 7);
    const Stats s = distance_stats(r.mesh, [](const Eigen::Vector3d& p) { return std::abs(p.norm() - 1.0); });
    std::printf("noisy sphere: mean=%.4g p99=%.4g (cell %.4g)\n", s.mean, s.p99, h);
    EXPECT_LT(s.mean, 0.25 * h);
    EXPECT_LT(s.p99, 0.5 * h);
    EXPECT_TRUE(is_watertight(r.mesh));
}

TEST(PoissonReconstruction, DensitiesAreHigherWhereSamplingIsDenser) {
    // Upper hemisphere sampled 10x more densely than the lower one.
    std::mt19937_64 rng(3);
    std::normal_distribution<double> g;
    PointCloud pc;
    int upper = 0, lower = 0;
    while (upper < 20000 || lower < 2000) {
        const Eigen::Vector3d d = Eigen::Vector3d(g(rng), g(rng), g(rng)).normalized();
        if (d.z() >= 0 && upper < 20000) {
            ++upper;
        } else if (d.z() < 0 && lower < 2000) {
            ++lower;
        } else {
            continue;
        }
        pc.points.push_back(d);
        pc.normals.push_back(d);
    }
    PoissonOptions o;
    o.depth = 6;
    const PoissonResult r = create_from_point_cloud_poisson(pc, o);
    ASSERT_EQ(r.densities.size(), r.mesh.vertices.size());
    double up = 0, down = 0;
    int nu = 0, nd = 0;
    for (size_t i = 0; i < r.densities.size(); ++i) {
        ASSERT_TRUE(std::isfinite(r.densities[i]));
        const double z = r.mesh.vertices[i].z();
        if (z > 0.3) up += r.densities[i], ++nu;
        if (z < -0.3) down += r.densities[i], ++nd;
    }
    up /= nu;
    down /= nd;
    std::printf("densities: upper %.3f lower %.3f\n", up, down);
    // 10x the samples per area is log4(10) = 1.66 octree depths.
    EXPECT_NEAR(up - down, std::log(10.0) / std::log(4.0), 0.3);
}

TEST(PoissonReconstruction, ColorsAreInterpolated) {
    PointCloud pc = fibonacci_sphere(8000);
    for (const auto& p : pc.points) pc.colors.push_back(p.z() > 0 ? Eigen::Vector3d(1, 0, 0) : Eigen::Vector3d(0, 0, 1));
    PoissonOptions o;
    o.depth = 5;
    const PoissonResult r = create_from_point_cloud_poisson(pc, o);
    ASSERT_EQ(r.mesh.vertex_colors.size(), r.mesh.vertices.size());
    for (size_t i = 0; i < r.mesh.vertices.size(); ++i) {
        const double z = r.mesh.vertices[i].z();
        if (z > 0.2) {
            EXPECT_NEAR(r.mesh.vertex_colors[i].x(), 1.0, 1e-9);
        }
        if (z < -0.2) {
            EXPECT_NEAR(r.mesh.vertex_colors[i].z(), 1.0, 1e-9);
        }
    }
}

TEST(PoissonReconstruction, SameResultForAnyThreadCount) {
    const PointCloud pc = lattice_torus(10000);
    PoissonOptions o;
    o.depth = 6;
    o.num_threads = 1;
    const PoissonResult a = create_from_point_cloud_poisson(pc, o);
    o.num_threads = 2;
    const PoissonResult b = create_from_point_cloud_poisson(pc, o);
    ASSERT_EQ(a.mesh.vertices.size(), b.mesh.vertices.size());
    ASSERT_EQ(a.mesh.triangles.size(), b.mesh.triangles.size());
    EXPECT_EQ(a.mesh.vertices, b.mesh.vertices);
    EXPECT_EQ(a.mesh.triangles, b.mesh.triangles);
    EXPECT_EQ(a.densities, b.densities);
}

TEST(PoissonReconstruction, ProgressReachesOneAndCancelThrows) {
    const PointCloud pc = fibonacci_sphere(5000);
    PoissonOptions o;
    o.depth = 6;
    std::vector<double> seen;
    o.progress = [&](double f) {
        seen.push_back(f);
        return true;
    };
    create_from_point_cloud_poisson(pc, o);
    ASSERT_FALSE(seen.empty());
    EXPECT_DOUBLE_EQ(seen.back(), 1.0);
    EXPECT_TRUE(std::is_sorted(seen.begin(), seen.end()));
    for (double cut : {0.0, 0.3, 0.9}) {
        o.progress = [cut](double f) { return f <= cut; };
        EXPECT_THROW(create_from_point_cloud_poisson(pc, o), o3d::Cancelled) << cut;
    }
}

TEST(PoissonReconstruction, WidthSetsTheDepth) {
    const PointCloud pc = fibonacci_sphere(5000);
    PoissonOptions o;
    o.width = 2.2 / 32;  // exactly depth 5 on the 2.2-wide cube
    const PoissonResult a = create_from_point_cloud_poisson(pc, o);
    PoissonOptions p;
    p.depth = 5;
    const PoissonResult b = create_from_point_cloud_poisson(pc, p);
    EXPECT_NEAR(double(a.mesh.vertices.size()), double(b.mesh.vertices.size()), 0.02 * b.mesh.vertices.size());
}

TEST(PoissonReconstruction, RejectsBadInput) {
    PointCloud empty;
    EXPECT_THROW(create_from_point_cloud_poisson(empty), o3d::InvalidArgument);
    PointCloud no_normals = fibonacci_sphere(100);
    no_normals.normals.clear();
    EXPECT_THROW(create_from_point_cloud_poisson(no_normals), o3d::InvalidArgument);
    PointCloud nan = fibonacci_sphere(100);
    nan.points[5].x() = std::nan("");
    EXPECT_THROW(create_from_point_cloud_poisson(nan), o3d::InvalidArgument);
    PointCloud nan_normal = fibonacci_sphere(100);
    nan_normal.normals[7].y() = INFINITY;
    EXPECT_THROW(create_from_point_cloud_poisson(nan_normal), o3d::InvalidArgument);
    const PointCloud ok = fibonacci_sphere(100);
    for (int depth : {0, 20, -1}) {
        PoissonOptions o;
        o.depth = depth;
        EXPECT_THROW(create_from_point_cloud_poisson(ok, o), o3d::InvalidArgument) << depth;
    }
    PoissonOptions o;
    o.width = -1;
    EXPECT_THROW(create_from_point_cloud_poisson(ok, o), o3d::InvalidArgument);
    o = PoissonOptions();
    o.width = 1e-9;  // would need depth > 16
    EXPECT_THROW(create_from_point_cloud_poisson(ok, o), o3d::InvalidArgument);
    for (double s : {0.0, -1.0, double(NAN), double(INFINITY)}) {
        o = PoissonOptions();
        o.scale = s;
        EXPECT_THROW(create_from_point_cloud_poisson(ok, o), o3d::InvalidArgument) << s;
    }
}

TEST(PoissonReconstruction, DegenerateCloudsDoNotCrash) {
    PointCloud one;
    one.points.push_back({1, 2, 3});
    one.normals.push_back({0, 0, 1});
    EXPECT_NO_THROW(create_from_point_cloud_poisson(one));
    PointCloud zero_normals = fibonacci_sphere(200);
    for (auto& n : zero_normals.normals) n.setZero();
    const PoissonResult r = create_from_point_cloud_poisson(zero_normals);
    EXPECT_EQ(r.densities.size(), r.mesh.vertices.size());
}

TEST(PoissonReconstruction, SparseRegionsAreExtractedCoarselyWithoutCracks) {
    // The octree follows the sampling density, so the sparse half is meshed on larger cells; where the cell
    // sizes meet, the mesh must still be closed and manifold.
    const PointCloud pc = two_density_sphere(40000, 1500, 11);
    PoissonOptions o;
    o.depth = 8;
    const PoissonResult r = create_from_point_cloud_poisson(pc, o);
    // Closed (every edge has two triangles) and manifold. (Not is_watertight: on random samples marching
    // cubes makes near-degenerate slivers that its self-intersection test can flag.)
    EXPECT_TRUE(is_edge_manifold(r.mesh, false));
    EXPECT_TRUE(is_vertex_manifold(r.mesh));
    const double up = mean_edge_length(r.mesh, [](const Eigen::Vector3d& p) { return p.z() > 0.3; });
    const double down = mean_edge_length(r.mesh, [](const Eigen::Vector3d& p) { return p.z() < -0.3; });
    std::printf("two-density sphere: V=%zu edge length upper %.4g lower %.4g\n", r.mesh.vertices.size(), up, down);
    EXPECT_GT(down, 1.5 * up);
    const Stats s = distance_stats(r.mesh, [](const Eigen::Vector3d& p) { return std::abs(p.norm() - 1.0); });
    EXPECT_LT(s.mean, 0.1 * cell_width(2.0, 7));
    // Outward orientation.
    double signed_vol = 0;
    for (const auto& t : r.mesh.triangles)
        signed_vol += r.mesh.vertices[size_t(t[0])].dot(
                          r.mesh.vertices[size_t(t[1])].cross(r.mesh.vertices[size_t(t[2])])) / 6.0;
    EXPECT_NEAR(signed_vol, 4.0 / 3.0 * M_PI, 0.03 * 4.0 / 3.0 * M_PI);
}

namespace {
// An open scan: the upper half of a sphere only, so the reconstruction bridges the unsampled lower half.
PointCloud hemisphere_scan(int n) {
    PointCloud pc = fibonacci_sphere(2 * n);
    PointCloud out;
    for (size_t i = 0; i < pc.points.size(); ++i)
        if (pc.points[i].z() > 0) out.points.push_back(pc.points[i]), out.normals.push_back(pc.normals[i]);
    return out;
}
}  // namespace

TEST(PoissonReconstruction, BridgingSurfaceIsCoarseAndCrackFree) {
    const PointCloud pc = hemisphere_scan(20000);
    PoissonOptions o;
    o.depth = 8;
    const PoissonResult r = create_from_point_cloud_poisson(pc, o);
    // No cracks between cell sizes: an edge used once lies on the reconstruction cube, where the surface
    // leaves the domain.
    EXPECT_TRUE(is_edge_manifold(r.mesh, true));
    EXPECT_TRUE(is_vertex_manifold(r.mesh));
    for (const auto& [a, b] : boundary_edges(r.mesh)) {
        ASSERT_TRUE(on_domain_boundary(pc, r.mesh.vertices[size_t(a)]) &&
                    on_domain_boundary(pc, r.mesh.vertices[size_t(b)]))
            << r.mesh.vertices[size_t(a)].transpose() << " - " << r.mesh.vertices[size_t(b)].transpose();
    }
    // The sampled cap is meshed at the depth its density supports, the bridge on much larger cells.
    const double h = cell_width(2.0, 8);
    size_t near = 0, far = 0;
    for (const auto& p : r.mesh.vertices) (std::abs(p.norm() - 1.0) < 2 * h && p.z() > 0.05 ? near : far)++;
    const double cap = mean_edge_length(r.mesh, [&](const Eigen::Vector3d& p) { return p.z() > 0.3; });
    const double bridge = mean_edge_length(r.mesh, [&](const Eigen::Vector3d& p) { return p.z() < -0.3; });
    std::printf("hemisphere: V=%zu near %zu far %zu edge length cap %.4g bridge %.4g (cell %.4g)\n",
                r.mesh.vertices.size(), near, far, cap, bridge, h);
    EXPECT_GT(bridge, 2.0 * cap);
    EXPECT_LT(far, near);
    // Closing it along the domain boundary gives a watertight mesh; either way the result does not depend on
    // the thread count.
    o.close_boundary = true;
    o.num_threads = 1;
    const PoissonResult c1 = create_from_point_cloud_poisson(pc, o);
    EXPECT_TRUE(is_edge_manifold(c1.mesh, false));
    EXPECT_TRUE(is_vertex_manifold(c1.mesh));
    o.num_threads = 2;
    const PoissonResult c2 = create_from_point_cloud_poisson(pc, o);
    EXPECT_EQ(c1.mesh.vertices, c2.mesh.vertices);
    EXPECT_EQ(c1.mesh.triangles, c2.mesh.triangles);
}
