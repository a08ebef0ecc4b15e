// SPDX-License-Identifier: MIT
#include "o3d/color_map/vertex_colors.h"

#include <algorithm>

#include "o3d/kdtree/kd_tree.h"

namespace o3d::color_map::detail {

void update_proxy_intensity(std::vector<double>& proxy, const Scene& scene, const std::vector<View>& views,
                            int threads) {
    const std::vector<Eigen::Vector3d>& vertices = *scene.vertices;
    const VertexViews& vv = scene.vertex_views;
    const int n = int(vertices.size());
#pragma omp parallel for schedule(static) num_threads(threads) if (threads > 1)
    for (int v = 0; v < n; ++v) {
        double sum = 0.0;
        int count = 0;
        Projection pr;
        for (size_t k = vv.offsets[size_t(v)]; k < vv.offsets[size_t(v) + 1]; ++k) {
            const int c = vv.views[k];
            const FloatGrid& intensity = scene.images[size_t(c)].intensity;
            if (!project(views[size_t(c)], vertices[size_t(v)], pr) ||
                !intensity.can_sample(pr.pixel.x(), pr.pixel.y()))
                continue;
            sum += intensity.sample(pr.pixel.x(), pr.pixel.y());
            ++count;
        }
        if (count > 0) proxy[size_t(v)] = sum / count;
    }
}

std::vector<Eigen::Vector3d> vertex_colors(const Scene& scene, const std::vector<View>& views, int knn, int threads) {
    const std::vector<Eigen::Vector3d>& vertices = *scene.vertices;
    const VertexViews& vv = scene.vertex_views;
    const int n = int(vertices.size());
    std::vector<Eigen::Vector3d> colors(vertices.size(), Eigen::Vector3d::Zero());
    std::vector<char> sampled(vertices.size(), 0);
#pragma omp parallel for schedule(static) num_threads(threads) if (threads > 1)
    for (int v = 0; v < n; ++v) {
        Eigen::Vector3d sum = Eigen::Vector3d::Zero();
        int count = 0;
        Projection pr;
        for (size_t k = vv.offsets[size_t(v)]; k < vv.offsets[size_t(v) + 1]; ++k) {
            const int c = vv.views[k];
            const FloatGrid& color = scene.images[size_t(c)].color;
            if (!project(views[size_t(c)], vertices[size_t(v)], pr) || !color.can_sample(pr.pixel.x(), pr.pixel.y()))
                continue;
            for (int ch = 0; ch < 3; ++ch) sum[ch] += color.sample(pr.pixel.x(), pr.pixel.y(), ch);
            ++count;
        }
        if (count > 0) {
            colors[size_t(v)] = sum / count;
            sampled[size_t(v)] = 1;
        }
    }

    // Vertices no image samples borrow from their nearest sampled neighbours (Open3D's invisible_vertex_color_knn).
    std::vector<int> seen;
    for (int v = 0; v < n; ++v)
        if (sampled[size_t(v)]) seen.push_back(v);
    if (seen.empty() || int(seen.size()) == n) return colors;
    std::vector<Eigen::Vector3d> seen_points;
    seen_points.reserve(seen.size());
    for (int v : seen) seen_points.push_back(vertices[size_t(v)]);
    const kdtree::KDTree tree(std::move(seen_points));
    const int k = std::min(knn, int(seen.size()));
#pragma omp parallel num_threads(threads) if (threads > 1)
    {
        std::vector<int> idx;
        std::vector<double> d2;
#pragma omp for schedule(static)
        for (int v = 0; v < n; ++v) {
            if (sampled[size_t(v)]) continue;
            const int found = tree.search_knn(vertices[size_t(v)], k, idx, d2);
            Eigen::Vector3d sum = Eigen::Vector3d::Zero();
            for (int j = 0; j < found; ++j) sum += colors[size_t(seen[size_t(idx[size_t(j)])])];
            if (found > 0) colors[size_t(v)] = sum / found;
        }
    }
    return colors;
}

}  // namespace o3d::color_map::detail
