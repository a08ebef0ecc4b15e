// SPDX-License-Identifier: MIT
#pragma once
/// @file handle.hpp
/// @brief UniqueHandle: move-only owner of one C handle, destroyed with its o3d_*_destroy function.
#include <utility>

namespace o3dpp {

template <typename T, void (*Destroy)(T*)>
class UniqueHandle {
public:
    UniqueHandle() noexcept = default;
    explicit UniqueHandle(T* owned) noexcept : p_(owned) {}
    ~UniqueHandle() { Destroy(p_); }
    UniqueHandle(const UniqueHandle&) = delete;
    UniqueHandle& operator=(const UniqueHandle&) = delete;
    UniqueHandle(UniqueHandle&& other) noexcept : p_(std::exchange(other.p_, nullptr)) {}
    UniqueHandle& operator=(UniqueHandle&& other) noexcept {
        if (this != &other) reset(std::exchange(other.p_, nullptr));
        return *this;
    }
    T* get() const noexcept { return p_; }
    /// @brief Give up ownership (the caller destroys the handle).
    T* release() noexcept { return std::exchange(p_, nullptr); }
    void reset(T* owned = nullptr) noexcept {
        T* old = std::exchange(p_, owned);
        Destroy(old);
    }
    explicit operator bool() const noexcept { return p_ != nullptr; }

private:
    T* p_ = nullptr;
};

}  // namespace o3dpp
