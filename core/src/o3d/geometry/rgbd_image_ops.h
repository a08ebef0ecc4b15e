// SPDX-License-Identifier: MIT
#pragma once
/// @file rgbd_image_ops.h
/// @brief Building an RGB-D image from a color and a depth image (RGBDImage.create_from_color_and_depth).
#include "o3d/geometry/rgbd_image.h"

namespace o3d::geometry {

/// @brief Open3D's create_from_color_and_depth keyword arguments and defaults.
struct RGBDOptions {
    double depth_scale = 1000.0;          ///< depth units per metre (uint16 and float32 depth alike, as Open3D)
    double depth_trunc = 3.0;             ///< depths at or beyond this (metres) become 0
    bool convert_rgb_to_intensity = true; ///< color -> 1-channel float32 intensity (Open3D's weighted gray)
};

/// @brief Pair `color` (8-bit 1 or 3 channels, or a 1-channel float32 intensity) with `depth` (1-channel uint16
/// or float32) of the same size. Depth becomes float32 metres (depth / depth_scale, 0 from depth_trunc on);
/// the color becomes a float intensity or is copied unchanged. Inputs are never modified; anything else
/// throws o3d::InvalidArgument.
RGBDImage create_rgbd_from_color_and_depth(const Image& color, const Image& depth, const RGBDOptions& options = {});

/// @brief Throw o3d::InvalidArgument unless `color` is a format an RGB-D image may carry (see above).
void require_rgbd_color(const Image& color, const char* what);

}  // namespace o3d::geometry
