// SPDX-License-Identifier: MIT
#include "o3d/reconstruction/stage_runner.h"

#include <omp.h>

#include <filesystem>

#include "o3d/io/file_bytes.h"
#include "o3d/utility/parallel.h"

namespace o3d::reconstruction {

void rethrow_with_context(const std::string& context) {
    const auto prefixed = [&](const std::exception& e) { return context + ": " + e.what(); };
    try {
        throw;
    } catch (const Cancelled&) {
        throw;
    } catch (const InvalidArgument& e) {
        throw InvalidArgument(prefixed(e));
    } catch (const IoError& e) {
        throw IoError(prefixed(e));
    } catch (const ParseError& e) {
        throw ParseError(prefixed(e));
    } catch (const Unsupported& e) {
        throw Unsupported(prefixed(e));
    } catch (const NotConverged& e) {
        throw NotConverged(prefixed(e));
    } catch (const BufferTooSmall& e) {
        throw BufferTooSmall(prefixed(e));
    }
    // std::bad_alloc and anything else keep their type: the C API guard maps them.
}

bool StageProgress::report() {
    if (cancelled()) return false;
    if (!callback_) return true;
    const size_t done = done_.load(std::memory_order_relaxed);
    const double fraction = total_ == 0 ? 1.0 : std::min(1.0, static_cast<double>(done) / static_cast<double>(total_));
    if (!callback_(fraction)) cancel();
    return !cancelled();
}

void StageProgress::throw_if_cancelled(const std::string& stage) const {
    if (cancelled()) throw Cancelled(stage + ": cancelled by the progress callback");
}

void parallel_for(size_t n, int num_threads, StageProgress& progress, const std::string& stage,
                  const std::function<void(size_t)>& fn) {
    progress.throw_if_cancelled(stage);
    std::exception_ptr error;
    std::mutex error_mutex;
    const int threads = std::max(1, std::min<int>(utility::resolve_num_threads(num_threads), static_cast<int>(n)));
    const auto n_items = static_cast<int64_t>(n);
#pragma omp parallel for schedule(dynamic, 1) num_threads(threads)
    for (int64_t i = 0; i < n_items; ++i) {
        if (progress.cancelled()) continue;
        try {
            fn(static_cast<size_t>(i));
            progress.complete();
        } catch (...) {
            const std::lock_guard<std::mutex> lock(error_mutex);
            if (!error) error = std::current_exception();
            progress.cancel();  // stops the other threads; the error, not a cancel, is what the caller sees
        }
        if (omp_get_thread_num() == 0) progress.report();  // a no-op once cancelled
    }
    if (error) std::rethrow_exception(error);
    progress.throw_if_cancelled(stage);
}

void write_whole_file(const std::string& path, const std::vector<uint8_t>& bytes) {
    namespace fs = std::filesystem;
    const fs::path target(path);
    std::error_code ec;
    if (target.has_parent_path()) fs::create_directories(target.parent_path(), ec);
    if (ec) throw IoError(path + ": cannot create its folder: " + ec.message());
    const std::string partial = path + ".partial";
    io::detail::write_file(partial, bytes);
    fs::rename(partial, target, ec);
    if (ec) {
        fs::remove(partial, ec);
        throw IoError(path + ": cannot write: " + ec.message());
    }
}

void write_whole_file(const std::string& path, const std::string& text) {
    write_whole_file(path, std::vector<uint8_t>(text.begin(), text.end()));
}

bool file_exists(const std::string& path) {
    std::error_code ec;
    return std::filesystem::is_regular_file(path, ec);
}

}  // namespace o3d::reconstruction
