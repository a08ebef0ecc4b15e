// SPDX-License-Identifier: MIT
// The robust plane of a point set: least-squares fit, robust (median / MAD) bounds and the planarity test.
#include <algorithm>
#include <cmath>
#include <limits>

#include "o3d/geometry/planar_patches_detail.h"
#include "o3d/geometry/symmetric_eigen3.h"

namespace o3d::geometry::planar_patches {
namespace {

/// Scale of the MAD that makes it estimate a normal distribution's standard deviation.
constexpr double kMadToSigma = 1.4826;
/// Robust bounds lie this many (MAD-estimated) deviations from the median.
constexpr double kBoundDeviations = 3.0;
/// Smallest s_min margin: points whose normals equal the patch's up to rounding always pass.
constexpr double kSimilarityFloor = 1e-9;

double median(std::vector<double>& values) {
    const size_t mid = values.size() / 2;
    std::nth_element(values.begin(), values.begin() + static_cast<std::ptrdiff_t>(mid), values.end());
    const double upper = values[mid];
    if (values.size() % 2 == 1) return upper;
    const double lower = *std::max_element(values.begin(), values.begin() + static_cast<std::ptrdiff_t>(mid));
    return 0.5 * (lower + upper);
}

/// @brief Median and MAD-scaled spread of the values (the values are reordered).
void robust_spread(std::vector<double>& values, double& centre, double& spread) {
    centre = median(values);
    for (double& x : values) x = std::abs(x - centre);
    spread = kBoundDeviations * kMadToSigma * median(values);
}

/// @brief The robust bounds of points[indices] about (normal, center), written into plane.
void robust_bounds(const Cloud& cloud, const std::vector<int>& indices, const Settings& settings, Plane& plane) {
    const auto& points = *cloud.points;
    std::vector<double> similarity(indices.size()), distance(indices.size());
    for (size_t k = 0; k < indices.size(); ++k) {
        const auto i = static_cast<size_t>(indices[k]);
        similarity[k] = std::abs(plane.normal.dot(cloud.normals[i]));
        distance[k] = std::abs(plane.normal.dot(points[i] - plane.center));
    }
    double centre = 0.0, spread = 0.0;
    robust_spread(similarity, centre, spread);
    plane.min_similarity = centre - std::max(spread, kSimilarityFloor);
    robust_spread(distance, centre, spread);
    plane.max_distance = centre + std::max(spread, settings.distance_floor);
}

std::vector<int> accepted(const Cloud& cloud, const std::vector<int>& indices, const Plane& plane) {
    std::vector<int> in;
    in.reserve(indices.size());
    for (int i : indices)
        if (plane.accepts((*cloud.points)[static_cast<size_t>(i)], cloud.normals[static_cast<size_t>(i)]))
            in.push_back(i);
    return in;
}

/// @brief Any unit vector orthogonal to the unit vector n.
Eigen::Vector3d orthogonal(const Eigen::Vector3d& n) {
    const Eigen::Vector3d axis = std::abs(n.x()) < 0.6 ? Eigen::Vector3d::UnitX() : Eigen::Vector3d::UnitY();
    return n.cross(axis).normalized();
}

double cross2(const Eigen::Vector2d& o, const Eigen::Vector2d& p, const Eigen::Vector2d& q) {
    return (p.x() - o.x()) * (q.y() - o.y()) - (p.y() - o.y()) * (q.x() - o.x());
}

/// @brief Counter-clockwise convex hull (Andrew's monotone chain), collinear points dropped.
std::vector<Eigen::Vector2d> convex_hull_2d(std::vector<Eigen::Vector2d> pts) {
    std::sort(pts.begin(), pts.end(), [](const Eigen::Vector2d& p, const Eigen::Vector2d& q) {
        return p.x() < q.x() || (p.x() == q.x() && p.y() < q.y());
    });
    if (pts.size() < 3) return pts;
    std::vector<Eigen::Vector2d> hull(2 * pts.size());
    size_t k = 0;
    for (size_t i = 0; i < pts.size(); ++i) {
        while (k >= 2 && cross2(hull[k - 2], hull[k - 1], pts[i]) <= 0.0) --k;
        hull[k++] = pts[i];
    }
    for (size_t i = pts.size() - 1, lower = k + 1; i-- > 0;) {
        while (k >= lower && cross2(hull[k - 2], hull[k - 1], pts[i]) <= 0.0) --k;
        hull[k++] = pts[i];
    }
    hull.resize(k - 1);
    return hull;
}

}  // namespace

bool fit_plane(const std::vector<Eigen::Vector3d>& points, const std::vector<int>& indices, Eigen::Vector3d& normal,
               Eigen::Vector3d& center) {
    if (indices.size() < 3) return false;
    Eigen::Vector3d mean = Eigen::Vector3d::Zero();
    for (int i : indices) mean += points[static_cast<size_t>(i)];
    mean /= static_cast<double>(indices.size());
    Eigen::Matrix3d cov = Eigen::Matrix3d::Zero();
    for (int i : indices) {
        const Eigen::Vector3d d = points[static_cast<size_t>(i)] - mean;
        cov.noalias() += d * d.transpose();
    }
    const Eigen::Vector3d n = smallest_eigenvector(cov / static_cast<double>(indices.size()));
    if (!(n.squaredNorm() > 0.5)) return false;
    normal = n;
    center = mean;
    return true;
}

Frame plane_frame(const std::vector<Eigen::Vector3d>& points, const std::vector<int>& indices,
                  const Eigen::Vector3d& normal, const Eigen::Vector3d& center) {
    // In-plane principal axis from the 2x2 scatter in an arbitrary in-plane basis (a, b).
    const Eigen::Vector3d a = orthogonal(normal), b = normal.cross(a);
    double saa = 0.0, sbb = 0.0, sab = 0.0;
    for (int i : indices) {
        const Eigen::Vector3d d = points[static_cast<size_t>(i)] - center;
        const double x = a.dot(d), y = b.dot(d);
        saa += x * x;
        sbb += y * y;
        sab += x * y;
    }
    const double angle = 0.5 * std::atan2(2.0 * sab, saa - sbb);
    Frame frame;
    frame.u = (std::cos(angle) * a + std::sin(angle) * b).normalized();
    frame.v = normal.cross(frame.u);
    frame.lo = Eigen::Vector3d::Constant(std::numeric_limits<double>::infinity());
    frame.hi = -frame.lo;
    for (int i : indices) {
        const Eigen::Vector3d d = points[static_cast<size_t>(i)] - center;
        const Eigen::Vector3d c(frame.u.dot(d), frame.v.dot(d), normal.dot(d));
        frame.lo = frame.lo.cwiseMin(c);
        frame.hi = frame.hi.cwiseMax(c);
    }
    return frame;
}

Frame tight_frame(const std::vector<Eigen::Vector3d>& points, const std::vector<int>& indices,
                  const Eigen::Vector3d& normal, const Eigen::Vector3d& center) {
    const Eigen::Vector3d a = orthogonal(normal), b = normal.cross(a);
    std::vector<Eigen::Vector2d> flat;
    flat.reserve(indices.size());
    for (int i : indices) {
        const Eigen::Vector3d d = points[static_cast<size_t>(i)] - center;
        flat.emplace_back(a.dot(d), b.dot(d));
    }
    const std::vector<Eigen::Vector2d> hull = convex_hull_2d(std::move(flat));
    if (hull.size() < 3) return plane_frame(points, indices, normal, center);
    // The minimum-area rectangle has a side along a hull edge (Freeman & Shapira 1975): try each edge.
    double best_area = std::numeric_limits<double>::infinity();
    Eigen::Vector2d best_dir(1.0, 0.0);
    for (size_t k = 0; k < hull.size(); ++k) {
        const Eigen::Vector2d edge = hull[(k + 1) % hull.size()] - hull[k];
        if (edge.squaredNorm() == 0.0) continue;
        const Eigen::Vector2d d = edge.normalized(), perp(-d.y(), d.x());
        double lo_d = std::numeric_limits<double>::infinity(), hi_d = -lo_d, lo_p = lo_d, hi_p = -lo_d;
        for (const auto& q : hull) {
            lo_d = std::min(lo_d, d.dot(q));
            hi_d = std::max(hi_d, d.dot(q));
            lo_p = std::min(lo_p, perp.dot(q));
            hi_p = std::max(hi_p, perp.dot(q));
        }
        const double area = (hi_d - lo_d) * (hi_p - lo_p);
        if (area < best_area) {
            best_area = area;
            // u runs along the longer side.
            best_dir = hi_d - lo_d >= hi_p - lo_p ? d : perp;
        }
    }
    Frame frame;
    frame.u = (best_dir.x() * a + best_dir.y() * b).normalized();
    frame.v = normal.cross(frame.u);
    frame.lo = Eigen::Vector3d::Constant(std::numeric_limits<double>::infinity());
    frame.hi = -frame.lo;
    for (int i : indices) {
        const Eigen::Vector3d d = points[static_cast<size_t>(i)] - center;
        const Eigen::Vector3d c(frame.u.dot(d), frame.v.dot(d), normal.dot(d));
        frame.lo = frame.lo.cwiseMin(c);
        frame.hi = frame.hi.cwiseMax(c);
    }
    return frame;
}

bool test_planarity(const Cloud& cloud, const std::vector<int>& indices, const Settings& settings, Plane& plane,
                    std::vector<int>& inliers) {
    if (indices.size() < settings.min_points) return false;
    const auto& points = *cloud.points;
    if (!fit_plane(points, indices, plane.normal, plane.center)) return false;
    robust_bounds(cloud, indices, settings, plane);
    // A cell straddling two surfaces biases the first fit; refit on its inliers, then judge that plane.
    inliers = accepted(cloud, indices, plane);
    if (!fit_plane(points, inliers, plane.normal, plane.center)) return false;
    robust_bounds(cloud, indices, settings, plane);
    inliers = accepted(cloud, indices, plane);

    if (inliers.size() < settings.min_points) return false;
    if (static_cast<double>(indices.size() - inliers.size()) > settings.outlier_ratio * static_cast<double>(indices.size()))
        return false;
    if (plane.min_similarity < settings.min_cos_normal) return false;
    const Frame frame = plane_frame(points, inliers, plane.normal, plane.center);
    const double radius = 0.5 * std::max(frame.hi.x() - frame.lo.x(), frame.hi.y() - frame.lo.y());
    return plane.max_distance <= radius * settings.cot_coplanarity;
}

}  // namespace o3d::geometry::planar_patches
