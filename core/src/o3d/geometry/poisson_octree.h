// SPDX-License-Identifier: MIT
#pragma once
/// @file poisson_octree.h
/// @brief Internal to Poisson reconstruction: the adaptive octree as sparse per-depth sets of B-spline
/// centres. At depth d the grid has spacing 2^-d on the unit cube; a node's function is the trilinear hat
/// centred on a grid vertex. Only the vertices near the samples exist at the fine depths, so memory grows
/// with the sampled surface, not with (2^depth)^3.
#include <cstddef>
#include <cstdint>
#include <type_traits>
#include <vector>

namespace o3d::geometry::poisson {

/// Grid vertex key: 20 bits per coordinate (depth <= 16 needs 17), x-major so sorted keys are raster order.
using Key = uint64_t;
constexpr int kKeyBits = 20;
constexpr uint64_t kKeyMask = (uint64_t(1) << kKeyBits) - 1;
inline Key pack(int64_t x, int64_t y, int64_t z) {
    return (Key(x) << (2 * kKeyBits)) | (Key(y) << kKeyBits) | Key(z);
}
inline int key_x(Key k) { return int(k >> (2 * kKeyBits)); }
inline int key_y(Key k) { return int((k >> kKeyBits) & kKeyMask); }
inline int key_z(Key k) { return int(k & kKeyMask); }

/// @brief Open-addressing hash from keys to their positions in an external key array (built once, then
/// read concurrently).
class KeyIndex {
public:
    void build(const std::vector<Key>& keys);
    /// Position of `k` in the array given to build, or -1.
    int64_t find(const Key* keys, Key k) const {
        if (slots_.empty()) return -1;
        uint64_t h = mix(k) & mask_;
        while (true) {
            const int64_t s = slots_[h];
            if (s < 0) return -1;
            if (keys[s] == k) return s;
            h = (h + 1) & mask_;
        }
    }
    static uint64_t mix(uint64_t x) {
        x ^= x >> 31;
        x *= 0x7fb5d329728ea185ULL;
        x ^= x >> 27;
        x *= 0x81dadef4bc2dd44dULL;
        x ^= x >> 33;
        return x;
    }

private:
    std::vector<int32_t> slots_;
    uint64_t mask_ = 0;
};

/// @brief The B-spline centres of one depth: `keys[0, n_active)` carry unknowns (sorted); the rest (sorted)
/// is their one-ring, where the accumulated solution is still known exactly.
struct Level {
    int depth = 0;
    int res = 1;  ///< cells per axis (2^depth); vertex coordinates run over [0, res]
    std::vector<Key> keys;
    size_t n_active = 0;
    KeyIndex index;
    std::vector<double> y;  ///< accumulated solution (all depths <= this one) as hat coefficients on keys

    int64_t find(Key k) const { return index.find(keys.data(), k); }
};

/// @brief The two-scale relation of the trilinear hat at one vertex of the next finer depth: an even fine vertex is a
/// coarse vertex, an odd one the mean of the two coarse vertices around it (per axis); coarse vertices not in
/// `coarse` count as 0. `values` holds one value (a number or a vector) per key of `coarse`.
template <typename T>
T prolonged_value(const Level& coarse, const std::vector<T>& values, Key fine_key) {
    const int c[3] = {key_x(fine_key), key_y(fine_key), key_z(fine_key)};
    int lo[3], hi[3];
    for (int a = 0; a < 3; ++a) lo[a] = c[a] >> 1, hi[a] = (c[a] + 1) >> 1;
    const double w = (lo[0] == hi[0] ? 1.0 : 0.5) * (lo[1] == hi[1] ? 1.0 : 0.5) * (lo[2] == hi[2] ? 1.0 : 0.5);
    T acc;
    if constexpr (std::is_arithmetic_v<T>) {
        acc = 0;
    } else {
        acc.setZero();  // an Eigen vector
    }
    for (int z = lo[2]; z <= hi[2]; ++z)
        for (int y = lo[1]; y <= hi[1]; ++y)
            for (int x = lo[0]; x <= hi[0]; ++x) {
                const int64_t idx = coarse.find(pack(x, y, z));
                if (idx >= 0) acc += w * values[size_t(idx)];
            }
    return acc;
}

/// @brief Sorted, duplicate-free keys (all below 2^bits).
void sort_unique(std::vector<Key>& keys, int bits = 3 * kKeyBits);
/// @brief Every vertex within Chebyshev distance r (clamped to [0,res]^3) of a vertex in `keys` (sorted unique).
std::vector<Key> dilate(const std::vector<Key>& keys, int r, int res);
/// @brief Coarse vertices (depth d-1) whose hats overlap the fine hats in `keys`, grown by r (clamped).
std::vector<Key> coarsen(const std::vector<Key>& keys, int r, int coarse_res);

/// @brief Builds levels[0..depth]: the active set of depth d is `seeds[d]` (grid vertices) grown by
/// `fine_dilation`, together with the parents of the finer active set grown by `coarse_dilation`; depths
/// <= full_depth are complete grids. Guarantees parents(active at d) ⊆ active at d-1, which makes the
/// prolongation of the accumulated solution onto every level's one-ring exact.
std::vector<Level> build_levels(std::vector<std::vector<Key>> seeds, int depth, int full_depth, int fine_dilation,
                                int coarse_dilation);

}  // namespace o3d::geometry::poisson
