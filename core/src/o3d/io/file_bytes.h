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
    struct Free {
        void operator()(uint8_t* p) const;
    };
    using Buffer = std::unique_ptr<uint8_t, Free>;
    static Buffer allocate(size_t bytes);
    Buffer data_;
    size_t size_ = 0;
};

/// @brief Map the pages of a fresh, large allocation in one system call instead of one page fault
/// per 4 KiB page as they are first written (a 1M-point cloud is ~6000 faults, several ms on VMs).
/// A no-op for small ranges and where the kernel lacks MADV_POPULATE_WRITE.
void prefault(void* data, size_t bytes);

/// @brief Create or truncate `path` and write `bytes`. Throws o3d::IoError naming the path.
void write_file(const std::string& path, const std::vector<uint8_t>& bytes);

}  // namespace o3d::io::detail
