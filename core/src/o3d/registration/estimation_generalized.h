// SPDX-License-Identifier: MIT
#pragma once
/// @file estimation_generalized.h
/// @brief Generalized ICP (Segal, Haehnel, Thrun, "Generalized-ICP", RSS 2009), as Open3D's
/// TransformationEstimationForGeneralizedICP: each pair (s, q) with covariances C_s, C_q contributes the
/// Mahalanobis distance d^T (C_q + R C_s R^T)^-1 d, d = R s + t - q. The step linearises d in the
/// rotation (R ~ I + [w]x) with the combined covariance held fixed, and rebuilds R from Euler angles.
/// With a robust kernel every row of W d (W = (C_q + R C_s R^T)^-1/2) is weighted on its own.
#include <Eigen/Core>
#include <Eigen/Geometry>
#include <vector>

#include "o3d/geometry/point_cloud.h"
#include "o3d/kdtree/kd_tree.h"
#include "o3d/registration/estimation_point_to_plane.h"
#include "o3d/registration/registration_result.h"
#include "o3d/registration/robust_kernel.h"

namespace o3d::registration {

/// @brief The per-point covariances generalized ICP uses (Open3D's InitializePointCloudForGeneralizedICP):
/// the cloud's own `covariances` when it has them; else, from each normal n, the plane-like
/// epsilon n n^T + (I - n n^T) (variance epsilon across the surface, 1 along it); else the same from
/// normals estimated over 20 nearest neighbours. `tree` (may be NULL) indexes cloud.points and is only
/// used for that estimation. Independent of num_threads (0 = default).
/// @throws o3d::InvalidArgument when epsilon is not finite and > 0, or the tree does not match.
std::vector<Eigen::Matrix3d> generalized_icp_covariances(const geometry::PointCloud& cloud, double epsilon = 1e-3,
                                                         int num_threads = 0, const kdtree::KDTree* tree = nullptr);

/// @brief One generalized-ICP step from `source[c(0)]` to `target[c(1)]`, both clouds carrying
/// covariances (see generalized_icp_covariances). Pairs whose combined covariance is not positive
/// definite are left out. Identity when no pair remains or the system is singular.
/// @see o3d.pipelines.registration.TransformationEstimationForGeneralizedICP.compute_transformation
/// @throws o3d::InvalidArgument when a cloud has no covariances, an index is out of range or the kernel is invalid.
Eigen::Matrix4d estimate_generalized(const geometry::PointCloud& source, const geometry::PointCloud& target,
                                     const CorrespondenceSet& corres, const RobustKernel& kernel = {});

namespace detail {

/// @brief Throw o3d::InvalidArgument unless epsilon is finite and > 0.
void check_epsilon(double epsilon);

/// @brief Normal equations of generalized ICP.
struct GeneralizedSums : NormalEquations6 {
    /// Moved source point `s`, d = s - q, combined covariance `c` (source part already rotated).
    void accumulate(const Eigen::Vector3d& s, const Eigen::Vector3d& d, const Eigen::Matrix3d& c,
                    const RobustKernel& kernel) {
        if (kernel.type == RobustKernelType::L2)
            accumulate_l2(s, d, c);
        else
            accumulate_robust(s, d, c, kernel);
    }

    /// Unweighted: J^T C^-1 J and J^T C^-1 d with J = [-[s]x, I], summed in closed form (the rows of
    /// C^-1/2 are never formed).
    void accumulate_l2(const Eigen::Vector3d& s, const Eigen::Vector3d& d, const Eigen::Matrix3d& c);
    /// Weighted: one row [s x w_i, w_i], residual w_i . d per row w_i of C^-1/2.
    void accumulate_robust(const Eigen::Vector3d& s, const Eigen::Vector3d& d, const Eigen::Matrix3d& c,
                           const RobustKernel& kernel);
};

}  // namespace detail
}  // namespace o3d::registration
