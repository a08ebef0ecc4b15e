// SPDX-License-Identifier: MIT
// Step 1 of planar patch detection: split the cloud's bounding cube as an octree, testing cells for planarity.
#include <cmath>
#include <exception>

#include "o3d/geometry/planar_patches_detail.h"

namespace o3d::geometry::planar_patches {
namespace {

/// Cells above this level are always split: a test over (most of) a whole scene would accept a dominant plane
/// together with whatever else the robust statistics let through.
constexpr int kFirstTestedLevel = 3;
/// Deepest level: keeps cells well above double resolution when many points coincide.
constexpr int kMaxLevel = 21;

struct Cell {
    Eigen::Vector3d origin;
    double size;
    int level;
    std::vector<int> indices;
};

struct CellResult {
    bool planar = false;
    Plane plane;
    std::vector<int> inliers;
};

std::vector<Cell> children_of(const std::vector<Eigen::Vector3d>& points, const Cell& cell, size_t min_points) {
    const double half = 0.5 * cell.size;
    const Eigen::Vector3d mid = cell.origin + Eigen::Vector3d::Constant(half);
    std::vector<int> octant[8];
    for (int i : cell.indices) {
        const Eigen::Vector3d& p = points[static_cast<size_t>(i)];
        const int k = (p.x() >= mid.x() ? 1 : 0) | (p.y() >= mid.y() ? 2 : 0) | (p.z() >= mid.z() ? 4 : 0);
        octant[k].push_back(i);
    }
    std::vector<Cell> children;
    for (int k = 0; k < 8; ++k) {
        // A child with too few points can neither be tested nor yield a testable grandchild.
        if (octant[k].size() < min_points) continue;
        const Eigen::Vector3d offset((k & 1) ? half : 0.0, (k & 2) ? half : 0.0, (k & 4) ? half : 0.0);
        children.push_back({cell.origin + offset, half, cell.level + 1, std::move(octant[k])});
    }
    return children;
}

}  // namespace

std::vector<Patch> split_and_detect(const Cloud& cloud, const Settings& settings, std::vector<int>& plane_of,
                                    int num_threads) {
    const auto& points = *cloud.points;
    plane_of.assign(points.size(), -1);
    Eigen::Vector3d lo = points[0], hi = points[0];
    for (const auto& p : points) {
        lo = lo.cwiseMin(p);
        hi = hi.cwiseMax(p);
    }
    const double size = (hi - lo).maxCoeff();
    std::vector<Patch> patches;
    if (!(size > 0.0) || points.size() < settings.min_points) return patches;

    // The root cube is centred on the bounding box; a small margin keeps the maxima off the far faces.
    const double root_size = size * (1.0 + 1e-9);
    Cell root{0.5 * (lo + hi) - Eigen::Vector3d::Constant(0.5 * root_size), root_size, 0, {}};
    root.indices.resize(points.size());
    for (size_t i = 0; i < points.size(); ++i) root.indices[i] = static_cast<int>(i);

    std::vector<Cell> level{std::move(root)};
    while (!level.empty()) {
        // Cells of one level are disjoint: test them in parallel, then act on the results in cell order.
        std::vector<CellResult> results(level.size());
        std::exception_ptr error;
#pragma omp parallel for schedule(dynamic, 1) num_threads(num_threads)
        for (int64_t c = 0; c < static_cast<int64_t>(level.size()); ++c) {
            const Cell& cell = level[static_cast<size_t>(c)];
            if (cell.level < kFirstTestedLevel) continue;
            try {
                CellResult& r = results[static_cast<size_t>(c)];
                r.planar = test_planarity(cloud, cell.indices, settings, r.plane, r.inliers);
            } catch (...) {
#pragma omp critical(o3d_planar_patches_split)
                if (!error) error = std::current_exception();
            }
        }
        if (error) std::rethrow_exception(error);

        std::vector<Cell> next;
        for (size_t c = 0; c < level.size(); ++c) {
            CellResult& r = results[c];
            if (r.planar) {
                Patch patch;
                patch.plane = r.plane;
                patch.members = std::move(r.inliers);
                patch.fitted_size = patch.members.size();
                for (int i : patch.members) plane_of[static_cast<size_t>(i)] = static_cast<int>(patches.size());
                patches.push_back(std::move(patch));
                continue;
            }
            // Cells smaller than min_edge_length are still split: their patches may grow past it.
            const Cell& cell = level[c];
            if (cell.level >= kMaxLevel) continue;
            for (Cell& child : children_of(points, cell, settings.min_points)) next.push_back(std::move(child));
        }
        level = std::move(next);
    }
    return patches;
}

}  // namespace o3d::geometry::planar_patches
