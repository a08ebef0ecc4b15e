// SPDX-License-Identifier: MIT
#pragma once
/// @file estimation_point_to_plane.h
/// @brief Linearised point-to-plane step (Low 2004), as Open3D's TransformationEstimationPointToPlane:
/// minimise sum(w(r) r^2) with r = (R s + t - q) . n_q, R ~ I + [w]x, solve the 6x6 normal equations,
/// and rebuild R = Rz(w_z) Ry(w_y) Rx(w_x). Also the 6-parameter normal equations that the other
/// Gauss-Newton estimations (colored, generalized) share.
#include <Eigen/Core>
#include <Eigen/Geometry>  // cross product
#include <cstdint>

#include "o3d/geometry/point_cloud.h"
#include "o3d/registration/registration_result.h"
#include "o3d/registration/robust_kernel.h"

namespace o3d::registration {

/// @brief One Gauss-Newton step aligning `source[c(0)]` to the planes of `target[c(1)]`, each residual
/// weighted by `kernel`. Identity when `corres` is empty or the system is singular.
/// @see o3d.pipelines.registration.TransformationEstimationPointToPlane.compute_transformation
/// @throws o3d::InvalidArgument when `target` has no normals, an index is out of range or the kernel is invalid.
Eigen::Matrix4d estimate_point_to_plane(const geometry::PointCloud& source, const geometry::PointCloud& target,
                                        const CorrespondenceSet& corres, const RobustKernel& kernel = {});

namespace detail {

/// @brief J^T W J (upper triangle, row-major, 21 values) and J^T W r of a least-squares problem in the
/// six parameters (rotation w, translation t), one scalar residual row at a time.
struct NormalEquations6 {
    double jtj[21] = {};
    double jtr[6] = {};

    void add_row(const double j[6], double r, double w) {
        int k = 0;
        for (int a = 0; a < 6; ++a) {
            const double wj = w * j[a];
            for (int b = a; b < 6; ++b) jtj[k++] += wj * j[b];
            jtr[a] += wj * r;
        }
    }
    void add(const NormalEquations6& o) {
        for (int k = 0; k < 21; ++k) jtj[k] += o.jtj[k];
        for (int k = 0; k < 6; ++k) jtr[k] += o.jtr[k];
    }
    /// @brief The solution x of J^T W J x = -J^T W r (LDLT, as Open3D's SolveLinearSystemPSD).
    Eigen::Matrix<double, 6, 1> solve() const;
};

/// @brief Point-to-plane rows: J = [s x n, n], r = (s - q) . n.
struct PointToPlaneSums : NormalEquations6 {
    void accumulate(const Eigen::Vector3d& s, const Eigen::Vector3d& q, const Eigen::Vector3d& n,
                    const RobustKernel& kernel) {
        const Eigen::Vector3d c = s.cross(n);
        const double j[6] = {c(0), c(1), c(2), n(0), n(1), n(2)};
        const double r = (s - q).dot(n);
        add_row(j, r, kernel.irls_weight(r));
    }
};

/// @brief x = (w, t) -> 4x4 with R = Rz(w_z) Ry(w_y) Rx(w_x) (Open3D's TransformVector6dToMatrix4d).
/// Identity when x is not finite.
Eigen::Matrix4d euler_pose_to_matrix(const Eigen::Matrix<double, 6, 1>& x);

/// @brief Solve the normal equations and turn the solution into a 4x4 (Euler angles).
inline Eigen::Matrix4d solve_point_to_plane(const NormalEquations6& sums) { return euler_pose_to_matrix(sums.solve()); }

/// @brief Throw o3d::InvalidArgument on a correspondence outside either cloud.
void check_correspondences(const CorrespondenceSet& corres, size_t num_source, size_t num_target);

}  // namespace detail
}  // namespace o3d::registration
