// SPDX-License-Identifier: MIT
#pragma once
/// @file stage_runner.h
/// @brief What every stage of the reconstruction system shares: errors that name the frame or fragment and
/// the stage, progress reported on the calling thread with cancellation, a parallel loop over independent
/// items (frames, pairs, fragments), and output files that appear whole or not at all (so a cancelled or
/// failed run never leaves a truncated file that a resumed run would trust).
#include <atomic>
#include <cstdint>
#include <exception>
#include <functional>
#include <mutex>
#include <string>
#include <vector>

#include "o3d/utility/error.h"

namespace o3d::reconstruction {

/// @brief Rethrow the exception in flight as the same o3d error type with "`context`: " in front of its message.
/// Cancellation passes through unchanged.
[[noreturn]] void rethrow_with_context(const std::string& context);

/// @brief Run `fn`; any error it throws gets `context` in front of its message.
template <typename F>
auto with_context(const std::string& context, F&& fn) -> decltype(fn()) {
    try {
        return fn();
    } catch (...) {
        rethrow_with_context(context);
    }
}

/// @brief A stage's progress over a number of work units that worker threads complete. Only the thread that
/// created it calls the callback (the C API promises callbacks on the calling thread); a false return from it
/// stops every worker at its next unit.
class StageProgress {
public:
    StageProgress(std::function<bool(double)> callback, size_t total_units)
        : callback_(std::move(callback)), total_(total_units) {}

    void add_units(size_t units) { total_ += units; }
    void complete(size_t units = 1) { done_.fetch_add(units, std::memory_order_relaxed); }
    /// Call the callback with the fraction done (calling thread only); returns false once cancelled.
    bool report();
    bool cancelled() const { return cancelled_.load(std::memory_order_relaxed); }
    void cancel() { cancelled_.store(true, std::memory_order_relaxed); }
    /// @throws o3d::Cancelled naming `stage` when the callback asked to stop.
    void throw_if_cancelled(const std::string& stage) const;

private:
    std::function<bool(double)> callback_;
    std::atomic<size_t> done_{0};
    size_t total_;
    std::atomic<bool> cancelled_{false};
};

/// @brief fn(i) for i in [0, n) on up to `num_threads` threads (dynamic schedule: items differ in cost),
/// each item completing one progress unit. The calling thread reports progress after each of its items.
/// The first error stops the loop and is rethrown; a cancel stops it and throws o3d::Cancelled naming `stage`.
void parallel_for(size_t n, int num_threads, StageProgress& progress, const std::string& stage,
                  const std::function<void(size_t)>& fn);

/// @brief Write `bytes` to `path` through a temporary file in the same folder and a rename, creating the
/// folder if needed. @throws o3d::IoError naming the path.
void write_whole_file(const std::string& path, const std::vector<uint8_t>& bytes);
void write_whole_file(const std::string& path, const std::string& text);

/// @brief Whether `path` exists as a regular file.
bool file_exists(const std::string& path);

}  // namespace o3d::reconstruction
