// SPDX-License-Identifier: MIT
// C API: indexlists.h (lists of indices of varying length, stored as compressed rows).
#include <memory>
#include <string>
#include <vector>

#include "internal.h"
#include "o3d/indexlists.h"

using o3d::capi::copy_out;
using o3d::capi::guard;
using o3d::capi::require;

namespace o3d::capi {

o3d_index_lists_t* make_index_lists(const std::vector<std::vector<int>>& lists) {
    auto handle = std::make_unique<o3d_index_lists>();
    handle->offsets.reserve(lists.size() + 1);
    size_t total = 0;
    for (const auto& list : lists) total += list.size();
    handle->values.reserve(total);
    for (const auto& list : lists) {
        handle->values.insert(handle->values.end(), list.begin(), list.end());
        handle->offsets.push_back(static_cast<int64_t>(handle->values.size()));
    }
    return handle.release();
}

o3d_index_lists_t* make_index_lists(const std::vector<int>& offsets, const std::vector<int>& values) {
    if (offsets.empty() && values.empty()) return new o3d_index_lists();
    if (offsets.empty() || offsets.front() != 0 || size_t(offsets.back()) != values.size())
        throw std::logic_error("make_index_lists: offsets do not cover the values");
    auto handle = std::make_unique<o3d_index_lists>();
    handle->offsets.assign(offsets.begin(), offsets.end());
    handle->values.assign(values.begin(), values.end());
    return handle.release();
}

}  // namespace o3d::capi

O3D_API void o3d_index_lists_destroy(o3d_index_lists_t* lists) { delete lists; }

O3D_API o3d_status o3d_index_lists_num_lists(size_t* out, const o3d_index_lists_t* lists) {
    return guard(__func__, [&] {
        require(out, "out");
        *out = require(lists, "lists")->offsets.size() - 1;
    });
}

O3D_API o3d_status o3d_index_lists_num_values(size_t* out, const o3d_index_lists_t* lists) {
    return guard(__func__, [&] {
        require(out, "out");
        *out = require(lists, "lists")->values.size();
    });
}

O3D_API o3d_status o3d_index_lists_get_offsets(int64_t* out, size_t capacity, size_t* out_n,
                                               const o3d_index_lists_t* lists) {
    return guard(__func__, [&] {
        require(lists, "lists");
        require(out_n, "out_n");
        copy_out(lists->offsets.data(), lists->offsets.size(), out, capacity, out_n);
    });
}

O3D_API o3d_status o3d_index_lists_get_values(int32_t* out, size_t capacity, size_t* out_n,
                                              const o3d_index_lists_t* lists) {
    return guard(__func__, [&] {
        require(lists, "lists");
        require(out_n, "out_n");
        copy_out(lists->values.data(), lists->values.size(), out, capacity, out_n);
    });
}
