// SPDX-License-Identifier: MIT
/// @file poisson_octree.cpp
/// @brief Sparse per-depth vertex sets of the Poisson octree.
#include "o3d/geometry/poisson_octree.h"

#include <algorithm>
#include <iterator>

#include "o3d/geometry/radix_sort.h"
#include "o3d/utility/error.h"

namespace o3d::geometry::poisson {

void KeyIndex::build(const std::vector<Key>& keys) {
    if (keys.size() >= size_t(INT32_MAX / 2)) throw InvalidArgument("poisson: octree too large");
    size_t cap = 16;
    while (cap < 2 * keys.size()) cap <<= 1;
    slots_.assign(cap, -1);
    mask_ = cap - 1;
    for (size_t i = 0; i < keys.size(); ++i) {
        uint64_t h = mix(keys[i]) & mask_;
        while (slots_[h] >= 0) h = (h + 1) & mask_;
        slots_[h] = int32_t(i);
    }
}

void sort_unique(std::vector<Key>& keys, int bits) {
    // Radix sort beats comparison sorting on the millions of keys of deep octrees.
    if (keys.size() > 4096) {
        std::vector<std::pair<uint64_t, size_t>> items(keys.size());
        for (size_t i = 0; i < keys.size(); ++i) items[i] = {keys[i], 0};
        radix_sort_by_key(items, bits);
        for (size_t i = 0; i < keys.size(); ++i) keys[i] = items[i].first;
    } else {
        std::sort(keys.begin(), keys.end());
    }
    keys.erase(std::unique(keys.begin(), keys.end()), keys.end());
}

namespace {

// One axis of a separable grow: coordinate c on `axis` becomes [lo(c), hi(c)] clamped to [0, res].
template <class Range>
std::vector<Key> grow_axis(const std::vector<Key>& keys, int axis, int res, Range range) {
    std::vector<Key> out;
    out.reserve(keys.size() * 2);
    const int shift = (2 - axis) * kKeyBits;
    for (Key k : keys) {
        const int c = int((k >> shift) & kKeyMask);
        int lo, hi;
        range(c, lo, hi);
        lo = std::max(lo, 0);
        hi = std::min(hi, res);
        const Key base = k & ~(kKeyMask << shift);
        for (int v = lo; v <= hi; ++v) out.push_back(base | (Key(v) << shift));
    }
    sort_unique(out);
    return out;
}

}  // namespace

std::vector<Key> dilate(const std::vector<Key>& keys, int r, int res) {
    std::vector<Key> out = keys;
    if (r <= 0) {
        sort_unique(out);
        return out;
    }
    for (int axis = 0; axis < 3; ++axis)
        out = grow_axis(out, axis, res, [r](int c, int& lo, int& hi) { lo = c - r, hi = c + r; });
    return out;
}

std::vector<Key> coarsen(const std::vector<Key>& keys, int r, int coarse_res) {
    std::vector<Key> out = keys;
    // A fine hat at even 2i refines from coarse i; at odd 2i+1 from i and i+1.
    for (int axis = 0; axis < 3; ++axis)
        out = grow_axis(out, axis, coarse_res,
                        [r](int c, int& lo, int& hi) { lo = (c >> 1) - r, hi = ((c + 1) >> 1) + r; });
    return out;
}

std::vector<Level> build_levels(std::vector<Key> finest_seed, int depth, int full_depth, int fine_dilation,
                                int coarse_dilation) {
    std::vector<Level> levels(size_t(depth) + 1);
    std::vector<Key> active = dilate(finest_seed, fine_dilation, 1 << depth);
    finest_seed.clear();
    finest_seed.shrink_to_fit();
    for (int d = depth; d >= 0; --d) {
        Level& L = levels[size_t(d)];
        L.depth = d;
        L.res = 1 << d;
        if (d < depth) {
            const Level& F = levels[size_t(d) + 1];
            active = coarsen(std::vector<Key>(F.keys.begin(), F.keys.begin() + std::ptrdiff_t(F.n_active)),
                             coarse_dilation, L.res);
        }
        if (d <= full_depth) {
            active.clear();
            for (int x = 0; x <= L.res; ++x)
                for (int y = 0; y <= L.res; ++y)
                    for (int z = 0; z <= L.res; ++z) active.push_back(pack(x, y, z));
        }
        // The one-ring: the accumulated solution is exact there because no finer-depth unknown reaches it.
        std::vector<Key> ring = dilate(active, 1, L.res);
        std::vector<Key> extra;
        extra.reserve(ring.size() - active.size());
        std::set_difference(ring.begin(), ring.end(), active.begin(), active.end(), std::back_inserter(extra));
        L.n_active = active.size();
        L.keys = std::move(active);
        L.keys.insert(L.keys.end(), extra.begin(), extra.end());
        L.index.build(L.keys);
        active.clear();
    }
    return levels;
}

}  // namespace o3d::geometry::poisson
