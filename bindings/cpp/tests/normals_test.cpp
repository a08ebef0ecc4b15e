// SPDX-License-Identifier: MIT
// estimate_normals through the wrapper: points on a tilted plane get the plane's normal; consistent
// orientation over a tangent-plane graph makes randomly flipped sphere normals agree.
#include <cmath>
#include <random>
#include <utility>

#include "test_util.hpp"

using o3dpp::Vec3;

namespace {
// z = 0.3 x - 0.2 y + 1 → normal ∝ (0.3, -0.2, -1).
std::vector<Vec3> plane_points(int n) {
    std::vector<Vec3> pts;
    for (int i = 0; i < n; ++i)
        for (int j = 0; j < n; ++j) {
            const double x = 0.05 * i + 0.001 * ((i * 7 + j * 3) % 5), y = 0.05 * j + 0.001 * ((i + j * 11) % 7);
            pts.push_back({x, y, 0.3 * x - 0.2 * y + 1.0});
        }
    return pts;
}
void expect_plane_normals(const o3dpp::PointCloud& pc) {
    const double len = std::sqrt(0.09 + 0.04 + 1.0);
    const Vec3 n = {0.3 / len, -0.2 / len, -1.0 / len};
    const auto normals = pc.normals();
    ASSERT_EQ(normals.size(), pc.size());
    for (size_t i = 0; i < normals.size(); ++i) {
        const double* m = normals[i];
        EXPECT_NEAR(std::sqrt(m[0] * m[0] + m[1] * m[1] + m[2] * m[2]), 1.0, 1e-9);
        EXPECT_NEAR(std::fabs(m[0] * n[0] + m[1] * n[1] + m[2] * n[2]), 1.0, 1e-9) << "point " << i;
    }
}
}  // namespace

TEST(Normals, PlaneKnn) {
    o3dpp::PointCloud pc(plane_points(20));
    pc.estimate_normals(o3dpp::SearchParam::Knn(10));
    EXPECT_TRUE(pc.has_normals());
    expect_plane_normals(pc);
}

TEST(Normals, PlaneHybridAndRadiusSameForAnyThreadCount) {
    o3dpp::PointCloud a(plane_points(20));
    a.estimate_normals(o3dpp::SearchParam::Hybrid(0.2, 30), 1);
    expect_plane_normals(a);
    o3dpp::PointCloud b(plane_points(20));
    b.estimate_normals(o3dpp::SearchParam::Hybrid(0.2, 30), 4);
    EXPECT_EQ(a.get_normals(), b.get_normals());
    o3dpp::PointCloud c(plane_points(20));
    c.estimate_normals(o3dpp::SearchParam::Radius(0.12));
    expect_plane_normals(c);
}

TEST(Normals, OrientedTowardsUpKeepsSignAfterReestimate) {
    o3dpp::PointCloud pc(plane_points(15));
    pc.estimate_normals();
    pc.orient_normals_to_align_with_direction({0, 0, 1});
    for (const auto& m : pc.get_normals()) EXPECT_GT(m[2], 0.0);
    // Existing normals: new ones are flipped to agree with them.
    pc.estimate_normals(o3dpp::SearchParam::Knn(8));
    for (const auto& m : pc.get_normals()) EXPECT_GT(m[2], 0.0);
}

TEST(Normals, ConsistentTangentPlaneMakesFlippedSphereNormalsAgree) {
    o3dpp::PointCloud pc = o3dpp_test::sphere_cloud(1000);
    auto normals = pc.get_normals();
    std::mt19937 rng(3);
    for (auto& n : normals)
        if (rng() % 2)
            for (double& x : n) x = -x;
    pc.set_normals(normals);
    const auto points = pc.get_points();
    // Default lambda and cos_alpha_tol (Hoppe's weights, every edge), then Open3D 0.18's penalty and a tolerance.
    for (const auto& [lambda, cos_alpha_tol] : {std::pair<double, double>{0.0, 1.0}, {1.0, 0.5}}) {
        o3dpp::PointCloud oriented = pc.clone();
        if (lambda == 0.0)
            oriented.orient_normals_consistent_tangent_plane(10);
        else
            oriented.orient_normals_consistent_tangent_plane(10, lambda, cos_alpha_tol);
        // Each normal is only flipped, and all agree up to one global sign.
        const auto got = oriented.get_normals();
        const double sign = got[0][0] * points[0][0] + got[0][1] * points[0][1] + got[0][2] * points[0][2];
        for (size_t i = 0; i < got.size(); ++i) {
            const double d = got[i][0] * points[i][0] + got[i][1] * points[i][1] + got[i][2] * points[i][2];
            EXPECT_NEAR(d * sign, 1.0, 1e-12) << "point " << i << " lambda " << lambda;
        }
    }
}

TEST(Normals, ConsistentTangentPlaneRejectsBadInput) {
    o3dpp::PointCloud no_normals(plane_points(5));
    EXPECT_O3D_ERROR(no_normals.orient_normals_consistent_tangent_plane(5), O3D_ERROR_INVALID_ARGUMENT);
    o3dpp::PointCloud pc = o3dpp_test::sphere_cloud(50);
    EXPECT_O3D_ERROR(pc.orient_normals_consistent_tangent_plane(0), O3D_ERROR_INVALID_ARGUMENT);
    EXPECT_O3D_ERROR(pc.orient_normals_consistent_tangent_plane(5, -1.0), O3D_ERROR_INVALID_ARGUMENT);
    EXPECT_O3D_ERROR(pc.orient_normals_consistent_tangent_plane(5, 0.0, std::nan("")), O3D_ERROR_INVALID_ARGUMENT);
    o3dpp::PointCloud moved = std::move(pc);
    EXPECT_O3D_ERROR(pc.orient_normals_consistent_tangent_plane(5), O3D_ERROR_INVALID_ARGUMENT);  // NULL handle
}
