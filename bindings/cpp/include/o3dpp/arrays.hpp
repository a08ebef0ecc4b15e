// SPDX-License-Identifier: MIT
#pragma once
/// @file arrays.hpp
/// @brief Arrays: the one array accessor of every geometry, over the C family o3d_<noun>_{has_array,
/// array_shape, set_array[_f32], get_array, array_view, array_mutable_view} and its int32 *_index_array twins.
/// The element type picks the C function: double (float64), float (set_array_f32), int32_t (index arrays),
/// uint8_t (image bytes).
#include <array>
#include <cstdint>
#include <string>
#include <type_traits>
#include <vector>

#include "o3dpp/error.hpp"
#include "o3dpp/span.hpp"

namespace o3dpp {
namespace detail {

/// @brief A noun's array functions; what it lacks is nullptr (a voxel grid has no setters or views).
template <auto Has, auto Shape, auto Get, auto View, auto MutableView, auto Set, auto SetF32,
          auto GetIndex = nullptr, auto IndexView = nullptr, auto IndexMutableView = nullptr, auto SetIndex = nullptr>
struct ArrayFns {
    static constexpr auto has = Has;
    static constexpr auto shape = Shape;
    static constexpr auto get = Get;
    static constexpr auto view = View;
    static constexpr auto mutable_view = MutableView;
    static constexpr auto set = Set;
    static constexpr auto set_f32 = SetF32;
    static constexpr auto get_index = GetIndex;
    static constexpr auto index_view = IndexView;
    static constexpr auto index_mutable_view = IndexMutableView;
    static constexpr auto set_index = SetIndex;
};

/// @brief Row types: std::array<T, N> is one row of N values; a plain T reads the array flat.
template <typename R>
struct RowOf {
    using type = R;
    static constexpr std::size_t cols = 0;
};
template <typename T, std::size_t N>
struct RowOf<std::array<T, N>> {
    static_assert(sizeof(std::array<T, N>) == N * sizeof(T), "std::array must be packed");
    using type = T;
    static constexpr std::size_t cols = N;
};

/// @brief The C copy-out convention: `fn(out, capacity, &n)` reports the count when out is NULL, then
/// fills a buffer of that size. `Row` may be a std::array of the element type.
template <typename Row, typename F>
std::vector<Row> copy_out(F&& fn) {
    using T = typename RowOf<Row>::type;
    size_t n = 0;
    check(fn(static_cast<T*>(nullptr), 0, &n));
    std::vector<Row> out(n);
    check(fn(reinterpret_cast<T*>(out.data()), n, &n));
    out.resize(n);
    return out;
}

/// @brief {at(0), ..., at(n - 1)}: a list read item by item (nodes, edges, camera poses).
template <typename F>
auto collect(std::size_t n, F&& at) {
    std::vector<decltype(at(std::size_t{0}))> out;
    out.reserve(n);
    for (std::size_t i = 0; i < n; ++i) out.push_back(at(i));
    return out;
}

}  // namespace detail

/// @brief Mixin of the geometry classes: array `which` (an enum of O3D_* constants) of `Derived`.
template <typename Derived, typename Which, typename Fns>
class Arrays {
public:
    /// @brief Whether the array counts (Open3D's has_*: present and of the matching size).
    bool has_array(Which which) const {
        int32_t v = 0;
        check(Fns::has(&v, self(), id(which)));
        return v != 0;
    }
    /// @brief {rows, values per row}.
    std::array<std::size_t, 2> array_shape(Which which) const {
        std::array<std::size_t, 2> s{};
        check(Fns::shape(&s[0], &s[1], self(), id(which)));
        return s;
    }
    /// @brief Copy of the array: rows of `Row` (std::array<T, values per row>), or all values with a plain T.
    template <typename Row = Vec3>
    std::vector<Row> get_array(Which which) const {
        using T = typename detail::RowOf<Row>::type;
        const std::size_t k = per_row<Row>(which);
        size_t n = 0;
        copy(static_cast<T*>(nullptr), 0, &n, which);
        std::vector<Row> out(n * k);
        copy(reinterpret_cast<T*>(out.data()), n, &n, which);
        out.resize(n * k);
        return out;
    }
    /// @brief Replace the array with `rows` (as get_array reads them); copied once.
    template <typename Row = Vec3>
    void set_array(Which which, const std::vector<Row>& rows) {
        const std::size_t k = per_row<Row>(which);
        if (k == 0 ? !rows.empty() : rows.size() % k != 0)
            throw Error(O3D_ERROR_INVALID_ARGUMENT, "o3dpp: " + std::to_string(rows.size()) +
                                                        " values are not whole rows of " + std::to_string(k));
        set_array(which, reinterpret_cast<const typename detail::RowOf<Row>::type*>(rows.data()),
                  k == 0 ? 0 : rows.size() / k);
    }
    /// @brief Replace the array with `rows` rows at `data` (float is converted in the one copy).
    template <typename T>
    void set_array(Which which, const T* data, std::size_t rows) {
        if constexpr (std::is_same_v<T, float>)
            check(Fns::set_f32(self(), id(which), data, rows));
        else if constexpr (std::is_same_v<T, int32_t>)
            check(Fns::set_index(self(), id(which), data, rows));
        else
            check(Fns::set(self(), id(which), data, rows));
    }
    /// @brief Borrowed view, valid until the next mutating call or destruction.
    template <typename T = double>
    Rows<const T> array(Which which) const {
        const T* d = nullptr;
        size_t n = 0;
        if constexpr (std::is_same_v<T, int32_t>)
            check(Fns::index_view(&d, &n, self(), id(which)));
        else
            check(Fns::view(&d, &n, self(), id(which)));
        return {d, n, array_shape(which)[1]};
    }
    /// @brief Writable view (writing through it is a mutating call); as array().
    template <typename T = double>
    Rows<T> array_mutable(Which which) {
        T* d = nullptr;
        size_t n = 0;
        if constexpr (std::is_same_v<T, int32_t>)
            check(Fns::index_mutable_view(&d, &n, self(), id(which)));
        else
            check(Fns::mutable_view(&d, &n, self(), id(which)));
        return {d, n, array_shape(which)[1]};
    }

private:
    static int32_t id(Which which) { return static_cast<int32_t>(which); }
    auto self() const { return static_cast<const Derived*>(this)->get(); }
    /// @brief Elements of `Row` per C row: 1 for a std::array of the right width, the width for a plain T.
    template <typename Row>
    std::size_t per_row(Which which) const {
        const std::size_t cols = array_shape(which)[1];
        if constexpr (detail::RowOf<Row>::cols == 0) return cols;
        if (cols != detail::RowOf<Row>::cols)
            throw Error(O3D_ERROR_INVALID_ARGUMENT, "o3dpp: array " + std::to_string(id(which)) + " has " +
                                                        std::to_string(cols) + " values per row, not " +
                                                        std::to_string(detail::RowOf<Row>::cols));
        return 1;
    }
    template <typename T>
    void copy(T* out, std::size_t capacity, size_t* n, Which which) const {
        if constexpr (std::is_same_v<T, int32_t>)
            check(Fns::get_index(out, capacity, n, self(), id(which)));
        else
            check(Fns::get(out, capacity, n, self(), id(which)));
    }
};

}  // namespace o3dpp
