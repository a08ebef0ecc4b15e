// SPDX-License-Identifier: MIT
// Two passes over the visited rows: count the valid pixels of each row, then let every row write its points
// at its prefix-sum offset. The output order is thus fixed, whatever the thread count. The arithmetic follows
// Open3D's order ((u - cx) * z / fx in double from a float depth) so that points agree with it bit for bit.
#include "o3d/geometry/depth_projection.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include "o3d/camera/camera_checks.h"
#include "o3d/geometry/image_ops.h"
#include "o3d/geometry/rgbd_image_ops.h"
#include "o3d/utility/error.h"
#include "o3d/utility/parallel.h"

namespace o3d::geometry {
namespace {

/// Below this many visited pixels a thread team costs more than it saves.
constexpr size_t kParallelPixels = 1 << 16;

struct Camera {
    double fx, fy, cx, cy;
    Eigen::Matrix4d pose;  // camera-to-world
    bool identity_pose;

    Eigen::Vector3d world(int u, int v, float depth) const {
        const double z = depth;
        const double x = (u - cx) * z / fx;
        const double y = (v - cy) * z / fy;
        if (identity_pose) return {x, y, z};
        const Eigen::Matrix4d& p = pose;
        return {p(0, 0) * x + p(0, 1) * y + p(0, 2) * z + p(0, 3), p(1, 0) * x + p(1, 1) * y + p(1, 2) * z + p(1, 3),
                p(2, 0) * x + p(2, 1) * y + p(2, 2) * z + p(2, 3)};
    }
};

Camera make_camera(const camera::PinholeCameraIntrinsic& intrinsic, const Eigen::Matrix4d& extrinsic) {
    camera::require_projectable_intrinsic(intrinsic, "intrinsic");
    camera::require_rigid_layout(extrinsic, "extrinsic");
    Camera cam{intrinsic.fx, intrinsic.fy, intrinsic.cx, intrinsic.cy, camera::checked_inverse(extrinsic, "extrinsic"),
               false};
    cam.identity_pose = cam.pose == Eigen::Matrix4d::Identity();
    return cam;
}

/// Pixels visited with `stride` along an axis of `size` pixels.
int visited(int size, int stride) { return 1 + (size - 1) / stride; }

/// No color: the projection writes points only.
struct NoColor {
    static constexpr bool enabled = false;
    void operator()(int, int, Eigen::Vector3d&) const {}
};

/// `Depth` gives typed rows (`row(v)`) and the depth in metres of a sample (`metres(sample)`), 0 where it
/// is invalid; `ColorAt(u, v, out)` writes a color.
template <typename Depth, typename ColorAt>
PointCloud back_project(int width, int height, int stride, bool valid_only, const Camera& cam, const Depth& depth,
                        ColorAt color_at, int num_threads) {
    // A stride beyond the image visits only pixel 0 along that axis; clamping it keeps u + stride in range.
    stride = std::min(stride, std::max(width, height));
    const int rows = visited(height, stride), cols = visited(width, stride);
    const size_t pixels = size_t(rows) * size_t(cols);
    const int threads = pixels >= kParallelPixels ? utility::resolve_num_threads(num_threads) : 1;

    // One thread team for both passes. Resizing does not touch the new memory (Eigen vectors are not
    // initialised), so the pages are first written, and faulted in, by the parallel fill.
    std::vector<size_t> offset(size_t(rows) + 1, 0);
    PointCloud cloud;
    const auto allocate = [&] {
        cloud.points.resize(offset[size_t(rows)]);
        if constexpr (ColorAt::enabled) cloud.colors.resize(cloud.points.size());
    };
    if (!valid_only) {
        for (int r = 0; r <= rows; ++r) offset[size_t(r)] = size_t(r) * size_t(cols);
        allocate();
    }
    const double nan = std::numeric_limits<double>::quiet_NaN();
#pragma omp parallel num_threads(threads)
    {
        if (valid_only) {
#pragma omp for schedule(static)
            for (int r = 0; r < rows; ++r) {
                const auto* row = depth.row(r * stride);
                size_t n = 0;
                if (stride == 1) {
                    for (int u = 0; u < width; ++u) n += depth.metres(row[u]) > 0.0f;
                } else {
                    for (int u = 0; u < width; u += stride) n += depth.metres(row[u]) > 0.0f;
                }
                offset[size_t(r) + 1] = n;
            }
#pragma omp single
            {
                for (int r = 0; r < rows; ++r) offset[size_t(r) + 1] += offset[size_t(r)];
                allocate();
            }
        }
#pragma omp for schedule(static)
        for (int r = 0; r < rows; ++r) {
            const int v = r * stride;
            const auto* row = depth.row(v);
            Eigen::Vector3d* points = cloud.points.data() + offset[size_t(r)];
            Eigen::Vector3d* colors = ColorAt::enabled ? cloud.colors.data() + offset[size_t(r)] : nullptr;
            for (int u = 0; u < width; u += stride) {
                const float z = depth.metres(row[u]);
                if (z > 0.0f) {
                    *points++ = cam.world(u, v, z);
                    if constexpr (ColorAt::enabled) color_at(u, v, *colors++);
                } else if (!valid_only) {
                    *points++ = Eigen::Vector3d(nan, nan, nan);
                    if constexpr (ColorAt::enabled) (colors++)->setZero();
                }
            }
        }
    }
    return cloud;
}

/// Open3D divides 8-bit colors by 255 (not a multiplication by 1/255): a table keeps that rounding.
struct ByteToUnit {
    double value[256];
    ByteToUnit() {
        for (int i = 0; i < 256; ++i) value[i] = i / 255.0;
    }
};

struct Rgb8Color {
    static constexpr bool enabled = true;
    const Image* image;
    const ByteToUnit* unit;
    void operator()(int u, int v, Eigen::Vector3d& out) const {
        const uint8_t* p = image->pixel<uint8_t>(u, v);
        out = {unit->value[p[0]], unit->value[p[1]], unit->value[p[2]]};
    }
};

struct Gray8Color {
    static constexpr bool enabled = true;
    const Image* image;
    const ByteToUnit* unit;
    void operator()(int u, int v, Eigen::Vector3d& out) const {
        out.setConstant(unit->value[*image->pixel<uint8_t>(u, v)]);
    }
};

struct IntensityColor {
    static constexpr bool enabled = true;
    const Image* image;
    void operator()(int u, int v, Eigen::Vector3d& out) const { out.setConstant(*image->pixel<float>(u, v)); }
};

/// A float depth in metres: valid when finite and in (0, trunc).
struct MetricDepth {
    const Image* image;
    float trunc;
    const float* row(int v) const { return image->pixel<float>(0, v); }
    float metres(float z) const {
        return (z > 0.0f && z < trunc) ? z : 0.0f;  // NaN fails both tests; +inf fails the second
    }
};

/// A raw uint16 depth: z = raw / scale in float (Open3D's ConvertDepthToFloatImage), invalid from trunc on.
struct RawDepth {
    const Image* image;
    float scale;
    double trunc;
    const uint16_t* row(int v) const { return image->pixel<uint16_t>(0, v); }
    float metres(uint16_t raw) const {
        const float z = float(raw) / scale;
        return double(z) < trunc ? z : 0.0f;
    }
};

void require_stride(int stride) {
    if (stride < 1) throw InvalidArgument("stride must be >= 1, not " + std::to_string(stride));
}

float truncation_as_float(double trunc) {
    // Depths are floats: compare against the truncation in float, saturating huge values to +inf.
    return trunc >= double(std::numeric_limits<float>::max()) ? std::numeric_limits<float>::infinity() : float(trunc);
}

}  // namespace

PointCloud create_point_cloud_from_depth_image(const Image& depth, const camera::PinholeCameraIntrinsic& intrinsic,
                                               const Eigen::Matrix4d& extrinsic, const DepthToCloudOptions& options) {
    require_valid_image(depth, "depth");
    if (depth.num_channels != 1 || (depth.bytes_per_channel != 2 && depth.bytes_per_channel != 4))
        throw InvalidArgument("depth: expected a 1-channel uint16 or float32 image, not " +
                              std::to_string(depth.num_channels) + " channel(s) of " +
                              std::to_string(depth.bytes_per_channel) + " byte(s)");
    require_stride(options.stride);
    if (!(options.depth_scale > 0.0) || !std::isfinite(options.depth_scale))
        throw InvalidArgument("depth_scale must be a finite number > 0");
    if (std::isnan(options.depth_trunc)) throw InvalidArgument("depth_trunc is NaN");
    const Camera cam = make_camera(intrinsic, extrinsic);
    if (depth.bytes_per_channel == 2)
        return back_project(depth.width, depth.height, options.stride, options.project_valid_depth_only, cam,
                            RawDepth{&depth, float(options.depth_scale), options.depth_trunc}, NoColor{},
                            options.num_threads);
    return back_project(depth.width, depth.height, options.stride, options.project_valid_depth_only, cam,
                        MetricDepth{&depth, truncation_as_float(options.depth_trunc)}, NoColor{}, options.num_threads);
}

PointCloud create_point_cloud_from_rgbd_image(const RGBDImage& rgbd, const camera::PinholeCameraIntrinsic& intrinsic,
                                              const Eigen::Matrix4d& extrinsic, bool project_valid_depth_only,
                                              int num_threads) {
    require_float_gray(rgbd.depth, "rgbd.depth");
    require_rgbd_color(rgbd.color, "rgbd.color");
    const Image& color = rgbd.color;
    if (color.width != rgbd.depth.width || color.height != rgbd.depth.height)
        throw InvalidArgument("rgbd: color and depth differ in size");
    const Camera cam = make_camera(intrinsic, extrinsic);
    const MetricDepth depth{&rgbd.depth, std::numeric_limits<float>::infinity()};
    const int w = color.width, h = color.height;
    static const ByteToUnit unit;
    if (color.bytes_per_channel == 4)
        return back_project(w, h, 1, project_valid_depth_only, cam, depth, IntensityColor{&color}, num_threads);
    if (color.num_channels == 3)
        return back_project(w, h, 1, project_valid_depth_only, cam, depth, Rgb8Color{&color, &unit}, num_threads);
    return back_project(w, h, 1, project_valid_depth_only, cam, depth, Gray8Color{&color, &unit}, num_threads);
}

}  // namespace o3d::geometry
