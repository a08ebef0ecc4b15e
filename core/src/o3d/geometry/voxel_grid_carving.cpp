// SPDX-License-Identifier: MIT
#include "o3d/geometry/voxel_grid_carving.h"

#include <algorithm>
#include <cmath>
#include <string>

#include "o3d/camera/camera_checks.h"
#include "o3d/geometry/voxel_grid_edit.h"
#include "o3d/utility/error.h"
#include "o3d/utility/parallel.h"

namespace o3d::geometry {

namespace {

void check_carving_input(const VoxelGrid& grid, const Image& image, const camera::PinholeCameraParameters& params,
                         const char* what) {
    const std::string name(what);
    if (image.num_channels != 1 || image.bytes_per_channel != 4)
        throw o3d::InvalidArgument(name + " must have 1 channel of float32 (got " +
                                   std::to_string(image.num_channels) + " channel(s) of " +
                                   std::to_string(image.bytes_per_channel) + " byte(s))");
    if (image.width <= 0 || image.height <= 0) throw o3d::InvalidArgument(name + " is empty");
    if (image.data.size() != image.byte_size())
        throw o3d::InvalidArgument(name + " holds " + std::to_string(image.data.size()) + " bytes, not " +
                                   std::to_string(image.byte_size()));
    if (image.width != params.intrinsic.width || image.height != params.intrinsic.height)
        throw o3d::InvalidArgument(name + " is " + std::to_string(image.width) + " x " +
                                   std::to_string(image.height) + " but the intrinsic is " +
                                   std::to_string(params.intrinsic.width) + " x " +
                                   std::to_string(params.intrinsic.height));
    camera::require_projectable_intrinsic(params.intrinsic, "the camera intrinsic");
    camera::require_rigid(params.extrinsic, "the camera extrinsic");
    if (!(grid.voxel_size > 0.0) || !std::isfinite(grid.voxel_size))
        throw o3d::InvalidArgument("the voxel grid's voxel_size must be finite and > 0");
    if (!grid.origin.allFinite()) throw o3d::InvalidArgument("the voxel grid's origin is not finite");
}

/// Bilinear value at (u, v), which the caller has checked to lie in [0, width - 1] x [0, height - 1]. The
/// cell's lower corner is clamped so that the far edge interpolates inside the image (Open3D's
/// FloatValueAt); a neighbour read is clamped too, for one-pixel-wide images, where its weight is 0.
double bilinear(const Image& image, double u, double v) {
    const int ui = std::max(std::min(static_cast<int>(u), image.width - 2), 0);
    const int vi = std::max(std::min(static_cast<int>(v), image.height - 2), 0);
    const int ui1 = std::min(ui + 1, image.width - 1), vi1 = std::min(vi + 1, image.height - 1);
    const double pu = u - ui, pv = v - vi;
    const double v00 = *image.pixel<float>(ui, vi), v10 = *image.pixel<float>(ui1, vi);
    const double v01 = *image.pixel<float>(ui, vi1), v11 = *image.pixel<float>(ui1, vi1);
    return (v00 * (1.0 - pu) + v10 * pu) * (1.0 - pv) + (v01 * (1.0 - pu) + v11 * pu) * pv;
}

/// Keep or drop each voxel by its 8 projected corners: keep when one corner is outside the image and
/// `keep_outside`, or inside with `sees(z, value)`. Voxels are decided in parallel, then compacted in order.
template <typename Sees>
void carve(VoxelGrid& grid, const Image& image, const camera::PinholeCameraParameters& params, bool keep_outside,
           int num_threads, Sees sees) {
    const Eigen::Matrix3d rotation = params.extrinsic.block<3, 3>(0, 0);
    const Eigen::Vector3d translation = params.extrinsic.block<3, 1>(0, 3);
    const camera::PinholeCameraIntrinsic& in = params.intrinsic;
    const double max_u = in.width - 1, max_v = in.height - 1;
    auto keeps = [&](const Voxel& voxel) {
        for (const Eigen::Vector3d& corner : voxel_bounding_points(grid, voxel.grid_index)) {
            const Eigen::Vector3d x = rotation * corner + translation;
            const double z = x(2);
            const double u = (in.fx * x(0) + in.cx * z) / z;
            const double v = (in.fy * x(1) + in.cy * z) / z;
            // Written so that NaN lands outside.
            const bool inside = z > 0.0 && u >= 0.0 && u <= max_u && v >= 0.0 && v <= max_v;
            if (inside ? sees(z, bilinear(image, u, v)) : keep_outside) return true;
        }
        return false;
    };
    const int64_t n = static_cast<int64_t>(grid.voxels.size());
    std::vector<char> keep(grid.voxels.size());
    const int threads = n > 4096 ? o3d::utility::resolve_num_threads(num_threads) : 1;
#pragma omp parallel for num_threads(threads) schedule(static)
    for (int64_t i = 0; i < n; ++i) keep[i] = keeps(grid.voxels[i]) ? 1 : 0;
    size_t out = 0;
    for (size_t i = 0; i < grid.voxels.size(); ++i)
        if (keep[i]) grid.voxels[out++] = grid.voxels[i];
    grid.voxels.resize(out);
}

}  // namespace

void carve_depth_map(VoxelGrid& grid, const Image& depth, const camera::PinholeCameraParameters& params,
                     bool keep_voxels_outside_image, int num_threads) {
    check_carving_input(grid, depth, params, "the depth map");
    carve(grid, depth, params, keep_voxels_outside_image, num_threads,
          [](double z, double d) { return d > 0.0 && z >= d; });
}

void carve_silhouette(VoxelGrid& grid, const Image& mask, const camera::PinholeCameraParameters& params,
                      bool keep_voxels_outside_image, int num_threads) {
    check_carving_input(grid, mask, params, "the silhouette mask");
    carve(grid, mask, params, keep_voxels_outside_image, num_threads, [](double, double m) { return m > 0.0; });
}

}  // namespace o3d::geometry
