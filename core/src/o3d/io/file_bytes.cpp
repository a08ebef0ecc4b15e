// SPDX-License-Identifier: MIT
#include "o3d/io/file_bytes.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>

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
    data_.reset(new uint8_t[capacity]);
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
            std::unique_ptr<uint8_t[]> bigger(new uint8_t[capacity * 2 + sizeof probe]);
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
