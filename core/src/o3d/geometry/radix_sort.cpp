// SPDX-License-Identifier: MIT
#include "o3d/geometry/radix_sort.h"

#include <array>

namespace o3d::geometry {

void radix_sort_by_key(std::vector<std::pair<uint64_t, size_t>>& items, int key_bits) {
    constexpr int kDigitBits = 11;
    constexpr size_t kBuckets = size_t{1} << kDigitBits;
    std::vector<std::pair<uint64_t, size_t>> scratch(items.size());
    for (int shift = 0; shift < key_bits; shift += kDigitBits) {
        std::array<size_t, kBuckets> count{};
        for (const auto& it : items) ++count[(it.first >> shift) & (kBuckets - 1)];
        size_t sum = 0;
        for (size_t& c : count) {
            const size_t here = c;
            c = sum;
            sum += here;
        }
        for (const auto& it : items) scratch[count[(it.first >> shift) & (kBuckets - 1)]++] = it;
        items.swap(scratch);
    }
}

}  // namespace o3d::geometry
