// SPDX-License-Identifier: MIT
#include "o3d/odometry/odometry_level.h"

#include <algorithm>
#include <cmath>

#include "o3d/geometry/image_ops.h"
#include "o3d/utility/parallel.h"

namespace o3d::odometry::detail {

namespace {

/// @brief Open3D's Sobel (geometry::filter_image) of `image`, read in place by the packing loop below.
struct Sobel {
    geometry::Image dx, dy;
    explicit Sobel(const FloatImage& image) {
        const geometry::Image in = to_image(image);
        dx = geometry::filter_image(in, geometry::ImageFilterType::Sobel3Dx);
        dy = geometry::filter_image(in, geometry::ImageFilterType::Sobel3Dy);
    }
    float x(size_t i) const { return reinterpret_cast<const float*>(dx.data.data())[i]; }
    float y(size_t i) const { return reinterpret_cast<const float*>(dy.data.data())[i]; }
};

}  // namespace

PackedLevel pack_level(const LevelCamera& camera, const FrameLevel& source, const FrameLevel& target) {
    PackedLevel out;
    out.camera = camera;
    const int w = camera.width, h = camera.height;
    out.source.resize(size_t(w) * size_t(h));
    out.target.resize(size_t(w) * size_t(h));
    const Sobel intensity(target.intensity), depth(target.depth);
    auto zero_nan = [](float x) { return std::isnan(x) ? 0.0f : x; };
    // Every pixel on its own: rows split among threads give the same records.
    const int threads = std::max(1, std::min(utility::resolve_num_threads(), h / 16));
#pragma omp parallel for schedule(static) num_threads(threads) if (threads > 1)
    for (int v = 0; v < h; ++v) {
        for (int u = 0; u < w; ++u) {
            const float z = source.depth.at(u, v);
            out.source[size_t(v) * size_t(w) + size_t(u)] = {float((u - camera.cx) * z / camera.fx),
                                                             float((v - camera.cy) * z / camera.fy), z,
                                                             source.intensity.at(u, v)};
            const size_t i = size_t(v) * size_t(w) + size_t(u);
            out.target[i] = {target.intensity.values[i], target.depth.values[i], intensity.x(i),
                             intensity.y(i),             zero_nan(depth.x(i)),   zero_nan(depth.y(i))};
        }
    }
    return out;
}

}  // namespace o3d::odometry::detail
