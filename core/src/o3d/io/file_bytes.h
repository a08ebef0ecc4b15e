// SPDX-License-Identifier: MIT
#pragma once
/// @file file_bytes.h
/// @brief Whole-file read and write, so that every parser works on memory (one code path, fuzzed).
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

namespace o3d::io::detail {

/// @brief The contents of a file. Throws o3d::IoError naming the path when it cannot be read.
class FileBytes {
public:
    explicit FileBytes(const std::string& path);
    const uint8_t* data() const { return data_.get(); }
    size_t size() const { return size_; }

private:
    std::unique_ptr<uint8_t[]> data_;
    size_t size_ = 0;
};

/// @brief Create or truncate `path` and write `bytes`. Throws o3d::IoError naming the path.
void write_file(const std::string& path, const std::vector<uint8_t>& bytes);

}  // namespace o3d::io::detail
