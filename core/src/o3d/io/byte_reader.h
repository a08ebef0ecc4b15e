// SPDX-License-Identifier: MIT
#pragma once
/// @file byte_reader.h
/// @brief Bounded access to an in-memory file: a text cursor whose numbers go through
/// std::from_chars, and unaligned, endian-aware scalar loads. Nothing here reads past `end`.
#include <Eigen/Core>
#include <charconv>
#include <cstdint>
#include <cstring>
#include <string_view>

namespace o3d::io::detail {

/// @brief Whitespace as C's isspace() in the "C" locale, by table: the tokenisers' inner loop.
struct SpaceTable {
    bool t[256] = {};
    constexpr SpaceTable() {
        t[static_cast<unsigned char>(' ')] = t[static_cast<unsigned char>('\t')] = true;
        t[static_cast<unsigned char>('\n')] = t[static_cast<unsigned char>('\r')] = true;
        t[static_cast<unsigned char>('\v')] = t[static_cast<unsigned char>('\f')] = true;
    }
};
inline constexpr SpaceTable kSpace{};
inline bool is_space(char c) { return kSpace.t[static_cast<unsigned char>(c)]; }
/// @brief Whitespace that does not end a line.
inline bool is_blank(char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\v' || c == '\f'; }

/// @brief Parse a whole token as a floating-point number. Accepts what strtod-based writers produce:
/// a leading '+', "nan", "inf". Overflowing literals fail rather than silently becoming infinities.
template <typename Real>
inline bool parse_real(std::string_view tok, Real& out) {
    const char* b = tok.data();
    const char* e = b + tok.size();
    if (b != e && *b == '+') {
        ++b;
        if (b != e && *b == '-') return false;
    }
    if (b == e) return false;
    auto [p, ec] = std::from_chars(b, e, out);
    return ec == std::errc() && p == e;
}

inline bool parse_double(std::string_view tok, double& out) { return parse_real(tok, out); }
inline bool parse_float(std::string_view tok, float& out) { return parse_real(tok, out); }

inline bool parse_int64(std::string_view tok, int64_t& out) {
    const char* b = tok.data();
    const char* e = b + tok.size();
    if (b != e && *b == '+') ++b;
    if (b == e) return false;
    auto [p, ec] = std::from_chars(b, e, out);
    return ec == std::errc() && p == e;
}

/// @brief Forward-only cursor over text. Tokens are maximal runs of non-whitespace.
class TextCursor {
public:
    TextCursor(const char* begin, const char* end) : p_(begin), end_(end) {}
    explicit TextCursor(std::string_view s) : p_(s.data()), end_(s.data() + s.size()) {}

    bool at_end() const { return p_ >= end_; }
    const char* pos() const { return p_; }
    size_t remaining() const { return static_cast<size_t>(end_ - p_); }

    /// @brief Next token, crossing line breaks; empty once only whitespace is left.
    std::string_view token() {
        while (p_ < end_ && is_space(*p_)) ++p_;
        const char* s = p_;
        while (p_ < end_ && !is_space(*p_)) ++p_;
        return {s, static_cast<size_t>(p_ - s)};
    }

    /// @brief Parse the next token as a double (as parse_double() would) without scanning it
    /// twice in the common case. On failure `tok` holds the offending token (empty at the end).
    bool number(double& out, std::string_view& tok) {
        while (p_ < end_ && is_space(*p_)) ++p_;
        const char* s = p_;
        auto [q, ec] = std::from_chars(s, end_, out);
        if (ec == std::errc() && q != s && (q == end_ || is_space(*q))) {
            p_ = q;
            return true;
        }
        while (p_ < end_ && !is_space(*p_)) ++p_;
        tok = std::string_view(s, static_cast<size_t>(p_ - s));
        return parse_double(tok, out);  // the rare forms from_chars alone refuses, such as "+1"
    }

    /// @brief Skip one token without looking at it; false when none is left.
    bool skip_token() { return !token().empty(); }

    /// @brief The current line without its terminator ("\n" or "\r\n"); moves past the terminator.
    std::string_view line() {
        const char* s = p_;
        const void* nl = p_ < end_ ? std::memchr(p_, '\n', static_cast<size_t>(end_ - p_)) : nullptr;
        const char* e = nl ? static_cast<const char*>(nl) : end_;
        p_ = nl ? e + 1 : end_;
        if (e > s && e[-1] == '\r') --e;
        return {s, static_cast<size_t>(e - s)};
    }

    /// @brief True when nothing but whitespace is left.
    bool only_whitespace_left() {
        while (p_ < end_ && is_space(*p_)) ++p_;
        return p_ >= end_;
    }

private:
    const char* p_;
    const char* end_;
};

/// @brief Number of '\n' in [b, e): an upper bound on the rows a text file can hold.
inline size_t count_lines(const char* b, const char* e) {
    size_t n = 0;
    while (b < e) {
        const void* nl = std::memchr(b, '\n', static_cast<size_t>(e - b));
        if (!nl) break;
        ++n;
        b = static_cast<const char*>(nl) + 1;
    }
    return n;
}

/// @brief Binary scalar types shared by PLY and PCD.
enum class ScalarType : uint8_t { Int8, UInt8, Int16, UInt16, Int32, UInt32, Int64, UInt64, Float32, Float64 };

inline size_t scalar_size(ScalarType t) {
    switch (t) {
        case ScalarType::Int8:
        case ScalarType::UInt8: return 1;
        case ScalarType::Int16:
        case ScalarType::UInt16: return 2;
        case ScalarType::Int32:
        case ScalarType::UInt32:
        case ScalarType::Float32: return 4;
        default: return 8;
    }
}

inline bool is_integer(ScalarType t) { return t != ScalarType::Float32 && t != ScalarType::Float64; }

constexpr bool kHostLittleEndian = __BYTE_ORDER__ == __ORDER_LITTLE_ENDIAN__;

template <typename T>
inline T byte_swap(T v) {
    if constexpr (sizeof(T) == 1) {
        return v;
    } else {
        using U = std::conditional_t<sizeof(T) == 2, uint16_t, std::conditional_t<sizeof(T) == 4, uint32_t, uint64_t>>;
        U u;
        std::memcpy(&u, &v, sizeof u);
        if constexpr (sizeof(T) == 2) u = __builtin_bswap16(u);
        if constexpr (sizeof(T) == 4) u = __builtin_bswap32(u);
        if constexpr (sizeof(T) == 8) u = __builtin_bswap64(u);
        std::memcpy(&v, &u, sizeof u);
        return v;
    }
}

/// @brief Unaligned load of a T stored with the other byte order when Swap.
template <typename T, bool Swap>
inline T load(const uint8_t* p) {
    T v;
    std::memcpy(&v, p, sizeof v);
    if constexpr (Swap) v = byte_swap(v);
    return v;
}

template <typename T>
inline T load(const uint8_t* p, bool swap) {
    return swap ? load<T, true>(p) : load<T, false>(p);
}

/// @brief Unaligned little-endian store (the byte order of every binary format o3d writes).
template <typename T>
inline void store_le(uint8_t* p, T v) {
    if constexpr (!kHostLittleEndian) v = byte_swap(v);
    std::memcpy(p, &v, sizeof v);
}

inline double load_as_double(const uint8_t* p, ScalarType t, bool swap) {
    switch (t) {
        case ScalarType::Int8: return load<int8_t>(p, swap);
        case ScalarType::UInt8: return load<uint8_t>(p, swap);
        case ScalarType::Int16: return load<int16_t>(p, swap);
        case ScalarType::UInt16: return load<uint16_t>(p, swap);
        case ScalarType::Int32: return load<int32_t>(p, swap);
        case ScalarType::UInt32: return load<uint32_t>(p, swap);
        case ScalarType::Int64: return static_cast<double>(load<int64_t>(p, swap));
        case ScalarType::UInt64: return static_cast<double>(load<uint64_t>(p, swap));
        case ScalarType::Float32: return load<float>(p, swap);
        default: return load<double>(p, swap);
    }
}

/// @brief An integer scalar (a PLY list length) widened to int64; UInt64 beyond INT64_MAX gives -1,
/// which callers reject like any negative length.
inline int64_t load_as_int64(const uint8_t* p, ScalarType t, bool swap) {
    switch (t) {
        case ScalarType::Int8: return load<int8_t>(p, swap);
        case ScalarType::UInt8: return load<uint8_t>(p, swap);
        case ScalarType::Int16: return load<int16_t>(p, swap);
        case ScalarType::UInt16: return load<uint16_t>(p, swap);
        case ScalarType::Int32: return load<int32_t>(p, swap);
        case ScalarType::UInt32: return load<uint32_t>(p, swap);
        case ScalarType::Int64: return load<int64_t>(p, swap);
        case ScalarType::UInt64: {
            const uint64_t v = load<uint64_t>(p, swap);
            return v > static_cast<uint64_t>(INT64_MAX) ? -1 : static_cast<int64_t>(v);
        }
        default: return -1;
    }
}

/// @brief Where the three components of a vector attribute live: component k of item i is the
/// scalar of type `type[k]` at `base[k] + i * stride[k]`.
struct TripleLayout {
    const uint8_t* base[3];
    size_t stride[3];
    ScalarType type[3];
};

template <typename T, bool Swap>
void decode_triples_typed(const TripleLayout& l, size_t n, double divisor, Eigen::Vector3d* out) {
    const uint8_t* b0 = l.base[0];
    const uint8_t* b1 = l.base[1];
    const uint8_t* b2 = l.base[2];
    const size_t s0 = l.stride[0], s1 = l.stride[1], s2 = l.stride[2];
    if (divisor == 1.0) {
        for (size_t i = 0; i < n; ++i) {
            double* o = out[i].data();
            o[0] = static_cast<double>(load<T, Swap>(b0 + i * s0));
            o[1] = static_cast<double>(load<T, Swap>(b1 + i * s1));
            o[2] = static_cast<double>(load<T, Swap>(b2 + i * s2));
        }
    } else {
        for (size_t i = 0; i < n; ++i) {
            double* o = out[i].data();
            o[0] = static_cast<double>(load<T, Swap>(b0 + i * s0)) / divisor;
            o[1] = static_cast<double>(load<T, Swap>(b1 + i * s1)) / divisor;
            o[2] = static_cast<double>(load<T, Swap>(b2 + i * s2)) / divisor;
        }
    }
}

template <bool Swap>
void decode_triples_swap(const TripleLayout& l, size_t n, double divisor, Eigen::Vector3d* out) {
    if (l.type[0] != l.type[1] || l.type[0] != l.type[2]) {
        // Mixed component types are legal but rare: take the generic path.
        for (size_t i = 0; i < n; ++i)
            for (int k = 0; k < 3; ++k) out[i][k] = load_as_double(l.base[k] + i * l.stride[k], l.type[k], Swap) / divisor;
        return;
    }
    switch (l.type[0]) {
        case ScalarType::Int8: return decode_triples_typed<int8_t, Swap>(l, n, divisor, out);
        case ScalarType::UInt8: return decode_triples_typed<uint8_t, Swap>(l, n, divisor, out);
        case ScalarType::Int16: return decode_triples_typed<int16_t, Swap>(l, n, divisor, out);
        case ScalarType::UInt16: return decode_triples_typed<uint16_t, Swap>(l, n, divisor, out);
        case ScalarType::Int32: return decode_triples_typed<int32_t, Swap>(l, n, divisor, out);
        case ScalarType::UInt32: return decode_triples_typed<uint32_t, Swap>(l, n, divisor, out);
        case ScalarType::Int64: return decode_triples_typed<int64_t, Swap>(l, n, divisor, out);
        case ScalarType::UInt64: return decode_triples_typed<uint64_t, Swap>(l, n, divisor, out);
        case ScalarType::Float32: return decode_triples_typed<float, Swap>(l, n, divisor, out);
        case ScalarType::Float64: return decode_triples_typed<double, Swap>(l, n, divisor, out);
    }
}

/// @brief Decode n vectors described by `l` into `out` (already sized), dividing by `divisor`.
/// The caller has checked that every byte addressed lies inside the input.
inline void decode_triples(const TripleLayout& l, size_t n, double divisor, bool swap, Eigen::Vector3d* out) {
    if (swap)
        decode_triples_swap<true>(l, n, divisor, out);
    else
        decode_triples_swap<false>(l, n, divisor, out);
}

}  // namespace o3d::io::detail
