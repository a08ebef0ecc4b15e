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
 *
 * **Out of memory:** any function here that allocates may also return O3D_ERROR_OUT_OF_MEMORY; the
 * per-function `@return` lists do not repeat it.
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

#define O3D_VERSION_MAJOR 0 /**< major version of this header */
#define O3D_VERSION_MINOR 1 /**< minor version of this header */
#define O3D_VERSION_PATCH 0 /**< patch version of this header */

/** Status code returned by every fallible call: 0 on success, negative on failure. */
typedef int32_t o3d_status;

#define O3D_OK 0 /**< success */
#define O3D_ERROR_INVALID_ARGUMENT (-1) /**< NULL handle, bad size, NaN parameter, contract broken. */
#define O3D_ERROR_OUT_OF_MEMORY (-2) /**< an allocation failed. */
#define O3D_ERROR_IO (-3)               /**< a file could not be opened, read or written. */
#define O3D_ERROR_PARSE (-4)            /**< malformed, truncated or inconsistent data. */
#define O3D_ERROR_UNSUPPORTED (-5)      /**< unknown format or feature not available. */
#define O3D_ERROR_BUFFER_TOO_SMALL (-6) /**< caller buffer too small; the needed count was reported. */
#define O3D_ERROR_NOT_CONVERGED (-7) /**< an iterative solver failed (singular system, divergence). */
#define O3D_ERROR_CANCELLED (-8)        /**< a progress callback returned non-zero. */
#define O3D_ERROR_INTERNAL (-9) /**< a bug or an unexpected failure inside the library. */

/* ---- Value types: int32_t in the ABI, named for what they hold. The bindings show them in their own idiom
 * (tools/gen_binding_tables.py): a flag as a bool, a count as an unsigned size, a constant group as an enum. */

/** A flag: 0 is false, any other value true. */
typedef int32_t o3d_bool;
/** A count or a limit (iterations, threads, neighbours, tuples): >= 0. */
typedef int32_t o3d_count;
/** An index, or -1 for none. */
typedef int32_t o3d_optional_index;

/** Log levels, most severe first (O3D_LOG_*). */
typedef int32_t o3d_log_level;
#define O3D_LOG_ERROR 0 /**< errors only */
#define O3D_LOG_WARNING 1 /**< warnings and errors (the default) */
#define O3D_LOG_INFO 2 /**< information too */
#define O3D_LOG_DEBUG 3 /**< everything, including each failure */

/** `which` constants of the array functions (o3d_<noun>_*_array): from this value on they name int32
 *  (index) arrays, below it float64 (or byte) arrays. */
#define O3D_INDEX_ARRAY_FIRST 100

/**
 * @brief Library version string, e.g. "0.1.0". Static storage.
 *
 * Threads: any thread.
 * Ownership: static storage owned by the library; valid forever.
 * @return the version string, e.g. "0.1.0". Never fails.
 */
O3D_API const char* o3d_version(void);
/**
 * @brief Library major version (equals the SONAME number).
 *
 * Threads: any thread.
 * @return the loaded library's major version. Never fails.
 */
O3D_API int32_t o3d_version_major(void);
/**
 * @brief Library minor version.
 *
 * Threads: any thread.
 * @return the loaded library's minor version. Never fails.
 */
O3D_API int32_t o3d_version_minor(void);
/**
 * @brief Library patch version.
 *
 * Threads: any thread.
 * @return the loaded library's patch version. Never fails.
 */
O3D_API int32_t o3d_version_patch(void);

/**
 * @brief Message of the last failure on this thread ("" when none). Never NULL.
 *
 * Threads: any thread; reads this thread's own error state.
 * Ownership: owned by the library; valid until the next o3d call on this thread.
 * @return the message ("" when none), never NULL. Never fails.
 */
O3D_API const char* o3d_last_error_message(void);
/**
 * @brief Status of the last failure on this thread (O3D_OK when none).
 *
 * Threads: any thread; reads this thread's own error state.
 * @return the code of the last failure on this thread (O3D_OK when none); never fails.
 */
O3D_API o3d_status o3d_last_error_code(void);
/**
 * @brief Forget the last failure on this thread.
 *
 * Threads: any thread; clears this thread's own error state.
 */
O3D_API void o3d_clear_error(void);
/**
 * @brief Static name of a status code ("O3D_OK", "O3D_ERROR_IO", ...). Never NULL.
 *
 * Threads: any thread.
 * Ownership: static storage owned by the library; valid forever.
 * @param status any status code
 * @return a name such as "O3D_ERROR_IO" (an unknown code gets a generic name), never NULL. Never fails.
 */
O3D_API const char* o3d_status_string(o3d_status status);

/**
 * @brief Receives log lines. Called on the thread that logged (never from inside a parallel region
 * concurrently with itself: logging is serialised by the library).
 */
typedef void (*o3d_log_callback)(o3d_log_level level, const char* message, void* user_data);

/**
 * @brief Show messages at `level` and more severe (default O3D_LOG_WARNING).
 *
 * Threads: any thread; the level is process-wide.
 * @param level O3D_LOG_ERROR ... O3D_LOG_DEBUG
 * @return O3D_OK, or O3D_ERROR_INVALID_ARGUMENT on a level outside 0..3.
 */
O3D_API o3d_status o3d_set_verbosity_level(o3d_log_level level);
/**
 * @brief The current log level.
 *
 * Threads: any thread; the level is process-wide.
 * @return the current level (O3D_LOG_*). Never fails.
 */
O3D_API o3d_log_level o3d_get_verbosity_level(void);
/**
 * @brief Route log lines to `callback` (NULL restores the default sink, stderr).
 *
 * Threads: any thread; the sink is process-wide and may be called from any thread that logs, serialised by the
 * library.
 * Ownership: `user_data` stays the caller's and must stay valid while the callback is registered.
 * @param callback the new sink (NULL: stderr)
 * @param user_data passed back to `callback`
 * @return O3D_OK; never fails (NULL `callback` is valid).
 */
O3D_API o3d_status o3d_set_log_callback(o3d_log_callback callback, void* user_data);

/**
 * @brief Default thread count for parallel algorithms when a call passes num_threads = 0.
 * 0 restores the OpenMP default (number of cores). Negative is invalid.
 *
 * Threads: any thread; the default is process-wide.
 * @param num_threads the default (0: the core count)
 * @return O3D_OK, or O3D_ERROR_INVALID_ARGUMENT on a negative `num_threads`.
 */
O3D_API o3d_status o3d_set_num_threads(int32_t num_threads);
/**
 * @brief The thread count a call with num_threads = 0 uses now (>= 1).
 *
 * Threads: any thread.
 * @return the thread count (>= 1). Never fails.
 */
O3D_API int32_t o3d_get_num_threads(void);

/**
 * @brief Progress report for long calls: `fraction` in [0,1]. Return 0 to go on, non-zero to cancel
 * (the call then fails with O3D_ERROR_CANCELLED). Always called on the calling thread.
 */
typedef int32_t (*o3d_progress_callback)(double fraction, void* user_data);

/** How a long call without tunables of its own runs: threads, progress and cancel. */
typedef struct o3d_progress_options {
    uint32_t struct_size;           /**< sizeof(o3d_progress_options_t) */
    o3d_count num_threads;          /**< 0 = library default; the result does not depend on it */
    o3d_progress_callback progress; /**< fraction of the work done; may be NULL */
    void* user_data;                /**< passed to `progress` */
} o3d_progress_options_t;

/**
 * @brief Fill defaults (library thread count, no callback).
 *
 * Threads: any thread.
 * @param opts the struct to fill
 * @param struct_size sizeof the struct as the caller knows it (an older, smaller size is accepted)
 * @return O3D_OK, or O3D_ERROR_INVALID_ARGUMENT on a NULL pointer or a `struct_size` this library does not know;
 *   O3D_ERROR_CANCELLED when the progress callback returns non-zero.
 */
O3D_API o3d_status o3d_progress_options_init(o3d_progress_options_t* opts, uint32_t struct_size);

/** Owned byte buffer (in-memory file contents). */
typedef struct o3d_buffer o3d_buffer_t;
/**
 * @brief Destroy a buffer. NULL is a no-op.
 *
 * Threads: needs exclusive access to `buffer`: no other call may use it during or after.
 * @param buffer the handle to destroy (NULL is a no-op)
 */
O3D_API void o3d_buffer_destroy(o3d_buffer_t* buffer);
/**
 * @brief Borrowed view of the bytes.
 *
 * Threads: any thread; concurrent calls on the same handles are safe (all read-only).
 * Ownership: `*out_data` points into `buffer` (never to be freed); valid until o3d_buffer_destroy.
 * @param out_data receives the address of the bytes (NULL when empty)
 * @param out_size receives the size in bytes
 * @param buffer the buffer
 * @return O3D_OK, or O3D_ERROR_INVALID_ARGUMENT on a NULL pointer.
 */
O3D_API o3d_status o3d_buffer_view(const uint8_t** out_data, size_t* out_size, const o3d_buffer_t* buffer);
/**
 * @brief Copy the bytes into `out` (capacity bytes); `*out_size` gets the size. NULL `out` queries it.
 *
 * Threads: any thread; concurrent calls on the same handles are safe (all read-only).
 * @param out caller buffer of `capacity` bytes (NULL: only report the size)
 * @param capacity bytes `out` holds
 * @param out_size receives the size in bytes (always)
 * @param buffer the buffer
 * @return O3D_OK, or O3D_ERROR_INVALID_ARGUMENT on a NULL `buffer` or `out_size`; O3D_ERROR_BUFFER_TOO_SMALL when
 *   `capacity` is short (the size is still reported).
 */
O3D_API o3d_status o3d_buffer_get_data(uint8_t* out, size_t capacity, size_t* out_size, const o3d_buffer_t* buffer);

/* ---- Random numbers ---- */

/**
 * @brief Seed the global generator that randomized calls draw from when they are not given a seed
 * (RANSAC, FGR). Without it the generator starts from a random device. @see o3d.utility.random.seed
 *
 * Threads: any thread; the generator is process-wide.
 * @param seed the seed
 * @return O3D_OK; never fails.
 */
O3D_API o3d_status o3d_random_seed(uint64_t seed);

O3D_END_DECL

#endif /* O3D_COMMON_H */
