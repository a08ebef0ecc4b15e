// SPDX-License-Identifier: MIT
#include "o3d/geometry/voxel_grid_mesh_bounds.h"

#include <algorithm>
#include <climits>
#include <cmath>
#include <omp.h>
#include <string>

#include "o3d/geometry/triangle_mesh_basics.h"
#include "o3d/geometry/voxel_grid_edit.h"
#include "o3d/geometry/voxel_grid_ops.h"
#include "o3d/utility/error.h"
#include "o3d/utility/parallel.h"

namespace o3d::geometry {

VoxelGrid voxel_grid_from_triangle_mesh_within_bounds(const TriangleMesh& mesh, double voxel_size,
                                                      const Eigen::Vector3d& min_bound,
                                                      const Eigen::Vector3d& max_bound, int num_threads) {
    if (!(voxel_size > 0.0) || !std::isfinite(voxel_size))
        throw o3d::InvalidArgument("voxel_size must be finite and > 0 (got " + std::to_string(voxel_size) + ")");
    if (!mesh.has_vertices()) throw o3d::InvalidArgument("the mesh has no vertices");
    validate_triangles(mesh);
    for (size_t i = 0; i < mesh.vertices.size(); ++i)
        if (!mesh.vertices[i].allFinite())
            throw o3d::InvalidArgument("vertex " + std::to_string(i) + " is not finite");
    if (!min_bound.allFinite() || !max_bound.allFinite()) throw o3d::InvalidArgument("bounds must be finite");
    if ((min_bound.array() > max_bound.array()).any()) throw o3d::InvalidArgument("min_bound exceeds max_bound");
    // The last cell along each axis; the grid must have int32 indices with a margin.
    const Eigen::Vector3d last_cell = ((max_bound - min_bound) / voxel_size).array().floor();
    if (!(last_cell.maxCoeff() < static_cast<double>(INT_MAX) - 2.0))
        throw o3d::InvalidArgument("voxel_size " + std::to_string(voxel_size) +
                                   " is too small for the bounds: grid indices would overflow int32");

    VoxelGrid grid;
    grid.voxel_size = voxel_size;
    grid.origin = min_bound;
    const Eigen::Vector3d half = Eigen::Vector3d::Constant(voxel_size / 2.0);
    const int64_t num_triangles = static_cast<int64_t>(mesh.triangles.size());
    const int threads = num_triangles > 2048 ? o3d::utility::resolve_num_threads(num_threads) : 1;
    // Each thread collects its hits; the merged list is sorted and deduplicated, so the result does not
    // depend on the thread count. Nothing in the loop throws.
    std::vector<std::vector<Eigen::Vector3i>> hits(threads);
#pragma omp parallel for num_threads(threads) schedule(static)
    for (int64_t t = 0; t < num_triangles; ++t) {
        std::vector<Eigen::Vector3i>& mine = hits[omp_get_thread_num()];
        const Eigen::Vector3i& tri = mesh.triangles[t];
        const Eigen::Vector3d& a = mesh.vertices[tri(0)];
        const Eigen::Vector3d& b = mesh.vertices[tri(1)];
        const Eigen::Vector3d& c = mesh.vertices[tri(2)];
        // Candidate cells as Open3D: from the floor of the bounding box's min corner, round(extent /
        // voxel_size) + 2 cells along each axis (past the max corner, so a vertex exactly on a cell face
        // reaches the cell beyond). In double first: a vertex far outside the bounds may be beyond int32.
        const Eigen::Vector3d tmin = a.cwiseMin(b).cwiseMin(c), tmax = a.cwiseMax(b).cwiseMax(c);
        const Eigen::Array3d lo_cell = ((tmin - min_bound) / voxel_size).array().floor();
        const Eigen::Array3d hi_cell = lo_cell + ((tmax - tmin) / voxel_size).array().round() + 1.0;
        const Eigen::Array3d lo_clip = lo_cell.max(0.0), hi_clip = hi_cell.min(last_cell.array());
        if ((lo_clip > hi_clip).any()) continue;
        const Eigen::Vector3i lo = lo_clip.cast<int>(), hi = hi_clip.cast<int>();
        for (int i = lo(0); i <= hi(0); ++i)
            for (int j = lo(1); j <= hi(1); ++j)
                for (int k = lo(2); k <= hi(2); ++k) {
                    const Eigen::Vector3d centre = min_bound + half + Eigen::Vector3d(i, j, k) * voxel_size;
                    if (triangle_box_overlap(centre, half, a, b, c)) mine.emplace_back(i, j, k);
                }
    }
    std::vector<Eigen::Vector3i> all;
    for (const auto& h : hits) all.insert(all.end(), h.begin(), h.end());
    std::sort(all.begin(), all.end(), voxel_index_less);
    all.erase(std::unique(all.begin(), all.end()), all.end());
    grid.voxels.reserve(all.size());
    for (const Eigen::Vector3i& h : all) grid.voxels.push_back({h, Eigen::Vector3d::Zero()});
    return grid;
}

}  // namespace o3d::geometry
