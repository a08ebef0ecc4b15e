// SPDX-License-Identifier: MIT
#include "o3d/geometry/ball_pivoting_mesher.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <string>

#include "o3d/geometry/ball_pivoting_geometry.h"
#include "o3d/utility/error.h"

namespace o3d::geometry::ball_pivoting {
namespace {

/// Pseudo-angles are in [0, 4): one full turn.
constexpr double kFullTurn = 4.0;

/// A strictly increasing function of atan2(y, x) taken in [0, 2 pi) (the "diamond angle"): comparing
/// contact angles needs their order only, and this costs a division where atan2 costs far more.
double pseudo_angle(double y, double x) {
    const double s = std::abs(x) + std::abs(y);
    if (s == 0.0) return 0.0;
    if (y >= 0.0) return x >= 0.0 ? y / s : 1.0 - x / s;
    return x < 0.0 ? 2.0 - y / s : 3.0 + x / s;
}

/// Seed pairs are taken among this many nearest unused neighbours (the paper takes all, in order of
/// distance): a valid seed, when one exists, is almost always among the first pairs, and the cap keeps
/// a huge radius (every point a neighbour) from costing a cubic number of pair tests per point.
constexpr size_t kMaxSeedNeighbours = 48;
/// Above this many candidates an emptiness test asks the tree for the nearest point instead of scanning.
constexpr size_t kMaxScannedCandidates = 64;
/// Progress is reported (and cancellation checked) every this many steps.
constexpr size_t kReportEvery = 2048;

}  // namespace

Mesher::Mesher(const std::vector<Eigen::Vector3d>& points, const std::vector<Eigen::Vector3d>& normals,
               const std::function<bool(double)>& progress)
    : points_(points), normals_(normals), progress_(progress), tree_(points), front_(points.size()) {
    Eigen::Vector3d lo = points.front(), hi = points.front();
    for (const auto& p : points) {
        lo = lo.cwiseMin(p);
        hi = hi.cwiseMax(p);
    }
    extent_ = (hi - lo).norm();
    merged_.assign(points.size(), 0);
}

void Mesher::set_radius(double radius) {
    radius_ = radius;
    radius2_ = radius * radius;
    // Tolerances scale with the larger of the cloud and the ball: points of a regular grid sit exactly on
    // each other's balls, and rounding must neither push them inside nor move their contact angle past 0.
    const double scale = std::max(extent_, radius);
    inside_margin_ = 2.0 * radius * 1e-9 * scale;
    same_center2_ = (1e-8 * scale) * (1e-8 * scale);
    // Every neighbourhood query has a radius of at most the ball's diameter (plus the merge distance).
    grid_ = std::make_unique<PointGrid>(points_, 2.0 * radius * (1.0 + 1e-9) + 2.0 * merge_);
}

void Mesher::report() {
    if (!progress_ || ++work_ < kReportEvery) return;
    work_ = 0;
    const double n = static_cast<double>(points_.size());
    const double within = 0.5 * (static_cast<double>(scan_) / n + static_cast<double>(front_.num_used()) / n);
    const double fraction = std::min(1.0, (static_cast<double>(pass_) + within) / static_cast<double>(num_passes_));
    if (!progress_(fraction))
        throw Cancelled("ball pivoting cancelled by the progress callback at " + std::to_string(fraction));
}

void Mesher::run(const std::vector<double>& radii) {
    num_passes_ = radii.size();
    // Far below any sensible sampling (and the ball), far above rounding: closer points are one point.
    merge_ = std::min(1e-8 * extent_, 1e-4 * radii.front());
    for (pass_ = 0; pass_ < radii.size(); ++pass_) {
        scan_ = 0;
        set_radius(radii[pass_]);
        if (pass_ > 0) {
            reactivate_boundary_edges();
            expand();
        }
        find_seeds();
    }
    pass_ = num_passes_;
    scan_ = 0;
    if (progress_ && !progress_(1.0)) throw Cancelled("ball pivoting cancelled by the progress callback at 1");
}

bool Mesher::ball_is_empty(const Eigen::Vector3d& center, const std::vector<int>& candidates) const {
    // A short list is scanned whole. A long one (a large ball) is scanned in part first, because a ball
    // that is not empty usually holds many of the candidates, then settled by one nearest-point query.
    const size_t scanned = std::min(candidates.size(), kMaxScannedCandidates);
    for (size_t i = 0; i < scanned; ++i)
        if (radius2_ - (points_[candidates[i]] - center).squaredNorm() > inside_margin_) return false;
    return scanned == candidates.size() || ball_is_empty(center);
}

bool Mesher::ball_is_empty(const Eigen::Vector3d& center) const {
    // The touching points lie on the sphere, so the nearest point is strictly inside only when another is.
    double d2 = 0.0;
    if (tree_.search_nearest(center, radius_, d2) < 0) return true;
    return !(radius2_ - d2 > inside_margin_);
}

void Mesher::claim(int v, const std::vector<int>& near) {
    const Eigen::Vector3d& pv = points_[v];
    const double merge2 = merge_ * merge_;
    for (const int k : near)
        if (k != v && !merged_[k] && front_.is_orphan(k) && (points_[k] - pv).squaredNorm() <= merge2)
            merged_[k] = 1;
}

void Mesher::reactivate_boundary_edges() {
    // Per triangle: 0 not yet tested with this radius, 1 its ball is empty, 2 no empty ball.
    std::vector<uint8_t> tested(front_.triangles().size(), 0);
    const size_t num_edges = front_.num_edges();
    for (size_t e = 0; e < num_edges; ++e) {
        const Edge& edge = front_.edge(static_cast<int>(e));
        if (edge.state != EdgeState::Boundary) continue;
        const int t = edge.triangle;
        if (tested[t] == 0) {
            const Eigen::Vector3i& tri = front_.triangles()[t];
            Eigen::Vector3d center;
            const bool ok = ball_center(points_[tri(0)], points_[tri(1)], points_[tri(2)], radius2_, center) &&
                            ball_is_empty(center);
            tested[t] = ok ? 1 : 2;
            if (ok) front_.centers()[t] = center;
        }
        if (tested[t] == 1) front_.reactivate(static_cast<int>(e));
        report();
    }
}

void Mesher::find_seeds() {
    const size_t n = points_.size();
    for (scan_ = 0; scan_ < n; ++scan_) {
        report();
        const int v = static_cast<int>(scan_);
        if (!front_.is_orphan(v) || merged_[v]) continue;
        if (try_seed(v)) expand();
    }
}

bool Mesher::try_seed(int v) {
    const Eigen::Vector3d& pv = points_[v];
    // Every point inside a ball touching v lies within 2 rho of v: one search serves the pair candidates
    // and the emptiness tests.
    grid_->search(pv, 2.0 * radius_ * (1.0 + 1e-12) + merge_, neighbours_, distances2_);
    orphans_.clear();
    const double merge2 = merge_ * merge_;
    for (size_t i = 0; i < neighbours_.size(); ++i) {
        const int k = neighbours_[i];
        if (k == v || !front_.is_orphan(k) || merged_[k] || distances2_[i] <= merge2) continue;
        orphans_.emplace_back(distances2_[i], k);
    }
    // The paper's order: pairs of neighbours by distance from v (ties by index, for determinism).
    const size_t count = std::min(orphans_.size(), kMaxSeedNeighbours);
    std::partial_sort(orphans_.begin(), orphans_.begin() + static_cast<std::ptrdiff_t>(count), orphans_.end());
    const Eigen::Vector3d& nv = normals_[v];
    for (size_t i = 0; i < count; ++i) {
        for (size_t j = i + 1; j < count; ++j) {
            int a = orphans_[i].second, b = orphans_[j].second;
            if ((points_[a] - points_[b]).squaredNorm() <= merge2) continue;
            Eigen::Vector3d d = triangle_direction(pv, points_[a], points_[b]);
            const double votes = d.dot(nv) + d.dot(normals_[a]) + d.dot(normals_[b]);
            if (votes == 0.0) continue;  // zero normals, or a triangle edge-on to them: no orientation
            if (votes < 0.0) {
                std::swap(a, b);
                d = -d;
            }
            if (!agrees_with_normals(d, nv, normals_[a], normals_[b])) continue;
            Eigen::Vector3d center;
            if (!ball_center(pv, points_[a], points_[b], radius2_, center)) continue;
            if (!ball_is_empty(center, neighbours_)) continue;
            front_.add_triangle(v, a, b, center);
            for (const int k : {v, a, b}) claim(k, neighbours_);
            return true;
        }
    }
    return false;
}

void Mesher::expand() {
    for (int e = front_.pop_active(); e >= 0; e = front_.pop_active()) {
        pivot(e);
        report();
    }
}

void Mesher::pivot(int e) {
    const Edge edge = front_.edge(e);
    const int a = edge.source, b = edge.target, o = edge.opposite;
    const Eigen::Vector3d& pa = points_[a];
    const Eigen::Vector3d& pb = points_[b];
    const Eigen::Vector3d& center = front_.centers()[edge.triangle];
    const Eigen::Vector3d mid = 0.5 * (pa + pb);
    // The ball keeps touching a and b, so its centre turns on the circle about the edge through `center`.
    // Turning positively about a->b carries it away from the triangle (a, b, o), which lies to the left of
    // a->b seen from its outside.
    const Eigen::Vector3d axis = (pb - pa).normalized();
    const Eigen::Vector3d start = center - mid;
    const double orbit = start.norm();
    const Eigen::Vector3d ahead = axis.cross(start);  // the centre's direction of motion
    grid_->search(mid, (orbit + radius_) * (1.0 + 1e-12) + merge_, neighbours_, distances2_);

    // Angle at which the ball first touches point k: the ball centre of triangle (b, a, k) on the side it
    // faces is where k enters the ball, the opposite one where it leaves (the paper's first contact).
    auto contact = [&](int k, Eigen::Vector3d& c) -> double {
        if (!ball_center(pb, pa, points_[k], radius2_, c)) return -1.0;
        const Eigen::Vector3d to = c - mid;
        const double y = axis.dot(start.cross(to));
        double angle = pseudo_angle(y, start.dot(to));
        if (y < 0.0) {
            // Past half a turn, or just before the start: a point on the starting ball (a cospherical
            // neighbour) ahead of the moving centre enters at angle 0, not a full turn later. Behind it
            // (o's side) the point is leaving: when the ball is barely larger than the circumcircle its
            // entry centre is close to `center` as well.
            const bool on_start = (c - center).squaredNorm() <= same_center2_;
            if (on_start && (points_[k] - mid).dot(ahead) > 0.0) angle = 0.0;
        }
        return angle;
    };

    double best_angle = kFullTurn;
    // The ball reaching o again means it has turned over the triangle without touching anything else.
    // (A ball exactly as large as the triangle's circumcircle touches o on both sides at once: no limit.)
    {
        Eigen::Vector3d c;
        const double back = contact(o, c);
        if (back > 0.0 && (c - center).squaredNorm() > same_center2_) best_angle = back;
    }
    int best = -1;
    Eigen::Vector3d best_center;
    const double reach2 = 4.0 * radius2_;
    double best_distance2 = 0.0;
    for (size_t i = 0; i < neighbours_.size(); ++i) {
        const int k = neighbours_[i];
        if (k == a || k == b || k == o || merged_[k]) continue;
        // A ball touching a, b and k has all three within its diameter.
        if ((points_[k] - pa).squaredNorm() > reach2 || (points_[k] - pb).squaredNorm() > reach2) continue;
        Eigen::Vector3d c;
        const double angle = contact(k, c);
        if (angle < 0.0 || angle > best_angle) continue;
        // Equal angles (cospherical points): the one nearest the edge, then the lowest index.
        if (angle == best_angle && (best < 0 || distances2_[i] > best_distance2 ||
                                    (distances2_[i] == best_distance2 && k > best)))
            continue;
        best_angle = angle;
        best = k;
        best_center = c;
        best_distance2 = distances2_[i];
    }
    if (best < 0) {
        front_.set_boundary(e);
        return;
    }
    // Join (an unused point) or glue (a point on the front); a point inside the mesh cannot take a
    // triangle, nor can one that disagrees with the normals or would break manifoldness or orientation.
    const bool reachable = front_.is_orphan(best) || front_.on_front(best);
    if (!reachable ||
        !agrees_with_normals(triangle_direction(pb, pa, points_[best]), normals_[a], normals_[b], normals_[best]) ||
        !front_.can_add(b, a, best)) {
        front_.set_boundary(e);
        return;
    }
    const bool first_use = front_.is_orphan(best);
    front_.add_triangle(b, a, best, best_center);
    if (first_use) claim(best, neighbours_);
}

}  // namespace o3d::geometry::ball_pivoting
