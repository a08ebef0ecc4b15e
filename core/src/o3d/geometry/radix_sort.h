// SPDX-License-Identifier: MIT
#pragma once
/// @file radix_sort.h
/// @brief Internal: stable LSD radix sort of (key, payload) pairs on the low `key_bits` of the key.
#include <cstddef>
#include <cstdint>
#include <utility>
#include <vector>

namespace o3d::geometry {

/// @brief Sort `items` by key ascending; equal keys keep their order (stable). Keys must be < 2^key_bits.
void radix_sort_by_key(std::vector<std::pair<uint64_t, size_t>>& items, int key_bits);

}  // namespace o3d::geometry
