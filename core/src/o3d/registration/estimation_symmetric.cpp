// SPDX-License-Identifier: MIT
#include "o3d/registration/estimation_symmetric.h"

#include <Eigen/Cholesky>
#include <cmath>

#include "o3d/registration/estimation_point_to_plane.h"
#include "o3d/utility/error.h"

namespace o3d::registration {
namespace detail {

namespace {

Eigen::Matrix3d skew(const Eigen::Vector3d& v) {
    Eigen::Matrix3d m;
    m << 0.0, -v(2), v(1), v(2), 0.0, -v(0), -v(1), v(0), 0.0;
    return m;
}

}  // namespace

Eigen::Matrix4d solve_symmetric(const SymmetricSums& sums, const Eigen::Vector3d& reference) {
    if (sums.count == 0) return Eigen::Matrix4d::Identity();
    const double inv_n = 1.0 / static_cast<double>(sums.count);
    const Eigen::Vector3d source_mean = sums.source_sum * inv_n;
    const Eigen::Vector3d target_mean = sums.target_sum * inv_n;
    // Centred, the rows are J = [(a - m) x n, n] = [u - K n, n] and r = rho - n . delta, with
    // m = mean(s) + mean(q), delta = mean(s) - mean(q) and K = [m]x; expanding the products needs only
    // the moments gathered in the pass.
    const Eigen::Vector3d m = source_mean + target_mean;
    const Eigen::Vector3d delta = source_mean - target_mean;
    const Eigen::Matrix3d k = skew(m);
    const Eigen::Matrix3d k_nn = k * sums.nn;
    const Eigen::Matrix3d un_kt = sums.un * k.transpose();
    Eigen::Matrix<double, 6, 6> jtj;
    jtj.topLeftCorner<3, 3>() = sums.uu - un_kt - un_kt.transpose() + k_nn * k.transpose();
    jtj.topRightCorner<3, 3>() = sums.un - k_nn;
    jtj.bottomLeftCorner<3, 3>() = jtj.topRightCorner<3, 3>().transpose();
    jtj.bottomRightCorner<3, 3>() = sums.nn;
    const Eigen::Vector3d nn_delta = sums.nn * delta;
    Eigen::Matrix<double, 6, 1> jtr;
    jtr.head<3>() = sums.u_rho - sums.un * delta - k * sums.n_rho + k * nn_delta;
    jtr.tail<3>() = sums.n_rho - nn_delta;

    const Eigen::Matrix<double, 6, 1> x = jtj.ldlt().solve(-jtr);
    Eigen::Matrix4d out = Eigen::Matrix4d::Identity();
    if (!x.allFinite()) return out;
    // x = (g, t): g = tan(theta) a is the half rotation; t is the translation between the rotated halves.
    const Eigen::Vector3d g = x.head<3>();
    const double g_norm = g.norm();
    const double theta = std::atan(g_norm);
    const Eigen::Matrix3d half =
        g_norm > 0.0 ? Eigen::AngleAxisd(theta, g / g_norm).toRotationMatrix() : Eigen::Matrix3d::Identity();
    const Eigen::Matrix3d rotation = half * half;
    out.topLeftCorner<3, 3>() = rotation;
    out.topRightCorner<3, 1>() = (target_mean + reference) + half * (x.tail<3>() * std::cos(theta)) -
                                 rotation * (source_mean + reference);
    return out;
}

}  // namespace detail

Eigen::Matrix4d estimate_symmetric(const geometry::PointCloud& source, const geometry::PointCloud& target,
                                   const CorrespondenceSet& corres, const RobustKernel& kernel) {
    if (!source.has_normals()) throw InvalidArgument("symmetric ICP needs source normals");
    if (!target.has_normals()) throw InvalidArgument("symmetric ICP needs target normals");
    check_robust_kernel(kernel);
    detail::check_correspondences(corres, source.size(), target.size());
    if (corres.empty()) return Eigen::Matrix4d::Identity();
    const Eigen::Vector3d reference = target.points[corres.front()(1)];
    detail::SymmetricSums sums;
    for (const auto& c : corres)
        sums.accumulate(source.points[c(0)] - reference, target.points[c(1)] - reference,
                        detail::symmetric_normal(source.normals[c(0)], target.normals[c(1)]), kernel);
    return detail::solve_symmetric(sums, reference);
}

}  // namespace o3d::registration
