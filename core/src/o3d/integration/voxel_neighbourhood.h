// SPDX-License-Identifier: MIT
#pragma once
/// @file voxel_neighbourhood.h
/// @brief Reading voxels around one block, across its faces, without a hash lookup per voxel: the 27
/// blocks around it are looked up once.
#include <array>

#include "o3d/integration/voxel_block.h"

namespace o3d::integration::detail {

struct VoxelSample {
    float tsdf = 0;
    float weight = 0;
    const Eigen::Vector3f* color = nullptr;  ///< null when the volume keeps no colour
};

class VoxelNeighbourhood {
public:
    VoxelNeighbourhood(const BlockMap& map, const VoxelBlock& centre);

    /// @brief The voxel at (x, y, z) relative to the centre block's first voxel, each in [-side, 2 side);
    /// false when its block does not exist or it was never observed (weight 0).
    bool observed(int x, int y, int z, VoxelSample& out) const {
        const int side = side_;
        const int bx = x < 0 ? 0 : (x < side ? 1 : 2), by = y < 0 ? 0 : (y < side ? 1 : 2),
                  bz = z < 0 ? 0 : (z < side ? 1 : 2);
        const VoxelBlock* block = blocks_[size_t((bx * 3 + by) * 3 + bz)];
        if (!block) return false;
        const size_t i = (size_t(x + (1 - bx) * side) * size_t(side) + size_t(y + (1 - by) * side)) * size_t(side) +
                         size_t(z + (1 - bz) * side);
        out.weight = block->weight[i];
        if (!(out.weight > 0.0f)) return false;
        out.tsdf = block->tsdf[i];
        out.color = block->color.empty() ? nullptr : &block->color[i];
        return true;
    }
    const Eigen::Vector3i& key() const { return key_; }

private:
    int side_;
    Eigen::Vector3i key_;
    std::array<const VoxelBlock*, 27> blocks_{};
};

}  // namespace o3d::integration::detail
