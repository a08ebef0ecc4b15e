// SPDX-License-Identifier: MIT
// TSDFVolume::extract_triangle_mesh: marching cubes block by block, in key order.
//
// Each crossed edge gets one vertex, shared by the up-to-four cubes around it. An edge whose cubes all lie in
// one block is found again through two x slices of that block (the cubes at x and x + 1 are the only ones to
// ask); an edge on a block face is shared with a neighbouring block and goes through a hash map. Most edges are
// of the first kind, so the map stays small.
#include <array>
#include <cmath>
#include <unordered_map>

#include "o3d/integration/marching_cubes_cases.h"
#include "o3d/integration/surface_extraction.h"
#include "o3d/integration/tsdf_volume.h"
#include "o3d/integration/voxel_neighbourhood.h"

namespace o3d::integration {
namespace {

using detail::VoxelSample;

struct EdgeKey {
    Eigen::Vector3i voxel;  // global voxel index of the edge's lower end
    int axis;
    bool operator==(const EdgeKey& o) const { return voxel == o.voxel && axis == o.axis; }
};

struct EdgeKeyHash {
    size_t operator()(const EdgeKey& k) const {
        uint64_t h = uint64_t(uint32_t(k.voxel.x())) * 0x9E3779B97F4A7C15ull;
        h ^= uint64_t(uint32_t(k.voxel.y())) * 0xC2B2AE3D27D4EB4Full + (h << 6) + (h >> 2);
        h ^= uint64_t(uint32_t(k.voxel.z())) * 0x165667B19E3779F9ull + (h << 6) + (h >> 2);
        return size_t(h ^ uint64_t(k.axis));
    }
};

class MeshBuilder {
public:
    MeshBuilder(const detail::BlockMap& map, geometry::TriangleMesh& mesh)
        : map_(map), mesh_(mesh), side_(map.side()), with_color_(map.with_color()) {
        for (std::vector<int>& slice : slices_) slice.resize(size_t(side_) * size_t(side_) * 3);
        for (int c = 0; c < 8; ++c)
            offset_[size_t(c)] = (size_t(c & 1) * size_t(side_) + size_t((c >> 1) & 1)) * size_t(side_) + size_t((c >> 2) & 1);
    }

    void add_block(const detail::VoxelBlock& block) {
        const detail::VoxelNeighbourhood around(map_, block);
        const std::array<detail::CubeCase, 256>& cases = detail::cube_cases();
        base_ = block.key * side_;
        std::array<VoxelSample, 8> corner;  // (outside the loops: clearing it per cube cost a quarter of the time)
        std::fill(slices_[0].begin(), slices_[0].end(), -1);
        for (int x = 0; x < side_; ++x) {
            // The slice for x + 1 last held x - 1's edges, which no cube from here on asks for.
            std::fill(slices_[size_t((x + 1) & 1)].begin(), slices_[size_t((x + 1) & 1)].end(), -1);
            for (int y = 0; y < side_; ++y) {
                for (int z = 0; z < side_; ++z) {
                    int pattern = 0;
                    bool observed = true;
                    if (x + 1 < side_ && y + 1 < side_ && z + 1 < side_) {
                        // Inside the block (most cubes): read the arrays directly, signs first, since most cubes
                        // lie on one side of the surface and need nothing more.
                        const size_t i = (size_t(x) * size_t(side_) + size_t(y)) * size_t(side_) + size_t(z);
                        for (int c = 0; c < 8; ++c)
                            if (block.tsdf[i + offset_[size_t(c)]] < 0) pattern |= 1 << c;
                        if (pattern == 0 || pattern == 255) continue;
                        for (int c = 0; c < 8 && observed; ++c) {
                            const size_t j = i + offset_[size_t(c)];
                            observed = block.weight[j] > 0.0f;
                            corner[size_t(c)] = {block.tsdf[j], block.weight[j],
                                                 block.color.empty() ? nullptr : &block.color[j]};
                        }
                    } else {
                        for (int c = 0; c < 8 && observed; ++c) {
                            observed = around.observed(x + (c & 1), y + ((c >> 1) & 1), z + ((c >> 2) & 1),
                                                       corner[size_t(c)]);
                            if (corner[size_t(c)].tsdf < 0) pattern |= 1 << c;
                        }
                    }
                    if (!observed || pattern == 0 || pattern == 255) continue;
                    const detail::CubeCase& cube = cases[size_t(pattern)];
                    std::array<int, 12> vertex;
                    vertex.fill(-1);
                    for (int t = 0; t < cube.num_triangles; ++t) {
                        Eigen::Vector3i triangle;
                        for (int k = 0; k < 3; ++k) {
                            const int e = cube.edges[size_t(3 * t + k)];
                            if (vertex[size_t(e)] < 0) vertex[size_t(e)] = vertex_on(x, y, z, e, corner);
                            triangle(k) = vertex[size_t(e)];
                        }
                        mesh_.triangles.push_back(triangle);
                    }
                }
            }
        }
    }

private:
    int vertex_on(int x, int y, int z, int edge, const std::array<VoxelSample, 8>& corner) {
        const int c0 = detail::edge_corner(edge), axis = detail::edge_axis(edge), c1 = c0 | (1 << axis);
        const Eigen::Vector3i v(x + (c0 & 1), y + ((c0 >> 1) & 1), z + ((c0 >> 2) & 1));
        bool inside_block = true;  // all four cubes around the edge are in this block
        for (int b = 0; b < 3; ++b)
            if (b != axis && (v(b) < 1 || v(b) >= side_)) inside_block = false;
        int* slot = nullptr;
        if (inside_block) {
            slot = &slices_[size_t(v.x() & 1)][(size_t(v.y()) * size_t(side_) + size_t(v.z())) * 3 + size_t(axis)];
        } else {
            slot = &shared_.try_emplace(EdgeKey{base_ + v, axis}, -1).first->second;
        }
        if (*slot >= 0) return *slot;
        const float f0 = std::fabs(corner[size_t(c0)].tsdf), f1 = std::fabs(corner[size_t(c1)].tsdf);
        const double t = double(f0) / double(f0 + f1);
        Eigen::Vector3d position = (base_ + v).cast<double>() + Eigen::Vector3d::Constant(0.5);
        position(axis) += t;
        *slot = int(mesh_.vertices.size());
        mesh_.vertices.push_back(map_.origin() + map_.voxel_length() * position);
        if (with_color_) {
            const Eigen::Vector3f color = (f1 * *corner[size_t(c0)].color + f0 * *corner[size_t(c1)].color) / (f0 + f1);
            mesh_.vertex_colors.push_back(color.cast<double>());
        }
        return *slot;
    }

    const detail::BlockMap& map_;
    geometry::TriangleMesh& mesh_;
    int side_;
    bool with_color_;
    Eigen::Vector3i base_;
    std::array<std::vector<int>, 2> slices_;
    std::array<size_t, 8> offset_{};  // index step from a cube's first voxel to each corner, inside a block
    std::unordered_map<EdgeKey, int, EdgeKeyHash> shared_;
};

}  // namespace

geometry::TriangleMesh detail::marching_cubes(const BlockMap& map) {
    geometry::TriangleMesh mesh;
    MeshBuilder builder(map, mesh);
    for (const VoxelBlock* block : map.sorted_blocks()) builder.add_block(*block);
    return mesh;
}

geometry::TriangleMesh TSDFVolume::extract_triangle_mesh() const { return detail::marching_cubes(blocks_); }

}  // namespace o3d::integration
