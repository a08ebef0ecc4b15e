// SPDX-License-Identifier: MIT
#pragma once
/// @file odometry.hpp
/// @brief o3d.pipelines.odometry: compute_rgbd_odometry and its OdometryOption.
#include <array>
#include <cstdint>
#include <vector>

#include "o3d/odometry.h"
#include "o3dpp/camera.hpp"
#include "o3dpp/error.hpp"
#include "o3dpp/generated/enums.hpp"
#include "o3dpp/generated/options.hpp"
#include "o3dpp/rgbd.hpp"
#include "o3dpp/span.hpp"

namespace o3dpp {

/// @brief Open3D's OdometryOption: the C struct's scalars (generated) plus the iterations per pyramid level,
/// which the C API takes as a separate array (coarsest level first; its length is the number of levels).
struct OdometryOption : OdometryOptions {
    std::vector<int> iteration_number_per_pyramid_level{20, 10, 5};
};

/// @brief What compute_rgbd_odometry returns: Open3D's (success, transformation, information) tuple.
struct OdometryResult {
    bool success = false;
    Mat4 transformation = identity4();       ///< row-major 4x4, source camera -> target camera
    std::array<double, 36> information{};    ///< row-major 6x6
};

/// @brief The motion taking `source` onto `target`, coarse to fine from `odo_init`. The frames must be float
/// intensity + float depth of the intrinsic's size (RgbdImage::create_from_color_and_depth's default). A pair
/// that cannot be aligned is not an error: success is false and the matrices are the identity.
inline OdometryResult compute_rgbd_odometry(const RgbdImage& source, const RgbdImage& target,
                                            const PinholeIntrinsic& intrinsic, const Mat4& odo_init = identity4(),
                                            OdometryJacobian jacobian = OdometryJacobian::ColorTerm,
                                            const OdometryOption& option = {}) {
    const o3d_odometry_options_t c = option.to_c();
    const std::vector<int32_t> iterations(option.iteration_number_per_pyramid_level.begin(),
                                          option.iteration_number_per_pyramid_level.end());
    OdometryResult r;
    o3d_bool ok = 0;
    // An empty list must reach the C call as 0 levels (an error), not as NULL (Open3D's default levels).
    const int32_t no_levels = 0;
    check(o3d_odometry_compute_rgbd(&ok, r.transformation.data(), r.information.data(), source.get(), target.get(),
                                    &intrinsic, odo_init.data(), static_cast<int32_t>(jacobian),
                                    iterations.empty() ? &no_levels : iterations.data(), iterations.size(), &c));
    r.success = ok != 0;
    return r;
}

}  // namespace o3dpp
