// SPDX-License-Identifier: MIT
#pragma once
/// @file error_quadric.h
/// @brief The Garland-Heckbert error quadric: sum of w * (n.x + d)^2 over planes, stored as
/// x^T A x + 2 b.x + c with A symmetric (6 values).
#include <Eigen/Core>
#include <cmath>

namespace o3d::geometry {

struct ErrorQuadric {
    double a00 = 0, a01 = 0, a02 = 0, a11 = 0, a12 = 0, a22 = 0;
    double b0 = 0, b1 = 0, b2 = 0;
    double c = 0;

    /// @brief weight * squared distance to the plane n.x + d = 0 (n unit length).
    static ErrorQuadric plane(const Eigen::Vector3d& n, double d, double weight) {
        ErrorQuadric q;
        q.a00 = weight * n(0) * n(0);
        q.a01 = weight * n(0) * n(1);
        q.a02 = weight * n(0) * n(2);
        q.a11 = weight * n(1) * n(1);
        q.a12 = weight * n(1) * n(2);
        q.a22 = weight * n(2) * n(2);
        q.b0 = weight * d * n(0);
        q.b1 = weight * d * n(1);
        q.b2 = weight * d * n(2);
        q.c = weight * d * d;
        return q;
    }

    ErrorQuadric& operator+=(const ErrorQuadric& o) {
        a00 += o.a00, a01 += o.a01, a02 += o.a02, a11 += o.a11, a12 += o.a12, a22 += o.a22;
        b0 += o.b0, b1 += o.b1, b2 += o.b2, c += o.c;
        return *this;
    }
    ErrorQuadric operator+(const ErrorQuadric& o) const { return ErrorQuadric(*this) += o; }

    double eval(const Eigen::Vector3d& v) const {
        const double x = v(0), y = v(1), z = v(2);
        return x * (a00 * x + a01 * y + a02 * z) + y * (a01 * x + a11 * y + a12 * z) +
               z * (a02 * x + a12 * y + a22 * z) + 2 * (b0 * x + b1 * y + b2 * z) + c;
    }

    /// @brief The minimiser -A^-1 b when A is well conditioned. A is a positive semi-definite sum of
    /// w n n^T, so det / (sum of principal 2x2 minors) estimates its smallest eigenvalue and the trace its
    /// largest; their ratio (about 1 / condition number) must exceed `min_ratio`. The test is scale-free,
    /// unlike Open3D's |det A| > 1e-4, which calls every quadric of a small or finely tessellated mesh
    /// singular and every one of a mesh in millimetres invertible.
    bool minimum(Eigen::Vector3d& out, double min_ratio = 1e-7) const {
        const double c00 = a11 * a22 - a12 * a12, c01 = a02 * a12 - a01 * a22, c02 = a01 * a12 - a02 * a11;
        const double det = a00 * c00 + a01 * c01 + a02 * c02;
        const double minors = c00 + (a00 * a22 - a02 * a02) + (a00 * a11 - a01 * a01);
        const double trace = a00 + a11 + a22;
        if (!(det > 0 && minors > 0 && trace > 0) || det < min_ratio * minors * trace) return false;
        const double c11 = a00 * a22 - a02 * a02, c12 = a01 * a02 - a00 * a12, c22 = a00 * a11 - a01 * a01;
        // x = -A^-1 b with A^-1 = adj(A) / det (A symmetric, so the adjugate is too).
        out(0) = -(c00 * b0 + c01 * b1 + c02 * b2) / det;
        out(1) = -(c01 * b0 + c11 * b1 + c12 * b2) / det;
        out(2) = -(c02 * b0 + c12 * b1 + c22 * b2) / det;
        return out.allFinite();
    }
};

/// @brief Unit normal n and offset d (n.x + d = 0) of the triangle's plane; false when it has no area.
inline bool triangle_plane(const Eigen::Vector3d& p0, const Eigen::Vector3d& p1, const Eigen::Vector3d& p2,
                           Eigen::Vector3d& n, double& d) {
    n = (p1 - p0).cross(p2 - p0);
    const double len = n.norm();
    if (!(len > 0) || !std::isfinite(len)) return false;
    n /= len;
    d = -n.dot(p0);
    return true;
}

}  // namespace o3d::geometry
