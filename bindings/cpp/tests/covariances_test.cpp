// SPDX-License-Identifier: MIT
// Per-point covariances through the wrapper: planar neighbourhoods are singular, explicit ones
// round-trip and rotate as R C R^T, errors as exceptions.
#include <cmath>

#include "test_util.hpp"

using o3dpp::Mat3;
using o3dpp::PointCloud;
using o3dpp::SearchParam;
using o3dpp::Vec3;

namespace {
double det(const Mat3& c) {
    return c[0] * (c[4] * c[8] - c[5] * c[7]) - c[1] * (c[3] * c[8] - c[5] * c[6]) + c[2] * (c[3] * c[7] - c[4] * c[6]);
}
Mat3 diag(double a, double b, double c) { return {a, 0, 0, 0, b, 0, 0, 0, c}; }
}  // namespace

TEST(Covariances, PlanarNeighbourhoodsAreSingular) {
    std::vector<Vec3> pts;
    for (int i = 0; i < 10; ++i)
        for (int j = 0; j < 10; ++j) pts.push_back({0.1 * i, 0.1 * j + 0.03 * i, 0.0});
    PointCloud cloud(pts);
    EXPECT_FALSE(cloud.has_covariances());
    EXPECT_TRUE(cloud.covariances().empty());
    cloud.estimate_covariances(SearchParam::Knn(10));
    ASSERT_TRUE(cloud.has_covariances());
    const auto covs = cloud.get_covariances();
    ASSERT_EQ(covs.size(), 100u);
    for (const auto& c : covs) {
        EXPECT_NEAR(det(c), 0.0, 1e-15);
        EXPECT_NEAR(c[8], 0.0, 1e-15);
        EXPECT_GT(c[0], 1e-4);
        EXPECT_GT(c[4], 1e-4);
    }
    const auto view = cloud.covariances();
    ASSERT_EQ(view.size(), 900u);
    EXPECT_EQ(view[9 * 5 + 4], covs[5][4]);
    EXPECT_NO_THROW(cloud.estimate_covariances());
}

TEST(Covariances, ExplicitOnesRoundTripAndRotate) {
    PointCloud cloud(std::vector<Vec3>{{0, 0, 0}, {1, 0, 0}});
    cloud.set_covariances({diag(1, 2, 3), diag(4, 5, 6)});
    EXPECT_TRUE(cloud.has_covariances());
    EXPECT_EQ(cloud.get_covariances()[1], diag(4, 5, 6));
    cloud.rotate({0, -1, 0, 1, 0, 0, 0, 0, 1}, {0, 0, 0});
    const auto rotated = cloud.get_covariances();
    for (int k = 0; k < 9; ++k) {
        EXPECT_NEAR(rotated[0][k], diag(2, 1, 3)[k], 1e-12);
        EXPECT_NEAR(rotated[1][k], diag(5, 4, 6)[k], 1e-12);
    }
    cloud.set_covariances({diag(1, 1, 1)});
    EXPECT_FALSE(cloud.has_covariances());
}

TEST(Covariances, BadSearchParametersThrow) {
    PointCloud cloud(o3dpp_test::random_points(20));
    EXPECT_O3D_ERROR(cloud.estimate_covariances(SearchParam::Knn(0)), O3D_ERROR_INVALID_ARGUMENT);
    EXPECT_O3D_ERROR(cloud.estimate_covariances(SearchParam::Radius(-1.0)), O3D_ERROR_INVALID_ARGUMENT);
    EXPECT_FALSE(cloud.has_covariances());
}
