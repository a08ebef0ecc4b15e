// SPDX-License-Identifier: MIT
#pragma once
/// @file options.hpp
/// @brief COptions: the base of the wrapper's option structs. Defaults come from the C `*_init` function;
/// `Fields::fields(self, c, copy)` (generated) names each field's C counterpart once, for both directions.
#include <algorithm>
#include <array>
#include <cstdint>
#include <optional>
#include <type_traits>

#include "o3dpp/error.hpp"

namespace o3dpp {
namespace detail {
/// @brief C -> C++ field copy (int32 flags to bool, int32 constants to enums, a nested C struct to its
/// option struct).
struct Load {
    template <typename W, typename C>
    void operator()(W& w, const C& c) const {
        if constexpr (std::is_class_v<W>) {
            w = W::from_c(c);
        } else {
            w = static_cast<W>(c);
        }
    }
    template <typename T, std::size_t N>
    void operator()(std::array<T, N>& w, const T (&c)[N]) const { std::copy(c, c + N, w.begin()); }
    void operator()(std::optional<uint64_t>& w, int32_t use, uint64_t seed) const {
        w = use ? std::optional<uint64_t>(seed) : std::nullopt;
    }
};
/// @brief C++ -> C field copy.
struct Store {
    template <typename W, typename C>
    void operator()(const W& w, C& c) const {
        if constexpr (std::is_class_v<W>) {
            c = w.to_c();
        } else {
            c = static_cast<C>(w);
        }
    }
    template <typename T, std::size_t N>
    void operator()(const std::array<T, N>& w, T (&c)[N]) const { std::copy(w.begin(), w.end(), c); }
    void operator()(const std::optional<uint64_t>& w, int32_t& use, uint64_t& seed) const {
        use = w ? 1 : 0;
        seed = w.value_or(0);
    }
};
}  // namespace detail

/// @brief Option struct over the C struct `C` filled by `Init` (o3d_<thing>_options_init): the members and
/// their `fields(self, c, copy)` come from `Fields` (generated/options.hpp, from the C header).
template <typename Derived, typename Fields, typename C, o3d_status (*Init)(C*, uint32_t)>
struct COptions : Fields {
    /// @brief The library's defaults.
    COptions() { load(library_defaults()); }
    /// @brief The library's defaults, as the C struct.
    static C library_defaults() {
        C c;
        check(Init(&c, sizeof c));
        return c;
    }
    /// @brief The options in `c`.
    static Derived from_c(const C& c) {
        Derived d;
        d.load(c);
        return d;
    }
    /// @brief The C struct: the library's defaults, then these fields.
    C to_c() const {
        C c = library_defaults();
        Fields::fields(static_cast<const Fields&>(*this), c, detail::Store{});
        return c;
    }

protected:
    void load(const C& c) { Fields::fields(static_cast<Fields&>(*this), c, detail::Load{}); }
};

}  // namespace o3dpp
