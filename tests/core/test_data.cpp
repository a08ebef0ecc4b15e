// SPDX-License-Identifier: MIT
#include "test_data.h"

#include <cstdlib>
#include <filesystem>

namespace o3d::test {

std::string data_path(const std::string& relative) {
    const char* env = std::getenv("O3D_TEST_DATA");
    std::filesystem::path root = (env && *env) ? env : O3D_TEST_DATA_DEFAULT;
    std::filesystem::path p = root / relative;
    std::error_code ec;
    return std::filesystem::exists(p, ec) ? std::filesystem::absolute(p).string() : std::string();
}

bool data_required() {
    const char* env = std::getenv("O3D_REQUIRE_TEST_DATA");
    return env && std::string(env) == "1";
}

}  // namespace o3d::test
