// SPDX-License-Identifier: MIT
#include "o3d/registration/estimation_point_to_point.h"

#include <Eigen/LU>  // determinant
#include <Eigen/SVD>
#include <cmath>
#include <string>

#include "o3d/utility/error.h"

namespace o3d::registration {
namespace detail {

Eigen::Matrix4d solve_point_to_point(const PointToPointSums& sums, const Eigen::Vector3d& reference,
                                     bool with_scaling) {
    Eigen::Matrix4d out = Eigen::Matrix4d::Identity();
    if (sums.count == 0) return out;
    const double inv_n = 1.0 / static_cast<double>(sums.count);
    const Eigen::Vector3d mean_s = sums.source_sum * inv_n;
    const Eigen::Vector3d mean_t = sums.target_sum * inv_n;
    const Eigen::Matrix3d sigma = sums.cross * inv_n - mean_t * mean_s.transpose();

    Eigen::JacobiSVD<Eigen::Matrix3d> svd(sigma, Eigen::ComputeFullU | Eigen::ComputeFullV);
    // A reflection is never a valid answer: flip the weakest axis instead (Umeyama eq. 39).
    Eigen::Vector3d s = Eigen::Vector3d::Ones();
    if (svd.matrixU().determinant() * svd.matrixV().determinant() < 0) s(2) = -1.0;
    const Eigen::Matrix3d rotation = svd.matrixU() * s.asDiagonal() * svd.matrixV().transpose();

    double scale = 1.0;
    if (with_scaling) {
        const double source_var = sums.source_norm2 * inv_n - mean_s.squaredNorm();
        // All sources coincide: the scale is undetermined; keep 1 rather than divide by zero.
        if (source_var > 0.0) scale = svd.singularValues().dot(s) / source_var;
    }
    if (!rotation.allFinite() || !std::isfinite(scale)) return out;
    out.topLeftCorner<3, 3>() = scale * rotation;
    // Means are relative to `reference`; t = mu_t - c R mu_s in absolute coordinates.
    out.topRightCorner<3, 1>() = (mean_t + reference) - scale * rotation * (mean_s + reference);
    return out;
}

}  // namespace detail

Eigen::Matrix4d estimate_point_to_point(const geometry::PointCloud& source, const geometry::PointCloud& target,
                                        const CorrespondenceSet& corres, bool with_scaling) {
    detail::PointToPointSums sums;
    const Eigen::Vector3d reference = target.points.empty() ? Eigen::Vector3d::Zero() : target.points[0];
    for (const auto& c : corres) {
        if (c(0) < 0 || static_cast<size_t>(c(0)) >= source.size() || c(1) < 0 ||
            static_cast<size_t>(c(1)) >= target.size())
            throw InvalidArgument("correspondence (" + std::to_string(c(0)) + ", " + std::to_string(c(1)) +
                                  ") is out of range");
        sums.accumulate(source.points[c(0)] - reference, target.points[c(1)] - reference);
    }
    return detail::solve_point_to_point(sums, reference, with_scaling);
}

}  // namespace o3d::registration
