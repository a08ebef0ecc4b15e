// SPDX-License-Identifier: MIT
#pragma once
/// @file vertex_colors.h
/// @brief The vertex side of the alternation: each vertex's intensity (the paper's proxy colour C(v)) is the
/// mean of what the images that see it show at their current poses, which is the C(v) minimising the
/// photometric error for fixed poses; and the final colouring of the mesh.
#include <Eigen/Core>
#include <vector>

#include "o3d/color_map/view.h"
#include "o3d/color_map/view_images.h"
#include "o3d/color_map/visibility.h"

namespace o3d::color_map::detail {

/// @brief Everything fixed during one optimization: the vertices, the prepared images and who sees what.
struct Scene {
    const std::vector<Eigen::Vector3d>* vertices = nullptr;
    std::vector<ViewImages> images;
    std::vector<std::vector<int>> visible;  ///< per image, the vertices it sees
    VertexViews vertex_views;               ///< per vertex, the images that see it
};

/// @brief Set `proxy[v]` to the mean intensity the images seeing v show at `views`; a vertex none of them
/// can sample any more (it moved off every image) keeps its value. Parallel over vertices; each mean is summed
/// in image order, so the result does not depend on the thread count.
void update_proxy_intensity(std::vector<double>& proxy, const Scene& scene, const std::vector<View>& views,
                            int threads);

/// @brief The mesh's colours: per vertex the mean RGB of the images that see it at `views`; a vertex no image
/// samples gets the mean colour of its `knn` nearest sampled vertices (all black when none is sampled).
std::vector<Eigen::Vector3d> vertex_colors(const Scene& scene, const std::vector<View>& views, int knn, int threads);

}  // namespace o3d::color_map::detail
