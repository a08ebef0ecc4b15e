// SPDX-License-Identifier: MIT
#include "o3d/integration/voxel_block.h"

#include <algorithm>

namespace o3d::integration::detail {
namespace {
constexpr int kKeyBits = 21;
constexpr int kKeyLimit = 1 << (kKeyBits - 1);
}  // namespace

BlockMap::BlockMap(int side, double voxel_length, const Eigen::Vector3d& origin, bool with_color)
    : side_(side), voxel_length_(voxel_length), origin_(origin), with_color_(with_color) {}

bool BlockMap::key_in_range(const Eigen::Vector3i& key) {
    return (key.array() >= -kKeyLimit).all() && (key.array() < kKeyLimit).all();
}

uint64_t BlockMap::pack(const Eigen::Vector3i& key) {
    const uint64_t mask = (uint64_t(1) << kKeyBits) - 1;
    return ((uint64_t(uint32_t(key.x())) & mask) << (2 * kKeyBits)) |
           ((uint64_t(uint32_t(key.y())) & mask) << kKeyBits) | (uint64_t(uint32_t(key.z())) & mask);
}

const VoxelBlock* BlockMap::find(const Eigen::Vector3i& key) const {
    if (!key_in_range(key)) return nullptr;
    const auto it = blocks_.find(pack(key));
    return it == blocks_.end() ? nullptr : it->second.get();
}

VoxelBlock* BlockMap::find(const Eigen::Vector3i& key) {
    return const_cast<VoxelBlock*>(static_cast<const BlockMap*>(this)->find(key));
}

VoxelBlock& BlockMap::find_or_create(const Eigen::Vector3i& key) {
    std::unique_ptr<VoxelBlock>& slot = blocks_[pack(key)];
    if (!slot) {
        slot = std::make_unique<VoxelBlock>();
        slot->key = key;
        slot->tsdf.assign(voxels_per_block(), 0.0f);
        slot->weight.assign(voxels_per_block(), 0.0f);
        if (with_color_) slot->color.assign(voxels_per_block(), Eigen::Vector3f::Zero());
    }
    return *slot;
}

std::vector<const VoxelBlock*> BlockMap::sorted_blocks() const {
    std::vector<const VoxelBlock*> out;
    out.reserve(blocks_.size());
    for (const auto& entry : blocks_) out.push_back(entry.second.get());
    std::sort(out.begin(), out.end(), [](const VoxelBlock* a, const VoxelBlock* b) {
        return grid_less(a->key, b->key);
    });
    return out;
}

}  // namespace o3d::integration::detail
