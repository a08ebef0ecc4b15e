// SPDX-License-Identifier: MIT
#pragma once
/// @file ball_pivoting_mesher.h
/// @brief Ball-pivoting internals: seed search, pivoting and the passes over increasing radii.
#include <Eigen/Core>
#include <functional>
#include <memory>
#include <utility>
#include <vector>

#include "o3d/geometry/ball_pivoting_front.h"
#include "o3d/geometry/ball_pivoting_grid.h"
#include "o3d/kdtree/kd_tree.h"

namespace o3d::geometry::ball_pivoting {

/// @brief Runs the passes of the algorithm over validated input (finite points and normals, radii
/// increasing and > 0). Single-threaded on purpose: every step depends on the front the previous one left.
class Mesher {
public:
    Mesher(const std::vector<Eigen::Vector3d>& points, const std::vector<Eigen::Vector3d>& normals,
           const std::function<bool(double)>& progress);

    /// @brief Run every pass; the triangles end in front().triangles().
    void run(const std::vector<double>& radii);
    const Front& front() const { return front_; }

private:
    void set_radius(double radius);
    /// Pass > 0: boundary edges whose triangle has an empty ball of the new radius pivot again.
    void reactivate_boundary_edges();
    /// Scan the unused points in index order; grow every seed triangle found.
    void find_seeds();
    bool try_seed(int v);
    /// Pivot active edges until the front has none.
    void expand();
    void pivot(int e);
    /// True when no point other than the touching ones lies strictly inside the ball.
    bool ball_is_empty(const Eigen::Vector3d& center, const std::vector<int>& candidates) const;
    bool ball_is_empty(const Eigen::Vector3d& center) const;
    /// Every kReportEvery steps: tell the progress callback, which may cancel.
    void report();
    /// `v` has just become a vertex: merge the unused points of `near` that coincide with it.
    void claim(int v, const std::vector<int>& near);

    const std::vector<Eigen::Vector3d>& points_;
    const std::vector<Eigen::Vector3d>& normals_;
    const std::function<bool(double)>& progress_;
    kdtree::KDTree tree_;         ///< nearest-point queries (emptiness of large balls)
    std::unique_ptr<PointGrid> grid_;  ///< neighbourhoods, rebuilt for each radius
    Front front_;
    /// Unused points within `merge2_` of a used one: the same surface point, never a vertex of their own
    /// (else two copies of a point could each take part of its triangle fan and fold the mesh over itself).
    std::vector<char> merged_;

    double extent_ = 0.0;  ///< bounding-box diagonal: the scale of the tolerances
    double radius_ = 0.0;
    double radius2_ = 0.0;
    double inside_margin_ = 0.0;  ///< rho^2 - |p - c|^2 above this: p is strictly inside the ball
    double same_center2_ = 0.0;   ///< squared distance under which two ball centres coincide
    double merge_ = 0.0;          ///< distance under which two points coincide
    size_t pass_ = 0;
    size_t num_passes_ = 1;
    size_t scan_ = 0;  ///< seed-scan position in the current pass
    size_t work_ = 0;  ///< steps since the last progress report

    std::vector<int> neighbours_;
    std::vector<double> distances2_;
    std::vector<std::pair<double, int>> orphans_;
};

}  // namespace o3d::geometry::ball_pivoting
