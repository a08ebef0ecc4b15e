// SPDX-License-Identifier: MIT
// Version, thread-local errors, logging and thread-count entry points, and the byte buffer.
#include <cmath>
#include <mutex>

#include "internal.h"
#include "o3d/utility/logging.h"
#include "o3d/utility/parallel.h"

namespace {
struct LastError {
    o3d_status code = O3D_OK;
    std::string message;
};
thread_local LastError t_error;
}  // namespace

namespace o3d::capi {

o3d_status fail(o3d_status status, const std::string& message) {
    try {
        t_error.code = status;
        t_error.message = message;
    } catch (...) {
        t_error.code = status;  // keep at least the code if the message cannot be stored
    }
    o3d::utility::log_debug(message);
    return status;
}

void reset_error() {
    t_error.code = O3D_OK;
    t_error.message.clear();
}

void require_finite(double x, const char* name) {
    if (!std::isfinite(x)) throw o3d::InvalidArgument(std::string(name) + " must be finite");
}

}  // namespace o3d::capi

using o3d::capi::guard;
using o3d::capi::require;

extern "C" {

O3D_API const char* o3d_version(void) { return O3D_VERSION_STRING; }
O3D_API int32_t o3d_version_major(void) { return O3D_VERSION_MAJOR; }
O3D_API int32_t o3d_version_minor(void) { return O3D_VERSION_MINOR; }
O3D_API int32_t o3d_version_patch(void) { return O3D_VERSION_PATCH; }

O3D_API const char* o3d_last_error_message(void) { return t_error.message.c_str(); }
O3D_API o3d_status o3d_last_error_code(void) { return t_error.code; }
O3D_API void o3d_clear_error(void) { o3d::capi::reset_error(); }

O3D_API const char* o3d_status_string(o3d_status status) {
    switch (status) {
        case O3D_OK: return "O3D_OK";
        case O3D_ERROR_INVALID_ARGUMENT: return "O3D_ERROR_INVALID_ARGUMENT";
        case O3D_ERROR_OUT_OF_MEMORY: return "O3D_ERROR_OUT_OF_MEMORY";
        case O3D_ERROR_IO: return "O3D_ERROR_IO";
        case O3D_ERROR_PARSE: return "O3D_ERROR_PARSE";
        case O3D_ERROR_UNSUPPORTED: return "O3D_ERROR_UNSUPPORTED";
        case O3D_ERROR_BUFFER_TOO_SMALL: return "O3D_ERROR_BUFFER_TOO_SMALL";
        case O3D_ERROR_NOT_CONVERGED: return "O3D_ERROR_NOT_CONVERGED";
        case O3D_ERROR_CANCELLED: return "O3D_ERROR_CANCELLED";
        case O3D_ERROR_INTERNAL: return "O3D_ERROR_INTERNAL";
        default: return "O3D_ERROR_UNKNOWN";
    }
}

O3D_API o3d_status o3d_set_verbosity_level(int32_t level) {
    return guard(__func__, [&] {
        if (level < O3D_LOG_ERROR || level > O3D_LOG_DEBUG)
            throw o3d::InvalidArgument("level must be O3D_LOG_ERROR..O3D_LOG_DEBUG (0..3), got " +
                                       std::to_string(level));
        o3d::utility::set_verbosity_level(static_cast<o3d::utility::LogLevel>(level));
    });
}

O3D_API int32_t o3d_get_verbosity_level(void) { return static_cast<int32_t>(o3d::utility::get_verbosity_level()); }

O3D_API o3d_status o3d_set_log_callback(o3d_log_callback callback, void* user_data) {
    return guard(__func__, [&] {
        if (!callback) {
            o3d::utility::set_log_sink({});
            return;
        }
        o3d::utility::set_log_sink([callback, user_data](o3d::utility::LogLevel level, const std::string& message) {
            callback(static_cast<int32_t>(level), message.c_str(), user_data);
        });
    });
}

O3D_API o3d_status o3d_set_num_threads(int32_t num_threads) {
    return guard(__func__, [&] {
        if (num_threads < 0) throw o3d::InvalidArgument("num_threads must be >= 0");
        o3d::utility::set_default_num_threads(num_threads);
    });
}

O3D_API int32_t o3d_get_num_threads(void) { return o3d::utility::resolve_num_threads(0); }

O3D_API void o3d_buffer_destroy(o3d_buffer_t* buffer) { delete buffer; }

O3D_API o3d_status o3d_buffer_view(const uint8_t** out_data, size_t* out_size, const o3d_buffer_t* buffer) {
    return guard(__func__, [&] {
        require(buffer, "buffer");
        require(out_data, "out_data");
        require(out_size, "out_size");
        *out_data = buffer->bytes.empty() ? nullptr : buffer->bytes.data();
        *out_size = buffer->bytes.size();
    });
}

O3D_API o3d_status o3d_buffer_get_data(uint8_t* out, size_t capacity, size_t* out_size, const o3d_buffer_t* buffer) {
    return guard(__func__, [&] {
        require(buffer, "buffer");
        o3d::capi::copy_out(buffer->bytes.data(), buffer->bytes.size(), out, capacity, out_size);
    });
}

}  // extern "C"
