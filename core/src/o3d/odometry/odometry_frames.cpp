// SPDX-License-Identifier: MIT
#include "o3d/odometry/odometry_frames.h"

#include <Eigen/LU>
#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>

#include "o3d/geometry/image_ops.h"
#include "o3d/odometry/odometry_reduce.h"

namespace o3d::odometry::detail {

LevelCamera LevelCamera::scaled(int level) const {
    const double s = 1.0 / double(1 << level);
    LevelCamera c = *this;
    c.width = width >> level;
    c.height = height >> level;
    c.fx = fx * s;
    c.fy = fy * s;
    c.cx = cx * s;
    c.cy = cy * s;
    return c;
}

FloatImage to_float_image(const geometry::Image& image) {
    FloatImage out;
    out.width = image.width;
    out.height = image.height;
    out.values.resize(size_t(image.width) * size_t(image.height));
    if (!out.values.empty()) std::memcpy(out.values.data(), image.data.data(), out.values.size() * sizeof(float));
    return out;
}

geometry::Image to_image(const FloatImage& image) {
    geometry::Image out = geometry::make_image(image.width, image.height, 1, 4);
    if (!image.values.empty()) std::memcpy(out.data.data(), image.values.data(), image.values.size() * sizeof(float));
    return out;
}

FloatImage mask_depth(const FloatImage& depth, const OdometryOption& option) {
    FloatImage out = depth;
    for (float& d : out.values)
        if (!(d >= option.depth_min && d <= option.depth_max && d > 0)) d = std::numeric_limits<float>::quiet_NaN();
    return out;
}

namespace {

FloatImage half(const FloatImage& in) {
    FloatImage out;
    out.width = in.width / 2;
    out.height = in.height / 2;
    out.values.resize(size_t(out.width) * size_t(out.height));
    for (int v = 0; v < out.height; ++v)
        for (int u = 0; u < out.width; ++u)
            out.values[size_t(v) * size_t(out.width) + size_t(u)] =
                (in.at(2 * u, 2 * v) + in.at(2 * u + 1, 2 * v) + in.at(2 * u, 2 * v + 1) + in.at(2 * u + 1, 2 * v + 1)) /
                4.0f;
    return out;
}

}  // namespace

std::vector<FrameLevel> pyramid(FrameLevel frame, int levels) {
    std::vector<FrameLevel> out;
    out.reserve(size_t(levels));
    out.push_back(std::move(frame));
    for (int level = 1; level < levels; ++level)
        out.push_back({half(out.back().intensity), half(out.back().depth)});
    return out;
}

Warp::Warp(const LevelCamera& camera, const Eigen::Matrix4d& motion) {
    Eigen::Matrix3d k = Eigen::Matrix3d::Identity();
    k(0, 0) = camera.fx;
    k(1, 1) = camera.fy;
    k(0, 2) = camera.cx;
    k(1, 2) = camera.cy;
    krk_inv = k * motion.topLeftCorner<3, 3>() * k.inverse();
    kt = k * motion.topRightCorner<3, 1>();
}

namespace {

struct IntensitySums {
    double source = 0, target = 0;
    size_t count = 0;
    IntensitySums& operator+=(const IntensitySums& o) {
        source += o.source;
        target += o.target;
        count += o.count;
        return *this;
    }
};

}  // namespace

void normalize_intensity(FrameLevel& source, FrameLevel& target, const LevelCamera& camera,
                         const Eigen::Matrix4d& motion, double depth_diff_max) {
    const Warp warp(camera, motion);
    const IntensitySums sums =
        reduce_row_blocks<IntensitySums>(source.depth.height, [&](int first, int last, IntensitySums& out) {
            visit_correspondences(warp, source.depth, target.depth, depth_diff_max, first, last,
                                  [&](int u_s, int v_s, int u_t, int v_t) {
                                      out.source += source.intensity.at(u_s, v_s);
                                      out.target += target.intensity.at(u_t, v_t);
                                      ++out.count;
                                  });
        });
    if (sums.count == 0) return;
    const double mean_s = sums.source / double(sums.count), mean_t = sums.target / double(sums.count);
    if (!(mean_s > 0) || !(mean_t > 0)) return;  // a black frame: nothing to scale
    for (float& x : source.intensity.values) x = float(x * (0.5 / mean_s));
    for (float& x : target.intensity.values) x = float(x * (0.5 / mean_t));
}

}  // namespace o3d::odometry::detail
