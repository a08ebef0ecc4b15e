// SPDX-License-Identifier: MIT
// compute_rgbd_odometry as Open3D's legacy pipeline runs it: Gaussian-smoothed intensity and masked depth,
// intensities normalized over the initial correspondences, then per pyramid level (coarsest first) Gauss-Newton
// steps on the correspondences of the current motion, and the information matrix of the final alignment.
#include <cmath>
#include <string>

#include "o3d/geometry/image_ops.h"
#include "o3d/odometry/odometry_frames.h"
#include "o3d/registration/estimation_point_to_plane.h"
#include "o3d/utility/error.h"
#include "o3d/utility/parallel.h"

namespace o3d::odometry {
namespace {

using detail::Correspondence;
using detail::FloatImage;
using detail::FrameLevel;
using detail::Gradients;
using detail::LevelCamera;
using registration::detail::NormalEquations6;

constexpr double kSobelScale = 0.125;     // the 3 x 3 Sobel kernels sum |weights| to 8
constexpr double kHybridDepthWeight = 0.968;  // Park et al.'s lambda between the depth and intensity terms

/// @brief The rows one correspondence adds (Open3D's ComputeJacobianAndResidual for each term).
struct RowBuilder {
    const FrameLevel& source;
    const FrameLevel& target;
    const Gradients& grad;
    const std::vector<Eigen::Vector3f>& source_xyz;
    const LevelCamera& camera;
    const Eigen::Matrix4d& motion;
    Jacobian jacobian;

    void add(const Correspondence& c, NormalEquations6& sums) const {
        const Eigen::Vector3d p0 = source_xyz[size_t(c.v_s) * size_t(source.depth.width) + size_t(c.u_s)].cast<double>();
        const Eigen::Vector3d p = motion.topLeftCorner<3, 3>() * p0 + motion.topRightCorner<3, 1>();
        const double inv_z = 1.0 / p(2);
        const bool hybrid = jacobian == Jacobian::HybridTerm;
        const double w_img = hybrid ? std::sqrt(1.0 - kHybridDepthWeight) : 1.0;
        // Photometric row: the target's intensity gradient through the projection's derivative.
        const double diff = double(target.intensity.at(c.u_t, c.v_t)) - double(source.intensity.at(c.u_s, c.v_s));
        const double dx = kSobelScale * grad.intensity_dx.at(c.u_t, c.v_t);
        const double dy = kSobelScale * grad.intensity_dy.at(c.u_t, c.v_t);
        const double c0 = dx * camera.fx * inv_z, c1 = dy * camera.fy * inv_z;
        const double c2 = -(c0 * p(0) + c1 * p(1)) * inv_z;
        const double j_img[6] = {w_img * (-p(2) * c1 + p(1) * c2), w_img * (p(2) * c0 - p(0) * c2),
                                 w_img * (-p(1) * c0 + p(0) * c1), w_img * c0, w_img * c1, w_img * c2};
        sums.add_row(j_img, w_img * diff, 1.0);
        if (!hybrid) return;
        // Geometric row: the target's depth against the moved point's depth.
        const double w_dep = std::sqrt(kHybridDepthWeight);
        const double diff_geo = double(target.depth.at(c.u_t, c.v_t)) - p(2);
        double ddx = kSobelScale * grad.depth_dx.at(c.u_t, c.v_t), ddy = kSobelScale * grad.depth_dy.at(c.u_t, c.v_t);
        if (std::isnan(ddx)) ddx = 0;
        if (std::isnan(ddy)) ddy = 0;
        const double d0 = ddx * camera.fx * inv_z, d1 = ddy * camera.fy * inv_z;
        const double d2 = -(d0 * p(0) + d1 * p(1)) * inv_z;
        const double j_dep[6] = {w_dep * ((-p(2) * d1 + p(1) * d2) - p(1)), w_dep * ((p(2) * d0 - p(0) * d2) + p(0)),
                                 w_dep * (-p(1) * d0 + p(0) * d1), w_dep * d0, w_dep * d1, w_dep * (d2 - 1.0)};
        sums.add_row(j_dep, w_dep * diff_geo, 1.0);
    }
};

/// @brief Sums over fixed chunks added in order: the same bits for any thread count.
NormalEquations6 reduce(const std::vector<Correspondence>& corres, const RowBuilder& rows) {
    constexpr size_t kChunk = 4096;
    const size_t chunks = (corres.size() + kChunk - 1) / kChunk;
    std::vector<NormalEquations6> partial(chunks);
    const int threads = chunks > 1 ? utility::resolve_num_threads() : 1;
#pragma omp parallel for schedule(static) num_threads(threads) if (threads > 1)
    for (long long k = 0; k < (long long)chunks; ++k) {
        const size_t end = std::min(corres.size(), size_t(k + 1) * kChunk);
        for (size_t i = size_t(k) * kChunk; i < end; ++i) rows.add(corres[i], partial[size_t(k)]);
    }
    NormalEquations6 total;
    for (const NormalEquations6& p : partial) total.add(p);
    return total;
}

std::vector<Eigen::Vector3f> back_project(const FloatImage& depth, const LevelCamera& camera) {
    std::vector<Eigen::Vector3f> xyz(depth.values.size());
    for (int v = 0; v < depth.height; ++v)
        for (int u = 0; u < depth.width; ++u) {
            const float z = depth.at(u, v);
            xyz[size_t(v) * size_t(depth.width) + size_t(u)] =
                Eigen::Vector3f(float((u - camera.cx) * z / camera.fx), float((v - camera.cy) * z / camera.fy), z);
        }
    return xyz;
}

/// @brief Open3D's CreateInformationMatrix: J^T J of the point-to-point rows at the target's points.
Matrix6d information_matrix(const LevelCamera& camera, const Eigen::Matrix4d& motion, const FrameLevel& source,
                            const FrameLevel& target, double depth_diff_max) {
    const auto corres = detail::correspondences(camera, motion, source.depth, target.depth, depth_diff_max);
    const std::vector<Eigen::Vector3f> xyz_t = back_project(target.depth, camera);
    Matrix6d gtg = Matrix6d::Zero();
    for (const Correspondence& c : corres) {
        const Eigen::Vector3d q = xyz_t[size_t(c.v_t) * size_t(target.depth.width) + size_t(c.u_t)].cast<double>();
        Eigen::Matrix<double, 6, 1> g;
        g << 0, q(2), -q(1), 1, 0, 0;
        gtg += g * g.transpose();
        g << -q(2), 0, q(0), 0, 1, 0;
        gtg += g * g.transpose();
        g << q(1), -q(0), 0, 0, 0, 1;
        gtg += g * g.transpose();
    }
    return gtg;
}

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
    detail::normalize_intensity(s.intensity, t.intensity,
                                detail::correspondences(camera, odo_init, s.depth, t.depth, option.depth_diff_max));

    const int levels = int(option.iteration_number_per_pyramid_level.size());
    const std::vector<FrameLevel> source_levels = detail::pyramid(s, levels);
    const std::vector<FrameLevel> target_levels = detail::pyramid(t, levels);
    OdometryResult result;
    Eigen::Matrix4d motion = odo_init;
    for (int level = levels - 1; level >= 0; --level) {
        const LevelCamera c = camera.scaled(level);
        const FrameLevel& sl = source_levels[size_t(level)];
        const FrameLevel& tl = target_levels[size_t(level)];
        const Gradients grad = detail::gradients(tl);
        const std::vector<Eigen::Vector3f> xyz = back_project(sl.depth, c);
        for (int it = 0; it < option.iteration_number_per_pyramid_level[size_t(levels - 1 - level)]; ++it) {
            const auto corres = detail::correspondences(c, motion, sl.depth, tl.depth, option.depth_diff_max);
            if (corres.empty()) return result;  // nothing overlaps: no solution (Open3D's "Num of corresps is 0")
            const NormalEquations6 sums = reduce(corres, RowBuilder{sl, tl, grad, xyz, c, motion, jacobian});
            const Eigen::Matrix<double, 6, 1> x = sums.solve();
            if (!x.allFinite()) return result;  // a singular system
            motion = registration::detail::euler_pose_to_matrix(x) * motion;
        }
    }
    result.success = true;
    result.transformation = motion;
    result.information = information_matrix(camera, motion, s, t, option.depth_diff_max);
    return result;
}

}  // namespace o3d::odometry
