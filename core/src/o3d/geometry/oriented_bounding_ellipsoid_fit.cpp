// SPDX-License-Identifier: MIT
#include "o3d/geometry/oriented_bounding_ellipsoid_fit.h"

#include <Eigen/Cholesky>
#include <Eigen/Eigenvalues>
#include <cmath>

#include "o3d/geometry/convex_hull.h"
#include "o3d/geometry/minimal_bounding_box.h"
#include "o3d/utility/error.h"

namespace o3d::geometry {
namespace {

constexpr double kWeightTolerance = 1e-6;  // Open3D's eps on |p_new - p|
constexpr int kMaxIterations = 1000;       // Open3D's maxiter

/// @brief Khachiyan's weights for the points (columns of `x`, centred): the dual of the minimum-volume
/// ellipsoid problem, approached by Frank-Wolfe steps on the log-determinant of the lifted moment matrix.
Eigen::VectorXd khachiyan_weights(const Eigen::Matrix3Xd& x) {
    const Eigen::Index n = x.cols();
    Eigen::Matrix4Xd q(4, n);
    q.topRows<3>() = x;
    q.row(3).setOnes();
    Eigen::VectorXd p = Eigen::VectorXd::Constant(n, 1.0 / static_cast<double>(n));
    double moved = 2.0 * kWeightTolerance;
    for (int iter = 0; iter < kMaxIterations && moved > kWeightTolerance; ++iter) {
        const Eigen::Matrix4d lambda = q * p.asDiagonal() * q.transpose();
        const Eigen::LDLT<Eigen::Matrix4d> ldlt(lambda);
        if (ldlt.info() != Eigen::Success) throw InvalidArgument("the ellipsoid's moment matrix is singular");
        // Only the diagonal of q^T Lambda^-1 q is needed: n small solves instead of Open3D's n x n product.
        const Eigen::Matrix4Xd solved = ldlt.solve(q);
        Eigen::Index j = 0;
        double m_max = -INFINITY;
        for (Eigen::Index i = 0; i < n; ++i) {
            const double m = q.col(i).dot(solved.col(i));
            if (m > m_max) {  // the first largest, as Eigen's maxCoeff
                m_max = m;
                j = i;
            }
        }
        const double step = (m_max - 4.0) / (4.0 * (m_max - 1.0));
        // |p_new - p|^2 = step^2 (|p|^2 - 2 p_j + 1), without forming p_new.
        moved = std::abs(step) * std::sqrt(std::max(0.0, p.squaredNorm() - 2.0 * p(j) + 1.0));
        p *= 1.0 - step;
        p(j) += step;
    }
    return p;
}

}  // namespace

OrientedBoundingEllipsoid ellipsoid_from_points(const std::vector<Eigen::Vector3d>& points, bool robust) {
    const ConvexHull hull_mesh = compute_convex_hull(points, robust);
    const std::vector<Eigen::Vector3d>& raw = hull_mesh.mesh.vertices;
    // Khachiyan's iteration is affine-invariant: centring only buys precision far from the origin.
    Eigen::Vector3d mean = Eigen::Vector3d::Zero();
    for (const auto& v : raw) mean += v;
    mean /= static_cast<double>(raw.size());
    std::vector<Eigen::Vector3d> centred(raw.size());
    Eigen::Matrix3Xd x(3, static_cast<Eigen::Index>(raw.size()));
    for (size_t i = 0; i < raw.size(); ++i) {
        centred[i] = raw[i] - mean;
        x.col(static_cast<Eigen::Index>(i)) = centred[i];
    }
    Eigen::Matrix3d cov = x * x.transpose();
    if (is_flat(centred, Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d>(cov).eigenvectors()))
        throw InvalidArgument("the points are coplanar: no solid ellipsoid encloses them (Open3D gives a NaN radius)");

    const Eigen::VectorXd p = khachiyan_weights(x);
    const Eigen::Vector3d c = x * p;
    const Eigen::Matrix3d spread = x * p.asDiagonal() * x.transpose() - c * c.transpose();
    // Q = spread^-1 / 3 shares spread's eigenvectors; its radii 1/sqrt(eig(Q)) are sqrt(3 eig(spread)).
    const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> es(spread);
    if (es.info() != Eigen::Success || !(es.eigenvalues().minCoeff() > 0.0))
        throw InvalidArgument("the ellipsoid fit degenerated (a zero-width axis)");

    OrientedBoundingEllipsoid e;
    e.center = c + mean;
    e.R = es.eigenvectors();
    e.radii = (3.0 * es.eigenvalues()).cwiseSqrt();
    if (e.R.determinant() < 0.0) e.R.col(2) = -e.R.col(2);  // a rotation, whatever the solver's signs
    permute_axes_closest_to_identity(e.R, e.radii);
    return e;
}

}  // namespace o3d::geometry
