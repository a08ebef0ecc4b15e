// SPDX-License-Identifier: MIT
#include "o3d/color_map/visibility.h"

#include <algorithm>
#include <cmath>

#include "o3d/geometry/image_ops.h"

namespace o3d::color_map::detail {

namespace {

/// Dilate a 0/1 mask by a square window: a row pass then a column pass (max over +-r).
std::vector<uint8_t> dilate(const std::vector<uint8_t>& mask, int width, int height, int r) {
    if (r == 0) return mask;
    std::vector<uint8_t> rows(mask.size(), 0), out(mask.size(), 0);
    for (int v = 0; v < height; ++v)
        for (int u = 0; u < width; ++u) {
            uint8_t m = 0;
            for (int x = std::max(0, u - r), x1 = std::min(width - 1, u + r); x <= x1 && !m; ++x)
                m = mask[size_t(v) * size_t(width) + size_t(x)];
            rows[size_t(v) * size_t(width) + size_t(u)] = m;
        }
    for (int v = 0; v < height; ++v)
        for (int u = 0; u < width; ++u) {
            uint8_t m = 0;
            for (int y = std::max(0, v - r), y1 = std::min(height - 1, v + r); y <= y1 && !m; ++y)
                m = rows[size_t(y) * size_t(width) + size_t(u)];
            out[size_t(v) * size_t(width) + size_t(u)] = m;
        }
    return out;
}

}  // namespace

std::vector<uint8_t> discontinuity_map(const geometry::Image& depth, double threshold, int half_kernel) {
    const geometry::Image dx = geometry::filter_image(depth, geometry::ImageFilterType::Sobel3Dx);
    const geometry::Image dy = geometry::filter_image(depth, geometry::ImageFilterType::Sobel3Dy);
    const float* gx = reinterpret_cast<const float*>(dx.data.data());
    const float* gy = reinterpret_cast<const float*>(dy.data.data());
    const size_t n = size_t(depth.width) * size_t(depth.height);
    std::vector<uint8_t> edge(n, 0);
    for (size_t i = 0; i < n; ++i) edge[i] = std::sqrt(double(gx[i]) * gx[i] + double(gy[i]) * gy[i]) > threshold;
    return dilate(edge, depth.width, depth.height, half_kernel);
}

std::vector<int> visible_vertices(const std::vector<Eigen::Vector3d>& vertices, const View& view,
                                  const ViewImages& images, const OptimizerOption& option) {
    const int w = images.depth.width, h = images.depth.height;
    const double margin = option.image_boundary_margin;
    std::vector<int> out;
    Projection pr;
    for (size_t i = 0; i < vertices.size(); ++i) {
        if (!project(view, vertices[i], pr)) continue;
        const double u = pr.pixel.x(), v = pr.pixel.y();
        if (!(u >= margin && v >= margin && u <= w - 1 - margin && v <= h - 1 - margin)) continue;
        const int iu = int(std::lround(u)), iv = int(std::lround(v));
        if (images.discontinuity[size_t(iv) * size_t(w) + size_t(iu)]) continue;
        const double d = images.depth.at(iu, iv);
        if (d <= 0.0 || d > option.maximum_allowable_depth) continue;
        if (std::abs(d - pr.point.z()) > option.depth_threshold_for_visibility_check) continue;
        out.push_back(int(i));
    }
    return out;
}

VertexViews invert_visibility(const std::vector<std::vector<int>>& visible, size_t num_vertices) {
    VertexViews out;
    out.offsets.assign(num_vertices + 1, 0);
    for (const auto& list : visible)
        for (int v : list) ++out.offsets[size_t(v) + 1];
    for (size_t v = 0; v < num_vertices; ++v) out.offsets[v + 1] += out.offsets[v];
    out.views.resize(out.offsets.back());
    std::vector<size_t> next(out.offsets.begin(), out.offsets.end() - 1);
    for (size_t c = 0; c < visible.size(); ++c)
        for (int v : visible[c]) out.views[next[size_t(v)]++] = int(c);
    return out;
}

}  // namespace o3d::color_map::detail
