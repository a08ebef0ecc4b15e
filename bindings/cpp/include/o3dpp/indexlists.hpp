// SPDX-License-Identifier: MIT
#pragma once
/// @file indexlists.hpp
/// @brief IndexLists (Open3D's List[IntVector]): lists of indices of varying length, copied out of an
/// o3d_index_lists_t (a mesh's adjacency list, the points behind each down-sampled point, boundary loops).
#include <cstdint>
#include <vector>

#include "o3d/indexlists.h"
#include "o3dpp/error.hpp"
#include "o3dpp/handle.hpp"

namespace o3dpp {

/// @brief One list of indices per item (what each is, and its order, is said by the function that made it).
using IndexLists = std::vector<std::vector<int>>;

namespace detail {
/// @brief Own the C lists (destroyed on return, also when copying fails) and copy them out.
inline IndexLists take_index_lists(o3d_index_lists_t* raw) {
    UniqueHandle<o3d_index_lists_t, &o3d_index_lists_destroy> owned(raw);
    size_t num_lists = 0, total = 0;
    check(o3d_index_lists_num_lists(&num_lists, owned.get()));
    check(o3d_index_lists_num_values(&total, owned.get()));
    std::vector<int64_t> offsets(num_lists + 1);
    std::vector<int32_t> values(total);
    size_t n = 0;
    check(o3d_index_lists_get_offsets(offsets.data(), offsets.size(), &n, owned.get()));
    check(o3d_index_lists_get_values(values.data(), values.size(), &n, owned.get()));
    IndexLists out(num_lists);
    for (size_t i = 0; i < num_lists; ++i) out[i].assign(values.begin() + offsets[i], values.begin() + offsets[i + 1]);
    return out;
}
/// @brief Run `fn(o3d_index_lists_t** out)` and copy out the lists it made (freed also when it failed).
template <typename F>
IndexLists index_lists(F&& fn) {
    o3d_index_lists_t* raw = nullptr;
    const o3d_status status = fn(&raw);
    UniqueHandle<o3d_index_lists_t, &o3d_index_lists_destroy> owned(raw);
    check(status);
    return take_index_lists(owned.release());
}
}  // namespace detail

}  // namespace o3dpp
