// SPDX-License-Identifier: MIT
#include "o3d/io/file_bytes.h"

#include <fcntl.h>
#include <sys/mman.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <new>

#include "o3d/utility/error.h"

namespace o3d::io::detail {
namespace {

[[noreturn]] void io_fail(const std::string& what, const std::string& path, int err) {
    throw IoError(what + " '" + path + "': " + std::strerror(err));
}

struct Fd {
    int fd;
    ~Fd() {
        if (fd >= 0) ::close(fd);
    }
};

}  // namespace

void prefault(void* data, size_t bytes) {
    // Each 4 KiB page costs a fault, a zeroing and a memory-cgroup charge when first written;
    // hinting huge pages for the 2 MiB-aligned interior and populating the range in one call
    // cuts that kernel time about tenfold on large clouds.
    constexpr uintptr_t kPage = 4096, kHuge = 2u << 20;
    if (bytes < (256u << 10)) return;
    const uintptr_t lo = reinterpret_cast<uintptr_t>(data), hi = lo + bytes;
#ifdef MADV_HUGEPAGE
    const uintptr_t hb = (lo + kHuge - 1) & ~(kHuge - 1), he = hi & ~(kHuge - 1);
    if (he > hb) (void)::madvise(reinterpret_cast<void*>(hb), he - hb, MADV_HUGEPAGE);
#endif
#ifdef MADV_POPULATE_WRITE
    const uintptr_t b = (lo + kPage - 1) & ~(kPage - 1), e = hi & ~(kPage - 1);
    if (e > b) (void)::madvise(reinterpret_cast<void*>(b), e - b, MADV_POPULATE_WRITE);
#endif
}

void FileBytes::Free::operator()(uint8_t* p) const { std::free(p); }

FileBytes::Buffer FileBytes::allocate(size_t bytes) {
    // Large buffers start on a 2 MiB boundary so that prefault() can back all of them with huge pages.
    constexpr size_t kHuge = 2u << 20;
    void* p = bytes >= kHuge / 2 ? std::aligned_alloc(kHuge, (bytes + kHuge - 1) & ~(kHuge - 1)) : std::malloc(bytes);
    if (!p) throw std::bad_alloc();
    prefault(p, bytes);
    return Buffer(static_cast<uint8_t*>(p));
}

// read() into a private buffer rather than mmap: a file truncated by another process while we
// parse it must give an error, not SIGBUS.
FileBytes::FileBytes(const std::string& path) {
    Fd f{::open(path.c_str(), O_RDONLY | O_CLOEXEC)};
    if (f.fd < 0) io_fail("cannot open", path, errno);
    struct stat st {};
    if (::fstat(f.fd, &st) != 0) io_fail("cannot stat", path, errno);
    if (S_ISDIR(st.st_mode)) io_fail("cannot read", path, EISDIR);

    size_t capacity = S_ISREG(st.st_mode) ? static_cast<size_t>(st.st_size) : 0;
    if (capacity == 0) capacity = 1 << 16;  // pipes and /proc files report no size
    data_ = allocate(capacity);
    for (;;) {
        if (size_ == capacity) {
            // Usually the end of a regular file: probe before growing, so a file whose size we
            // knew is read with one allocation and no copy.
            uint8_t probe[4096];
            const ssize_t got = ::read(f.fd, probe, sizeof probe);
            if (got < 0) {
                if (errno == EINTR) continue;
                io_fail("cannot read", path, errno);
            }
            if (got == 0) break;
            Buffer bigger = allocate(capacity * 2 + sizeof probe);
            std::memcpy(bigger.get(), data_.get(), size_);
            std::memcpy(bigger.get() + size_, probe, static_cast<size_t>(got));
            data_ = std::move(bigger);
            capacity = capacity * 2 + sizeof probe;
            size_ += static_cast<size_t>(got);
            continue;
        }
        const ssize_t got = ::read(f.fd, data_.get() + size_, capacity - size_);
        if (got < 0) {
            if (errno == EINTR) continue;
            io_fail("cannot read", path, errno);
        }
        if (got == 0) break;
        size_ += static_cast<size_t>(got);
    }
}

void write_file(const std::string& path, const std::vector<uint8_t>& bytes) {
    Fd f{::open(path.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644)};
    if (f.fd < 0) io_fail("cannot create", path, errno);
    size_t done = 0;
    while (done < bytes.size()) {
        const ssize_t put = ::write(f.fd, bytes.data() + done, bytes.size() - done);
        if (put < 0) {
            if (errno == EINTR) continue;
            io_fail("cannot write", path, errno);
        }
        done += static_cast<size_t>(put);
    }
    const int fd = f.fd;
    f.fd = -1;
    if (::close(fd) != 0) io_fail("cannot write", path, errno);
}

}  // namespace o3d::io::detail
