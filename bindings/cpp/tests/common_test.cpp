// SPDX-License-Identifier: MIT
// Version, verbosity, log callback (std::function through the C trampoline), thread count.
#include <stdexcept>
#include <string>
#include <thread>

#include "test_util.hpp"

TEST(Common, VersionMatchesHeader) {
    EXPECT_EQ(o3dpp::version_major(), O3D_VERSION_MAJOR);
    EXPECT_EQ(o3dpp::version_minor(), O3D_VERSION_MINOR);
    EXPECT_EQ(o3dpp::version_patch(), O3D_VERSION_PATCH);
    EXPECT_EQ(o3dpp::version(), std::to_string(O3D_VERSION_MAJOR) + "." + std::to_string(O3D_VERSION_MINOR) + "." +
                                    std::to_string(O3D_VERSION_PATCH));
}

TEST(Common, VerbositySetGet) {
    const auto old = o3dpp::get_verbosity_level();
    o3dpp::set_verbosity_level(o3dpp::LogLevel::Debug);
    EXPECT_EQ(o3dpp::get_verbosity_level(), o3dpp::LogLevel::Debug);
    o3dpp::set_verbosity_level(o3dpp::LogLevel::Error);
    EXPECT_EQ(o3dpp::get_verbosity_level(), o3dpp::LogLevel::Error);
    o3dpp::set_verbosity_level(old);
}

TEST(Common, LogCallbackReceivesFailureMessages) {
    std::vector<std::pair<o3dpp::LogLevel, std::string>> lines;
    o3dpp::set_verbosity_level(o3dpp::LogLevel::Debug);
    o3dpp::set_log_callback([&](o3dpp::LogLevel level, const std::string& m) { lines.emplace_back(level, m); });
    EXPECT_THROW(o3dpp::set_num_threads(-5), o3dpp::Error);  // failures are logged at Debug
    o3dpp::set_log_callback(nullptr);
    o3dpp::set_verbosity_level(o3dpp::LogLevel::Warning);
    ASSERT_FALSE(lines.empty());
    EXPECT_EQ(lines.back().first, o3dpp::LogLevel::Debug);
    EXPECT_NE(lines.back().second.find("num_threads"), std::string::npos) << lines.back().second;
    // After reset, nothing more arrives.
    const size_t before = lines.size();
    EXPECT_THROW(o3dpp::set_num_threads(-5), o3dpp::Error);
    EXPECT_EQ(lines.size(), before);
}

TEST(Common, ThrowingLogCallbackDoesNotEscapeThroughC) {
    int calls = 0;
    o3dpp::set_verbosity_level(o3dpp::LogLevel::Debug);
    o3dpp::set_log_callback([&](o3dpp::LogLevel, const std::string&) {
        ++calls;
        throw std::runtime_error("log sink failure");
    });
    // The failing call still reports its own error, not the callback's exception.
    EXPECT_O3D_ERROR(o3dpp::set_num_threads(-1), O3D_ERROR_INVALID_ARGUMENT);
    o3dpp::set_log_callback(nullptr);
    o3dpp::set_verbosity_level(o3dpp::LogLevel::Warning);
    EXPECT_GE(calls, 1);
}

TEST(Common, ReplacingTheCallbackSwitchesTarget) {
    int first = 0, second = 0;
    o3dpp::set_verbosity_level(o3dpp::LogLevel::Debug);
    o3dpp::set_log_callback([&](o3dpp::LogLevel, const std::string&) { ++first; });
    EXPECT_THROW(o3dpp::set_num_threads(-1), o3dpp::Error);
    o3dpp::set_log_callback([&](o3dpp::LogLevel, const std::string&) { ++second; });
    EXPECT_THROW(o3dpp::set_num_threads(-1), o3dpp::Error);
    o3dpp::set_log_callback({});
    o3dpp::set_verbosity_level(o3dpp::LogLevel::Warning);
    EXPECT_EQ(first, 1);
    EXPECT_EQ(second, 1);
}

TEST(Common, NumThreads) {
    o3dpp::set_num_threads(3);
    EXPECT_EQ(o3dpp::get_num_threads(), 3);
    o3dpp::set_num_threads(0);
    EXPECT_GE(o3dpp::get_num_threads(), 1);
}

TEST(Common, ErrorStateIsPerThread) {
    o3dpp::clear_error();
    std::thread t([] { EXPECT_THROW(o3dpp::set_num_threads(-1), o3dpp::Error); });
    t.join();
    EXPECT_EQ(o3dpp::last_error_code(), O3D_OK);
}
