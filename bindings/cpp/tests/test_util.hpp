// SPDX-License-Identifier: MIT
#pragma once
// Helpers of the o3dpp GoogleTest tests: test data lookup and small synthetic clouds.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <fstream>
#include <random>
#include <string>
#include <vector>

#include "o3dpp/o3dpp.hpp"

namespace o3dpp_test {

/// Path of `relative` under $O3D_TEST_DATA (default ../shared/data), or "" when it is not readable.
inline std::string data_path(const std::string& relative) {
    const char* env = std::getenv("O3D_TEST_DATA");
    std::string root = (env && *env) ? env : O3D_TEST_DATA_DEFAULT;
    std::string path = root + "/" + relative;
    return std::ifstream(path).good() ? path : std::string();
}

inline bool data_required() {
    const char* env = std::getenv("O3D_REQUIRE_TEST_DATA");
    return env && std::string(env) == "1";
}

/// Declare `var` as the data path, or skip (fail under O3D_REQUIRE_TEST_DATA=1) when missing.
#define O3DPP_DATA_OR_SKIP(var, relative)                                          \
    const std::string var = ::o3dpp_test::data_path(relative);                     \
    if (var.empty()) {                                                             \
        if (::o3dpp_test::data_required()) FAIL() << "missing test data " << relative; \
        GTEST_SKIP() << "missing test data " << relative;                          \
    }

/// Path for a scratch file in the build tree.
inline std::string tmp_path(const std::string& name) { return std::string(O3DPP_TEST_TMP_DIR) + "/" + name; }

/// `n` uniform random points in [lo, hi]^3, fixed seed.
inline std::vector<o3dpp::Vec3> random_points(std::size_t n, double lo = -1.0, double hi = 1.0,
                                              unsigned seed = 42) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<double> u(lo, hi);
    std::vector<o3dpp::Vec3> pts(n);
    for (auto& p : pts) p = {u(rng), u(rng), u(rng)};
    return pts;
}

/// `n` points spread evenly over the sphere of `radius` about `center` (a Fibonacci lattice: no two coincide,
/// spacing about radius * sqrt(4 pi / n)), with outward unit normals.
inline o3dpp::PointCloud sphere_cloud(std::size_t n, double radius = 1.0, const o3dpp::Vec3& center = {0, 0, 0}) {
    const double golden = 3.14159265358979323846 * (3.0 - std::sqrt(5.0));
    std::vector<o3dpp::Vec3> points(n), normals(n);
    for (std::size_t i = 0; i < n; ++i) {
        const double z = 1.0 - (2.0 * static_cast<double>(i) + 1.0) / static_cast<double>(n);
        const double r = std::sqrt(1.0 - z * z), phi = golden * static_cast<double>(i);
        normals[i] = {r * std::cos(phi), r * std::sin(phi), z};
        for (int k = 0; k < 3; ++k) points[i][k] = center[k] + radius * normals[i][k];
    }
    o3dpp::PointCloud cloud(points);
    cloud.set_normals(normals);
    return cloud;
}

/// Assert that `stmt` throws o3dpp::Error with `code` and a non-empty message.
#define EXPECT_O3D_ERROR(stmt, expected_code)                                   \
    do {                                                                        \
        try {                                                                   \
            stmt;                                                               \
            ADD_FAILURE() << #stmt " did not throw";                            \
        } catch (const o3dpp::Error& e) {                                       \
            EXPECT_EQ(e.code(), (expected_code)) << e.what();                   \
            EXPECT_STRNE(e.what(), "");                                         \
        }                                                                       \
    } while (0)

}  // namespace o3dpp_test
