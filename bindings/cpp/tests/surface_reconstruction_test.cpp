// SPDX-License-Identifier: MIT
// Surface reconstruction through the wrapper: Poisson and ball pivoting rebuild a sampled sphere, the alpha shape
// of a convex sampling with a huge alpha is its convex hull (with or without a precomputed tetra mesh), progress
// rises and cancels when the callback returns false, and bad input throws.
#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <vector>

#include "test_util.hpp"

using o3dpp::PointCloud;
using o3dpp::PoissonOptions;
using o3dpp::ProgressOptions;
using o3dpp::TetraMesh;
using o3dpp::TriangleMesh;
using o3dpp::Vec3;
using o3dpp_test::sphere_cloud;

namespace {
constexpr double kPi = 3.14159265358979323846;

double distance(const Vec3& a, const Vec3& b) {
    return std::sqrt((a[0] - b[0]) * (a[0] - b[0]) + (a[1] - b[1]) * (a[1] - b[1]) + (a[2] - b[2]) * (a[2] - b[2]));
}

/// Records the fractions a progress callback sees; `stop_after` calls return false from then on.
struct Recorder {
    std::vector<double> seen;
    std::size_t stop_after = std::numeric_limits<std::size_t>::max();
    o3dpp::ProgressCallback callback() {
        return [this](double f) {
            seen.push_back(f);
            return seen.size() < stop_after;
        };
    }
    void expect_rising_fractions() const {
        ASSERT_FALSE(seen.empty());
        for (std::size_t i = 0; i < seen.size(); ++i) {
            EXPECT_GE(seen[i], 0.0);
            EXPECT_LE(seen[i], 1.0);
            if (i > 0) {
                EXPECT_GE(seen[i], seen[i - 1]);
            }
        }
    }
};
}  // namespace

TEST(Poisson, OptionsComeFromTheCHeader) {
    o3d_poisson_options_t c;
    o3dpp::check(o3d_poisson_options_init(&c, sizeof c));
    const PoissonOptions o;
    EXPECT_EQ(o.depth, c.depth);
    EXPECT_EQ(o.width, c.width);
    EXPECT_EQ(o.scale, c.scale);
    EXPECT_EQ(o.linear_fit, c.linear_fit != 0);
    EXPECT_EQ(o.num_threads, c.num_threads);
    EXPECT_FALSE(o.progress);
    o3d_progress_options_t p;
    o3dpp::check(o3d_progress_options_init(&p, sizeof p));
    EXPECT_EQ(ProgressOptions().num_threads, p.num_threads);
}

TEST(Poisson, SphereWithOutwardNormalsGivesAWatertightSphere) {
    const PointCloud cloud = sphere_cloud(3000, 2.0, {1, -1, 0.5});
    PoissonOptions options;
    options.depth = 6;
    const auto [mesh, densities] = TriangleMesh::create_from_point_cloud_poisson(cloud, options);
    ASSERT_GT(mesh.num_triangles(), 100u);
    ASSERT_EQ(densities.size(), mesh.num_vertices());
    for (double d : densities) EXPECT_TRUE(std::isfinite(d));
    // Cells at depth 6 of a 4.4-wide cube are 0.07 wide: the vertices lie on the sphere to a fraction of that.
    double mean = 0;
    for (const auto& v : mesh.get_vertices()) {
        const double r = distance(v, {1, -1, 0.5});
        EXPECT_NEAR(r, 2.0, 0.05);
        mean += r;
    }
    EXPECT_NEAR(mean / static_cast<double>(mesh.num_vertices()), 2.0, 0.01);
    // Closed, manifold, of a sphere's topology (is_watertight would add a slow self-intersection test).
    EXPECT_TRUE(mesh.is_edge_manifold(/*allow_boundary_edges=*/false));
    EXPECT_TRUE(mesh.is_vertex_manifold());
    EXPECT_EQ(mesh.euler_poincare_characteristic(), 2);
    EXPECT_NEAR(mesh.get_volume(), 4.0 / 3.0 * kPi * 8.0, 0.01 * 4.0 / 3.0 * kPi * 8.0);

    // Open3D's trim: drop the vertices whose density is below a quantile.
    std::vector<double> sorted = densities;
    std::sort(sorted.begin(), sorted.end());
    const double cut = sorted[sorted.size() / 10];
    std::vector<bool> low;
    for (double d : densities) low.push_back(d < cut);
    TriangleMesh trimmed = mesh.clone();
    trimmed.remove_vertices_by_mask(low);
    EXPECT_EQ(trimmed.num_vertices(),
              mesh.num_vertices() - static_cast<std::size_t>(std::count(low.begin(), low.end(), true)));
}

TEST(Poisson, SameResultForAnyThreadCount) {
    const PointCloud cloud = sphere_cloud(1000);
    PoissonOptions one;
    one.depth = 5;
    one.num_threads = 1;
    PoissonOptions four = one;
    four.num_threads = 4;
    const auto a = TriangleMesh::create_from_point_cloud_poisson(cloud, one);
    const auto b = TriangleMesh::create_from_point_cloud_poisson(cloud, four);
    EXPECT_EQ(a.first.get_vertices(), b.first.get_vertices());
    EXPECT_EQ(a.first.get_triangles(), b.first.get_triangles());
    EXPECT_EQ(a.second, b.second);
}

TEST(Poisson, ReportsProgressCancelsAndRethrowsTheCallbacksException) {
    const PointCloud cloud = sphere_cloud(1000);
    PoissonOptions options;
    options.depth = 5;
    Recorder all;
    options.progress = all.callback();
    EXPECT_GT(TriangleMesh::create_from_point_cloud_poisson(cloud, options).first.num_triangles(), 0u);
    all.expect_rising_fractions();

    Recorder first_only;
    first_only.stop_after = 1;
    options.progress = first_only.callback();
    EXPECT_O3D_ERROR(TriangleMesh::create_from_point_cloud_poisson(cloud, options), O3D_ERROR_CANCELLED);
    EXPECT_EQ(first_only.seen.size(), 1u);

    options.progress = [](double) -> bool { throw std::domain_error("stop here"); };
    EXPECT_THROW(TriangleMesh::create_from_point_cloud_poisson(cloud, options), std::domain_error);
}

TEST(Poisson, BadInputThrows) {
    PointCloud no_normals(sphere_cloud(200).get_points());
    EXPECT_O3D_ERROR(TriangleMesh::create_from_point_cloud_poisson(no_normals), O3D_ERROR_INVALID_ARGUMENT);
    EXPECT_O3D_ERROR(TriangleMesh::create_from_point_cloud_poisson(PointCloud()), O3D_ERROR_INVALID_ARGUMENT);
    PoissonOptions too_deep;
    too_deep.depth = 17;
    EXPECT_O3D_ERROR(TriangleMesh::create_from_point_cloud_poisson(sphere_cloud(200), too_deep),
                     O3D_ERROR_INVALID_ARGUMENT);
    PoissonOptions no_scale;
    no_scale.scale = 0;
    EXPECT_O3D_ERROR(TriangleMesh::create_from_point_cloud_poisson(sphere_cloud(200), no_scale),
                     O3D_ERROR_INVALID_ARGUMENT);
}

TEST(BallPivoting, DenseSphereGivesItsAreaOnTheInputPoints) {
    // 4000 points on the unit sphere are about 0.056 apart: balls of twice and three times that close the surface.
    const PointCloud cloud = sphere_cloud(4000);
    const auto mesh = TriangleMesh::create_from_point_cloud_ball_pivoting(cloud, {0.1, 0.15});
    EXPECT_EQ(mesh.get_vertices(), cloud.get_points());
    EXPECT_EQ(mesh.get_vertex_normals(), cloud.get_normals());
    // A closed sphere: every edge in two triangles, V - E + F = 2 (so 7996 triangles).
    EXPECT_TRUE(mesh.is_edge_manifold(/*allow_boundary_edges=*/false));
    EXPECT_EQ(mesh.euler_poincare_characteristic(), 2);
    EXPECT_NEAR(mesh.get_surface_area(), 4 * kPi, 0.01 * 4 * kPi);
    // Wound to agree with the outward normals.
    const auto v = mesh.get_vertices();
    std::size_t outward = 0;
    for (const auto& t : mesh.get_triangles()) {
        const Vec3 a = v[t[0]], b = v[t[1]], c = v[t[2]];
        const Vec3 e1{b[0] - a[0], b[1] - a[1], b[2] - a[2]}, e2{c[0] - a[0], c[1] - a[1], c[2] - a[2]};
        const Vec3 n{e1[1] * e2[2] - e1[2] * e2[1], e1[2] * e2[0] - e1[0] * e2[2], e1[0] * e2[1] - e1[1] * e2[0]};
        if (n[0] * a[0] + n[1] * a[1] + n[2] * a[2] > 0) ++outward;
    }
    EXPECT_EQ(outward, mesh.num_triangles());
}

TEST(BallPivoting, ReportsProgressAndCancels) {
    const PointCloud cloud = sphere_cloud(1000);
    Recorder all;
    ProgressOptions options;
    options.progress = all.callback();
    EXPECT_GT(TriangleMesh::create_from_point_cloud_ball_pivoting(cloud, {0.2, 0.3}, options).num_triangles(), 0u);
    all.expect_rising_fractions();
    options.progress = [](double) { return false; };
    EXPECT_O3D_ERROR(TriangleMesh::create_from_point_cloud_ball_pivoting(cloud, {0.2, 0.3}, options),
                     O3D_ERROR_CANCELLED);
}

TEST(BallPivoting, BadInputThrows) {
    const PointCloud cloud = sphere_cloud(200);
    EXPECT_O3D_ERROR(TriangleMesh::create_from_point_cloud_ball_pivoting(cloud, {}), O3D_ERROR_INVALID_ARGUMENT);
    EXPECT_O3D_ERROR(TriangleMesh::create_from_point_cloud_ball_pivoting(cloud, {0.2, -0.1}),
                     O3D_ERROR_INVALID_ARGUMENT);
    EXPECT_O3D_ERROR(TriangleMesh::create_from_point_cloud_ball_pivoting(cloud, {std::nan("")}),
                     O3D_ERROR_INVALID_ARGUMENT);
    EXPECT_O3D_ERROR(TriangleMesh::create_from_point_cloud_ball_pivoting(PointCloud(cloud.get_points()), {0.2}),
                     O3D_ERROR_INVALID_ARGUMENT);
}

TEST(AlphaShape, HugeAlphaGivesTheConvexHull) {
    // Random points in a cube: in general position (no five on a sphere), so the hull's faces are triangles.
    const PointCloud cloud(o3dpp_test::random_points(400));
    const auto [hull, hull_points] = o3dpp::compute_convex_hull(cloud);
    const auto shape = TriangleMesh::create_from_point_cloud_alpha_shape(cloud, 1e6);
    EXPECT_EQ(shape.num_triangles(), hull.num_triangles());
    // The alpha is beyond every circumradius: even the flat slivers on the hull (four nearly coplanar points, radii
    // up to ~1e3 for such samplings) are in, so the shape is the whole Delaunay volume.
    EXPECT_NEAR(shape.get_surface_area(), hull.get_surface_area(), 1e-9);
    EXPECT_NEAR(shape.get_volume(), hull.get_volume(), 1e-9);
    // Its used vertices are the hull's points.
    auto used = shape.clone();
    used.remove_unreferenced_vertices();
    auto got = used.get_vertices(), want = hull.get_vertices();
    std::sort(got.begin(), got.end());
    std::sort(want.begin(), want.end());
    EXPECT_EQ(got, want);
}

TEST(AlphaShape, SmallAlphaKeepsLessAndATetraMeshIsReused) {
    const PointCloud cloud(o3dpp_test::random_points(400));
    // A circumradius is at least half an edge, and no two of these points are 2e-4 apart: nothing is left.
    EXPECT_EQ(TriangleMesh::create_from_point_cloud_alpha_shape(cloud, 1e-4).num_triangles(), 0u);

    const auto [tetra, point_map] = TetraMesh::create_from_point_cloud(cloud);
    for (double alpha : {0.3, 1e6}) {
        const auto fresh = TriangleMesh::create_from_point_cloud_alpha_shape(cloud, alpha);
        const auto reused = TriangleMesh::create_from_point_cloud_alpha_shape(cloud, alpha, tetra, point_map);
        EXPECT_EQ(reused.num_triangles(), fresh.num_triangles()) << alpha;
        EXPECT_NEAR(reused.get_surface_area(), fresh.get_surface_area(), 1e-9) << alpha;
    }
    EXPECT_GT(TriangleMesh::create_from_point_cloud_alpha_shape(cloud, 0.3).num_triangles(), 0u);
}

TEST(AlphaShape, ReportsProgressAndCancels) {
    const PointCloud cloud(o3dpp_test::random_points(500));
    Recorder all;
    ProgressOptions options;
    options.progress = all.callback();
    EXPECT_GT(TriangleMesh::create_from_point_cloud_alpha_shape(cloud, 0.5, options).num_triangles(), 0u);
    all.expect_rising_fractions();
    options.progress = [](double) { return false; };
    EXPECT_O3D_ERROR(TriangleMesh::create_from_point_cloud_alpha_shape(cloud, 0.5, options), O3D_ERROR_CANCELLED);
}

TEST(AlphaShape, BadInputThrows) {
    const PointCloud cloud = sphere_cloud(100);
    EXPECT_O3D_ERROR(TriangleMesh::create_from_point_cloud_alpha_shape(cloud, 0.0), O3D_ERROR_INVALID_ARGUMENT);
    EXPECT_O3D_ERROR(TriangleMesh::create_from_point_cloud_alpha_shape(cloud, -1.0), O3D_ERROR_INVALID_ARGUMENT);
    EXPECT_O3D_ERROR(TriangleMesh::create_from_point_cloud_alpha_shape(cloud, std::nan("")),
                     O3D_ERROR_INVALID_ARGUMENT);
    const PointCloud flat(std::vector<Vec3>{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {1, 1, 0}, {0.5, 0.3, 0}});
    EXPECT_O3D_ERROR(TriangleMesh::create_from_point_cloud_alpha_shape(flat, 1.0), O3D_ERROR_INVALID_ARGUMENT);
    // A point map that does not fit the tetra mesh.
    const auto [tetra, point_map] = TetraMesh::create_from_point_cloud(cloud);
    std::vector<int32_t> short_map(point_map.begin(), point_map.end() - 1);
    EXPECT_O3D_ERROR(TriangleMesh::create_from_point_cloud_alpha_shape(cloud, 1.0, tetra, short_map),
                     O3D_ERROR_INVALID_ARGUMENT);
}
