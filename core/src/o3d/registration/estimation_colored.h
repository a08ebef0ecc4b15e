// SPDX-License-Identifier: MIT
#pragma once
/// @file estimation_colored.h
/// @brief Colored ICP (Park, Zhou, Koltun, "Colored Point Cloud Registration Revisited", ICCV 2017), as
/// Open3D's TransformationEstimationForColoredICP: a Gauss-Newton step on the joint objective
/// lambda * r_G^2 + (1 - lambda) * r_C^2, where r_G is the point-to-plane residual and r_C compares the
/// source intensity with the target intensity extrapolated along the target's tangent-plane gradient.
/// Intensity is the mean of R, G and B.
#include <Eigen/Core>
#include <Eigen/Geometry>
#include <cmath>
#include <vector>

#include "o3d/geometry/point_cloud.h"
#include "o3d/kdtree/kd_tree.h"
#include "o3d/registration/estimation_point_to_plane.h"
#include "o3d/registration/registration_result.h"
#include "o3d/registration/robust_kernel.h"

namespace o3d::registration {

/// @brief Mean of R, G and B of each color.
std::vector<double> color_intensities(const std::vector<Eigen::Vector3d>& colors);

/// @brief Intensity gradient of each target point within its tangent plane (Open3D's
/// InitializePointCloudForColoredICP, 0.20): the least-squares g with g . (p_j - p) = I_j - I over the
/// neighbours j, plus the constraint g . n = 0 weighted by the neighbour count. Neighbours come from a
/// hybrid search (`radius`, `max_nn`, the point itself included); fewer than 4, or neighbours on a line
/// (the gradient across it undetermined), give a zero gradient.
/// `tree` indexes target.points. Independent of num_threads (0 = default).
/// @throws o3d::InvalidArgument when `target` lacks colors or normals, the tree does not match, or the
/// search parameters are not > 0.
std::vector<Eigen::Vector3d> compute_color_gradients(const geometry::PointCloud& target, const kdtree::KDTree& tree,
                                                     double radius, int max_nn, int num_threads = 0);

/// @brief One colored-ICP step from `source[c(0)]` to `target[c(1)]`, with `target_gradients` from
/// compute_color_gradients. Identity when `corres` is empty or the system is singular.
/// @see o3d.pipelines.registration.TransformationEstimationForColoredICP.compute_transformation
/// @throws o3d::InvalidArgument when a cloud lacks colors, the target lacks normals, the gradients do not
/// match the target, an index is out of range, lambda_geometric is outside [0, 1] or the kernel is invalid.
Eigen::Matrix4d estimate_colored(const geometry::PointCloud& source, const geometry::PointCloud& target,
                                 const std::vector<Eigen::Vector3d>& target_gradients, const CorrespondenceSet& corres,
                                 double lambda_geometric = 0.968, const RobustKernel& kernel = {});

/// @brief Open3D's TransformationEstimationForColoredICP.compute_rmse: despite the name, the plain sum
/// over the pairs of lambda r_G^2 + (1 - lambda) r_C^2 (neither averaged nor rooted). Throws as estimate_colored.
double colored_residual(const geometry::PointCloud& source, const geometry::PointCloud& target,
                        const std::vector<Eigen::Vector3d>& target_gradients, const CorrespondenceSet& corres,
                        double lambda_geometric = 0.968);

namespace detail {

/// @brief Throw o3d::InvalidArgument unless 0 <= lambda_geometric <= 1 (NaN rejected).
void check_lambda_geometric(double lambda_geometric);

/// @brief The two weighted rows of one colored-ICP pair.
struct ColoredRows {
    double sqrt_geometric;    ///< sqrt(lambda)
    double sqrt_photometric;  ///< sqrt(1 - lambda)

    explicit ColoredRows(double lambda_geometric)
        : sqrt_geometric(std::sqrt(lambda_geometric)), sqrt_photometric(std::sqrt(1.0 - lambda_geometric)) {}

    /// Source point `s` with intensity `is`; target point `q`, normal `n`, gradient `g`, intensity `it`.
    /// Writes the geometric row (jg, rg) and the photometric row (jc, rc).
    void rows(const Eigen::Vector3d& s, double is, const Eigen::Vector3d& q, const Eigen::Vector3d& n,
              const Eigen::Vector3d& g, double it, double jg[6], double& rg, double jc[6], double& rc) const {
        const Eigen::Vector3d sxn = s.cross(n);
        const double distance = (s - q).dot(n);
        for (int a = 0; a < 3; ++a) {
            jg[a] = sqrt_geometric * sxn(a);
            jg[a + 3] = sqrt_geometric * n(a);
        }
        rg = sqrt_geometric * distance;
        // The intensity the target's plane predicts at s projected onto it; its derivative is the
        // gradient with the normal component removed: -(I - n n^T) g.
        const Eigen::Vector3d projected = s - distance * n;
        const double predicted = g.dot(projected - q) + it;
        const Eigen::Vector3d dg = -(g - n.dot(g) * n);
        const Eigen::Vector3d sxdg = s.cross(dg);
        for (int a = 0; a < 3; ++a) {
            jc[a] = sqrt_photometric * sxdg(a);
            jc[a + 3] = sqrt_photometric * dg(a);
        }
        rc = sqrt_photometric * (is - predicted);
    }
};

/// @brief Normal equations of colored ICP.
struct ColoredSums : NormalEquations6 {
    void accumulate(const ColoredRows& rows, const Eigen::Vector3d& s, double is, const Eigen::Vector3d& q,
                    const Eigen::Vector3d& n, const Eigen::Vector3d& g, double it, const RobustKernel& kernel) {
        double jg[6], jc[6], rg, rc;
        rows.rows(s, is, q, n, g, it, jg, rg, jc, rc);
        add_row(jg, rg, kernel.irls_weight(rg));
        add_row(jc, rc, kernel.irls_weight(rc));
    }
};

}  // namespace detail
}  // namespace o3d::registration
