// SPDX-License-Identifier: MIT
#pragma once
/// @file rgbd_image.h
/// @brief A color (or float intensity) image and a 1-channel float32 depth image in metres, same size.
#include "o3d/geometry/image.h"

namespace o3d::geometry {

struct RGBDImage {
    Image color;
    Image depth;
};

}  // namespace o3d::geometry
