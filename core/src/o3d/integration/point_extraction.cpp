// SPDX-License-Identifier: MIT
// TSDFVolume::extract_point_cloud: a point where the tsdf changes sign between two neighbouring voxels along
// an axis, both observed and neither truncated (|tsdf| < 0.98, Open3D's bound), placed at the linear zero.
#include <cmath>

#include "o3d/integration/surface_extraction.h"
#include "o3d/integration/tsdf_volume.h"
#include "o3d/integration/voxel_neighbourhood.h"
#include "o3d/utility/parallel.h"

namespace o3d::integration {
namespace {

using detail::VoxelSample;

constexpr float kUntruncated = 0.98f;

bool usable(const detail::VoxelNeighbourhood& around, int x, int y, int z, VoxelSample& s) {
    return around.observed(x, y, z, s) && s.tsdf < kUntruncated && s.tsdf >= -kUntruncated;
}

/// Central differences of the tsdf at a voxel; one-sided where a neighbour is unobserved.
Eigen::Vector3d gradient_at(const detail::VoxelNeighbourhood& around, const Eigen::Vector3i& v, float centre) {
    Eigen::Vector3d g;
    for (int axis = 0; axis < 3; ++axis) {
        Eigen::Vector3i lo = v, hi = v;
        lo(axis) -= 1;
        hi(axis) += 1;
        VoxelSample a, b;
        const float f_lo = around.observed(lo.x(), lo.y(), lo.z(), a) ? a.tsdf : centre;
        const float f_hi = around.observed(hi.x(), hi.y(), hi.z(), b) ? b.tsdf : centre;
        g(axis) = double(f_hi) - double(f_lo);
    }
    return g;
}

void crossings_of_block(const detail::BlockMap& map, const detail::VoxelBlock& block, geometry::PointCloud& out) {
    const detail::VoxelNeighbourhood around(map, block);
    const int side = map.side();
    const Eigen::Vector3i base = block.key * side;
    for (int x = 0; x < side; ++x) {
        for (int y = 0; y < side; ++y) {
            for (int z = 0; z < side; ++z) {
                VoxelSample s0;
                if (!usable(around, x, y, z, s0)) continue;
                const Eigen::Vector3i v0(x, y, z);
                for (int axis = 0; axis < 3; ++axis) {
                    Eigen::Vector3i v1 = v0;
                    v1(axis) += 1;
                    VoxelSample s1;
                    if (!usable(around, v1.x(), v1.y(), v1.z(), s1) || !(s0.tsdf * s1.tsdf < 0)) continue;
                    const double r0 = std::fabs(s0.tsdf), r1 = std::fabs(s1.tsdf);
                    const double t = r0 / (r0 + r1);
                    Eigen::Vector3d position = (base + v0).cast<double>() + Eigen::Vector3d::Constant(0.5);
                    position(axis) += t;
                    out.points.push_back(map.origin() + map.voxel_length() * position);
                    const Eigen::Vector3d normal =
                        (1.0 - t) * gradient_at(around, v0, s0.tsdf) + t * gradient_at(around, v1, s1.tsdf);
                    out.normals.push_back(normal.normalized());
                    if (s0.color)
                        out.colors.push_back(((r1 * s0.color->cast<double>() + r0 * s1.color->cast<double>()) /
                                              (r0 + r1)));
                }
            }
        }
    }
}

}  // namespace

geometry::PointCloud detail::zero_crossings(const BlockMap& map) {
    const std::vector<const VoxelBlock*> blocks = map.sorted_blocks();
    std::vector<geometry::PointCloud> parts(blocks.size());
    const int threads = utility::resolve_num_threads();
#pragma omp parallel for schedule(dynamic, 4) num_threads(threads)
    for (long i = 0; i < long(blocks.size()); ++i) crossings_of_block(map, *blocks[size_t(i)], parts[size_t(i)]);
    geometry::PointCloud cloud;
    for (const geometry::PointCloud& part : parts) {
        cloud.points.insert(cloud.points.end(), part.points.begin(), part.points.end());
        cloud.normals.insert(cloud.normals.end(), part.normals.begin(), part.normals.end());
        cloud.colors.insert(cloud.colors.end(), part.colors.begin(), part.colors.end());
    }
    return cloud;
}

geometry::PointCloud TSDFVolume::extract_point_cloud() const { return detail::zero_crossings(blocks_); }

}  // namespace o3d::integration
