// SPDX-License-Identifier: MIT
#pragma once
/// @file text_writer.h
/// @brief A growable byte sink for the writers. Numbers go through std::to_chars: the shortest text
/// that reads back to the same value, so ASCII files round-trip exactly.
#include <algorithm>
#include <charconv>
#include <cstdint>
#include <cstring>
#include <string_view>
#include <vector>

#include "o3d/io/io_internal.h"

namespace o3d::io::detail {

class ByteSink {
public:
    explicit ByteSink(size_t expected = 0) : buf_(output_buffer(expected < 64 ? 64 : expected)) {}

    void put(std::string_view s) {
        char* p = grow(s.size());
        if (!s.empty()) std::memcpy(p, s.data(), s.size());
        len_ += s.size();
    }
    void put(char c) {
        *grow(1) = c;
        ++len_;
    }
    template <typename T>
    void put_number(T v) {
        // 32 chars hold any shortest double ("-2.2250738585072014e-308") and any 64-bit integer.
        char* p = grow(32);
        auto [e, ec] = std::to_chars(p, p + 32, v);
        (void)ec;
        len_ += static_cast<size_t>(e - p);
    }
    /// @brief Reserve n raw bytes at the end and return where they start.
    uint8_t* append_raw(size_t n) {
        uint8_t* p = reinterpret_cast<uint8_t*>(grow(n));
        len_ += n;
        return p;
    }
    std::vector<uint8_t> finish() {
        buf_.resize(len_);
        return std::move(buf_);
    }

private:
    char* grow(size_t n) {
        if (buf_.size() - len_ < n) buf_.resize(std::max(buf_.size() * 2, len_ + n));
        return reinterpret_cast<char*>(buf_.data() + len_);
    }
    std::vector<uint8_t> buf_;
    size_t len_ = 0;
};

}  // namespace o3d::io::detail
