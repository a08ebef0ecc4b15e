// SPDX-License-Identifier: MIT
#include "o3d/geometry/minimal_bounding_box.h"

#include <Eigen/Eigenvalues>
#include <Eigen/Geometry>
#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <utility>

#include "o3d/geometry/convex_hull.h"
#include "o3d/utility/error.h"

namespace o3d::geometry {
namespace {

/// @brief 2-D convex hull (Andrew's monotone chain), counter-clockwise, collinear points dropped.
std::vector<Eigen::Vector2d> convex_hull_2d(std::vector<Eigen::Vector2d> pts) {
    std::sort(pts.begin(), pts.end(), [](const Eigen::Vector2d& a, const Eigen::Vector2d& b) {
        return a.x() < b.x() || (a.x() == b.x() && a.y() < b.y());
    });
    pts.erase(std::unique(pts.begin(), pts.end()), pts.end());
    if (pts.size() < 3) return pts;
    auto cross = [](const Eigen::Vector2d& o, const Eigen::Vector2d& a, const Eigen::Vector2d& b) {
        return (a.x() - o.x()) * (b.y() - o.y()) - (a.y() - o.y()) * (b.x() - o.x());
    };
    std::vector<Eigen::Vector2d> hull(2 * pts.size());
    size_t k = 0;
    for (size_t i = 0; i < pts.size(); ++i) {
        while (k >= 2 && cross(hull[k - 2], hull[k - 1], pts[i]) <= 0.0) --k;
        hull[k++] = pts[i];
    }
    for (size_t i = pts.size() - 1, lower = k + 1; i-- > 0;) {
        while (k >= lower && cross(hull[k - 2], hull[k - 1], pts[i]) <= 0.0) --k;
        hull[k++] = pts[i];
    }
    hull.resize(k - 1);
    return hull;
}

/// @brief Direction of one side of the minimum-area rectangle around a 2-D convex polygon: one side is
/// flush with a polygon edge (Freeman & Shapira), so trying every edge is exact. Returns the area.
double min_area_rectangle(const std::vector<Eigen::Vector2d>& hull, Eigen::Vector2d* side) {
    if (hull.size() < 2) {
        *side = Eigen::Vector2d::UnitX();
        return 0.0;
    }
    if (hull.size() == 2) {  // a segment: zero area, its sides along the segment
        *side = (hull[1] - hull[0]).normalized();
        return 0.0;
    }
    double best = std::numeric_limits<double>::infinity();
    const size_t n = hull.size();
    for (size_t i = 0; i < n; ++i) {
        const Eigen::Vector2d e = (hull[(i + 1) % n] - hull[i]).normalized();
        const Eigen::Vector2d f(-e.y(), e.x());
        double lo_e = INFINITY, hi_e = -INFINITY, lo_f = INFINITY, hi_f = -INFINITY;
        for (const auto& p : hull) {
            const double a = p.dot(e), b = p.dot(f);
            lo_e = std::min(lo_e, a);
            hi_e = std::max(hi_e, a);
            lo_f = std::min(lo_f, b);
            hi_f = std::max(hi_f, b);
        }
        const double area = (hi_e - lo_e) * (hi_f - lo_f);
        if (area < best) {
            best = area;
            *side = e;
        }
    }
    return best;
}

/// @brief Two unit vectors completing unit `d` to a right-handed frame (d, u, v).
void complete_frame(const Eigen::Vector3d& d, Eigen::Vector3d* u, Eigen::Vector3d* v) {
    Eigen::Index axis;
    d.cwiseAbs().minCoeff(&axis);
    *u = d.cross(Eigen::Vector3d::Unit(axis)).normalized();
    *v = d.cross(*u);
}

/// @brief The best box with one axis along `d` (unit): its volume and frame.
struct Candidate {
    double volume = std::numeric_limits<double>::infinity();
    Eigen::Matrix3d R = Eigen::Matrix3d::Identity();
};

/// @brief The hull's edges with the normals of their two faces: the outline of the hull seen along d runs
/// over the edges whose faces turn to opposite sides of d, so only their vertices need projecting.
struct HullEdges {
    std::vector<std::array<int, 2>> vertices;
    std::vector<std::array<Eigen::Vector3d, 2>> normals;
};

HullEdges hull_edges(const std::vector<Eigen::Vector3d>& hull, const std::vector<Eigen::Vector3i>& triangles) {
    std::vector<std::pair<std::pair<int, int>, size_t>> half;  // (sorted vertex pair, face)
    half.reserve(3 * triangles.size());
    std::vector<Eigen::Vector3d> face_normal(triangles.size());
    for (size_t f = 0; f < triangles.size(); ++f) {
        const Eigen::Vector3i& t = triangles[f];
        face_normal[f] = (hull[t(1)] - hull[t(0)]).cross(hull[t(2)] - hull[t(0)]);
        for (int k = 0; k < 3; ++k) {
            const int a = t(k), b = t((k + 1) % 3);
            half.push_back({{std::min(a, b), std::max(a, b)}, f});
        }
    }
    std::sort(half.begin(), half.end());
    HullEdges edges;
    for (size_t i = 0; i + 1 < half.size(); ++i) {
        if (half[i].first != half[i + 1].first) continue;
        edges.vertices.push_back({half[i].first.first, half[i].first.second});
        edges.normals.push_back({face_normal[half[i].second], face_normal[half[i + 1].second]});
        ++i;
    }
    return edges;
}

/// @param edges when given, only the outline's vertices are projected (every hull vertex that is extreme in
/// some direction normal to d lies on an edge whose faces' normals change sign along d).
Candidate best_box_along(const Eigen::Vector3d& d, const std::vector<Eigen::Vector3d>& hull,
                         const HullEdges* edges = nullptr) {
    Eigen::Vector3d u, v;
    complete_frame(d, &u, &v);
    std::vector<Eigen::Vector2d> projected;
    double lo = INFINITY, hi = -INFINITY;
    for (const auto& p : hull) {
        const double h = p.dot(d);
        lo = std::min(lo, h);
        hi = std::max(hi, h);
    }
    if (edges) {
        for (size_t e = 0; e < edges->vertices.size(); ++e) {
            if ((edges->normals[e][0].dot(d) > 0.0) == (edges->normals[e][1].dot(d) > 0.0)) continue;
            for (int k : edges->vertices[e]) projected.emplace_back(hull[k].dot(u), hull[k].dot(v));
        }
    } else {
        for (const auto& p : hull) projected.emplace_back(p.dot(u), p.dot(v));
    }
    Eigen::Vector2d side;
    const double area = min_area_rectangle(convex_hull_2d(std::move(projected)), &side);
    Candidate c;
    c.volume = (hi - lo) * area;
    c.R.col(0) = d;
    c.R.col(1) = (side.x() * u + side.y() * v).normalized();
    c.R.col(2) = d.cross(c.R.col(1));
    return c;
}

/// @brief Nelder-Mead over the axis direction, in the tangent plane at `start`: the volume as a function of
/// the direction is continuous and piecewise smooth, and its minimum need not sit at a face normal.
Candidate refine(const Candidate& start, const std::vector<Eigen::Vector3d>& hull, const HullEdges& edges) {
    const Eigen::Vector3d d0 = start.R.col(0);
    Eigen::Vector3d t1, t2;
    complete_frame(d0, &t1, &t2);
    auto eval = [&](const Eigen::Vector2d& x) { return best_box_along((d0 + x(0) * t1 + x(1) * t2).normalized(), hull, &edges);
    };

    Candidate best = start;
    Eigen::Vector2d best_x = Eigen::Vector2d::Zero();
    // Two passes: a wide simplex to leave the face-normal kink, a narrow one to polish.
    for (double step : {0.05, 0.005}) {
        std::array<Eigen::Vector2d, 3> x = {best_x, best_x + Eigen::Vector2d(step, 0), best_x + Eigen::Vector2d(0, step)};
        std::array<Candidate, 3> f = {best, eval(x[1]), eval(x[2])};
        for (int iter = 0; iter < 200; ++iter) {
            std::array<int, 3> order = {0, 1, 2};
            std::sort(order.begin(), order.end(), [&](int a, int b) { return f[a].volume < f[b].volume; });
            const int lo = order[0], mid = order[1], hi = order[2];
            const double size = std::max((x[mid] - x[lo]).norm(), (x[hi] - x[lo]).norm());
            if (size < 1e-10) break;
            const Eigen::Vector2d centroid = 0.5 * (x[lo] + x[mid]);
            const Eigen::Vector2d xr = centroid + (centroid - x[hi]);
            const Candidate fr = eval(xr);
            if (fr.volume < f[lo].volume) {
                const Eigen::Vector2d xe = centroid + 2.0 * (centroid - x[hi]);
                const Candidate fe = eval(xe);
                if (fe.volume < fr.volume) {
                    x[hi] = xe;
                    f[hi] = fe;
                } else {
                    x[hi] = xr;
                    f[hi] = fr;
                }
            } else if (fr.volume < f[mid].volume) {
                x[hi] = xr;
                f[hi] = fr;
            } else {
                const bool outside = fr.volume < f[hi].volume;
                const Eigen::Vector2d xc = outside ? centroid + 0.5 * (xr - centroid) : centroid + 0.5 * (x[hi] - centroid);
                const Candidate fc = eval(xc);
                if (fc.volume < std::min(fr.volume, f[hi].volume)) {
                    x[hi] = xc;
                    f[hi] = fc;
                } else {  // shrink towards the best vertex
                    for (int k : {mid, hi}) {
                        x[k] = x[lo] + 0.5 * (x[k] - x[lo]);
                        f[k] = eval(x[k]);
                    }
                }
            }
        }
        for (int k = 0; k < 3; ++k)
            if (f[k].volume < best.volume) {
                best = f[k];
                best_x = x[k];
            }
    }
    return best;
}

/// @brief The tight box of `hull` in the frame R (columns = axes).
OrientedBoundingBox box_in_frame(const Eigen::Matrix3d& R, const std::vector<Eigen::Vector3d>& hull,
                                 const Eigen::Vector3d& origin) {
    Eigen::Vector3d lo = Eigen::Vector3d::Constant(INFINITY), hi = Eigen::Vector3d::Constant(-INFINITY);
    for (const auto& p : hull) {
        const Eigen::Vector3d local = R.transpose() * (p - origin);
        lo = lo.cwiseMin(local);
        hi = hi.cwiseMax(local);
    }
    OrientedBoundingBox box;
    box.R = R;
    box.extent = hi - lo;
    box.center = origin + R * (0.5 * (lo + hi));
    return box;
}

}  // namespace

bool is_flat(const std::vector<Eigen::Vector3d>& centred, const Eigen::Matrix3d& axes) {
    double lo = INFINITY, hi = -INFINITY, span = 0.0;
    for (const auto& p : centred) {
        const double h = p.dot(axes.col(0));
        lo = std::min(lo, h);
        hi = std::max(hi, h);
        span = std::max(span, p.norm());
    }
    return hi - lo <= 1e-12 * span;
}

void permute_axes_closest_to_identity(Eigen::Matrix3d& R, Eigen::Vector3d& extent) {
    static const std::array<std::array<int, 3>, 6> permutations = {
            {{{0, 1, 2}}, {{0, 2, 1}}, {{1, 0, 2}}, {{1, 2, 0}}, {{2, 0, 1}}, {{2, 1, 0}}}};
    const double det = R.determinant();
    double best_score = -INFINITY;
    Eigen::Matrix3d best_R = R;
    Eigen::Vector3d best_extent = extent;
    for (const auto& p : permutations) {
        for (int signs = 0; signs < 8; ++signs) {
            Eigen::Matrix3d C;
            for (int k = 0; k < 3; ++k) C.col(k) = ((signs >> k) & 1 ? 1.0 : -1.0) * R.col(p[k]);
            // Keep rotations only: a reflection would turn a right-handed frame left-handed.
            if (C.determinant() * det < 0.0 || !(det != 0.0)) continue;
            const double score = C.trace();
            if (score > best_score) {
                best_score = score;
                best_R = C;
                for (int k = 0; k < 3; ++k) best_extent(k) = extent(p[k]);
            }
        }
    }
    R = best_R;
    extent = best_extent;
}

OrientedBoundingBox minimal_obb_from_points(const std::vector<Eigen::Vector3d>& points, bool robust) {
    const ConvexHull hull_mesh = compute_convex_hull(points, robust);
    const std::vector<Eigen::Vector3d>& raw = hull_mesh.mesh.vertices;
    // Work relative to the centroid: projections then keep their precision far from the origin.
    Eigen::Vector3d mean = Eigen::Vector3d::Zero();
    for (const auto& p : raw) mean += p;
    mean /= static_cast<double>(raw.size());
    std::vector<Eigen::Vector3d> hull(raw.size());
    for (size_t i = 0; i < raw.size(); ++i) hull[i] = raw[i] - mean;

    // Candidate axes: every face normal, plus the principal axes (the only good ones for a flat, joggled set,
    // whose faces are slivers with meaningless normals).
    std::vector<Candidate> candidates;
    candidates.reserve(hull_mesh.mesh.triangles.size() + 3);
    const HullEdges edges = hull_edges(hull, hull_mesh.mesh.triangles);
    for (const auto& t : hull_mesh.mesh.triangles) {
        const Eigen::Vector3d n = (hull[t(1)] - hull[t(0)]).cross(hull[t(2)] - hull[t(0)]);
        if (n.norm() > 0.0) candidates.push_back(best_box_along(n.normalized(), hull, &edges));
    }
    Eigen::Matrix3d cov = Eigen::Matrix3d::Zero();
    for (const auto& p : hull) cov.noalias() += p * p.transpose();
    const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> pca(cov);
    for (int k = 0; k < 3; ++k) candidates.push_back(best_box_along(pca.eigenvectors().col(k).normalized(), hull));
    // A flat (joggled) set: the box is the plane's minimum-area rectangle; sliver normals and rounding would
    // otherwise pick an arbitrary zero-volume box.
    if (is_flat(hull, pca.eigenvectors())) {
        OrientedBoundingBox box = box_in_frame(best_box_along(pca.eigenvectors().col(0).normalized(), hull).R, hull,
                                               Eigen::Vector3d::Zero());
        box.center += mean;
        permute_axes_closest_to_identity(box.R, box.extent);
        return box;
    }
    std::stable_sort(candidates.begin(), candidates.end(),
                     [](const Candidate& a, const Candidate& b) { return a.volume < b.volume; });

    // Refine the best few distinct directions; the first is the face-flush optimum.
    Candidate best = candidates.front();
    if (best.volume > 0.0) {
        std::vector<Eigen::Vector3d> seeds;
        constexpr size_t kSeeds = 8;
        for (const auto& c : candidates) {
            if (seeds.size() == kSeeds) break;
            const Eigen::Vector3d d = c.R.col(0);
            bool fresh = true;
            for (const auto& s : seeds) fresh = fresh && std::abs(s.dot(d)) < 1.0 - 1e-9;
            if (!fresh) continue;
            seeds.push_back(d);
            const Candidate r = refine(c, hull, edges);
            if (r.volume < best.volume) best = r;
        }
    }

    OrientedBoundingBox box = box_in_frame(best.R, hull, Eigen::Vector3d::Zero());
    box.center += mean;
    permute_axes_closest_to_identity(box.R, box.extent);
    return box;
}

}  // namespace o3d::geometry
