// SPDX-License-Identifier: MIT
#include "o3d/registration/estimation_generalized.h"

#include <Eigen/Eigenvalues>
#include <Eigen/LU>  // 3x3 inverse
#include <cmath>
#include <string>

#include "o3d/geometry/normals.h"
#include "o3d/utility/error.h"
#include "o3d/utility/parallel.h"

namespace o3d::registration {
namespace detail {

void check_epsilon(double epsilon) {
    if (!(std::isfinite(epsilon) && epsilon > 0.0))
        throw InvalidArgument("epsilon must be finite and > 0, got " + std::to_string(epsilon));
}

void GeneralizedSums::accumulate_l2(const Eigen::Vector3d& s, const Eigen::Vector3d& d, const Eigen::Matrix3d& c) {
    const double det = c.determinant();
    if (!(det > 0.0) || !std::isfinite(det)) return;  // not positive definite: no information
    const Eigen::Matrix3d a = c.inverse();
    // With S = [s]x: J^T A J = [[S A S^T, S A], [A S^T, A]] and J^T A d = [S A d, A d].
    Eigen::Matrix3d sa;
    for (int j = 0; j < 3; ++j) sa.col(j) = s.cross(a.col(j));
    Eigen::Matrix3d sas;
    for (int j = 0; j < 3; ++j) sas.col(j) = s.cross(sa.row(j).transpose());
    const Eigen::Vector3d ad = a * d;
    const Eigen::Vector3d sad = s.cross(ad);
    // Upper triangle of the 6x6, row-major (rotation rows 0-2, translation rows 3-5).
    const double h[21] = {sas(0, 0), sas(0, 1), sas(0, 2), sa(0, 0),  sa(0, 1), sa(0, 2), sas(1, 1),
                          sas(1, 2), sa(1, 0),  sa(1, 1),  sa(1, 2),  sas(2, 2), sa(2, 0), sa(2, 1),
                          sa(2, 2),  a(0, 0),   a(0, 1),   a(0, 2),   a(1, 1),   a(1, 2),  a(2, 2)};
    for (int k = 0; k < 21; ++k) jtj[k] += h[k];
    for (int k = 0; k < 3; ++k) {
        jtr[k] += sad(k);
        jtr[k + 3] += ad(k);
    }
}

void GeneralizedSums::accumulate_robust(const Eigen::Vector3d& s, const Eigen::Vector3d& d, const Eigen::Matrix3d& c,
                                        const RobustKernel& kernel) {
    if (!c.allFinite()) return;
    Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eig;
    eig.computeDirect(c);
    if (eig.info() != Eigen::Success || !(eig.eigenvalues().minCoeff() > 0.0)) return;
    // The symmetric square root of the inverse, as Open3D's M.inverse().sqrt().
    const Eigen::Matrix3d w =
        eig.eigenvectors() * eig.eigenvalues().cwiseSqrt().cwiseInverse().asDiagonal() * eig.eigenvectors().transpose();
    for (int i = 0; i < 3; ++i) {
        const Eigen::Vector3d row = w.row(i).transpose();
        const Eigen::Vector3d sxw = s.cross(row);
        const double j[6] = {sxw(0), sxw(1), sxw(2), row(0), row(1), row(2)};
        const double r = row.dot(d);
        add_row(j, r, kernel.irls_weight(r));
    }
}

}  // namespace detail

std::vector<Eigen::Matrix3d> generalized_icp_covariances(const geometry::PointCloud& cloud, double epsilon,
                                                         int num_threads, const kdtree::KDTree* tree) {
    detail::check_epsilon(epsilon);
    if (cloud.has_covariances()) return cloud.covariances;
    if (tree && tree->size() != cloud.size())
        throw InvalidArgument("the tree indexes " + std::to_string(tree->size()) + " points but the cloud has " +
                              std::to_string(cloud.size()));
    std::vector<Eigen::Vector3d> estimated;
    if (!cloud.has_normals()) {
        // As the original GICP: the normal of each point's 20-neighbourhood (orientation is irrelevant here).
        geometry::PointCloud points_only;
        points_only.points = cloud.points;
        const auto param = kdtree::SearchParam::make_knn(20);
        if (tree)
            geometry::estimate_normals(points_only, *tree, param, num_threads);
        else
            geometry::estimate_normals(points_only, param, num_threads);
        estimated = std::move(points_only.normals);
    }
    const std::vector<Eigen::Vector3d>& normals = cloud.has_normals() ? cloud.normals : estimated;
    std::vector<Eigen::Matrix3d> out(normals.size());
    for (size_t i = 0; i < normals.size(); ++i) {
        const Eigen::Vector3d& n = normals[i];
        // Open3D rotates diag(epsilon, 1, 1) so that its first axis becomes n: that is this matrix.
        out[i] = Eigen::Matrix3d::Identity() - (1.0 - epsilon) * n * n.transpose();
    }
    return out;
}

Eigen::Matrix4d estimate_generalized(const geometry::PointCloud& source, const geometry::PointCloud& target,
                                     const CorrespondenceSet& corres, const RobustKernel& kernel) {
    if (!source.has_covariances()) throw InvalidArgument("generalized ICP estimation needs source covariances");
    if (!target.has_covariances()) throw InvalidArgument("generalized ICP estimation needs target covariances");
    check_robust_kernel(kernel);
    detail::check_correspondences(corres, source.size(), target.size());
    detail::GeneralizedSums sums;
    for (const auto& c : corres) {
        const Eigen::Vector3d& s = source.points[c(0)];
        sums.accumulate(s, s - target.points[c(1)], source.covariances[c(0)] + target.covariances[c(1)], kernel);
    }
    return detail::solve_point_to_plane(sums);
}

}  // namespace o3d::registration
