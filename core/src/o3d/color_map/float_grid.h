// SPDX-License-Identifier: MIT
#pragma once
/// @file float_grid.h
/// @brief A float image as a plain array with bilinear sampling: the optimization samples images at the
/// sub-pixel points vertices project to, and its gradients must vary smoothly with the pose.
#include <cmath>
#include <vector>

namespace o3d::color_map::detail {

/// @brief `width` x `height` pixels of `channels` floats each, row-major, channels interleaved.
struct FloatGrid {
    int width = 0, height = 0, channels = 1;
    std::vector<float> values;

    FloatGrid() = default;
    FloatGrid(int w, int h, int c) : width(w), height(h), channels(c), values(size_t(w) * size_t(h) * size_t(c)) {}

    float& at(int u, int v, int c = 0) { return values[(size_t(v) * size_t(width) + size_t(u)) * size_t(channels) + c]; }
    float at(int u, int v, int c = 0) const {
        return values[(size_t(v) * size_t(width) + size_t(u)) * size_t(channels) + size_t(c)];
    }

    /// @brief True when (u, v) has four pixels around it, i.e. bilinear sampling is defined there.
    bool can_sample(double u, double v) const { return u >= 0.0 && v >= 0.0 && u < width - 1 && v < height - 1; }

    /// @brief Bilinear value of channel `c` at (u, v); the caller checks can_sample first.
    double sample(double u, double v, int c = 0) const {
        const int u0 = int(u), v0 = int(v);
        const double a = u - u0, b = v - v0;
        return (1 - b) * ((1 - a) * at(u0, v0, c) + a * at(u0 + 1, v0, c)) +
               b * ((1 - a) * at(u0, v0 + 1, c) + a * at(u0 + 1, v0 + 1, c));
    }
};

}  // namespace o3d::color_map::detail
