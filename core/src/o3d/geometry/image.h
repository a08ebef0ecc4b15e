// SPDX-License-Identifier: MIT
#pragma once
/// @file image.h
/// @brief The image container: rows top to bottom, channels interleaved, native byte order.
#include <cstdint>
#include <cstring>
#include <vector>

namespace o3d::geometry {

/// @brief width x height pixels of num_channels (1, 3, 4) values of bytes_per_channel (1 = uint8,
/// 2 = uint16, 4 = float32) bytes each. `data` holds exactly byte_size() bytes.
struct Image {
    int width = 0;
    int height = 0;
    int num_channels = 0;
    int bytes_per_channel = 0;
    std::vector<uint8_t> data;

    bool empty() const { return width <= 0 || height <= 0 || data.empty(); }
    size_t byte_size() const {
        return size_t(width) * size_t(height) * size_t(num_channels) * size_t(bytes_per_channel);
    }
    size_t bytes_per_line() const { return size_t(width) * size_t(num_channels) * size_t(bytes_per_channel); }
    /// @brief Pointer to channel 0 of pixel (u, v), typed; the caller checks the format.
    template <typename T>
    T* pixel(int u, int v) {
        return reinterpret_cast<T*>(data.data() + (size_t(v) * size_t(width) + size_t(u)) * size_t(num_channels) *
                                                      size_t(bytes_per_channel));
    }
    template <typename T>
    const T* pixel(int u, int v) const {
        return reinterpret_cast<const T*>(data.data() + (size_t(v) * size_t(width) + size_t(u)) *
                                                            size_t(num_channels) * size_t(bytes_per_channel));
    }
};

}  // namespace o3d::geometry
