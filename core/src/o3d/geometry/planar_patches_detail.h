// SPDX-License-Identifier: MIT
#pragma once
/// @file planar_patches_detail.h
/// @brief Planar patch detection internals: the robust plane, the octree split and the grow/merge loop.
#include <Eigen/Core>
#include <Eigen/Geometry>
#include <cmath>
#include <cstddef>
#include <vector>

#include "o3d/kdtree/kd_tree.h"

namespace o3d::geometry::planar_patches {

/// @brief The resolved parameters of one detection.
struct Settings {
    double min_cos_normal = 0.5;        ///< cos(normal_variance_threshold)
    double cot_coplanarity = 0.0;       ///< cot(coplanarity): allowed d_max per unit of in-plane radius
    double outlier_ratio = 0.75;
    size_t min_points = 10;             ///< >= 3
    double min_edge_length = 0.0;
    double distance_floor = 0.0;        ///< smallest d_max margin, so a noise-free plane still has a slab
};

/// @brief The points with unit (or zero) normals, and each point's neighbours.
struct Cloud {
    const std::vector<Eigen::Vector3d>* points = nullptr;
    std::vector<Eigen::Vector3d> normals;  ///< normalised copies
    kdtree::SearchResult neighbours;       ///< self included
};

/// @brief A plane with its robust inlier bounds.
struct Plane {
    Eigen::Vector3d normal = Eigen::Vector3d::UnitZ();
    Eigen::Vector3d center = Eigen::Vector3d::Zero();
    double min_similarity = 1.0;  ///< s_min: smallest |normal . point normal| of an inlier
    double max_distance = 0.0;    ///< d_max: largest |normal . (p - center)| of an inlier

    bool accepts(const Eigen::Vector3d& p, const Eigen::Vector3d& n) const {
        return std::abs(normal.dot(n)) >= min_similarity && std::abs(normal.dot(p - center)) <= max_distance;
    }
};

/// @brief Points of a plane in its frame: u the in-plane direction of largest spread, v = normal x u, and the
/// coordinate ranges along u, v and the normal.
struct Frame {
    Eigen::Vector3d u, v;
    Eigen::Vector3d lo, hi;  ///< ranges of (u, v, normal) . (p - center)
};

/// @brief Least-squares plane (mean, smallest principal axis) of points[indices]; false when they do not span
/// a plane direction (fewer than 3 points, all equal).
bool fit_plane(const std::vector<Eigen::Vector3d>& points, const std::vector<int>& indices, Eigen::Vector3d& normal,
               Eigen::Vector3d& center);

/// @brief frame of points[indices] about plane (normal, center).
Frame plane_frame(const std::vector<Eigen::Vector3d>& points, const std::vector<int>& indices,
                  const Eigen::Vector3d& normal, const Eigen::Vector3d& center);

/// @brief As plane_frame, but u along the longer side of the smallest-area rectangle holding the points'
/// projections (PCA axes of a near-square patch wander with the sampling; this box is tight).
Frame tight_frame(const std::vector<Eigen::Vector3d>& points, const std::vector<int>& indices,
                  const Eigen::Vector3d& normal, const Eigen::Vector3d& center);

/// @brief The robust planarity test of points[indices] (see planar_patches.h). On success `plane` holds the
/// fit and its bounds and `inliers` the accepted points, in the order of `indices`.
bool test_planarity(const Cloud& cloud, const std::vector<int>& indices, const Settings& settings, Plane& plane,
                    std::vector<int>& inliers);

/// @brief A detected patch: its plane and its points (plane_of in the loop says who owns which point).
struct Patch {
    Plane plane;
    std::vector<int> members;
    size_t fitted_size = 0;  ///< members.size() at the last refit
    bool alive = true;
};

/// @brief Step 1: octree split and per-cell tests. Returns the patches in detection order (level by level,
/// children in octant order) and sets plane_of[i] to the patch holding point i (-1: none).
std::vector<Patch> split_and_detect(const Cloud& cloud, const Settings& settings, std::vector<int>& plane_of,
                                    int num_threads);

/// @brief Steps 2-4: grow, merge and refit until stable (sequential, so deterministic).
void grow_and_merge(const Cloud& cloud, const Settings& settings, std::vector<Patch>& patches,
                    std::vector<int>& plane_of);

}  // namespace o3d::geometry::planar_patches
