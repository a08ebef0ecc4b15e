// SPDX-License-Identifier: MIT
#pragma once
/// @file dataset.h
/// @brief The RGB-D sequence a reconstruction reads: Open3D's folder layout (colour in image/, rgb/ or color/,
/// depth in depth/, each sorted by file name) and how each frame becomes an RGB-D image.
#include <string>
#include <vector>

#include "o3d/camera/pinhole_camera.h"
#include "o3d/geometry/rgbd_image.h"
#include "o3d/reconstruction/config.h"

namespace o3d::reconstruction {

struct Dataset {
    std::vector<std::string> color_files;  ///< .jpg then .png files, each group sorted, as Open3D lists them
    std::vector<std::string> depth_files;  ///< .png files, sorted
    camera::PinholeCameraIntrinsic intrinsic;
    int frames_per_fragment = 1;

    int frame_count() const { return static_cast<int>(color_files.size()); }
    int fragment_count() const { return (frame_count() + frames_per_fragment - 1) / frames_per_fragment; }
    int first_frame(int fragment) const { return fragment * frames_per_fragment; }
    int end_frame(int fragment) const { return std::min(frame_count(), first_frame(fragment) + frames_per_fragment); }
};

/// @brief List the frames and read the intrinsic. @throws o3d::IoError when the dataset folder, its colour or
/// depth folder, or the intrinsic file is missing; o3d::InvalidArgument when there are no frames or the colour
/// and depth counts differ (naming both).
Dataset open_dataset(const Config& config);

/// @brief Frame `frame` as Open3D's read_rgbd_image: depth / depth_scale, truncated at depth_max; the colour as
/// a float intensity (odometry) or 8-bit RGB (integration). @throws what reading or pairing the images throws,
/// with the frame's number and file names in front of the message.
geometry::RGBDImage read_frame(const Config& config, const Dataset& dataset, int frame, bool convert_rgb_to_intensity);

}  // namespace o3d::reconstruction
