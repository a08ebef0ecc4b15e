// SPDX-License-Identifier: MIT
#pragma once
/// @file odometry_frames.h
/// @brief What odometry works on: preprocessed intensity and depth, their pyramids and gradients, the
/// back-projected source points, and the pixel correspondences a motion gives.
#include <Eigen/Core>
#include <vector>

#include "o3d/geometry/image.h"
#include "o3d/odometry/odometry.h"

namespace o3d::odometry::detail {

/// @brief Intrinsics of one pyramid level (Open3D halves fx, fy, cx, cy per level).
struct LevelCamera {
    int width = 0, height = 0;
    double fx = 0, fy = 0, cx = 0, cy = 0;
    LevelCamera scaled(int level) const;
};

/// @brief One float image as a plain array (row-major, `width` x `height`).
struct FloatImage {
    int width = 0, height = 0;
    std::vector<float> values;
    float at(int u, int v) const { return values[size_t(v) * size_t(width) + size_t(u)]; }
};

/// @brief One level of a frame: intensity and depth (NaN where there is none).
struct FrameLevel {
    FloatImage intensity, depth;
};

/// @brief A target level's Sobel gradients (Open3D's unscaled 3x3 Sobel; the Jacobians scale by 1/8).
struct Gradients {
    FloatImage intensity_dx, intensity_dy, depth_dx, depth_dy;
};

/// @brief A pixel of the source and the target pixel it lands on.
struct Correspondence {
    int u_s, v_s, u_t, v_t;
};

FloatImage to_float_image(const geometry::Image& image);
geometry::Image to_image(const FloatImage& image);

/// @brief Depth outside [depth_min, depth_max], zero or not finite becomes NaN (ignored from then on).
FloatImage mask_depth(const FloatImage& depth, const OdometryOption& option);

/// @brief Levels 0 (full size) .. n-1, each a 2 x 2 average of the one before (Open3D's pyramid, no filter).
std::vector<FrameLevel> pyramid(const FrameLevel& frame, int levels);
Gradients gradients(const FrameLevel& level);

/// @brief Every source pixel of `depth_s` that `motion` moves onto a target pixel whose depth is within
/// depth_diff_max of the moved point's, in source scan order (as Open3D: several may share a target pixel).
std::vector<Correspondence> correspondences(const LevelCamera& camera, const Eigen::Matrix4d& motion,
                                            const FloatImage& depth_s, const FloatImage& depth_t,
                                            double depth_diff_max);

/// @brief Scale both intensities so that their means over the correspondences are 0.5 (Open3D's
/// NormalizeIntensity): lighting that differs between the frames then cancels.
void normalize_intensity(FloatImage& source, FloatImage& target, const std::vector<Correspondence>& corres);

}  // namespace o3d::odometry::detail
