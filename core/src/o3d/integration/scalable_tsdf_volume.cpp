// SPDX-License-Identifier: MIT
#include "o3d/integration/scalable_tsdf_volume.h"

#include <Eigen/LU>
#include <omp.h>
#include <algorithm>
#include <climits>
#include <cmath>
#include <cstdint>
#include <string>

#include "o3d/utility/error.h"
#include "o3d/utility/parallel.h"

namespace o3d::integration {
namespace {

int checked_unit_resolution(int resolution) {
    if (resolution < 2 || resolution > 256)
        throw InvalidArgument("ScalableTSDFVolume: volume_unit_resolution must be in [2, 256], got " +
                              std::to_string(resolution));
    return resolution;
}

}  // namespace

ScalableTSDFVolume::ScalableTSDFVolume(double voxel_length, double sdf_trunc, ColorType color_type,
                                       int volume_unit_resolution, int depth_sampling_stride)
    : TSDFVolume(voxel_length, sdf_trunc, color_type, checked_unit_resolution(volume_unit_resolution),
                 Eigen::Vector3d::Zero()),
      depth_sampling_stride_(depth_sampling_stride) {
    if (depth_sampling_stride < 1) throw InvalidArgument("ScalableTSDFVolume: depth_sampling_stride must be >= 1");
}

void ScalableTSDFVolume::integrate(const geometry::RGBDImage& image,
                                   const camera::PinholeCameraIntrinsic& intrinsic,
                                   const Eigen::Matrix4d& extrinsic) {
    check_frame(image, intrinsic, extrinsic);
    const Eigen::Matrix4d camera_to_world = extrinsic.inverse();
    if (!camera_to_world.allFinite()) throw InvalidArgument("integrate: the extrinsic is not invertible");
    const double unit_length = voxel_length_ * double(blocks_.side());
    const geometry::Image& depth = image.depth;
    // Rows of samples are shared out among threads, each gathering its own keys; the sorted union does not depend
    // on how they were shared.
    const int threads = utility::resolve_num_threads();
    std::vector<std::vector<Eigen::Vector3i>> gathered(static_cast<size_t>(threads));
#pragma omp parallel num_threads(threads)
    {
        std::vector<Eigen::Vector3i>& keys = gathered[size_t(omp_get_thread_num())];
        Eigen::Vector3i last_lo(1, 1, 1), last_hi(0, 0, 0);  // the previous sample's box, to skip repeats
        // Neighbouring samples (in the row above, too) mostly name the same blocks: a small direct-mapped table
        // of recent keys drops those repeats, so the sort below sees thousands of keys, not a hundred thousand.
        constexpr size_t kRecentSlots = 4096;
        std::vector<Eigen::Vector3i> recent(kRecentSlots, Eigen::Vector3i(INT32_MIN, INT32_MIN, INT32_MIN));
#pragma omp for schedule(static)
        for (int v = 0; v < depth.height; v += depth_sampling_stride_) {
            for (int u = 0; u < depth.width; u += depth_sampling_stride_) {
                const float d = *depth.pixel<float>(u, v);
                if (!(d > 0.0f) || !std::isfinite(d)) continue;
                const Eigen::Vector4d camera_point((u - intrinsic.cx) * d / intrinsic.fx,
                                                   (v - intrinsic.cy) * d / intrinsic.fy, d, 1.0);
                const Eigen::Vector3d p = (camera_to_world * camera_point).head<3>();
                const Eigen::Vector3d lo_f = ((p.array() - sdf_trunc_) / unit_length).floor();
                const Eigen::Vector3d hi_f = ((p.array() + sdf_trunc_) / unit_length).floor();
                if (!(lo_f.array().abs() < 1e6).all() || !(hi_f.array().abs() < 1e6).all()) continue;
                const Eigen::Vector3i lo = lo_f.cast<int>(), hi = hi_f.cast<int>();
                if (lo == last_lo && hi == last_hi) continue;
                last_lo = lo;
                last_hi = hi;
                for (int x = lo.x(); x <= hi.x(); ++x)
                    for (int y = lo.y(); y <= hi.y(); ++y)
                        for (int z = lo.z(); z <= hi.z(); ++z) {
                            const Eigen::Vector3i key(x, y, z);
                            const size_t slot = (uint32_t(x) * 73856093u ^ uint32_t(y) * 19349663u ^
                                                 uint32_t(z) * 83492791u) % kRecentSlots;
                            if (recent[slot] == key) continue;
                            recent[slot] = key;
                            if (detail::BlockMap::key_in_range(key)) keys.push_back(key);
                        }
            }
        }
    }
    std::vector<Eigen::Vector3i> keys;
    for (const std::vector<Eigen::Vector3i>& part : gathered) keys.insert(keys.end(), part.begin(), part.end());
    std::sort(keys.begin(), keys.end(), detail::grid_less);
    keys.erase(std::unique(keys.begin(), keys.end()), keys.end());
    integrate_into(image, intrinsic, extrinsic, keys);
}

}  // namespace o3d::integration
