// SPDX-License-Identifier: MIT
#include "o3d/integration/uniform_tsdf_volume.h"

#include <cmath>

#include "o3d/utility/error.h"

namespace o3d::integration {
namespace {

constexpr float kUntruncated = 0.98f;

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
    integrate_into(image, intrinsic, extrinsic, {Eigen::Vector3i::Zero()});
}

geometry::PointCloud UniformTSDFVolume::extract_voxel_point_cloud() const {
    const detail::VoxelBlock& block = voxels();
    geometry::PointCloud cloud;
    size_t i = 0;
    for (int x = 0; x < resolution_; ++x) {
        for (int y = 0; y < resolution_; ++y) {
            for (int z = 0; z < resolution_; ++z, ++i) {
                const float f = block.tsdf[i];
                if (block.weight[i] == 0.0f || !(f < kUntruncated && f >= -kUntruncated)) continue;
                cloud.points.push_back(origin() + voxel_length_ * Eigen::Vector3d(x + 0.5, y + 0.5, z + 0.5));
                const double grey = (double(f) + 1.0) * 0.5;
                cloud.colors.push_back(Eigen::Vector3d::Constant(grey));
            }
        }
    }
    return cloud;
}

geometry::VoxelGrid UniformTSDFVolume::extract_voxel_grid() const {
    const detail::VoxelBlock& block = voxels();
    geometry::VoxelGrid grid;
    grid.voxel_size = voxel_length_;
    grid.origin = origin();
    size_t i = 0;
    for (int x = 0; x < resolution_; ++x) {
        for (int y = 0; y < resolution_; ++y) {
            for (int z = 0; z < resolution_; ++z, ++i) {
                const float f = block.tsdf[i];
                if (block.weight[i] == 0.0f || !(f < kUntruncated && f >= -kUntruncated)) continue;
                const double grey = (double(f) + 1.0) * 0.5;
                // x-major order is the grid's sorted order, so the voxels need no sort.
                grid.voxels.push_back({Eigen::Vector3i(x, y, z), Eigen::Vector3d::Constant(grey)});
            }
        }
    }
    return grid;
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
