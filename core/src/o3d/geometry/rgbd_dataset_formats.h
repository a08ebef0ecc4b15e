// SPDX-License-Identifier: MIT
#pragma once
/// @file rgbd_dataset_formats.h
/// @brief The RGB-D dataset readers of Open3D (RGBDImage.create_from_{redwood,tum,sun,nyu}_format).
/// Unlike Open3D's SUN and NYU readers, the caller's depth image is never modified.
#include "o3d/geometry/rgbd_image.h"

namespace o3d::geometry {

/// Values match the O3D_RGBD_FORMAT_* constants of the C API.
enum class RGBDDatasetFormat {
    Redwood = 0,  ///< uint16 depth in mm, truncated at 4 m
    TUM = 1,      ///< uint16 depth in 1/5000 m, truncated at 4 m
    SUN = 2,      ///< uint16 depth in mm with its bits rotated left by 3, truncated at 7 m
    NYU = 3,      ///< uint16 byte-swapped Kinect disparity, truncated at 7 m
};

/// @brief An RGB-D image from a dataset's color image and raw uint16 depth image (same size).
/// Bad formats, sizes or an unknown `format` throw o3d::InvalidArgument.
RGBDImage create_rgbd_from_dataset_format(RGBDDatasetFormat format, const Image& color, const Image& depth,
                                          bool convert_rgb_to_intensity);

}  // namespace o3d::geometry
