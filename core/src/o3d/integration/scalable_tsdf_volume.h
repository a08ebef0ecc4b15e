// SPDX-License-Identifier: MIT
#pragma once
/// @file scalable_tsdf_volume.h
/// @brief Open3D's ScalableTSDFVolume: blocks ("volume units") of volume_unit_resolution^3 voxels in a hash
/// map, created around the surface each frame sees, so memory grows with the surface, not the bounding box.
#include "o3d/integration/tsdf_volume.h"

namespace o3d::integration {

class ScalableTSDFVolume : public TSDFVolume {
public:
    /// @param depth_sampling_stride every stride-th pixel of each row and column places blocks (Open3D's 4)
    /// @throws InvalidArgument on voxel_length, sdf_trunc <= 0 or non-finite, volume_unit_resolution
    /// outside [2, 256], or depth_sampling_stride < 1.
    ScalableTSDFVolume(double voxel_length, double sdf_trunc, ColorType color_type, int volume_unit_resolution = 16,
                       int depth_sampling_stride = 4);

    int volume_unit_resolution() const { return blocks_.side(); }
    int depth_sampling_stride() const { return depth_sampling_stride_; }
    /// @brief Blocks allocated so far.
    size_t block_count() const { return blocks_.size(); }

    void reset() override { blocks_.clear(); }
    /// @brief Opens every block within sdf_trunc (a box around each sampled depth point, as Open3D), then
    /// fuses the frame into those blocks in parallel.
    void integrate(const geometry::RGBDImage& image, const camera::PinholeCameraIntrinsic& intrinsic,
                   const Eigen::Matrix4d& extrinsic) override;

private:
    int depth_sampling_stride_;
};

}  // namespace o3d::integration
