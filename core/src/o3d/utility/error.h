// SPDX-License-Identifier: MIT
#pragma once
/// @file error.h
/// @brief Exception types of the core. The C API guard maps each to one o3d_status.
#include <stdexcept>
#include <string>

namespace o3d {

/// @brief A caller broke a contract: bad size, NaN parameter, out-of-range index.
struct InvalidArgument : std::invalid_argument {
    using std::invalid_argument::invalid_argument;
};
/// @brief A file could not be opened, read or written.
struct IoError : std::runtime_error {
    using std::runtime_error::runtime_error;
};
/// @brief Malformed, truncated or inconsistent input data.
struct ParseError : std::runtime_error {
    using std::runtime_error::runtime_error;
};
/// @brief Unknown format or feature.
struct Unsupported : std::runtime_error {
    using std::runtime_error::runtime_error;
};
/// @brief A caller buffer is too small.
struct BufferTooSmall : std::runtime_error {
    using std::runtime_error::runtime_error;
};
/// @brief An iterative method did not converge where convergence is required.
struct NotConverged : std::runtime_error {
    using std::runtime_error::runtime_error;
};
/// @brief A progress callback asked to stop.
struct Cancelled : std::runtime_error {
    using std::runtime_error::runtime_error;
};

}  // namespace o3d
