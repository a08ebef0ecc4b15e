// SPDX-License-Identifier: MIT
#pragma once
/// @file simd4.h
/// @brief Four-lane float and int vectors (GCC/Clang vector extensions: SSE on x86-64, NEON on arm64), with the few
/// helpers integration's voxel runs need. Comparisons give Int4 masks of all ones or zeros per lane.
#include <cmath>
#include <cstdint>
#include <cstring>
#if defined(__SSE2__)
#include <emmintrin.h>
#endif

namespace o3d::integration::detail {

using Float4 = float __attribute__((vector_size(16)));
using Int4 = int32_t __attribute__((vector_size(16)));

inline Float4 splat(float value) { return Float4{value, value, value, value}; }

inline Float4 select(Int4 mask, Float4 if_set, Float4 otherwise) {
    return Float4(((Int4)if_set & mask) | ((Int4)otherwise & ~mask));
}

inline Float4 min4(Float4 a, Float4 b) { return select(a < b, a, b); }
inline Float4 max4(Float4 a, Float4 b) { return select(a > b, a, b); }

/// @brief The smallest and the largest lane.
inline float lowest(Float4 a) {
    a = min4(a, __builtin_shufflevector(a, a, 2, 3, 0, 1));
    return std::fmin(a[0], a[1]);
}
inline float highest(Float4 a) {
    a = max4(a, __builtin_shufflevector(a, a, 2, 3, 0, 1));
    return std::fmax(a[0], a[1]);
}

// Element-wise loops over lanes cost an extract per lane; SSE has single instructions for these two.
inline bool any(Int4 mask) {
#if defined(__SSE2__)
    return _mm_movemask_ps(__m128(mask)) != 0;
#else
    return (mask[0] | mask[1] | mask[2] | mask[3]) != 0;
#endif
}

inline Float4 sqrt4(Float4 a) {
#if defined(__SSE2__)
    return Float4(_mm_sqrt_ps(__m128(a)));
#else
    return Float4{std::sqrt(a[0]), std::sqrt(a[1]), std::sqrt(a[2]), std::sqrt(a[3])};
#endif
}

inline Float4 load4(const float* p) {
    Float4 out;
    std::memcpy(&out, p, sizeof out);
    return out;
}

inline void store4(float* p, Float4 value) { std::memcpy(p, &value, sizeof value); }

/// @brief Lane k of `per_voxel` repeated for the three colour channels of voxel k: the three vectors that line up
/// with four consecutive RGB triples (r0 g0 b0 r1 | g1 b1 r2 g2 | b2 r3 g3 b3).
struct PerChannel {
    Float4 v[3];
};
inline PerChannel per_channel(Float4 per_voxel) {
    return {{__builtin_shufflevector(per_voxel, per_voxel, 0, 0, 0, 1),
             __builtin_shufflevector(per_voxel, per_voxel, 1, 1, 2, 2),
             __builtin_shufflevector(per_voxel, per_voxel, 2, 3, 3, 3)}};
}

}  // namespace o3d::integration::detail
