// SPDX-License-Identifier: MIT
#pragma once
/// @file voxel_block.h
/// @brief A cube of side x side x side TSDF voxels, and the hash map of them that both volumes store.
///
/// The uniform volume is one block as large as the volume; the scalable volume is a map of small blocks
/// (Open3D's "volume units") created where a frame observes a surface, so memory follows the surface.
/// Voxel (x, y, z) of a block is at index (x * side + y) * side + z, Open3D's order. Its centre is
/// origin + voxel_length * (side * key + (x, y, z) + 0.5).
#include <Eigen/Core>
#include <cstdint>
#include <memory>
#include <unordered_map>
#include <vector>

namespace o3d::integration::detail {

/// @brief Grid order of block keys and voxel indices: x, then y, then z.
inline bool grid_less(const Eigen::Vector3i& a, const Eigen::Vector3i& b) {
    return a.x() != b.x() ? a.x() < b.x() : a.y() != b.y() ? a.y() < b.y() : a.z() < b.z();
}

struct VoxelBlock {
    Eigen::Vector3i key;
    std::vector<float> tsdf;              ///< in [-1, 1]: signed distance / sdf_trunc
    std::vector<float> weight;            ///< frames integrated; 0: never observed
    std::vector<Eigen::Vector3f> color;   ///< RGB in [0, 1]; empty when the volume keeps no colour
};

class BlockMap {
public:
    BlockMap(int side, double voxel_length, const Eigen::Vector3d& origin, bool with_color);

    int side() const { return side_; }
    double voxel_length() const { return voxel_length_; }
    const Eigen::Vector3d& origin() const { return origin_; }
    bool with_color() const { return with_color_; }
    size_t size() const { return blocks_.size(); }
    size_t voxels_per_block() const { return size_t(side_) * size_t(side_) * size_t(side_); }

    /// @brief Whether a key fits the map's 21 bits a coordinate (about a million blocks each way).
    static bool key_in_range(const Eigen::Vector3i& key);
    const VoxelBlock* find(const Eigen::Vector3i& key) const;
    VoxelBlock* find(const Eigen::Vector3i& key);
    /// @brief The block at `key`, created unobserved (tsdf 0, weight 0) when absent; the key must be in range.
    VoxelBlock& find_or_create(const Eigen::Vector3i& key);
    /// @brief Every block, ordered by key (x, then y, then z): extraction walks them in this order, so its
    /// output does not depend on the hash map's.
    std::vector<const VoxelBlock*> sorted_blocks() const;
    void clear() { blocks_.clear(); }

private:
    static uint64_t pack(const Eigen::Vector3i& key);
    int side_;
    double voxel_length_;
    Eigen::Vector3d origin_;
    bool with_color_;
    std::unordered_map<uint64_t, std::unique_ptr<VoxelBlock>> blocks_;
};

}  // namespace o3d::integration::detail
