// SPDX-License-Identifier: MIT
#pragma once
/// @file qhull_support.h
/// @brief Internal: RAII wrappers for one reentrant Qhull (libqhull_r) run and its captured error stream.
#include <cstdio>
#include <cstdlib>
#include <string>

extern "C" {
#include <libqhull_r/qhull_ra.h>
}

namespace o3d::geometry::detail {

/// @brief Qhull's error stream captured in memory, so its diagnostics become our exception message
/// instead of noise on the caller's stderr.
class QhullErrorStream {
public:
    QhullErrorStream() : file_(open_memstream(&buffer_, &size_)) {}
    ~QhullErrorStream() {
        if (file_) std::fclose(file_);
        std::free(buffer_);
    }
    QhullErrorStream(const QhullErrorStream&) = delete;
    QhullErrorStream& operator=(const QhullErrorStream&) = delete;
    /// Null when open_memstream failed; Qhull then writes nowhere.
    FILE* file() const { return file_; }
    /// @brief Qhull's first paragraph, which names the problem (the rest are option dumps).
    std::string first_paragraph() {
        if (!file_) return {};
        std::fflush(file_);
        std::string s(buffer_ ? buffer_ : "", size_);
        const size_t cut = s.find("\n\n");
        return cut == std::string::npos ? s : s.substr(0, cut);
    }

private:
    char* buffer_ = nullptr;
    size_t size_ = 0;
    FILE* file_;
};

/// @brief Owns one reentrant Qhull state and frees it on every path (errors inside qh_new_qhull
/// longjmp back to it and return an exit code; nothing aborts).
class QhullRun {
public:
    QhullRun() { qh_zero(&qh_, nullptr); }
    ~QhullRun() {
        // !qh_ALL frees the long-memory blocks wholesale, which is much faster than walking every facet.
        qh_freeqhull(&qh_, !qh_ALL);
        int curlong = 0, totlong = 0;
        qh_memfreeshort(&qh_, &curlong, &totlong);
    }
    QhullRun(const QhullRun&) = delete;
    QhullRun& operator=(const QhullRun&) = delete;
    qhT* get() { return &qh_; }

private:
    qhT qh_;
};

}  // namespace o3d::geometry::detail
