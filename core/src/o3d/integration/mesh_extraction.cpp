// SPDX-License-Identifier: MIT
// TSDFVolume::extract_triangle_mesh: marching cubes block by block, the blocks in parallel, merged in key order.
//
// Each crossed edge gets one vertex, shared by the up-to-four cubes around it. An edge whose cubes all lie in
// one block is found again through two x slices of that block (the cubes at x and x + 1 are the only ones to
// ask); an edge on a block face may be shared with a neighbouring block: the block lists it by its global key,
// and the merge, walking the blocks in key order, gives it the vertex of the first block that made it. So the
// mesh is the one a serial walk in key order builds, whatever the thread count.
#include <array>
#include <cmath>
#include <unordered_map>

#include "o3d/io/file_bytes.h"  // prefault
#include "o3d/utility/parallel.h"

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

/// One block's share of the mesh: its vertices, its triangles over them, and which of them lie on block-face
/// edges (by global edge key), for the merge.
struct BlockMesh {
    geometry::TriangleMesh mesh;
    std::vector<std::pair<EdgeKey, int>> shared;
};

class MeshBuilder {
public:
    explicit MeshBuilder(const detail::BlockMap& map)
        : map_(map), side_(map.side()), with_color_(map.with_color()) {
        for (std::vector<int>& slice : slices_) slice.resize(size_t(side_) * size_t(side_) * 3);
        for (int c = 0; c < 8; ++c)
            offset_[size_t(c)] = (size_t(c & 1) * size_t(side_) + size_t((c >> 1) & 1)) * size_t(side_) + size_t((c >> 2) & 1);
    }

    void build(const detail::VoxelBlock& block, BlockMesh& out) {
        mesh_ = &out.mesh;
        shared_.clear();
        add_block(block);
        out.shared.assign(shared_.begin(), shared_.end());
    }

private:
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
                        mesh_->triangles.push_back(triangle);
                    }
                }
            }
        }
    }

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
        *slot = int(mesh_->vertices.size());
        mesh_->vertices.push_back(map_.origin() + map_.voxel_length() * position);
        if (with_color_) {
            const Eigen::Vector3f color = (f1 * *corner[size_t(c0)].color + f0 * *corner[size_t(c1)].color) / (f0 + f1);
            mesh_->vertex_colors.push_back(color.cast<double>());
        }
        return *slot;
    }

    const detail::BlockMap& map_;
    geometry::TriangleMesh* mesh_ = nullptr;
    int side_;
    bool with_color_;
    Eigen::Vector3i base_;
    std::array<std::vector<int>, 2> slices_;
    std::array<size_t, 8> offset_{};  // index step from a cube's first voxel to each corner, inside a block
    std::unordered_map<EdgeKey, int, EdgeKeyHash> shared_;  // this block's face edges -> its vertex
};

/// Append `part` to `mesh`: its face-edge vertices another block made already become that block's vertex.
void merge(const BlockMesh& part, bool with_color, std::unordered_map<EdgeKey, int, EdgeKeyHash>& face_vertices,
           std::vector<int>& local_to_global, geometry::TriangleMesh& mesh) {
    local_to_global.assign(part.mesh.vertices.size(), -1);
    for (const auto& [key, local] : part.shared) {
        const auto found = face_vertices.find(key);
        if (found != face_vertices.end()) local_to_global[size_t(local)] = found->second;
    }
    for (size_t i = 0; i < local_to_global.size(); ++i) {
        if (local_to_global[i] >= 0) continue;
        local_to_global[i] = int(mesh.vertices.size());
        mesh.vertices.push_back(part.mesh.vertices[i]);
        if (with_color) mesh.vertex_colors.push_back(part.mesh.vertex_colors[i]);
    }
    for (const auto& [key, local] : part.shared) face_vertices.try_emplace(key, local_to_global[size_t(local)]);
    for (const Eigen::Vector3i& t : part.mesh.triangles)
        mesh.triangles.emplace_back(local_to_global[size_t(t(0))], local_to_global[size_t(t(1))],
                                    local_to_global[size_t(t(2))]);
}

}  // namespace

geometry::TriangleMesh detail::marching_cubes(const BlockMap& map) {
    const std::vector<const VoxelBlock*> blocks = map.sorted_blocks();
    std::vector<BlockMesh> parts(blocks.size());
    const int threads = utility::resolve_num_threads(0);
#pragma omp parallel num_threads(threads) if (threads > 1 && blocks.size() > 1)
    {
        MeshBuilder builder(map);
#pragma omp for schedule(dynamic, 16)
        for (int64_t i = 0; i < int64_t(blocks.size()); ++i) builder.build(*blocks[size_t(i)], parts[size_t(i)]);
    }
    geometry::TriangleMesh mesh;
    size_t vertices = 0, triangles = 0;
    for (const BlockMesh& part : parts) vertices += part.mesh.vertices.size(), triangles += part.mesh.triangles.size();
    // Map the output's pages in one call each rather than a fault per 4 KiB page as the merge first writes them.
    mesh.vertices.reserve(vertices);
    io::detail::prefault(mesh.vertices.data(), vertices * sizeof(Eigen::Vector3d));
    if (map.with_color()) {
        mesh.vertex_colors.reserve(vertices);
        io::detail::prefault(mesh.vertex_colors.data(), vertices * sizeof(Eigen::Vector3d));
    }
    mesh.triangles.reserve(triangles);
    io::detail::prefault(mesh.triangles.data(), triangles * sizeof(Eigen::Vector3i));
    size_t shared = 0;
    for (const BlockMesh& part : parts) shared += part.shared.size();
    std::unordered_map<EdgeKey, int, EdgeKeyHash> face_vertices;
    face_vertices.reserve(shared);
    std::vector<int> local_to_global;
    for (BlockMesh& part : parts) {
        merge(part, map.with_color(), face_vertices, local_to_global, mesh);
        part = BlockMesh();  // free as we go: the parts together are as large as the mesh
    }
    return mesh;
}

geometry::TriangleMesh TSDFVolume::extract_triangle_mesh() const { return detail::marching_cubes(blocks_); }

}  // namespace o3d::integration
