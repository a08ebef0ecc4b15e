// SPDX-License-Identifier: MIT
#include "o3d/camera/intrinsic_presets.h"

#include <string>

#include "o3d/utility/error.h"

namespace o3d::camera {

PinholeCameraIntrinsic intrinsic_preset(IntrinsicPreset preset) {
    switch (preset) {
        case IntrinsicPreset::PrimeSenseDefault: return {640, 480, 525.0, 525.0, 319.5, 239.5};
        case IntrinsicPreset::Kinect2DepthCameraDefault: return {512, 424, 365.456, 365.456, 254.878, 205.395};
        case IntrinsicPreset::Kinect2ColorCameraDefault: return {1920, 1080, 1059.9718, 1059.9718, 975.7193, 545.9533};
    }
    throw InvalidArgument("unknown intrinsic preset " + std::to_string(static_cast<int>(preset)));
}

}  // namespace o3d::camera
