// SPDX-License-Identifier: MIT
#pragma once
/// @file view_images.h
/// @brief What the optimization reads from one RGB-D image, prepared once: the intensity it aligns and its
/// gradients, the colour the mesh is finally painted with, depth and where depth cannot be trusted.
#include <cstdint>
#include <vector>

#include "o3d/color_map/color_map.h"
#include "o3d/color_map/float_grid.h"

namespace o3d::color_map::detail {

struct ViewImages {
    FloatGrid intensity;  ///< gray in [0, 1], Gaussian-smoothed: a wider basin and steadier gradients
    FloatGrid dx, dy;     ///< d intensity / d pixel (Sobel / 8, so Gauss-Newton steps are in true pixel units)
    FloatGrid color;      ///< 3 channels in [0, 1], unsmoothed: the final vertex colours
    FloatGrid depth;      ///< metres; 0 where there is none
    std::vector<uint8_t> discontinuity;  ///< 1 where a vertex is not to be seen (near a depth edge or a hole)
};

/// @brief Throw o3d::InvalidArgument unless the inputs are ones the optimizers accept (see color_map.h).
void check_inputs(const geometry::TriangleMesh& mesh, const std::vector<const geometry::RGBDImage*>& images,
                  const camera::PinholeCameraTrajectory& trajectory, const OptimizerOption& option);

/// @brief Prepare one (already checked) RGB-D image.
ViewImages prepare_view_images(const geometry::RGBDImage& image, const OptimizerOption& option);

}  // namespace o3d::color_map::detail
