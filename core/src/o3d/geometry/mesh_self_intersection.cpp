// SPDX-License-Identifier: MIT
#include "o3d/geometry/mesh_self_intersection.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstdint>
#include <utility>
#include <vector>

#include "o3d/geometry/triangle_box_grid.h"
#include "o3d/geometry/triangle_mesh_basics.h"
#include "o3d/utility/parallel.h"

namespace o3d::geometry {
namespace {

constexpr double kRelativeTolerance = 1e-10;

double orient2(const Eigen::Vector2d& a, const Eigen::Vector2d& b, const Eigen::Vector2d& c) {
    return (b - a).x() * (c - a).y() - (b - a).y() * (c - a).x();
}

int sign_of(double x, double tol) { return x > tol ? 1 : (x < -tol ? -1 : 0); }

bool on_segment(const Eigen::Vector2d& a, const Eigen::Vector2d& b, const Eigen::Vector2d& p) {
    return std::min(a.x(), b.x()) <= p.x() && p.x() <= std::max(a.x(), b.x()) && std::min(a.y(), b.y()) <= p.y() &&
           p.y() <= std::max(a.y(), b.y());
}

/// @brief Closed 2-D segments ab and cd share a point (orientations within `tol` count as collinear).
bool segments_intersect(const Eigen::Vector2d& a, const Eigen::Vector2d& b, const Eigen::Vector2d& c,
                        const Eigen::Vector2d& d, double tol) {
    const int o1 = sign_of(orient2(a, b, c), tol), o2 = sign_of(orient2(a, b, d), tol);
    const int o3 = sign_of(orient2(c, d, a), tol), o4 = sign_of(orient2(c, d, b), tol);
    if (o1 * o2 < 0 && o3 * o4 < 0) return true;
    return (o1 == 0 && on_segment(a, b, c)) || (o2 == 0 && on_segment(a, b, d)) ||
           (o3 == 0 && on_segment(c, d, a)) || (o4 == 0 && on_segment(c, d, b));
}

bool point_in_triangle(const Eigen::Vector2d& p, const Eigen::Vector2d t[3], double tol) {
    const int s0 = sign_of(orient2(t[0], t[1], p), tol), s1 = sign_of(orient2(t[1], t[2], p), tol),
              s2 = sign_of(orient2(t[2], t[0], p), tol);
    return (s0 >= 0 && s1 >= 0 && s2 >= 0) || (s0 <= 0 && s1 <= 0 && s2 <= 0);
}

/// @brief Both triangles lie in one plane of normal n: project along n's largest axis and test in 2-D.
bool coplanar_intersect(const Eigen::Vector3d& n, const Eigen::Vector3d p[3], const Eigen::Vector3d q[3],
                        double length) {
    int drop = 0;
    n.cwiseAbs().maxCoeff(&drop);
    const int u = (drop + 1) % 3, v = (drop + 2) % 3;
    Eigen::Vector2d a[3], b[3];
    for (int i = 0; i < 3; ++i) {
        a[i] = Eigen::Vector2d(p[i](u), p[i](v));
        b[i] = Eigen::Vector2d(q[i](u), q[i](v));
    }
    const double tol = kRelativeTolerance * length * length;
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j)
            if (segments_intersect(a[i], a[(i + 1) % 3], b[j], b[(j + 1) % 3], tol)) return true;
    return point_in_triangle(a[0], b, tol) || point_in_triangle(b[0], a, tol);
}

/// @brief The interval where a triangle crosses the line of the two planes, as parameters along the
/// line's projection `proj`, from the signed distances `d` of its vertices to the other plane.
/// Needs a vertex on each side or on the plane, not all on it.
std::pair<double, double> crossing_interval(const double proj[3], const double d[3]) {
    int lone;  // the vertex alone on its side of the plane
    if (d[0] * d[1] > 0) lone = 2;
    else if (d[0] * d[2] > 0) lone = 1;
    else if (d[1] * d[2] > 0 || d[0] != 0) lone = 0;
    else if (d[1] != 0) lone = 1;
    else lone = 2;
    const int i = (lone + 1) % 3, j = (lone + 2) % 3;
    const double a = proj[lone] + (proj[i] - proj[lone]) * d[lone] / (d[lone] - d[i]);
    const double b = proj[lone] + (proj[j] - proj[lone]) * d[lone] / (d[lone] - d[j]);
    return {std::min(a, b), std::max(a, b)};
}

/// @brief Signed distances (times |n|) of `v` to the plane through `origin` with normal `n`; values within
/// `tol` snap to zero, so touching and coplanar configurations are decided consistently.
bool all_one_side(const Eigen::Vector3d& n, const Eigen::Vector3d& origin, const Eigen::Vector3d v[3], double tol,
                  double d[3]) {
    for (int i = 0; i < 3; ++i) {
        d[i] = n.dot(v[i] - origin);
        if (std::abs(d[i]) <= tol) d[i] = 0.0;
    }
    return (d[0] > 0 && d[1] > 0 && d[2] > 0) || (d[0] < 0 && d[1] < 0 && d[2] < 0);
}

}  // namespace

bool triangles_intersect(const Eigen::Vector3d& p0, const Eigen::Vector3d& p1, const Eigen::Vector3d& p2,
                         const Eigen::Vector3d& q0, const Eigen::Vector3d& q1, const Eigen::Vector3d& q2) {
    const Eigen::Vector3d p[3] = {p0, p1, p2}, q[3] = {q0, q1, q2};
    const Eigen::Vector3d np = (p1 - p0).cross(p2 - p0), nq = (q1 - q0).cross(q2 - q0);
    const double np_norm = np.norm(), nq_norm = nq.norm();
    if (!(np_norm > 0) || !(nq_norm > 0)) return false;
    double length = 0;
    for (int i = 0; i < 3; ++i) {
        length = std::max(length, (p[i] - p[(i + 1) % 3]).norm());
        length = std::max(length, (q[i] - q[(i + 1) % 3]).norm());
    }
    double dp[3], dq[3];
    if (all_one_side(nq, q0, p, kRelativeTolerance * nq_norm * length, dp)) return false;
    if (all_one_side(np, p0, q, kRelativeTolerance * np_norm * length, dq)) return false;
    if (dp[0] == 0 && dp[1] == 0 && dp[2] == 0) return coplanar_intersect(np, p, q, length);
    if (dq[0] == 0 && dq[1] == 0 && dq[2] == 0) return coplanar_intersect(nq, p, q, length);

    const Eigen::Vector3d line = np.cross(nq);
    int axis = 0;
    line.cwiseAbs().maxCoeff(&axis);
    const double pp[3] = {p0(axis), p1(axis), p2(axis)}, qq[3] = {q0(axis), q1(axis), q2(axis)};
    const auto a = crossing_interval(pp, dp), b = crossing_interval(qq, dq);
    return !(a.second < b.first || b.second < a.first);
}

bool is_self_intersecting(const TriangleMesh& mesh) {
    validate_triangles(mesh);
    std::vector<detail::TriangleBox> boxes;
    detail::add_boxes(mesh, 0, boxes);
    if (boxes.size() < 2) return false;
    const detail::BoxGrid grid(boxes);
    // The answer is "does any pair intersect", so the parallel search returns the same for any thread count.
    std::atomic<bool> found{false};
    grid.for_each_overlap(
        [&](size_t i, size_t j) {
            const Eigen::Vector3i &ta = mesh.triangles[boxes[i].index], &tb = mesh.triangles[boxes[j].index];
            if (detail::share_vertex(ta, tb)) return;
            const auto& v = mesh.vertices;
            if (triangles_intersect(v[ta(0)], v[ta(1)], v[ta(2)], v[tb(0)], v[tb(1)], v[tb(2)]))
                found.store(true, std::memory_order_relaxed);
        },
        found);
    return found.load();
}

}  // namespace o3d::geometry
