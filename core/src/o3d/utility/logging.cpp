// SPDX-License-Identifier: MIT
#include "o3d/utility/logging.h"

#include <atomic>
#include <cstdio>
#include <mutex>

namespace o3d::utility {
namespace {
std::atomic<int> g_level{static_cast<int>(LogLevel::Warning)};
std::mutex g_sink_mutex;
std::function<void(LogLevel, const std::string&)>& sink() {
    static std::function<void(LogLevel, const std::string&)> s;
    return s;
}
const char* level_name(LogLevel level) {
    switch (level) {
        case LogLevel::Error: return "Error";
        case LogLevel::Warning: return "Warning";
        case LogLevel::Info: return "Info";
        default: return "Debug";
    }
}
}  // namespace

void set_verbosity_level(LogLevel level) { g_level.store(static_cast<int>(level)); }
LogLevel get_verbosity_level() { return static_cast<LogLevel>(g_level.load()); }

void set_log_sink(std::function<void(LogLevel, const std::string&)> s) {
    std::lock_guard<std::mutex> lock(g_sink_mutex);
    sink() = std::move(s);
}

void log(LogLevel level, const std::string& message) {
    if (!log_enabled(level)) return;
    std::lock_guard<std::mutex> lock(g_sink_mutex);
    if (sink()) {
        sink()(level, message);
    } else {
        std::fprintf(stderr, "[o3d %s] %s\n", level_name(level), message.c_str());
    }
}

}  // namespace o3d::utility
