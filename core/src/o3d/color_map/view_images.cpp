// SPDX-License-Identifier: MIT
#include "o3d/color_map/view_images.h"

#include <cmath>
#include <cstring>
#include <string>

#include "o3d/camera/camera_checks.h"
#include "o3d/color_map/visibility.h"
#include "o3d/geometry/image_ops.h"
#include "o3d/geometry/rgbd_image_ops.h"
#include "o3d/utility/error.h"

namespace o3d::color_map::detail {

namespace {

std::string nth(const char* what, size_t i) { return std::string(what) + "[" + std::to_string(i) + "]"; }

void check_option(const OptimizerOption& o) {
    if (o.maximum_iteration < 0)
        throw InvalidArgument("maximum_iteration must be >= 0, got " + std::to_string(o.maximum_iteration));
    if (!(o.maximum_allowable_depth > 0.0))
        throw InvalidArgument("maximum_allowable_depth must be > 0, got " + std::to_string(o.maximum_allowable_depth));
    if (!(o.depth_threshold_for_visibility_check > 0.0) || !std::isfinite(o.depth_threshold_for_visibility_check))
        throw InvalidArgument("depth_threshold_for_visibility_check must be finite and > 0, got " +
                              std::to_string(o.depth_threshold_for_visibility_check));
    if (!(o.depth_threshold_for_discontinuity_check > 0.0))
        throw InvalidArgument("depth_threshold_for_discontinuity_check must be > 0, got " +
                              std::to_string(o.depth_threshold_for_discontinuity_check));
    if (o.half_dilation_kernel_size_for_discontinuity_map < 0)
        throw InvalidArgument("half_dilation_kernel_size_for_discontinuity_map must be >= 0, got " +
                              std::to_string(o.half_dilation_kernel_size_for_discontinuity_map));
    if (o.image_boundary_margin < 0)
        throw InvalidArgument("image_boundary_margin must be >= 0, got " + std::to_string(o.image_boundary_margin));
    if (o.invisible_vertex_color_knn < 1)
        throw InvalidArgument("invisible_vertex_color_knn must be >= 1, got " +
                              std::to_string(o.invisible_vertex_color_knn));
    if (o.num_threads < 0) throw InvalidArgument("num_threads must be >= 0, got " + std::to_string(o.num_threads));
}

FloatGrid to_grid(const geometry::Image& gray) {
    FloatGrid out(gray.width, gray.height, 1);
    std::memcpy(out.values.data(), gray.data.data(), out.values.size() * sizeof(float));
    return out;
}

/// Sobel / 8: the 3x3 Sobel weights sum to 8 times a central difference.
FloatGrid derivative(const geometry::Image& gray, geometry::ImageFilterType sobel) {
    FloatGrid out = to_grid(geometry::filter_image(gray, sobel));
    for (float& x : out.values) x *= 0.125f;
    return out;
}

/// The colour as 3 channels in [0, 1]; a gray or intensity image gives three equal channels.
FloatGrid color_channels(const geometry::Image& color) {
    FloatGrid out(color.width, color.height, 3);
    const size_t n = size_t(color.width) * size_t(color.height);
    if (color.bytes_per_channel == 4) {
        const float* src = reinterpret_cast<const float*>(color.data.data());
        for (size_t i = 0; i < n; ++i) out.values[3 * i] = out.values[3 * i + 1] = out.values[3 * i + 2] = src[i];
        return out;
    }
    const int c = color.num_channels;
    for (size_t i = 0; i < n; ++i)
        for (int k = 0; k < 3; ++k) out.values[3 * i + size_t(k)] = color.data[i * size_t(c) + size_t(c == 3 ? k : 0)] / 255.0f;
    return out;
}

}  // namespace

void check_inputs(const geometry::TriangleMesh& mesh, const std::vector<const geometry::RGBDImage*>& images,
                  const camera::PinholeCameraTrajectory& trajectory, const OptimizerOption& option) {
    check_option(option);
    if (mesh.vertices.empty()) throw InvalidArgument("the mesh has no vertices");
    for (size_t i = 0; i < mesh.vertices.size(); ++i)
        if (!mesh.vertices[i].allFinite()) throw InvalidArgument(nth("mesh vertex", i) + " is not finite");
    if (images.empty()) throw InvalidArgument("no RGB-D images");
    if (images.size() != trajectory.parameters.size())
        throw InvalidArgument(std::to_string(images.size()) + " RGB-D images but the trajectory has " +
                              std::to_string(trajectory.parameters.size()) + " poses; they must pair up");
    for (size_t i = 0; i < images.size(); ++i) {
        if (!images[i]) throw InvalidArgument(nth("image", i) + " is null");
        const geometry::RGBDImage& im = *images[i];
        const camera::PinholeCameraParameters& cam = trajectory.parameters[i];
        geometry::require_rgbd_color(im.color, nth("color of image", i).c_str());
        geometry::require_float_gray(im.depth, nth("depth of image", i).c_str());
        if (im.color.width != im.depth.width || im.color.height != im.depth.height)
            throw InvalidArgument(nth("image", i) + ": color and depth differ in size");
        if (cam.intrinsic.width != im.depth.width || cam.intrinsic.height != im.depth.height)
            throw InvalidArgument(nth("image", i) + " is " + std::to_string(im.depth.width) + "x" +
                                  std::to_string(im.depth.height) + " but its intrinsic says " +
                                  std::to_string(cam.intrinsic.width) + "x" + std::to_string(cam.intrinsic.height));
        if (im.depth.width < 3 || im.depth.height < 3)
            throw InvalidArgument(nth("image", i) + " is smaller than 3x3");
        camera::require_projectable_intrinsic(cam.intrinsic, nth("intrinsic of pose", i).c_str());
        camera::require_rigid_layout(cam.extrinsic, nth("extrinsic of pose", i).c_str());
    }
}

ViewImages prepare_view_images(const geometry::RGBDImage& image, const OptimizerOption& option) {
    ViewImages out;
    const geometry::Image gray = geometry::filter_image(
        geometry::create_float_image(image.color, geometry::ImageConvertType::Weighted),
        geometry::ImageFilterType::Gaussian3);
    out.intensity = to_grid(gray);
    out.dx = derivative(gray, geometry::ImageFilterType::Sobel3Dx);
    out.dy = derivative(gray, geometry::ImageFilterType::Sobel3Dy);
    out.color = color_channels(image.color);
    // Missing depth is 0 from here on: its edges then show up as discontinuities, which is what is wanted.
    geometry::Image depth = image.depth;
    float* d = reinterpret_cast<float*>(depth.data.data());
    for (size_t i = 0, n = size_t(depth.width) * size_t(depth.height); i < n; ++i)
        if (!(d[i] > 0.0f) || !std::isfinite(d[i])) d[i] = 0.0f;
    out.depth = to_grid(depth);
    out.discontinuity = discontinuity_map(depth, option.depth_threshold_for_discontinuity_check,
                                          option.half_dilation_kernel_size_for_discontinuity_map);
    return out;
}

}  // namespace o3d::color_map::detail
