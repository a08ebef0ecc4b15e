// SPDX-License-Identifier: MIT
#pragma once
/// @file options.hpp
/// @brief COptions: the base of the wrapper's option structs. Defaults come from the C `*_init` function;
/// `Derived::fields(self, c, copy)` names each field's C counterpart once, for both directions.
#include <algorithm>
#include <array>
#include <cstdint>
#include <optional>

#include "o3dpp/error.hpp"

namespace o3dpp {
namespace detail {
/// @brief C -> C++ field copy (int32 flags to bool, int32 constants to enums).
struct Load {
    template <typename W, typename C>
    void operator()(W& w, const C& c) const { w = static_cast<W>(c); }
    template <typename T, std::size_t N>
    void operator()(std::array<T, N>& w, const T (&c)[N]) const { std::copy(c, c + N, w.begin()); }
    void operator()(std::optional<uint64_t>& w, int32_t use, uint64_t seed) const {
        w = use ? std::optional<uint64_t>(seed) : std::nullopt;
    }
};
/// @brief C++ -> C field copy.
struct Store {
    template <typename W, typename C>
    void operator()(const W& w, C& c) const { c = static_cast<C>(w); }
    template <typename T, std::size_t N>
    void operator()(const std::array<T, N>& w, T (&c)[N]) const { std::copy(w.begin(), w.end(), c); }
    void operator()(const std::optional<uint64_t>& w, int32_t& use, uint64_t& seed) const {
        use = w ? 1 : 0;
        seed = w.value_or(0);
    }
};
}  // namespace detail

/// @brief Option struct bound to the C struct `C` filled by `Init` (o3d_<thing>_options_init).
template <typename Derived, typename C, o3d_status (*Init)(C*, uint32_t)>
struct COptions {
    /// @brief The library's defaults.
    static C library_defaults() {
        C c;
        check(Init(&c, sizeof c));
        return c;
    }
    /// @brief The C struct: the library's defaults, then these fields.
    C to_c() const {
        C c = library_defaults();
        Derived::fields(static_cast<const Derived&>(*this), c, detail::Store{});
        return c;
    }

protected:
    /// @brief Set every field from `c` (the derived constructor calls it with library_defaults()).
    void load(C c) { Derived::fields(static_cast<Derived&>(*this), c, detail::Load{}); }
};

}  // namespace o3dpp
