// SPDX-License-Identifier: MIT
// TSDFVolume::extract_voxel_point_cloud / extract_voxel_grid: Open3D's debug views of the voxels near the
// surface (observed, |tsdf| < 0.98), grey by (tsdf + 1) / 2.
#include <algorithm>

#include "o3d/integration/tsdf_volume.h"

namespace o3d::integration {
namespace {

constexpr float kUntruncated = 0.98f;

/// Every shown voxel's global grid index and grey, in grid order (x, then y, then z).
std::vector<geometry::Voxel> shown_voxels(const detail::BlockMap& map) {
    std::vector<geometry::Voxel> voxels;
    const int side = map.side();
    for (const detail::VoxelBlock* block : map.sorted_blocks()) {
        size_t i = 0;
        for (int x = 0; x < side; ++x)
            for (int y = 0; y < side; ++y)
                for (int z = 0; z < side; ++z, ++i) {
                    const float f = block->tsdf[i];
                    if (block->weight[i] == 0.0f || !(f < kUntruncated && f >= -kUntruncated)) continue;
                    voxels.push_back({block->key * side + Eigen::Vector3i(x, y, z),
                                      Eigen::Vector3d::Constant((double(f) + 1.0) * 0.5)});
                }
    }
    if (map.size() > 1)  // blocks interleave in grid order
        std::sort(voxels.begin(), voxels.end(), [](const geometry::Voxel& a, const geometry::Voxel& b) {
            return detail::grid_less(a.grid_index, b.grid_index);
        });
    return voxels;
}

}  // namespace

geometry::PointCloud TSDFVolume::extract_voxel_point_cloud() const {
    geometry::PointCloud cloud;
    for (const geometry::Voxel& v : shown_voxels(blocks_)) {
        cloud.points.push_back(blocks_.origin() +
                               voxel_length_ * (v.grid_index.cast<double>() + Eigen::Vector3d::Constant(0.5)));
        cloud.colors.push_back(v.color);
    }
    return cloud;
}

geometry::VoxelGrid TSDFVolume::extract_voxel_grid() const {
    geometry::VoxelGrid grid;
    grid.voxel_size = voxel_length_;
    grid.origin = blocks_.origin();
    grid.voxels = shown_voxels(blocks_);
    return grid;
}

}  // namespace o3d::integration
