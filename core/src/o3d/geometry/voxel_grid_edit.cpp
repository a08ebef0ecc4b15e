// SPDX-License-Identifier: MIT
#include "o3d/geometry/voxel_grid_edit.h"

#include <algorithm>
#include <cmath>
#include <string>

#include "o3d/utility/error.h"

namespace o3d::geometry {

namespace {

std::vector<Voxel>::const_iterator lower_bound_of(const std::vector<Voxel>& voxels, const Eigen::Vector3i& index) {
    return std::lower_bound(voxels.begin(), voxels.end(), index,
                            [](const Voxel& v, const Eigen::Vector3i& i) { return voxel_index_less(v.grid_index, i); });
}

/// Voxels along one axis: round(extent / voxel_size), checked to be a count before it is converted.
int64_t cells_along(double extent, double voxel_size, const char* name) {
    if (!std::isfinite(extent) || extent < 0.0)
        throw o3d::InvalidArgument(std::string(name) + " must be finite and >= 0 (got " + std::to_string(extent) +
                                   ")");
    const double n = std::round(extent / voxel_size);
    if (!(n <= static_cast<double>(kMaxDenseVoxels)))
        throw o3d::InvalidArgument(std::string(name) + " / voxel_size is too large for a dense grid");
    return static_cast<int64_t>(n);
}

}  // namespace

bool voxel_index_less(const Eigen::Vector3i& a, const Eigen::Vector3i& b) {
    if (a(0) != b(0)) return a(0) < b(0);
    if (a(1) != b(1)) return a(1) < b(1);
    return a(2) < b(2);
}

VoxelGrid voxel_grid_create_dense(const Eigen::Vector3d& origin, const Eigen::Vector3d& color, double voxel_size,
                                  double width, double height, double depth) {
    if (!(voxel_size > 0.0) || !std::isfinite(voxel_size))
        throw o3d::InvalidArgument("voxel_size must be finite and > 0 (got " + std::to_string(voxel_size) + ")");
    if (!origin.allFinite()) throw o3d::InvalidArgument("the dense grid's origin is not finite");
    if (!color.allFinite()) throw o3d::InvalidArgument("the dense grid's color is not finite");
    const int64_t nx = cells_along(width, voxel_size, "width");
    const int64_t ny = cells_along(height, voxel_size, "height");
    const int64_t nz = cells_along(depth, voxel_size, "depth");
    // Each factor is <= 2^31, so the product of the first two fits int64; test the third by division.
    const int64_t nxy = nx * ny;
    if (nxy > kMaxDenseVoxels || (nz > 0 && nxy > kMaxDenseVoxels / nz))
        throw o3d::InvalidArgument("the dense grid would have more than " + std::to_string(kMaxDenseVoxels) +
                                   " voxels (" + std::to_string(nx) + " x " + std::to_string(ny) + " x " +
                                   std::to_string(nz) + ")");
    VoxelGrid grid;
    grid.voxel_size = voxel_size;
    grid.origin = origin;
    grid.voxels.reserve(static_cast<size_t>(nxy * nz));
    // x outermost, z innermost: already the sorted order.
    for (int64_t i = 0; i < nx; ++i)
        for (int64_t j = 0; j < ny; ++j)
            for (int64_t k = 0; k < nz; ++k)
                grid.voxels.push_back({Eigen::Vector3i(int(i), int(j), int(k)), color});
    return grid;
}

void add_voxel(VoxelGrid& grid, const Voxel& voxel) {
    if (!voxel.color.allFinite()) throw o3d::InvalidArgument("the voxel's color is not finite");
    const auto at = lower_bound_of(grid.voxels, voxel.grid_index);
    const auto pos = grid.voxels.begin() + (at - grid.voxels.cbegin());
    if (pos != grid.voxels.end() && pos->grid_index == voxel.grid_index)
        pos->color = voxel.color;
    else
        grid.voxels.insert(pos, voxel);
}

void remove_voxel(VoxelGrid& grid, const Eigen::Vector3i& index) {
    const auto at = lower_bound_of(grid.voxels, index);
    if (at != grid.voxels.cend() && at->grid_index == index) grid.voxels.erase(at);
}

const Voxel* find_voxel(const VoxelGrid& grid, const Eigen::Vector3i& index) {
    const auto at = lower_bound_of(grid.voxels, index);
    return at != grid.voxels.cend() && at->grid_index == index ? &*at : nullptr;
}

Eigen::Vector3d voxel_center_coordinate(const VoxelGrid& grid, const Eigen::Vector3i& index) {
    return grid.origin + (index.cast<double>().array() + 0.5).matrix() * grid.voxel_size;
}

std::array<Eigen::Vector3d, 8> voxel_bounding_points(const VoxelGrid& grid, const Eigen::Vector3i& index) {
    const Eigen::Vector3d centre = voxel_center_coordinate(grid, index);
    const double r = grid.voxel_size / 2.0;
    std::array<Eigen::Vector3d, 8> corners;
    for (int k = 0; k < 8; ++k) {
        const Eigen::Vector3d sign((k & 2) ? 1.0 : -1.0, (k & 4) ? 1.0 : -1.0, (k & 1) ? 1.0 : -1.0);
        corners[k] = centre + r * sign;
    }
    return corners;
}

}  // namespace o3d::geometry
