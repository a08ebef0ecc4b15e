// SPDX-License-Identifier: MIT
#pragma once
/// @file visibility.h
/// @brief Which vertices each image sees. Decided once, at the initial poses, as in the paper: the
/// optimization then only moves where a seen vertex lands, it never changes what was seen.
#include <Eigen/Core>
#include <cstdint>
#include <vector>

#include "o3d/color_map/view.h"
#include "o3d/color_map/view_images.h"
#include "o3d/geometry/image.h"

namespace o3d::color_map::detail {

/// @brief 1 for every pixel within `half_kernel` pixels (square window) of one whose depth Sobel magnitude
/// (unscaled 3x3, as Open3D's filter) exceeds `threshold`: colour there may belong to either side of the edge.
/// `depth` is 1-channel float with 0 for missing depth.
std::vector<uint8_t> discontinuity_map(const geometry::Image& depth, double threshold, int half_kernel);

/// @brief The vertices `view` sees, ascending: in front of the camera, projected inside the image at least
/// image_boundary_margin pixels from its border, onto a pixel that is not near a discontinuity, whose depth is
/// valid, at most maximum_allowable_depth and within depth_threshold_for_visibility_check of the vertex's.
std::vector<int> visible_vertices(const std::vector<Eigen::Vector3d>& vertices, const View& view,
                                  const ViewImages& images, const OptimizerOption& option);

/// @brief The inverse of per-image visibility: for each vertex, the images that see it, ascending, as a
/// flat list (vertex v's are [offsets[v], offsets[v + 1])).
struct VertexViews {
    std::vector<size_t> offsets;
    std::vector<int> views;
};
VertexViews invert_visibility(const std::vector<std::vector<int>>& visible, size_t num_vertices);

}  // namespace o3d::color_map::detail
