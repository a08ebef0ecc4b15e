// SPDX-License-Identifier: MIT
#include "o3d/geometry/voxel_grid_ops.h"

#include <algorithm>
#include <climits>
#include <cmath>
#include <omp.h>
#include <string>
#include <utility>

#include "o3d/geometry/triangle_mesh_basics.h"
#include "o3d/utility/error.h"
#include "o3d/utility/parallel.h"

namespace o3d::geometry {

namespace {

bool index_less(const Eigen::Vector3i& a, const Eigen::Vector3i& b) {
    if (a(0) != b(0)) return a(0) < b(0);
    if (a(1) != b(1)) return a(1) < b(1);
    return a(2) < b(2);
}

void check_voxel_size(double voxel_size) {
    if (!(voxel_size > 0.0) || !std::isfinite(voxel_size))
        throw o3d::InvalidArgument("voxel_size must be finite and > 0 (got " + std::to_string(voxel_size) + ")");
}

void check_finite(const std::vector<Eigen::Vector3d>& points, const char* what) {
    for (size_t i = 0; i < points.size(); ++i)
        if (!points[i].allFinite())
            throw o3d::InvalidArgument(std::string(what) + " " + std::to_string(i) + " is not finite");
}

/// The grid's cells must have int32 indices: the box spanned (in voxels) must fit with a margin.
void check_grid_extent(const Eigen::Vector3d& min_bound, const Eigen::Vector3d& max_bound, double voxel_size) {
    if (!min_bound.allFinite() || !max_bound.allFinite())
        throw o3d::InvalidArgument("bounds must be finite");
    if ((min_bound.array() > max_bound.array()).any())
        throw o3d::InvalidArgument("min_bound exceeds max_bound");
    const double cells = ((max_bound - min_bound) / voxel_size).maxCoeff();
    if (!(cells < static_cast<double>(INT_MAX) - 2.0))
        throw o3d::InvalidArgument("voxel_size " + std::to_string(voxel_size) +
                                   " is too small for the extent: grid indices would overflow int32");
}

Eigen::Vector3i floor_index(const Eigen::Vector3d& p, const Eigen::Vector3d& origin, double voxel_size) {
    const Eigen::Vector3d cell = ((p - origin) / voxel_size).array().floor();
    return cell.cast<int>();
}

Eigen::Vector3d min_bound_of(const std::vector<Eigen::Vector3d>& pts) {
    Eigen::Vector3d m = pts[0];
    for (const Eigen::Vector3d& p : pts) m = m.cwiseMin(p);
    return m;
}

Eigen::Vector3d max_bound_of(const std::vector<Eigen::Vector3d>& pts) {
    Eigen::Vector3d m = pts[0];
    for (const Eigen::Vector3d& p : pts) m = m.cwiseMax(p);
    return m;
}

/// Sort (cell, point) pairs and fold each run into one voxel with the mean color of its points.
std::vector<Voxel> voxels_from_cells(std::vector<std::pair<Eigen::Vector3i, int>>& cells,
                                     const std::vector<Eigen::Vector3d>* colors) {
    std::stable_sort(cells.begin(), cells.end(),
                     [](const auto& a, const auto& b) { return index_less(a.first, b.first); });
    std::vector<Voxel> voxels;
    for (size_t i = 0; i < cells.size();) {
        size_t j = i;
        Eigen::Vector3d sum = Eigen::Vector3d::Zero();
        while (j < cells.size() && cells[j].first == cells[i].first) {
            if (colors) sum += (*colors)[cells[j].second];
            ++j;
        }
        voxels.push_back({cells[i].first, sum / static_cast<double>(j - i)});
        i = j;
    }
    return voxels;
}

}  // namespace

VoxelGrid voxel_grid_from_point_cloud_within_bounds(const PointCloud& cloud, double voxel_size,
                                                    const Eigen::Vector3d& min_bound,
                                                    const Eigen::Vector3d& max_bound) {
    check_voxel_size(voxel_size);
    if (!cloud.has_points()) throw o3d::InvalidArgument("the point cloud is empty");
    check_finite(cloud.points, "point");
    check_grid_extent(min_bound, max_bound, voxel_size);
    VoxelGrid grid;
    grid.voxel_size = voxel_size;
    grid.origin = min_bound;
    std::vector<std::pair<Eigen::Vector3i, int>> cells;
    cells.reserve(cloud.points.size());
    for (size_t i = 0; i < cloud.points.size(); ++i) {
        const Eigen::Vector3d& p = cloud.points[i];
        if ((p.array() < min_bound.array()).any() || (p.array() > max_bound.array()).any()) continue;
        cells.emplace_back(floor_index(p, min_bound, voxel_size), static_cast<int>(i));
    }
    grid.voxels = voxels_from_cells(cells, cloud.has_colors() ? &cloud.colors : nullptr);
    return grid;
}

VoxelGrid voxel_grid_from_point_cloud(const PointCloud& cloud, double voxel_size) {
    check_voxel_size(voxel_size);
    if (!cloud.has_points()) throw o3d::InvalidArgument("the point cloud is empty");
    check_finite(cloud.points, "point");
    const Eigen::Vector3d half = Eigen::Vector3d::Constant(voxel_size / 2.0);
    return voxel_grid_from_point_cloud_within_bounds(cloud, voxel_size, min_bound_of(cloud.points) - half,
                                                     max_bound_of(cloud.points) + half);
}

namespace {

/// A triangle prepared for many box tests against boxes of one half size: the 13 separating axes of
/// Akenine-Moller's test (9 edge x box-axis products, the 3 box axes, the normal), the triangle's extent
/// along each, and the box's radius along each (the same for every box of that size).
struct TriangleAxes {
    Eigen::Vector3d axis[13];
    double lo[13], hi[13], radius[13];

    TriangleAxes(const Eigen::Vector3d& a, const Eigen::Vector3d& b, const Eigen::Vector3d& c,
                 const Eigen::Vector3d& half_size) {
        const Eigen::Vector3d edges[3] = {b - a, c - b, a - c};
        int n = 0;
        for (const Eigen::Vector3d& e : edges)
            for (int k = 0; k < 3; ++k) axis[n++] = Eigen::Vector3d::Unit(k).cross(e);
        for (int k = 0; k < 3; ++k) axis[n++] = Eigen::Vector3d::Unit(k);
        axis[n] = edges[0].cross(edges[1]);
        for (int i = 0; i < 13; ++i) {
            const double pa = axis[i].dot(a), pb = axis[i].dot(b), pc = axis[i].dot(c);
            lo[i] = std::min({pa, pb, pc});
            hi[i] = std::max({pa, pb, pc});
            radius[i] = half_size.dot(axis[i].cwiseAbs());
        }
    }

    /// Touching counts as overlapping; a zero axis (degenerate edge or triangle) never separates.
    bool overlaps(const Eigen::Vector3d& center) const {
        for (int i = 0; i < 13; ++i) {
            const double pc = axis[i].dot(center);
            if (lo[i] - pc > radius[i] || hi[i] - pc < -radius[i]) return false;
        }
        return true;
    }
};

}  // namespace

bool triangle_box_overlap(const Eigen::Vector3d& center, const Eigen::Vector3d& half_size, const Eigen::Vector3d& a,
                          const Eigen::Vector3d& b, const Eigen::Vector3d& c) {
    // Work relative to the centre, where the projections are best conditioned.
    return TriangleAxes(a - center, b - center, c - center, half_size).overlaps(Eigen::Vector3d::Zero());
}

VoxelGrid voxel_grid_from_triangle_mesh(const TriangleMesh& mesh, double voxel_size) {
    check_voxel_size(voxel_size);
    if (!mesh.has_vertices()) throw o3d::InvalidArgument("the mesh has no vertices");
    validate_triangles(mesh);
    check_finite(mesh.vertices, "vertex");
    const Eigen::Vector3d half = Eigen::Vector3d::Constant(voxel_size / 2.0);
    const Eigen::Vector3d min_bound = min_bound_of(mesh.vertices) - half;
    const Eigen::Vector3d max_bound = max_bound_of(mesh.vertices) + half;
    check_grid_extent(min_bound, max_bound, voxel_size);

    VoxelGrid grid;
    grid.voxel_size = voxel_size;
    grid.origin = min_bound;
    // Each thread collects its hits; the merged list is sorted and deduplicated, so the result does not
    // depend on the thread count.
    const int threads = mesh.triangles.size() > 2048 ? o3d::utility::resolve_num_threads() : 1;
    std::vector<std::vector<Eigen::Vector3i>> hits(threads);
    const int64_t num_triangles = static_cast<int64_t>(mesh.triangles.size());
#pragma omp parallel for num_threads(threads) schedule(static)
    for (int64_t t = 0; t < num_triangles; ++t) {
        std::vector<Eigen::Vector3i>& mine = hits[omp_get_thread_num()];
        const Eigen::Vector3i& tri = mesh.triangles[t];
        const Eigen::Vector3d& a = mesh.vertices[tri(0)];
        const Eigen::Vector3d& b = mesh.vertices[tri(1)];
        const Eigen::Vector3d& c = mesh.vertices[tri(2)];
        const Eigen::Vector3i lo = floor_index(a.cwiseMin(b).cwiseMin(c), min_bound, voxel_size);
        const Eigen::Vector3i hi = floor_index(a.cwiseMax(b).cwiseMax(c), min_bound, voxel_size);
        // Relative to the first candidate cell's centre, to keep the projections small and exact-ish.
        const Eigen::Vector3d base = min_bound + half + lo.cast<double>() * voxel_size;
        const TriangleAxes axes(a - base, b - base, c - base, half);
        for (int i = lo(0); i <= hi(0); ++i)
            for (int j = lo(1); j <= hi(1); ++j)
                for (int k = lo(2); k <= hi(2); ++k) {
                    const Eigen::Vector3d offset = Eigen::Vector3d(i - lo(0), j - lo(1), k - lo(2)) * voxel_size;
                    if (axes.overlaps(offset)) mine.emplace_back(i, j, k);
                }
    }
    std::vector<Eigen::Vector3i> all;
    for (auto& h : hits) all.insert(all.end(), h.begin(), h.end());
    std::sort(all.begin(), all.end(), index_less);
    all.erase(std::unique(all.begin(), all.end()), all.end());
    grid.voxels.reserve(all.size());
    for (const Eigen::Vector3i& h : all) grid.voxels.push_back({h, Eigen::Vector3d::Zero()});
    return grid;
}

Eigen::Vector3i voxel_index_of(const VoxelGrid& grid, const Eigen::Vector3d& point) {
    if (!point.allFinite()) throw o3d::InvalidArgument("the query point is not finite");
    const Eigen::Vector3d cell = ((point - grid.origin) / grid.voxel_size).array().floor();
    if ((cell.array().abs() > static_cast<double>(INT_MAX)).any())
        throw o3d::InvalidArgument("the query point's grid index does not fit int32");
    return cell.cast<int>();
}

std::vector<bool> voxels_include(const VoxelGrid& grid, const std::vector<Eigen::Vector3d>& points) {
    std::vector<bool> out(points.size(), false);
    for (size_t i = 0; i < points.size(); ++i) {
        const Eigen::Vector3i cell = voxel_index_of(grid, points[i]);
        const auto it = std::lower_bound(grid.voxels.begin(), grid.voxels.end(), cell,
                                         [](const Voxel& v, const Eigen::Vector3i& c) { return index_less(v.grid_index, c); });
        out[i] = it != grid.voxels.end() && it->grid_index == cell;
    }
    return out;
}

}  // namespace o3d::geometry
