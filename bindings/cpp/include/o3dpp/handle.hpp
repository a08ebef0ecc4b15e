// SPDX-License-Identifier: MIT
#pragma once
/// @file handle.hpp
/// @brief UniqueHandle (move-only owner of one C handle, destroyed with its o3d_*_destroy) and Owner, the
/// base of every wrapper class: get / release / bool / adopt, and a NULL check on adoption.
#include <utility>
#include <vector>

#include "o3dpp/arrays.hpp"
#include "o3dpp/error.hpp"
#include "o3dpp/span.hpp"

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

/// @brief Base of the wrapper classes: owns one `T` (move-only, so the classes are too).
template <typename Derived, typename T, void (*Destroy)(T*)>
class Owner {
public:
    /// @brief The handle (NULL after a move). Still owned by this object.
    T* get() const noexcept { return h_.get(); }
    /// @brief Give up ownership: the caller destroys the handle with its o3d_*_destroy.
    T* release() noexcept { return h_.release(); }
    explicit operator bool() const noexcept { return static_cast<bool>(h_); }

    /// @brief Run `create(T** out)` (a C constructor) and own what it wrote.
    template <typename F>
    static Derived adopt(F&& create) { return Derived(make(std::forward<F>(create))); }

    /// @brief A new object from the C constructor `fn(T** out, args...)`.
    template <typename Fn, typename... Args>
    static Derived create(Fn fn, const Args&... args) { return adopt([&](T** out) { return fn(out, args...); }); }

protected:
    /// @brief A new `R` (default: Derived) from the C call `fn(R's handle** out, this handle, args...)`.
    template <typename R = Derived, typename Fn, typename... Args>
    R derive(Fn fn, const Args&... args) const { return R::adopt([&](auto** out) { return fn(out, get(), args...); }); }
    /// @brief Copy-out of the C call `fn(out, capacity, &n, this handle, args...)` as rows of `Row`.
    template <typename Row, typename Fn, typename... Args>
    std::vector<Row> copy_out(Fn fn, const Args&... args) const {
        return detail::copy_out<Row>([&](auto* out, size_t cap, size_t* n) { return fn(out, cap, n, get(), args...); });
    }
    /// @brief No handle (only for classes that allow an empty state).
    Owner() noexcept = default;
    /// @brief Take ownership of `owned` (must not be NULL).
    explicit Owner(T* owned) : h_(owned) {
        if (!owned) throw Error(O3D_ERROR_INVALID_ARGUMENT, "o3dpp: cannot adopt a NULL handle");
    }
    /// @brief Run `create(T** out)` and return the new handle (for constructors).
    template <typename F>
    static T* make(F&& create) {
        T* p = nullptr;
        check(create(&p));
        return p;
    }
    /// @brief Check `status` of a call that changed this object; *this, for chaining.
    Derived& done(o3d_status status) {
        check(status);
        return static_cast<Derived&>(*this);
    }
    /// @brief What a C getter `fn(V* out, const T*)` writes.
    template <typename V>
    V query(o3d_status (*fn)(V*, const T*)) const {
        V v{};
        check(fn(&v, get()));
        return v;
    }
    /// @brief The three values a C getter `fn(double out[3], const T*)` writes.
    Vec3 query3(o3d_status (*fn)(double*, const T*)) const {
        Vec3 v{};
        check(fn(v.data(), get()));
        return v;
    }

private:
    UniqueHandle<T, Destroy> h_;
};

}  // namespace o3dpp
