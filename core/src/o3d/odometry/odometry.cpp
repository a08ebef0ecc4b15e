// SPDX-License-Identifier: MIT
// compute_rgbd_odometry as Open3D's legacy pipeline runs it: Gaussian-smoothed intensity and masked depth,
// intensities normalized over the initial correspondences, then per pyramid level (coarsest first) Gauss-Newton
// steps on the correspondences of the current motion, and the information matrix of the final alignment.
#include <cmath>
#include <string>
#include <utility>

#include "o3d/geometry/image_ops.h"
#include "o3d/odometry/odometry_frames.h"
#include "o3d/odometry/odometry_information.h"
#include "o3d/odometry/odometry_step.h"
#include "o3d/registration/estimation_point_to_plane.h"
#include "o3d/utility/error.h"

namespace o3d::odometry {
namespace {

using detail::FloatImage;
using detail::FrameLevel;
using detail::LevelCamera;

void check_input(const geometry::RGBDImage& source, const geometry::RGBDImage& target,
                 const camera::PinholeCameraIntrinsic& k, const Eigen::Matrix4d& odo_init, const OdometryOption& o) {
    const std::pair<const geometry::Image*, const char*> images[] = {
        {&source.color, "source color"}, {&source.depth, "source depth"},
        {&target.color, "target color"}, {&target.depth, "target depth"}};
    for (const auto& [image, what] : images) {
        if (image->empty()) throw InvalidArgument(std::string(what) + " is empty");
        geometry::require_float_gray(*image, what);  // Open3D's odometry input: float intensity and metres
        if (image->width != source.color.width || image->height != source.color.height)
            throw InvalidArgument("the four images must have one size: " + std::string(what) + " is " +
                                  std::to_string(image->width) + " x " + std::to_string(image->height) +
                                  ", source color " + std::to_string(source.color.width) + " x " +
                                  std::to_string(source.color.height));
    }
    if (k.width != source.color.width || k.height != source.color.height)
        throw InvalidArgument("the intrinsic is " + std::to_string(k.width) + " x " + std::to_string(k.height) +
                              ", the images " + std::to_string(source.color.width) + " x " +
                              std::to_string(source.color.height));
    if (!(k.fx > 0) || !(k.fy > 0) || !std::isfinite(k.fx) || !std::isfinite(k.fy) || !std::isfinite(k.cx) ||
        !std::isfinite(k.cy))
        throw InvalidArgument("the intrinsic needs finite values and fx, fy > 0");
    if (!odo_init.allFinite()) throw InvalidArgument("odo_init must be finite");
    const int levels = int(o.iteration_number_per_pyramid_level.size());
    if (levels < 1) throw InvalidArgument("iteration_number_per_pyramid_level is empty");
    for (int n : o.iteration_number_per_pyramid_level)
        if (n < 0) throw InvalidArgument("iteration_number_per_pyramid_level has a negative count");
    if ((source.color.width >> (levels - 1)) < 1 || (source.color.height >> (levels - 1)) < 1)
        throw InvalidArgument("the images are too small for " + std::to_string(levels) + " pyramid levels");
    if (!(o.depth_diff_max > 0) || !std::isfinite(o.depth_diff_max) || !std::isfinite(o.depth_min) ||
        !std::isfinite(o.depth_max) || o.depth_min > o.depth_max)
        throw InvalidArgument("depth_diff_max must be > 0 and depth_min <= depth_max, all finite");
}

}  // namespace

OdometryResult compute_rgbd_odometry(const geometry::RGBDImage& source, const geometry::RGBDImage& target,
                                     const camera::PinholeCameraIntrinsic& intrinsic, const Eigen::Matrix4d& odo_init,
                                     Jacobian jacobian, const OdometryOption& option) {
    check_input(source, target, intrinsic, odo_init, option);
    using geometry::ImageFilterType;
    auto smooth = [](const geometry::Image& image) {
        return detail::to_float_image(geometry::filter_image(image, ImageFilterType::Gaussian3));
    };
    auto smooth_depth = [&](const geometry::Image& depth) {
        const FloatImage masked = detail::mask_depth(detail::to_float_image(depth), option);
        return detail::to_float_image(geometry::filter_image(detail::to_image(masked), ImageFilterType::Gaussian3));
    };
    FrameLevel s{smooth(source.color), smooth_depth(source.depth)};
    FrameLevel t{smooth(target.color), smooth_depth(target.depth)};
    const LevelCamera camera{intrinsic.width, intrinsic.height, intrinsic.fx, intrinsic.fy, intrinsic.cx, intrinsic.cy};
    detail::normalize_intensity(s, t, camera, odo_init, option.depth_diff_max);

    const int levels = int(option.iteration_number_per_pyramid_level.size());
    const std::vector<FrameLevel> source_levels = detail::pyramid(std::move(s), levels);
    const std::vector<FrameLevel> target_levels = detail::pyramid(std::move(t), levels);
    OdometryResult result;
    Eigen::Matrix4d motion = odo_init;
    detail::PackedLevel packed;  // after the loop: level 0, the full-size frames the information matrix is of
    for (int level = levels - 1; level >= 0; --level) {
        const LevelCamera c = camera.scaled(level);
        packed = detail::pack_level(c, source_levels[size_t(level)], target_levels[size_t(level)]);
        for (int it = 0; it < option.iteration_number_per_pyramid_level[size_t(levels - 1 - level)]; ++it) {
            const detail::StepSums sums = detail::step_sums(packed, motion, jacobian, option.depth_diff_max);
            // Nothing overlaps: no solution (Open3D's "Num of corresps is 0").
            if (sums.correspondences == 0) return result;
            const Eigen::Matrix<double, 6, 1> x = sums.equations.solve();
            if (!x.allFinite()) return result;  // a singular system
            motion = registration::detail::euler_pose_to_matrix(x) * motion;
        }
    }
    result.success = true;
    result.transformation = motion;
    result.information = detail::information_matrix(packed, motion, option.depth_diff_max);
    return result;
}

}  // namespace o3d::odometry
