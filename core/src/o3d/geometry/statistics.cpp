// SPDX-License-Identifier: MIT
#include "o3d/geometry/statistics.h"

#include <Eigen/Eigenvalues>
#include <cmath>
#include <limits>

#include "o3d/utility/error.h"
#include "o3d/utility/parallel.h"

namespace o3d::geometry {

std::pair<Eigen::Vector3d, Eigen::Matrix3d> compute_mean_and_covariance(const PointCloud& cloud) {
    if (cloud.points.empty()) throw InvalidArgument("point cloud is empty: mean and covariance are undefined");
    const double n = static_cast<double>(cloud.points.size());
    Eigen::Vector3d mean = Eigen::Vector3d::Zero();
    for (const auto& p : cloud.points) mean += p;
    mean /= n;
    Eigen::Matrix3d cov = Eigen::Matrix3d::Zero();
    for (const auto& p : cloud.points) {
        const Eigen::Vector3d d = p - mean;
        cov.noalias() += d * d.transpose();
    }
    cov /= n;
    return {mean, cov};
}

std::vector<double> compute_mahalanobis_distance(const PointCloud& cloud, int num_threads) {
    const auto [mean, cov] = compute_mean_and_covariance(cloud);
    Eigen::Matrix3d cov_pinv = Eigen::Matrix3d::Zero();
    if (cov.allFinite()) {
        const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eig(cov);
        const Eigen::Vector3d ev = eig.eigenvalues();
        const double largest = ev.cwiseAbs().maxCoeff();
        const double tol = 1e-12 * largest;
        Eigen::Vector3d inv = Eigen::Vector3d::Zero();
        for (int i = 0; i < 3; ++i)
            if (largest > 0.0 && ev[i] > tol) inv[i] = 1.0 / ev[i];
        cov_pinv = eig.eigenvectors() * inv.asDiagonal() * eig.eigenvectors().transpose();
    } else {
        cov_pinv.setConstant(std::numeric_limits<double>::quiet_NaN());  // non-finite points: NaN, as Open3D
    }
    const int64_t n = static_cast<int64_t>(cloud.points.size());
    std::vector<double> out(cloud.points.size());
    const int threads = utility::resolve_num_threads(num_threads);
#pragma omp parallel for schedule(static) num_threads(threads) if (n > 4096)
    for (int64_t i = 0; i < n; ++i) {
        const Eigen::Vector3d d = cloud.points[i] - mean;
        const double q = d.dot(cov_pinv * d);
        out[i] = q < 0.0 ? 0.0 : std::sqrt(q);  // rounding can dip below 0; NaN stays NaN
    }
    return out;
}

}  // namespace o3d::geometry
