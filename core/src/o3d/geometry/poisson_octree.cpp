// SPDX-License-Identifier: MIT
/// @file poisson_octree.cpp
/// @brief Sparse per-depth vertex sets of the Poisson octree.
#include "o3d/geometry/poisson_octree.h"

#include <algorithm>
#include <iterator>

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
    // LSD radix sort of the bare keys (beats comparison sorting on the millions of keys of deep octrees);
    // a digit that is the same for every key costs one counting pass and no scatter.
    if (keys.size() > 4096) {
        constexpr int kDigitBits = 11;
        constexpr size_t kBuckets = size_t{1} << kDigitBits;
        std::vector<Key> scratch(keys.size());
        for (int shift = 0; shift < bits; shift += kDigitBits) {
            std::vector<size_t> count(kBuckets, 0);
            for (Key k : keys) ++count[(k >> shift) & (kBuckets - 1)];
            if (count[(keys[0] >> shift) & (kBuckets - 1)] == keys.size()) continue;
            size_t sum = 0;
            for (size_t& c : count) {
                const size_t here = c;
                c = sum;
                sum += here;
            }
            for (Key k : keys) scratch[count[(k >> shift) & (kBuckets - 1)]++] = k;
            keys.swap(scratch);
        }
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
    sort_unique(out);
    // Per axis: the union of the set shifted by -r..r along it. A shift adds one constant to every key that
    // stays inside the grid, so each shifted copy is still sorted and the union is a merge, not a sort.
    std::vector<Key> shifted, merged;
    for (int axis = 0; axis < 3 && r > 0; ++axis) {
        const int shift = (2 - axis) * kKeyBits;
        std::vector<Key> acc = out;
        for (int dlt = -r; dlt <= r; ++dlt) {
            if (dlt == 0) continue;
            shifted.clear();
            for (Key k : out) {
                const int c = int((k >> shift) & kKeyMask) + dlt;
                if (c >= 0 && c <= res) shifted.push_back(dlt > 0 ? k + (Key(dlt) << shift) : k - (Key(-dlt) << shift));
            }
            merged.resize(acc.size() + shifted.size());
            merged.erase(std::set_union(acc.begin(), acc.end(), shifted.begin(), shifted.end(), merged.begin()),
                         merged.end());
            acc.swap(merged);
        }
        out.swap(acc);
    }
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

std::vector<Level> build_levels(std::vector<std::vector<Key>> seeds, int depth, int full_depth, int fine_dilation,
                                int coarse_dilation) {
    std::vector<Level> levels(size_t(depth) + 1);
    std::vector<Key> active;
    for (int d = depth; d >= 0; --d) {
        Level& L = levels[size_t(d)];
        L.depth = d;
        L.res = 1 << d;
        if (d < depth) {
            const Level& F = levels[size_t(d) + 1];
            active = coarsen(std::vector<Key>(F.keys.begin(), F.keys.begin() + std::ptrdiff_t(F.n_active)),
                             coarse_dilation, L.res);
        }
        if (!seeds[size_t(d)].empty() && d > full_depth) {
            std::vector<Key> own = dilate(seeds[size_t(d)], fine_dilation, L.res);
            std::vector<Key> merged;
            merged.reserve(active.size() + own.size());
            std::set_union(active.begin(), active.end(), own.begin(), own.end(), std::back_inserter(merged));
            active.swap(merged);
        }
        std::vector<Key>().swap(seeds[size_t(d)]);
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
