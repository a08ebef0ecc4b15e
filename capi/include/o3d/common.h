/* SPDX-License-Identifier: MIT */
/**
 * @file common.h
 * @brief Export macro, status codes, thread-local errors, version, logging and threads.
 *
 * Everything in o3d's C API returns an ::o3d_status. On failure the library always sets a
 * thread-local message readable with o3d_last_error_message() on the same thread.
 *
 * **Thread safety:** distinct handles may be used from any threads at once; concurrent calls on the
 * same handle are safe only if all of them take a `const` handle. The error state is per thread.
 */
#ifndef O3D_COMMON_H
#define O3D_COMMON_H

#include <stddef.h>
#include <stdint.h>

#if defined(SWIG)
#define O3D_API
#elif defined(_WIN32)
#if defined(O3D_BUILDING_LIBRARY)
#define O3D_API __declspec(dllexport)
#else
#define O3D_API __declspec(dllimport)
#endif
#else
#define O3D_API __attribute__((visibility("default")))
#endif

#ifdef __cplusplus
#define O3D_BEGIN_DECL extern "C" {
#define O3D_END_DECL }
#else
#define O3D_BEGIN_DECL
#define O3D_END_DECL
#endif

O3D_BEGIN_DECL

#define O3D_VERSION_MAJOR 0
#define O3D_VERSION_MINOR 1
#define O3D_VERSION_PATCH 0

/** Status code returned by every fallible call: 0 on success, negative on failure. */
typedef int32_t o3d_status;

#define O3D_OK 0
#define O3D_ERROR_INVALID_ARGUMENT (-1) /**< NULL handle, bad size, NaN parameter, contract broken. */
#define O3D_ERROR_OUT_OF_MEMORY (-2)
#define O3D_ERROR_IO (-3)               /**< a file could not be opened, read or written. */
#define O3D_ERROR_PARSE (-4)            /**< malformed, truncated or inconsistent data. */
#define O3D_ERROR_UNSUPPORTED (-5)      /**< unknown format or feature not available. */
#define O3D_ERROR_BUFFER_TOO_SMALL (-6) /**< caller buffer too small; the needed count was reported. */
#define O3D_ERROR_NOT_CONVERGED (-7)
#define O3D_ERROR_CANCELLED (-8)        /**< a progress callback returned non-zero. */
#define O3D_ERROR_INTERNAL (-9)

/** Log levels, most severe first. */
#define O3D_LOG_ERROR 0
#define O3D_LOG_WARNING 1
#define O3D_LOG_INFO 2
#define O3D_LOG_DEBUG 3

/** `which` constants of the array functions (o3d_<noun>_*_array): from this value on they name int32
 *  (index) arrays, below it float64 (or byte) arrays. */
#define O3D_INDEX_ARRAY_FIRST 100

/** @brief Library version string, e.g. "0.1.0". Static storage. */
O3D_API const char* o3d_version(void);
/** @brief Library major version (equals the SONAME number). */
O3D_API int32_t o3d_version_major(void);
O3D_API int32_t o3d_version_minor(void);
O3D_API int32_t o3d_version_patch(void);

/**
 * @brief Message of the last failure on this thread ("" when none). Never NULL.
 * **Ownership:** owned by the library; valid until the next o3d call on this thread.
 */
O3D_API const char* o3d_last_error_message(void);
/** @brief Status of the last failure on this thread (O3D_OK when none). */
O3D_API o3d_status o3d_last_error_code(void);
/** @brief Forget the last failure on this thread. */
O3D_API void o3d_clear_error(void);
/** @brief Static name of a status code ("O3D_OK", "O3D_ERROR_IO", ...). Never NULL. */
O3D_API const char* o3d_status_string(o3d_status status);

/**
 * @brief Receives log lines. Called on the thread that logged (never from inside a parallel region
 * concurrently with itself: logging is serialised by the library).
 */
typedef void (*o3d_log_callback)(int32_t level, const char* message, void* user_data);

/** @brief Show messages at `level` and more severe (default O3D_LOG_WARNING). */
O3D_API o3d_status o3d_set_verbosity_level(int32_t level);
O3D_API int32_t o3d_get_verbosity_level(void);
/** @brief Route log lines to `callback` (NULL restores the default sink, stderr). */
O3D_API o3d_status o3d_set_log_callback(o3d_log_callback callback, void* user_data);

/**
 * @brief Default thread count for parallel algorithms when a call passes num_threads = 0.
 * 0 restores the OpenMP default (number of cores). Negative is invalid.
 */
O3D_API o3d_status o3d_set_num_threads(int32_t num_threads);
/** @brief The thread count a call with num_threads = 0 uses now (>= 1). */
O3D_API int32_t o3d_get_num_threads(void);

/**
 * @brief Progress report for long calls: `fraction` in [0,1]. Return 0 to go on, non-zero to cancel
 * (the call then fails with O3D_ERROR_CANCELLED). Always called on the calling thread.
 */
typedef int32_t (*o3d_progress_callback)(double fraction, void* user_data);

/** Owned byte buffer (in-memory file contents). */
typedef struct o3d_buffer o3d_buffer_t;
/** @brief Destroy a buffer. NULL is a no-op. */
O3D_API void o3d_buffer_destroy(o3d_buffer_t* buffer);
/**
 * @brief Borrowed view of the bytes. **Ownership:** valid until o3d_buffer_destroy.
 */
O3D_API o3d_status o3d_buffer_view(const uint8_t** out_data, size_t* out_size, const o3d_buffer_t* buffer);
/** @brief Copy the bytes into `out` (capacity bytes); `*out_size` gets the size. NULL `out` queries it. */
O3D_API o3d_status o3d_buffer_get_data(uint8_t* out, size_t capacity, size_t* out_size, const o3d_buffer_t* buffer);

/* ---- Random numbers ---- */

/**
 * @brief Seed the global generator that randomized calls draw from when they are not given a seed
 * (RANSAC, FGR). Without it the generator starts from a random device. @see o3d.utility.random.seed
 */
O3D_API o3d_status o3d_random_seed(uint64_t seed);

O3D_END_DECL

#endif /* O3D_COMMON_H */
