// SPDX-License-Identifier: MIT
#pragma once
/// @file error.hpp
/// @brief o3dpp::Error (a failed o3d_status with its message) and the check() helper.
#include <cstdint>
#include <stdexcept>
#include <string>

#include "o3d/common.h"

namespace o3dpp {

/// @brief Thrown for every failed C call: the status code plus the thread-local message.
class Error : public std::runtime_error {
public:
    Error(o3d_status code, const std::string& message) : std::runtime_error(message), code_(code) {}
    /// @brief The O3D_ERROR_* code.
    o3d_status code() const noexcept { return code_; }
    /// @brief Static name of the code, e.g. "O3D_ERROR_IO".
    const char* code_name() const noexcept { return o3d_status_string(code_); }

private:
    o3d_status code_;
};

/// @brief Message of the last failure on this thread ("" when none).
inline std::string last_error_message() { return o3d_last_error_message(); }
/// @brief Code of the last failure on this thread (O3D_OK when none).
inline o3d_status last_error_code() noexcept { return o3d_last_error_code(); }
/// @brief Forget the last failure on this thread.
inline void clear_error() noexcept { o3d_clear_error(); }
/// @brief Static name of a status code.
inline const char* status_string(o3d_status status) noexcept { return o3d_status_string(status); }

/// @brief Throw o3dpp::Error when `status` is not O3D_OK. Read the message right away (same thread).
inline void check(o3d_status status) {
    if (status == O3D_OK) return;
    std::string message = o3d_last_error_message();
    if (message.empty()) message = o3d_status_string(status);
    throw Error(status, message);
}

}  // namespace o3dpp
