// SPDX-License-Identifier: MIT
#include "o3d/integration/voxel_neighbourhood.h"

namespace o3d::integration::detail {

VoxelNeighbourhood::VoxelNeighbourhood(const BlockMap& map, const VoxelBlock& centre)
    : side_(map.side()), key_(centre.key) {
    for (int dx = -1; dx <= 1; ++dx)
        for (int dy = -1; dy <= 1; ++dy)
            for (int dz = -1; dz <= 1; ++dz)
                blocks_[size_t(((dx + 1) * 3 + dy + 1) * 3 + dz + 1)] =
                    (dx | dy | dz) == 0 ? &centre : map.find(centre.key + Eigen::Vector3i(dx, dy, dz));
}

}  // namespace o3d::integration::detail
