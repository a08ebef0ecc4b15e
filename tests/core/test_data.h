// SPDX-License-Identifier: MIT
#pragma once
/// @file test_data.h
/// @brief Locating the shared test data: $O3D_TEST_DATA, else ../shared/data beside the checkout.
/// A test whose file is missing is skipped, except under O3D_REQUIRE_TEST_DATA=1 (CI), where it fails.
#include <gtest/gtest.h>

#include <string>

namespace o3d::test {
/// @brief Absolute path of `relative` under the data root ("" when the file does not exist).
std::string data_path(const std::string& relative);
/// @brief True when O3D_REQUIRE_TEST_DATA=1.
bool data_required();
}  // namespace o3d::test

/// Declare `var` as the path of `relative`, or skip/fail the test when it is missing.
#define O3D_TEST_DATA_OR_SKIP(var, relative)                                                   \
    const std::string var = ::o3d::test::data_path(relative);                                  \
    if (var.empty()) {                                                                         \
        if (::o3d::test::data_required()) FAIL() << "missing test data file " << (relative);   \
        GTEST_SKIP() << "test data " << (relative) << " not found (set O3D_TEST_DATA)";         \
    }
