// SPDX-License-Identifier: MIT
#pragma once
/// @file random.h
/// @brief The library's random numbers: one global generator that hands each unseeded call a seed
/// (o3d.utility.random.seed), and SplitMix64 streams that make parallel randomized algorithms
/// reproducible: draw number i of a call depends only on (seed, i), never on the thread that made it.
#include <cstdint>

namespace o3d::utility::random {

/// @brief Reseed the global generator. Calls made afterwards without their own seed repeat.
/// Thread-safe. @see o3d.utility.random.seed
void seed(uint64_t value);

/// @brief A fresh 64-bit seed for one call that was not given a seed, drawn from the global generator
/// (seeded from std::random_device until seed() is called). Thread-safe.
uint64_t draw_call_seed();

/// @brief SplitMix64 (Steele, Lea, Flood 2014): a tiny, fast, statistically strong generator whose
/// state is a single counter, so a stream can be started anywhere in O(1).
struct SplitMix64 {
    uint64_t state;

    uint64_t next() {
        uint64_t z = (state += 0x9E3779B97F4A7C15ull);
        z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
        z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
        return z ^ (z >> 31);
    }
    /// @brief Uniform in [0, n) by Lemire's multiply-shift (bias below n / 2^64; n > 0).
    uint64_t below(uint64_t n) { return static_cast<uint64_t>((static_cast<unsigned __int128>(next()) * n) >> 64); }
    /// @brief Uniform double in [0, 1) with 53 random bits.
    double uniform() { return static_cast<double>(next() >> 11) * 0x1.0p-53; }
};

/// @brief The stream of draw number `index` of a call seeded with `seed`: a function of the pair only,
/// and streams of different indices are decorrelated by a full SplitMix64 mix of both.
inline SplitMix64 stream(uint64_t seed, uint64_t index) {
    SplitMix64 mixer{seed};
    const uint64_t base = mixer.next();
    SplitMix64 with_index{base ^ (index * 0xD1B54A32D192ED03ull)};
    return SplitMix64{with_index.next()};
}

}  // namespace o3d::utility::random
