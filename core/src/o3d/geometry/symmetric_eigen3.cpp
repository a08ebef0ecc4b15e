// SPDX-License-Identifier: MIT
#include "o3d/geometry/symmetric_eigen3.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>

namespace o3d::geometry {
namespace {

/// @brief A unit vector in the null space of the (nearly) rank-2 matrix m: the longest cross
/// product of two of its rows. Zero when m has rank < 2.
Eigen::Vector3d null_vector_of_rank2(const Eigen::Matrix3d& m) {
    const Eigen::Vector3d r0 = m.row(0), r1 = m.row(1), r2 = m.row(2);
    const Eigen::Vector3d c[3] = {r0.cross(r1), r0.cross(r2), r1.cross(r2)};
    int best = 0;
    double best_norm2 = c[0].squaredNorm();
    for (int i = 1; i < 3; ++i) {
        const double n2 = c[i].squaredNorm();
        if (n2 > best_norm2) {
            best_norm2 = n2;
            best = i;
        }
    }
    if (best_norm2 == 0.0) return Eigen::Vector3d::Zero();
    return c[best] / std::sqrt(best_norm2);
}

/// @brief Any unit vector orthogonal to the unit vector v.
Eigen::Vector3d any_orthogonal(const Eigen::Vector3d& v) {
    Eigen::Vector3d u = std::abs(v.x()) > std::abs(v.y()) ? Eigen::Vector3d(-v.z(), 0.0, v.x())
                                                          : Eigen::Vector3d(0.0, v.z(), -v.y());
    return u.normalized();
}

/// @brief Smallest eigenvector of `a` inside the plane orthogonal to the unit eigenvector `v_max`.
Eigen::Vector3d smallest_in_plane(const Eigen::Matrix3d& a, const Eigen::Vector3d& v_max) {
    const Eigen::Vector3d u = any_orthogonal(v_max);
    const Eigen::Vector3d w = v_max.cross(u);
    const double p = u.dot(a * u), q = u.dot(a * w), r = w.dot(a * w);
    // 2x2 symmetric [[p q][q r]]: smaller eigenvalue and its eigenvector, picking the better-conditioned form.
    const double lambda = 0.5 * (p + r) - std::hypot(0.5 * (p - r), q);
    const Eigen::Vector2d e1(q, lambda - p), e2(lambda - r, q);
    const Eigen::Vector2d e = e1.squaredNorm() >= e2.squaredNorm() ? e1 : e2;
    const double norm = e.norm();
    if (norm == 0.0) return u;  // isotropic in the plane: every direction is an eigenvector
    return (e.x() * u + e.y() * w) / norm;
}

}  // namespace

Eigen::Vector3d smallest_eigenvector(const Eigen::Matrix3d& input) {
    const double max_coeff = input.cwiseAbs().maxCoeff();
    if (!(max_coeff > 0.0) || !std::isfinite(max_coeff)) return Eigen::Vector3d::Zero();
    const Eigen::Matrix3d a = input / max_coeff;

    const double off = a(0, 1) * a(0, 1) + a(0, 2) * a(0, 2) + a(1, 2) * a(1, 2);
    if (off == 0.0) {
        int axis = 2;
        for (int i = 1; i >= 0; --i)
            if (a(i, i) < a(axis, axis)) axis = i;
        return Eigen::Vector3d::Unit(axis);
    }

    // Eigenvalues of a = q I + p B with tr(B) = 0, |B|_F^2 = 6: they are q + 2p cos(phi + 2k pi / 3).
    const double q = a.trace() / 3.0;
    const Eigen::Matrix3d shifted = a - q * Eigen::Matrix3d::Identity();
    const double p = std::sqrt((shifted.squaredNorm()) / 6.0);
    if (p == 0.0) return Eigen::Vector3d::UnitZ();
    const double half_det = std::clamp((shifted / p).determinant() / 2.0, -1.0, 1.0);
    const double phi = std::acos(half_det) / 3.0;
    const double two_pi_3 = 2.0943951023931954923;
    const double e_max = q + 2.0 * p * std::cos(phi);
    const double e_min = q + 2.0 * p * std::cos(phi + two_pi_3);
    const double e_mid = 3.0 * q - e_max - e_min;

    // Solve first for whichever extreme eigenvalue is better separated from the middle one:
    // its shifted matrix then has a well-defined rank-2 row space.
    if (e_mid - e_min >= e_max - e_mid) {
        const Eigen::Vector3d v = null_vector_of_rank2(a - e_min * Eigen::Matrix3d::Identity());
        if (v.squaredNorm() > 0.0) return v;
    }
    const Eigen::Vector3d v_max = null_vector_of_rank2(a - e_max * Eigen::Matrix3d::Identity());
    if (v_max.squaredNorm() == 0.0) return Eigen::Vector3d::UnitZ();
    return smallest_in_plane(a, v_max);
}

}  // namespace o3d::geometry
