// SPDX-License-Identifier: MIT
#pragma once
/// @file span.hpp
/// @brief Span<T> (pointer + size, C++17 stand-in for std::span) and Rows<T> (N x cols row-major view).
#include <array>
#include <cstddef>
#include <stdexcept>

namespace o3dpp {

using Vec3 = std::array<double, 3>;
using Mat3 = std::array<double, 9>;   ///< row-major 3x3
using Mat4 = std::array<double, 16>;  ///< row-major 4x4
using Mat6 = std::array<double, 36>;  ///< row-major 6x6

/// @brief Identity 4x4.
inline Mat4 identity4() { return {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1}; }

/// @brief Non-owning contiguous view of `size` elements. Borrowed: see the owner's rules.
template <typename T>
class Span {
public:
    constexpr Span() noexcept = default;
    constexpr Span(T* data, std::size_t size) noexcept : data_(data), size_(size) {}
    constexpr T* data() const noexcept { return data_; }
    constexpr std::size_t size() const noexcept { return size_; }
    constexpr bool empty() const noexcept { return size_ == 0; }
    constexpr T* begin() const noexcept { return data_; }
    constexpr T* end() const noexcept { return data_ + size_; }
    constexpr T& operator[](std::size_t i) const noexcept { return data_[i]; }
    T& at(std::size_t i) const {
        if (i >= size_) throw std::out_of_range("o3dpp::Span index out of range");
        return data_[i];
    }

private:
    T* data_ = nullptr;
    std::size_t size_ = 0;
};

/// @brief Non-owning view of `rows` rows of `cols` values (points, normals, triangles, descriptors...).
/// `view[i]` is a pointer to row i. Borrowed: valid until the owner is mutated or destroyed.
template <typename T>
class Rows {
public:
    constexpr Rows() noexcept = default;
    constexpr Rows(T* data, std::size_t rows, std::size_t cols = 3) noexcept : data_(data), rows_(rows), cols_(cols) {}
    constexpr T* data() const noexcept { return data_; }
    /// @brief Number of rows.
    constexpr std::size_t size() const noexcept { return rows_; }
    /// @brief Values per row.
    constexpr std::size_t cols() const noexcept { return cols_; }
    constexpr bool empty() const noexcept { return rows_ == 0; }
    constexpr T* operator[](std::size_t i) const noexcept { return data_ + cols_ * i; }
    /// @brief All size() * cols() values.
    constexpr Span<T> flat() const noexcept { return Span<T>(data_, cols_ * rows_); }

private:
    T* data_ = nullptr;
    std::size_t rows_ = 0;
    std::size_t cols_ = 3;
};
/// @brief The N x 3 views of earlier versions: the same type.
template <typename T>
using Rows3 = Rows<T>;

}  // namespace o3dpp
