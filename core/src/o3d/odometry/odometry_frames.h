// SPDX-License-Identifier: MIT
#pragma once
/// @file odometry_frames.h
/// @brief What odometry works on: preprocessed intensity and depth and their pyramids, the warp a motion gives,
/// and the pixel correspondences it makes.
#include <Eigen/Core>
#include <cmath>
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

FloatImage to_float_image(const geometry::Image& image);
geometry::Image to_image(const FloatImage& image);

/// @brief Depth outside [depth_min, depth_max], zero or not finite becomes NaN (ignored from then on).
FloatImage mask_depth(const FloatImage& depth, const OdometryOption& option);

/// @brief Levels 0 (full size) .. n-1, each a 2 x 2 average of the one before (Open3D's pyramid, no filter).
std::vector<FrameLevel> pyramid(FrameLevel frame, int levels);

/// @brief Where a motion moves a source pixel: K R K^-1 (u, v, 1) d + K t, rounded to a target pixel as Open3D does.
/// One definition shared by every pass, so that they all agree on which pixels correspond.
struct Warp {
    Eigen::Matrix3d krk_inv;
    Eigen::Vector3d kt;
    Warp(const LevelCamera& camera, const Eigen::Matrix4d& motion);
    /// @brief The target pixel (u_t, v_t) that source pixel (u_s, v_s) at depth d_s lands on if it is inside a
    /// w x h image, and the moved depth z. Always inlined: a call per pixel costs more than the warp (GCC left
    /// it out of line in the long odometry loop).
    [[gnu::always_inline]] bool apply(int u_s, int v_s, float d_s, int w, int h, int& u_t, int& v_t, double& z) const {
        const Eigen::Vector3d uv = double(d_s) * (krk_inv * Eigen::Vector3d(u_s, v_s, 1.0)) + kt;
        z = uv(2);
        // Open3D's rounding: add a half and truncate toward zero, so (-1, 0) still lands on pixel 0. The range is
        // tested in double first: a point near the camera plane gives a quotient no int holds (or NaN), and
        // casting that is undefined.
        const double u_f = uv(0) / z + 0.5, v_f = uv(1) / z + 0.5;
        if (!(u_f > -1.0 && u_f < double(w) && v_f > -1.0 && v_f < double(h))) return false;
        u_t = int(u_f);
        v_t = int(v_f);
        return true;
    }
    /// @brief Open3D's depth test: the target has a depth within depth_diff_max of the moved point's.
    static bool depths_agree(double z, float d_t, double depth_diff_max) {
        return !std::isnan(d_t) && std::abs(z - double(d_t)) <= depth_diff_max;
    }
};

/// @brief Call f(u_s, v_s, u_t, v_t) for every source pixel of rows [v_first, v_last) of `depth_s` that `warp`
/// moves onto a target pixel whose depth is within depth_diff_max of the moved point's, in scan order (as Open3D:
/// several may land on one target pixel, and all count).
template <typename F>
void visit_correspondences(const Warp& warp, const FloatImage& depth_s, const FloatImage& depth_t,
                           double depth_diff_max, int v_first, int v_last, F&& f) {
    for (int v_s = v_first; v_s < v_last; ++v_s)
        for (int u_s = 0; u_s < depth_s.width; ++u_s) {
            const float d_s = depth_s.at(u_s, v_s);
            if (std::isnan(d_s)) continue;
            int u_t, v_t;
            double z;
            if (!warp.apply(u_s, v_s, d_s, depth_t.width, depth_t.height, u_t, v_t, z)) continue;
            if (!Warp::depths_agree(z, depth_t.at(u_t, v_t), depth_diff_max)) continue;
            f(u_s, v_s, u_t, v_t);
        }
}

/// @brief Scale both intensities so that their means over the correspondences of `motion` are 0.5 (Open3D's
/// NormalizeIntensity): lighting that differs between the frames then cancels.
void normalize_intensity(FrameLevel& source, FrameLevel& target, const LevelCamera& camera,
                         const Eigen::Matrix4d& motion, double depth_diff_max);

}  // namespace o3d::odometry::detail
