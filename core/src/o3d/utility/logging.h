// SPDX-License-Identifier: MIT
#pragma once
/// @file logging.h
/// @brief The one logger: verbosity-filtered, silent below Warning by default, redirectable.
#include <functional>
#include <string>

namespace o3d::utility {

enum class LogLevel { Error = 0, Warning = 1, Info = 2, Debug = 3 };

/// @brief Messages at `level` and more severe are emitted.
void set_verbosity_level(LogLevel level);
LogLevel get_verbosity_level();
/// @brief Replace the sink (empty function: stderr). The sink is called under a mutex.
void set_log_sink(std::function<void(LogLevel, const std::string&)> sink);
/// @brief Emit `message` if `level` passes the verbosity filter.
void log(LogLevel level, const std::string& message);
inline bool log_enabled(LogLevel level) { return static_cast<int>(level) <= static_cast<int>(get_verbosity_level()); }

inline void log_error(const std::string& m) { log(LogLevel::Error, m); }
inline void log_warning(const std::string& m) { log(LogLevel::Warning, m); }
inline void log_info(const std::string& m) { log(LogLevel::Info, m); }
inline void log_debug(const std::string& m) { log(LogLevel::Debug, m); }

}  // namespace o3d::utility
