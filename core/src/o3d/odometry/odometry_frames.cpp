// SPDX-License-Identifier: MIT
#include "o3d/odometry/odometry_frames.h"

#include <Eigen/LU>
#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>

#include "o3d/geometry/image_ops.h"
#include "o3d/utility/parallel.h"

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

FloatImage filtered(const FloatImage& image, geometry::ImageFilterType type) {
    return to_float_image(geometry::filter_image(to_image(image), type));
}

}  // namespace

std::vector<FrameLevel> pyramid(const FrameLevel& frame, int levels) {
    std::vector<FrameLevel> out{frame};
    for (int level = 1; level < levels; ++level)
        out.push_back({half(out.back().intensity), half(out.back().depth)});
    return out;
}

Gradients gradients(const FrameLevel& level) {
    using geometry::ImageFilterType;
    return {filtered(level.intensity, ImageFilterType::Sobel3Dx), filtered(level.intensity, ImageFilterType::Sobel3Dy),
            filtered(level.depth, ImageFilterType::Sobel3Dx), filtered(level.depth, ImageFilterType::Sobel3Dy)};
}

std::vector<Correspondence> correspondences(const LevelCamera& camera, const Eigen::Matrix4d& motion,
                                            const FloatImage& depth_s, const FloatImage& depth_t,
                                            double depth_diff_max) {
    Eigen::Matrix3d k = Eigen::Matrix3d::Identity();
    k(0, 0) = camera.fx;
    k(1, 1) = camera.fy;
    k(0, 2) = camera.cx;
    k(1, 2) = camera.cy;
    const Eigen::Matrix3d krk_inv = k * motion.topLeftCorner<3, 3>() * k.inverse();
    const Eigen::Vector3d kt = k * motion.topRightCorner<3, 1>();
    const int w = depth_t.width, h = depth_t.height;
    // Rows are split among threads, each keeping its own list; the lists are joined in row order, so the result is
    // the serial one for any thread count.
    const int threads = std::max(1, std::min(utility::resolve_num_threads(), depth_s.height / 16));
    std::vector<std::vector<Correspondence>> parts(static_cast<size_t>(threads));
#pragma omp parallel for schedule(static) num_threads(threads) if (threads > 1)
    for (int part = 0; part < threads; ++part) {
        std::vector<Correspondence>& out = parts[size_t(part)];
        const int first = int(int64_t(depth_s.height) * part / threads);
        const int last = int(int64_t(depth_s.height) * (part + 1) / threads);
        for (int v_s = first; v_s < last; ++v_s)
            for (int u_s = 0; u_s < depth_s.width; ++u_s) {
                const float d_s = depth_s.at(u_s, v_s);
                if (std::isnan(d_s)) continue;
                const Eigen::Vector3d uv = double(d_s) * (krk_inv * Eigen::Vector3d(u_s, v_s, 1.0)) + kt;
                const double z = uv(2);
                // Open3D's rounding: add a half and truncate toward zero.
                const int u_t = int(uv(0) / z + 0.5), v_t = int(uv(1) / z + 0.5);
                if (u_t < 0 || u_t >= w || v_t < 0 || v_t >= h) continue;
                const float d_t = depth_t.at(u_t, v_t);
                if (std::isnan(d_t) || !(std::abs(z - double(d_t)) <= depth_diff_max)) continue;
                out.push_back({u_s, v_s, u_t, v_t});
            }
    }
    size_t total = 0;
    for (const auto& part : parts) total += part.size();
    std::vector<Correspondence> out;
    out.reserve(total);
    for (const auto& part : parts) out.insert(out.end(), part.begin(), part.end());
    return out;
}

void normalize_intensity(FloatImage& source, FloatImage& target, const std::vector<Correspondence>& corres) {
    if (corres.empty()) return;
    double mean_s = 0, mean_t = 0;
    for (const Correspondence& c : corres) {
        mean_s += source.at(c.u_s, c.v_s);
        mean_t += target.at(c.u_t, c.v_t);
    }
    mean_s /= double(corres.size());
    mean_t /= double(corres.size());
    if (!(mean_s > 0) || !(mean_t > 0)) return;  // a black frame: nothing to scale
    for (float& x : source.values) x = float(x * (0.5 / mean_s));
    for (float& x : target.values) x = float(x * (0.5 / mean_t));
}

}  // namespace o3d::odometry::detail
