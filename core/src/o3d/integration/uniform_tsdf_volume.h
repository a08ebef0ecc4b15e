// SPDX-License-Identifier: MIT
#pragma once
/// @file uniform_tsdf_volume.h
/// @brief Open3D's UniformTSDFVolume: a dense cube of resolution^3 voxels of edge length / resolution,
/// allocated up front, whose first corner is `origin`.
#include "o3d/integration/tsdf_volume.h"

namespace o3d::integration {

class UniformTSDFVolume : public TSDFVolume {
public:
    /// @throws InvalidArgument on length, sdf_trunc <= 0 or non-finite, resolution outside [1, 2048], or a
    /// non-finite origin. std::bad_alloc when resolution^3 voxels do not fit in memory.
    UniformTSDFVolume(double length, int resolution, double sdf_trunc, ColorType color_type,
                      const Eigen::Vector3d& origin = Eigen::Vector3d::Zero());

    double length() const { return length_; }
    int resolution() const { return resolution_; }
    const Eigen::Vector3d& origin() const { return blocks_.origin(); }

    void reset() override;
    void integrate(const geometry::RGBDImage& image, const camera::PinholeCameraIntrinsic& intrinsic,
                   const Eigen::Matrix4d& extrinsic) override;

    /// @brief tsdf and weight of every voxel (2 values each), index (x * resolution + y) * resolution + z.
    std::vector<float> extract_volume_tsdf() const;
    /// @brief The colour of every voxel (3 values each, in [0, 1]), same order; zeros without colour.
    std::vector<float> extract_volume_color() const;

private:
    const detail::VoxelBlock& voxels() const;
    double length_;
    int resolution_;
};

}  // namespace o3d::integration
