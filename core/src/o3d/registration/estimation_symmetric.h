// SPDX-License-Identifier: MIT
#pragma once
/// @file estimation_symmetric.h
/// @brief Symmetric point-to-plane ICP (Rusinkiewicz, "A Symmetric Objective Function for ICP",
/// SIGGRAPH 2019), as Open3D's TransformationEstimationSymmetric: each pair (s, q) with normals n_s, n_q
/// contributes ((s - q) . n)^2 with n = n_q + n_s (n_q - n_s when they disagree). About the pair means
/// the step linearises a half rotation applied to both sides; the solution g = tan(theta) a is turned
/// into the full rotation R = R_half^2 (eq. 11 of the paper). The kernel weighs the raw residual.
#include <Eigen/Core>
#include <Eigen/Geometry>
#include <cstdint>

#include "o3d/geometry/point_cloud.h"
#include "o3d/registration/registration_result.h"
#include "o3d/registration/robust_kernel.h"

namespace o3d::registration {

/// @brief One symmetric step from `source[c(0)]` to `target[c(1)]` (both clouds need normals).
/// Identity when `corres` is empty or the system is singular.
/// @see o3d.pipelines.registration.TransformationEstimationSymmetric.compute_transformation
/// @throws o3d::InvalidArgument when a cloud has no normals, an index is out of range or the kernel is invalid.
Eigen::Matrix4d estimate_symmetric(const geometry::PointCloud& source, const geometry::PointCloud& target,
                                   const CorrespondenceSet& corres, const RobustKernel& kernel = {});

namespace detail {

/// @brief The symmetric normal of a pair.
inline Eigen::Vector3d symmetric_normal(const Eigen::Vector3d& source_normal, const Eigen::Vector3d& target_normal) {
    return source_normal.dot(target_normal) < 0.0 ? (target_normal - source_normal).eval()
                                                  : (target_normal + source_normal).eval();
}

/// @brief One-pass moments from which the normal equations about the (not yet known) pair means follow
/// exactly. Points are taken relative to a fixed `reference` near the clouds, so that the moments stay
/// small. With a = s + q, e = s - q (relative), u = a x n, rho = e . n and w the kernel weight of rho:
/// the sums of s, q, w u u^T, w u n^T, w n n^T, w u rho and w n rho.
struct SymmetricSums {
    int64_t count = 0;
    Eigen::Vector3d source_sum = Eigen::Vector3d::Zero();
    Eigen::Vector3d target_sum = Eigen::Vector3d::Zero();
    Eigen::Matrix3d uu = Eigen::Matrix3d::Zero();
    Eigen::Matrix3d un = Eigen::Matrix3d::Zero();
    Eigen::Matrix3d nn = Eigen::Matrix3d::Zero();
    Eigen::Vector3d u_rho = Eigen::Vector3d::Zero();
    Eigen::Vector3d n_rho = Eigen::Vector3d::Zero();

    /// `s`, `q` relative to the reference; `n` the symmetric normal.
    void accumulate(const Eigen::Vector3d& s, const Eigen::Vector3d& q, const Eigen::Vector3d& n,
                    const RobustKernel& kernel) {
        ++count;
        source_sum += s;
        target_sum += q;
        const Eigen::Vector3d u = (s + q).cross(n);
        const double rho = (s - q).dot(n);
        const double w = kernel.irls_weight(rho);
        const Eigen::Vector3d wu = w * u;
        const Eigen::Vector3d wn = w * n;
        uu.noalias() += wu * u.transpose();
        un.noalias() += wu * n.transpose();
        nn.noalias() += wn * n.transpose();
        u_rho += wu * rho;
        n_rho += wn * rho;
    }
    void add(const SymmetricSums& o) {
        count += o.count;
        source_sum += o.source_sum;
        target_sum += o.target_sum;
        uu += o.uu;
        un += o.un;
        nn += o.nn;
        u_rho += o.u_rho;
        n_rho += o.n_rho;
    }
};

/// @brief Solve the centred system and return the full transformation in absolute coordinates
/// (the moments were taken relative to `reference`). Identity when there are no pairs or no solution.
Eigen::Matrix4d solve_symmetric(const SymmetricSums& sums, const Eigen::Vector3d& reference);

}  // namespace detail
}  // namespace o3d::registration
