// SPDX-License-Identifier: MIT
#include "o3d/integration/uniform_tsdf_volume.h"

#include <cmath>

#include "o3d/utility/error.h"

namespace o3d::integration {
namespace {

int checked_resolution(int resolution) {
    if (resolution < 1 || resolution > 2048)
        throw InvalidArgument("UniformTSDFVolume: resolution must be in [1, 2048], got " + std::to_string(resolution));
    return resolution;
}

double checked_length(double length) {
    if (!(length > 0) || !std::isfinite(length))
        throw InvalidArgument("UniformTSDFVolume: length must be a finite number > 0");
    return length;
}

}  // namespace

UniformTSDFVolume::UniformTSDFVolume(double length, int resolution, double sdf_trunc, ColorType color_type,
                                     const Eigen::Vector3d& origin)
    : TSDFVolume(checked_length(length) / double(checked_resolution(resolution)), sdf_trunc, color_type, resolution,
                 origin),
      length_(length),
      resolution_(resolution) {
    blocks_.find_or_create(Eigen::Vector3i::Zero());
}

const detail::VoxelBlock& UniformTSDFVolume::voxels() const { return *blocks_.find(Eigen::Vector3i::Zero()); }

void UniformTSDFVolume::reset() {
    blocks_.clear();
    blocks_.find_or_create(Eigen::Vector3i::Zero());
}

void UniformTSDFVolume::integrate(const geometry::RGBDImage& image, const camera::PinholeCameraIntrinsic& intrinsic,
                                  const Eigen::Matrix4d& extrinsic) {
    check_frame(image, intrinsic, extrinsic);
    integrate_into(image, intrinsic, extrinsic, {Eigen::Vector3i::Zero()});
}

std::vector<float> UniformTSDFVolume::extract_volume_tsdf() const {
    const detail::VoxelBlock& block = voxels();
    std::vector<float> out(2 * block.tsdf.size());
    for (size_t i = 0; i < block.tsdf.size(); ++i) {
        out[2 * i] = block.tsdf[i];
        out[2 * i + 1] = block.weight[i];
    }
    return out;
}

std::vector<float> UniformTSDFVolume::extract_volume_color() const {
    const detail::VoxelBlock& block = voxels();
    std::vector<float> out(3 * block.tsdf.size(), 0.0f);
    for (size_t i = 0; i < block.color.size(); ++i)
        for (int c = 0; c < 3; ++c) out[3 * i + size_t(c)] = block.color[i](c);
    return out;
}

}  // namespace o3d::integration
