// SPDX-License-Identifier: MIT
#pragma once
/// @file integration.hpp
/// @brief o3dpp::TSDFVolume (move-only owner of an o3d_tsdf_volume_t): Open3D's UniformTSDFVolume and
/// ScalableTSDFVolume behind one class. The constructors (uniform, scalable), reset, extraction and getters are
/// generated (detail::TSDFVolumeCalls); written here: integrate and the uniform volume's arrays.
#include <array>
#include <vector>

#include "o3d/integration.h"
#include "o3dpp/camera.hpp"
#include "o3dpp/generated/integration.hpp"
#include "o3dpp/handle.hpp"
#include "o3dpp/rgbd.hpp"

namespace o3dpp {

class TSDFVolume : public Owner<TSDFVolume, o3d_tsdf_volume_t, &o3d_tsdf_volume_destroy>,
                   public detail::TSDFVolumeCalls<TSDFVolume> {
    friend class detail::TSDFVolumeCalls<TSDFVolume>;  // checks its calls with done

public:
    /// @brief Take ownership of `owned` (must not be NULL).
    explicit TSDFVolume(o3d_tsdf_volume_t* owned) : Owner(owned) {}

    /// @brief Fuse a frame seen by `intrinsic` from `extrinsic` (row-major 4x4, world to camera).
    TSDFVolume& integrate(const RgbdImage& image, const PinholeIntrinsic& intrinsic, const Mat4& extrinsic) {
        return done(o3d_tsdf_volume_integrate(get(), image.get(), &intrinsic, extrinsic.data()));
    }
    /// @brief A uniform volume's (tsdf, weight) per voxel, voxel (x, y, z) at (x * resolution + y) * resolution + z.
    std::vector<std::array<float, 2>> extract_volume_tsdf() const {
        return copy_out<std::array<float, 2>>(&o3d_tsdf_volume_extract_volume_tsdf);
    }
    /// @brief A uniform volume's RGB in [0, 1] per voxel, in the same order.
    std::vector<std::array<float, 3>> extract_volume_color() const {
        return copy_out<std::array<float, 3>>(&o3d_tsdf_volume_extract_volume_color);
    }
};

}  // namespace o3dpp
