// SPDX-License-Identifier: MIT
#pragma once
/// @file common.hpp
/// @brief Version, verbosity, log callback (std::function), thread count, Buffer.
#include <cstdint>
#include <exception>
#include <functional>
#include <memory>
#include <mutex>
#include <string>
#include <vector>

#include "o3d/common.h"
#include "o3dpp/arrays.hpp"
#include "o3dpp/error.hpp"
#include "o3dpp/generated/enums.hpp"
#include "o3dpp/handle.hpp"
#include "o3dpp/span.hpp"

namespace o3dpp {

/// @brief Version string of the loaded library, e.g. "0.1.0".
inline std::string version() { return o3d_version(); }
inline int version_major() noexcept { return o3d_version_major(); }
inline int version_minor() noexcept { return o3d_version_minor(); }
inline int version_patch() noexcept { return o3d_version_patch(); }

/// @brief Show messages at `level` and more severe.
inline void set_verbosity_level(LogLevel level) { check(o3d_set_verbosity_level(static_cast<int32_t>(level))); }
inline LogLevel get_verbosity_level() noexcept { return static_cast<LogLevel>(o3d_get_verbosity_level()); }

using LogCallback = std::function<void(LogLevel level, const std::string& message)>;

namespace detail {
struct LogState {
    std::mutex mutex;
    std::unique_ptr<LogCallback> current;
};
// Leaked on purpose: the library may log during static destruction, after a static would be gone.
inline LogState& log_state() {
    static LogState* state = new LogState;
    return *state;
}
// C++ exceptions must never cross back through C: swallow them here.
inline void log_trampoline(int32_t level, const char* message, void* user_data) noexcept {
    try {
        auto* fn = static_cast<LogCallback*>(user_data);
        (*fn)(static_cast<LogLevel>(level), message ? std::string(message) : std::string());
    } catch (...) {
    }
}
}  // namespace detail

/// @brief Route log lines to `callback`; an empty function restores the default sink (stderr).
/// The callback runs under the library's log mutex: it must not call back into o3d.
/// Exceptions it throws are swallowed.
inline void set_log_callback(LogCallback callback) {
    auto& state = detail::log_state();
    std::lock_guard<std::mutex> lock(state.mutex);
    if (!callback) {
        check(o3d_set_log_callback(nullptr, nullptr));
        state.current.reset();
        return;
    }
    auto next = std::make_unique<LogCallback>(std::move(callback));
    check(o3d_set_log_callback(&detail::log_trampoline, next.get()));
    // The library has switched to `next` under its own mutex: the old callback is no longer in use.
    state.current = std::move(next);
}

/// @brief Default thread count for calls given num_threads = 0 (0: OpenMP default).
inline void set_num_threads(int num_threads) { check(o3d_set_num_threads(num_threads)); }
inline int get_num_threads() noexcept { return o3d_get_num_threads(); }

/// @brief Owned bytes (an in-memory file).
class Buffer : public Owner<Buffer, o3d_buffer_t, &o3d_buffer_destroy> {
public:
    /// @brief No buffer.
    Buffer() noexcept = default;
    /// @brief Take ownership of `owned` (must not be NULL).
    explicit Buffer(o3d_buffer_t* owned) : Owner(owned) {}

    /// @brief Borrowed view of the bytes, valid while this Buffer lives.
    Span<const uint8_t> view() const {
        const uint8_t* data = nullptr;
        size_t size = 0;
        check(o3d_buffer_view(&data, &size, get()));
        return {data, size};
    }
    std::size_t size() const { return view().size(); }
    /// @brief Copy of the bytes.
    std::vector<uint8_t> to_vector() const { return copy_out<uint8_t>(&o3d_buffer_get_data); }
    std::string to_string() const {
        auto v = view();
        return std::string(reinterpret_cast<const char*>(v.data()), v.size());
    }
};

/// @brief Progress callback: gets a fraction in [0,1]; return false to cancel.
using ProgressCallback = std::function<bool(double fraction)>;

namespace detail {
/// @brief user_data of the progress trampoline: the callback, plus any exception it threw.
struct ProgressContext {
    const ProgressCallback* callback = nullptr;
    std::exception_ptr error;
};
inline int32_t progress_trampoline(double fraction, void* user_data) noexcept {
    auto* ctx = static_cast<ProgressContext*>(user_data);
    try {
        return (*ctx->callback)(fraction) ? 0 : 1;
    } catch (...) {
        ctx->error = std::current_exception();  // rethrown after the C call returns
        return 1;
    }
}
/// @brief Wire `progress` into the C options `c` (its progress and user_data fields), then run `call(&c)`.
/// An exception the callback threw is rethrown here; otherwise the call's status is returned.
template <typename COptions, typename Call>
o3d_status with_progress(COptions c, const ProgressCallback& progress, Call&& call) {
    ProgressContext ctx;
    if (progress) {
        ctx.callback = &progress;
        c.progress = &progress_trampoline;
        c.user_data = &ctx;
    }
    const o3d_status status = call(&c);
    if (ctx.error) std::rethrow_exception(ctx.error);
    return status;
}
}  // namespace detail

}  // namespace o3dpp
