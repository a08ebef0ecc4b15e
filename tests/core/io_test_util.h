// SPDX-License-Identifier: MIT
#pragma once
/// @file io_test_util.h
/// @brief Helpers shared by the point-cloud I/O tests: synthetic clouds, comparisons, byte views.
#include <gtest/gtest.h>

#include <cstdint>
#include <random>
#include <string>
#include <vector>

#include "o3d/geometry/point_cloud.h"
#include "o3d/io/point_cloud_io.h"
#include "o3d/utility/error.h"

namespace o3d::test {

/// @brief A reproducible cloud with coordinates that are not float-exact (so precision loss shows).
inline geometry::PointCloud make_cloud(size_t n, bool normals, bool colors, uint32_t seed = 7) {
    std::mt19937_64 rng(seed);
    std::uniform_real_distribution<double> coord(-100.0, 100.0), unit(0.0, 1.0);
    geometry::PointCloud pc;
    for (size_t i = 0; i < n; ++i) {
        pc.points.emplace_back(coord(rng), coord(rng), coord(rng));
        if (normals) pc.normals.push_back(Eigen::Vector3d(unit(rng) - 0.5, unit(rng) - 0.5, unit(rng)).normalized());
        // Colours on the 1/255 grid survive uchar quantisation exactly.
        if (colors) pc.colors.emplace_back(int(unit(rng) * 255) / 255.0, int(unit(rng) * 255) / 255.0, 1.0);
    }
    return pc;
}

/// @brief Element-wise comparison of two attribute arrays within `tol` (0: bit-exact).
inline void expect_near(const std::vector<Eigen::Vector3d>& a, const std::vector<Eigen::Vector3d>& b, double tol,
                        const char* what) {
    ASSERT_EQ(a.size(), b.size()) << what;
    for (size_t i = 0; i < a.size(); ++i)
        for (int k = 0; k < 3; ++k) {
            if (tol == 0.0)
                ASSERT_EQ(a[i][k], b[i][k]) << what << " " << i << "," << k;
            else
                ASSERT_NEAR(a[i][k], b[i][k], tol * std::max(1.0, std::abs(a[i][k]))) << what << " " << i << "," << k;
        }
}

inline std::vector<uint8_t> bytes_of(const std::string& s) { return std::vector<uint8_t>(s.begin(), s.end()); }

inline geometry::PointCloud read_text(const std::string& text, const std::string& format,
                                      const io::ReadOptions& options = {}) {
    return io::read_point_cloud_from_memory(reinterpret_cast<const uint8_t*>(text.data()), text.size(), format,
                                            options);
}

/// @brief The ParseError message reading `bytes` as `format` raises ("" when it does not throw one).
inline std::string parse_error_of(const std::vector<uint8_t>& bytes, const std::string& format) {
    try {
        io::read_point_cloud_from_memory(bytes.data(), bytes.size(), format);
    } catch (const ParseError& e) {
        return e.what();
    }
    return "";
}

}  // namespace o3d::test
